"""Short result summaries for the terminal, read back from the files a run wrote.

A summary is built from the HDF5 file, not from the solver's objects, so what a user reads on the
terminal (or a script reads with ``--json``) is what the file holds.  One function per file name
(:data:`SUMMARIES`); each returns ``(lines, data)``: a few text lines and the same numbers as a
JSON-able dict.  Engineering conventions used here:

* critical speeds, amplification factors and separation margins are the analysis's (campbell.h5
  /campbell/crossings: API 684 AF and SM computed once, in analysis/resonance.py); the summary
  only prints them;
* the stability threshold is the lowest speed at which a mode's damping ratio turns negative.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Callable

import numpy as np

from .labels import frequency_label, readable_keys
from .numbers import clean, g as _g, with_resolution
from .summary_bearings import _bearing, _contact, _dtrb


def summarize(paths: list[Path]) -> list[tuple[str, list[str], dict[str, Any]]]:
    """(file name, lines, data) for every HDF5 file among ``paths`` that has a summary."""
    import h5py

    out = []
    for p in paths:
        fn = SUMMARIES.get(Path(p).stem)
        if fn is None or Path(p).suffix != ".h5":
            continue
        with h5py.File(p, "r") as f:
            lines, data = fn(f)
            if not f.attrs.get("complete", True):
                reason = f.attrs.get("incomplete_reason", "")
                lines.insert(0, f"INCOMPLETE: {reason}" if reason else "INCOMPLETE")
                data["complete"] = False
        out.append((Path(p).name, lines, data))
    return out


def _f(x) -> float:
    return float(np.asarray(x))


def _static(f):
    g = f["static"]
    a = g.attrs
    lines, data = [], {"speed_rpm": _f(a["speed_rpm"])}
    F = g["applied_force_N"][:]
    load = f"Fx {_g(F[0])} N, Fy {_g(F[1])} N"
    if "applied_axial_force_N" in g:
        load += f", Fz {_g(_f(g['applied_axial_force_N'][()]))} N"
    lines.append(f"at {data['speed_rpm']:g} rpm under the applied loads (gravity included): {load}")
    data["applied_force_N"] = F.tolist()
    noise = float(np.max(np.abs(g["displacement_m"][:]), initial=0.0))  # deflections below its noise: 0
    if "static_stiffness_N_m" in g:
        k = _f(g["static_stiffness_N_m"][()])
        node, dof = int(a["stiffness_node"]), str(a["stiffness_dof"])
        i = node - 1
        disp = clean(g["displacement_m"][i], noise)
        lines.append(f"static stiffness at node {node} {dof}: {k / 1e6:.4g} N/um; deflection there "
                     f"x {_g(disp[0] * 1e6)} um, y {_g(disp[1] * 1e6)} um")
        data.update(stiffness_N_m=k, stiffness_node=node, deflection_m=disp.tolist())
    if "tool_tip_stiffness_N_m" in g:
        tip = int(a["tool_tip_node"])
        ks = dict(zip(g["tip_dof"][:].astype(str), g["tool_tip_stiffness_N_m"][:]))
        disp = clean(g["displacement_m"][tip - 1], noise)
        words = [f"{'axial' if d == 'z' else 'radial'} {d} {v / 1e6:.4g}" for d, v in ks.items()]
        lines.append(f"tool tip (node {tip}) static stiffness: {', '.join(words)} N/um; deflection there "
                     f"x {_g(disp[0] * 1e6)} um, y {_g(disp[1] * 1e6)} um")
        data.update(tool_tip_node=tip, tool_tip_stiffness_N_m={d: float(v) for d, v in ks.items()})
    names = [str(n) for n in g["bearing_name"][:].astype(str)]
    forces = g["bearing_force_N"][:]
    data["bearing_force_N"] = {n: fb.tolist() for n, fb in zip(names, forces)}
    shown = clean(forces, max(float(np.max(np.abs(forces), initial=0.0)), float(np.max(np.abs(F), initial=0.0))))
    for n, fb in zip(names, shown):  # below the noise of the largest force: 0
        lines.append(f"  bearing {n:12s} reaction " + ", ".join(f"{_g(v):>10s}" for v in np.ravel(fb)[:5]) + " N")
    return lines, data


def _modal(f):
    g = f["modal"]
    fr, z, ld = g["frequency_hz"][:], g["damping_ratio"][:], g["log_dec"][:]
    wh = g["whirl"][:].astype(str)
    lines = [f"modes at {_f(g.attrs['speed_rpm']):g} rpm:", "   #  frequency Hz  damping ratio   log dec  whirl"]
    for k, (a, b, c, w) in enumerate(zip(fr, z, ld, wh)):
        lines.append(f"  {k + 1:2d}  {a:12.2f}  {b:13.3g}  {c:8.3g}  {w}" + ("   UNSTABLE" if b < 0 else ""))
    data = {"speed_rpm": _f(g.attrs["speed_rpm"]), "frequency_hz": fr.tolist(), "damping_ratio": z.tolist(),
            "log_dec": ld.tolist(), "whirl": wh.tolist()}
    return lines, data


def _campbell(f):
    g = f["campbell"]
    sp, fr, z = g["speed_rpm"][:], g["frequency_hz"][:], g["damping_ratio"][:]
    wh = g["whirl"][:].astype(str)
    op = _deck_speed(f)
    lines = [f"{len(sp)} speeds {sp[0]:g}-{sp[-1]:g} rpm, {fr.shape[1]} modes ({g.attrs.get('model', '')})"]
    crossings = _crossing_rows(g["crossings"]) if "crossings" in g else []
    if "crossings" in g:
        a = g["crossings"].attrs
        orders = ", ".join(f"{n:g}x" for n in np.asarray(a.get("orders", []), float))
        if "min_operating_rpm" in a:
            lo, hi = float(a["min_operating_rpm"]), float(a["max_continuous_rpm"])
            where = f"{lo:g} rpm" if lo == hi else f"{lo:g}-{hi:g} rpm"
            lines.append(f"  operating speed {where}; API 684 separation margins from it")
        if crossings:
            lines.append(f"  crossings of {orders} with the tracked modes (AF = 1/(2 zeta), API 684 critical when "
                         ">= 2.5):")
            lines.append("     speed rpm  order  mode  whirl      freq Hz          AF  margin req  margin  API 684")
            lines += [_crossing_line(c) for c in crossings]
        else:
            lines.append(f"  no crossing of {orders} with a tracked mode in the range")
    crit = [c for c in crossings if c["order"] == 1.0 and c["critical"] and c["whirl"] != "backward"]
    if "crossings" not in g:  # a file from before the crossings: its critical speeds only
        crit = [{"speed_rpm": float(s), "mode": int(k) + 1} for s, k in zip(g["critical_speed_rpm"][:],
                                                                                g["critical_mode"][:])]
    if crit:
        lines.append("  critical speeds (1x, AF >= 2.5, not backward): "
                     + ", ".join(f"{c['speed_rpm']:.0f} rpm (mode {c['mode']})" for c in crit))
    else:
        lines.append("  no critical speed (1x crossing with AF >= 2.5 of a mode other than backward) in the range")
    unstable = np.argwhere(z < 0)
    threshold = None
    if unstable.size:
        i, k = unstable[np.argmin(sp[unstable[:, 0]])]
        threshold = {"speed_rpm": float(sp[i]), "mode": int(k) + 1, "frequency_hz": float(fr[i, k]),
                     "whirl": str(wh[i, k])}
        lines.append(f"  UNSTABLE from {sp[i]:g} rpm: mode {k + 1} ({wh[i, k]}, {fr[i, k]:.1f} Hz) has negative damping")
    else:
        lines.append("  every tracked mode is stable over the range")
    return lines, {"critical_speeds": crit, "crossings": crossings, "stability_threshold": threshold,
                   "operating_speed_rpm": op}


def _crossing_rows(c) -> list[dict]:
    """The crossings of a campbell.h5 or unbalance.h5 group, as written by the analysis."""
    keys = ("speed_rpm", "order", "mode", "frequency_hz", "damping_ratio", "amplification_factor",
            "required_separation_margin", "separation_margin")
    cols = {k: c[k][:] for k in keys}
    whirl = c["whirl"][:].astype(str)
    crit, meets = c["critical"][:], c["meets_api684"][:]
    rows = []
    for j in range(len(cols["speed_rpm"])):
        row = {k: (int(v[j]) if k == "mode" else _finite(v[j])) for k, v in cols.items()}
        row.update(whirl=str(whirl[j]), critical=bool(crit[j]), meets_api684=bool(meets[j]))
        rows.append(row)
    return rows


def _finite(x) -> float | None:
    x = float(x)
    return x if np.isfinite(x) else None


def _crossing_line(c: dict) -> str:
    af = "unstable" if c["amplification_factor"] is None else f"{c['amplification_factor']:.3g}"
    sm = c["separation_margin"]
    if not c["critical"]:
        req, have, verdict = "-", "-" if sm is None else f"{100 * sm:.1f} %", "not critical (AF < 2.5)"
    else:
        req = f"{100 * c['required_separation_margin']:.1f} %"
        have = "-" if sm is None else f"{100 * sm:.1f} %"
        verdict = "no operating speed" if sm is None else ("met" if c["meets_api684"] else "NOT MET")
    return (f"  {c['speed_rpm']:11.0f}  {c['order']:4g}x  {c['mode']:4d}  {c['whirl']:9s} {c['frequency_hz']:8.1f}  "
            f"{af:>10s}  {req:>10s}  {have:>6s}  {verdict}")


def _deck_speed(f) -> float | None:
    import yaml

    try:
        d = yaml.safe_load(str(f.attrs.get("deck_text", ""))) or {}
        s = float(d.get("operating", {}).get("speed_rpm"))
        return s if s > 0 else None
    except (TypeError, ValueError, AttributeError, yaml.YAMLError):
        return None


def _frf(f):
    g = f["frf"]
    fr, h = g["frequency_hz"][:], g["receptance_m_N"][:]
    a = g.attrs
    mag = np.abs(h)
    head = (f"response at node {int(a['output_node'])} {a['output_dof']} / force at node {int(a['input_node'])} "
            f"{a['input_dof']}, {_f(a['speed_rpm']):g} rpm; ")
    data: dict[str, Any] = {"peaks": []}
    if "static_compliance_m_N" in g:
        c0 = _f(g["static_compliance_m_N"][()])
        head += f"static compliance (0 Hz, K^-1) {c0 * 1e6:.4g} um/N"
        data["static_compliance_m_N"] = c0
    else:
        head += f"|H| at {fr[0]:g} Hz {mag[0] * 1e6:.4g} um/N (no static compliance in the file)"
    lines = [head]
    if "added" in g:
        n_add = int(np.sum(g["added"][:]))
        lines.append(f"  {len(fr) - n_add} frequencies of the deck's grid + {n_add} added around the modes in range")
    local = [i for i in range(1, len(mag) - 1) if mag[i] >= mag[i - 1] and mag[i] > mag[i + 1]]
    if "modes" in g:  # every mode in range, with the peak of |H| nearest to it within its band f_n (1 +- 3 zeta)
        m = g["modes"]
        lo, hi = fr[0], fr[-1]
        by_peak: dict[int, list[str]] = {}
        unseen: list[tuple[float, str]] = []
        for fd, fn, zk, wk in zip(m["frequency_hz"][:], m["undamped_frequency_hz"][:], m["damping_ratio"][:],
                                  m["whirl"][:].astype(str)):
            if not lo <= fd <= hi:
                continue
            near = [i for i in local if abs(fr[i] - fn) <= 3 * max(abs(zk), 1e-6) * fn]
            name = f"{fd:.1f} Hz {wk} (zeta {zk:.3g})"
            if near:
                by_peak.setdefault(min(near, key=lambda i: abs(fr[i] - fn)), []).append(name)
            else:
                unseen.append((float(fd), f"  mode {name}: no peak of |H| (not seen at this output and input)"))
        rows = [(float(fr[i]), f"  peak {fr[i]:9.2f} Hz  |H| {mag[i] * 1e6:.4g} um/N  dynamic stiffness "
                               f"{1e-6 / mag[i]:.4g} N/um  (mode {', '.join(by_peak[i])})") for i in by_peak]
        lines += [text for _, text in sorted(rows + unseen)]
        for i in sorted(by_peak):
            data["peaks"].append({"frequency_hz": float(fr[i]), "receptance_m_N": float(mag[i]),
                                  "dynamic_stiffness_N_m": float(1 / mag[i]), "modes": by_peak[i]})
    else:  # a file without the modes: the local maxima of |H|
        for i in local:
            lines.append(f"  peak {fr[i]:9.1f} Hz  |H| {mag[i] * 1e6:.4g} um/N  dynamic stiffness "
                         f"{1e-6 / mag[i]:.4g} N/um")
            data["peaks"].append({"frequency_hz": float(fr[i]), "receptance_m_N": float(mag[i]),
                                  "dynamic_stiffness_N_m": float(1 / mag[i])})
    if "tool_point" in g:
        H = g["tool_point/receptance_m_N"][:]
        ft = g["tool_point/frequency_hz"][:]
        re = H[:, 0, 0].real
        i = int(np.argmin(re))
        lines.append(f"  tool point: most negative real part of H_xx {re[i] * 1e6:.4g} um/N at {ft[i]:.1f} Hz")
        data["tool_point_min_real_m_N"] = float(re[i])
    return lines, data


def _unbalance(f):
    g = f["unbalance"]
    a = g.attrs
    node, dof = int(a["output_node"]), str(a["output_dof"])
    r = g["response_m"][:, node - 1, 0 if dof == "x" else 1]
    sp = g["speed_rpm"][:]
    i = int(np.argmax(np.abs(r)))
    kind = str(a.get("amplitude", "0-peak")).split(" ")[0]  # the phasor modulus: 0-peak
    amp = abs(r[i])
    lines = [f"peak response at node {node} {dof}: {amp * 1e6:.4g} um {kind} ({2 * amp * 1e6:.4g} um peak-to-peak) at "
             f"{sp[i]:.6g} rpm (unbalance {float(a['unbalance_kg_m']) * 1e6:g} g mm at node "
             f"{int(a['unbalance_node'])})"]
    data: dict[str, Any] = {"peak_m": float(amp), "peak_to_peak_m": float(2 * amp), "peak_speed_rpm": float(sp[i]),
                            "amplitude": kind}
    if "added" in g:
        n_add = int(np.sum(g["added"][:]))
        lines.append(f"  {len(sp) - n_add} speeds of the deck's grid + {n_add} added around the 1x crossings")
    if "resonances" in g:
        res = g["resonances"]
        rows = _crossing_rows(res)
        for row, ps, pa, af in zip(rows, res["peak_speed_rpm"][:], res["peak_amplitude_m"][:],
                                   res["half_power_amplification_factor"][:]):
            row.update(peak_speed_rpm=_finite(ps), peak_amplitude_m=_finite(pa), half_power_af=_finite(af))
            eig = "-" if row["amplification_factor"] is None else f"{row['amplification_factor']:.3g}"
            text = (f"  1x crossing {row['speed_rpm']:.6g} rpm, mode {row['mode']} ({row['whirl']}, "
                    f"{row['frequency_hz']:.1f} Hz, AF 1/(2 zeta) {eig}): ")
            if np.isfinite(pa):
                hp = f", AF from half-power speeds {af:.3g}" if np.isfinite(af) else ""
                text += f"peak {pa * 1e6:.4g} um {kind} at {ps:.6g} rpm{hp}"
            else:
                text += "no response peak at the output"
            lines.append(text)
        if not rows:
            lines.append("  no 1x crossing of a mode in the speed range")
        data["resonances"] = rows
    return lines, data


def _per_bearing(f, group: str, fields: list[tuple[str, str, float, str]]):
    g = f[group]
    lines, data = [], {}
    for name in g:
        b = g[name]
        row = {k: float(np.asarray(b[k][()])) for k, *_ in fields if k in b}
        data[name] = row
        lines.append(f"  {name:10s} " + "  ".join(f"{lab} {row[k] * s:.4g}{u}" for k, lab, s, u in fields if k in row))
    return lines, data


def _thermal(f):
    if "spindle_thermal" in f:
        return _spindle_thermal(f)
    return _fluid_film_thermal(f)


def _spindle_thermal(f):
    """Heat, bearing temperatures, operating preload and tool-tip drift at each speed; the runaway."""
    g = f["spindle_thermal"]
    a = g.attrs
    lines, data = [], {}
    if "speed_rpm" in g:
        sp = g["speed_rpm"][:]
        names = [str(n) for n in g["bearing"][:].astype(str)]
        sources = [str(n) for n in g["source"][:].astype(str)]
        heat, inner, outer = g["heat_W"][:], g["inner_ring_C"][:], g["outer_ring_C"][:]
        thrust = g["row_thrust_N"][:]
        drift = g["tool_tip_axial_drift_m"][:]
        lines.append(f"thermal equilibrium at {len(sp)} speed(s), ambient {float(a['ambient_C']):g} C, "
                     f"{a['lubrication']}, motor load {float(a['motor_load_fraction']):g}")
        for i, s in enumerate(sp):
            motor = sum(heat[i, k] for k, n in enumerate(sources) if n.startswith("motor"))
            parts = [f"{n} {heat[i, sources.index('bearing:' + n)]:.0f} W, rings {inner[i, j]:.1f}/{outer[i, j]:.1f} C, "
                     f"preload {np.nanmax(thrust[i, j]):.0f} N" for j, n in enumerate(names) if f"bearing:{n}" in sources]
            tip = "" if not np.isfinite(drift[i]) else f"; tool tip {drift[i] * 1e6:+.1f} um axially"
            lines.append(f"  {s:7.0f} rpm: motor {motor:.0f} W; " + "; ".join(parts) + tip)
        data.update(speed_rpm=sp.tolist(), heat_W=heat.tolist(), tool_tip_axial_drift_m=drift.tolist())
    if "speed_limit_rpm" in a:
        lo, hi = (float(v) for v in a["speed_limit_rpm"])
        lines.append(f"  THERMAL SPEED LIMIT: stable up to {lo:.0f} rpm, runs away from {hi:.0f} rpm")
        data["speed_limit_rpm"] = [lo, hi]
    if "runaway" in a:
        lines.append(f"  THERMAL RUNAWAY: {a['runaway']}")
        data["runaway"] = str(a["runaway"])
        if "runaway_speed_rpm" in a:
            data["runaway_speed_rpm"] = float(a["runaway_speed_rpm"])
    if "warm_up" in g:
        w = g["warm_up"]
        t = w["time_s"][:]
        drift = w["tool_tip_axial_drift_m"][:]
        fr = w["natural_frequency_hz"][:]
        line = f"  warm-up over {t[-1] / 60:.0f} min ({len(t)} instants)"
        if np.isfinite(drift).any():
            line += f": tool tip axial drift {np.nanmin(drift) * 1e6:+.1f} .. {np.nanmax(drift) * 1e6:+.1f} um"
        if fr.size and np.isfinite(fr[:, 0]).all():
            line += f"; first natural frequency {fr[0, 0]:.1f} -> {fr[-1, 0]:.1f} Hz"
        lines.append(line)
        data["warm_up_final_drift_m"] = float(drift[-1])
    return lines, data


def _fluid_film_thermal(f):
    fields = [("temperature_mean_C", "T_mean", 1.0, " C"), ("temperature_out_C", "T_out", 1.0, " C"),
              ("eccentricity_ratio", "eps", 1.0, ""), ("min_film_m", "h_min", 1e6, " um"),
              ("power_loss_W", "loss", 1.0, " W"), ("heat_to_housing_W", "to housing", 1.0, " W")]
    from ..bearings.fluidfilm.viscosity import OIL_MAX_C

    lines, data = _per_bearing(f, "thermal", fields)
    iso = [n for n, g in f["thermal"].items() if "not_computed" in g.attrs]
    if iso:
        lines.append(f"  {', '.join(iso)}: isoviscous film, no heat balance (the oil has no density and specific heat)")
    hot = [n for n, row in data.items() if row.get("temperature_mean_C", 0.0) > OIL_MAX_C]
    if hot:
        lines.append(f"  WARNING: {', '.join(hot)} above {OIL_MAX_C:g} C mean film temperature (beyond a mineral "
                     "oil's usable range)")
    return [f"thermal equilibrium at {_f(f['thermal'].attrs['speed_rpm']):g} rpm:"] + lines, data


def _coefficients(f):
    g = f["coefficients"]
    lines, data = [f"bearing coefficients at {_f(g.attrs['speed_rpm']):g} rpm (x, y):"], {}
    for name in g:
        K, C = g[name]["K_N_m"][:], g[name]["C_Ns_m"][:]
        data[name] = {"K_N_m": K.tolist(), "C_Ns_m": C.tolist()}
        lines.append(f"  {name:10s} K [N/um] xx {K[0, 0] / 1e6:.4g} xy {K[0, 1] / 1e6:.4g} yx {K[1, 0] / 1e6:.4g} "
                     f"yy {K[1, 1] / 1e6:.4g}   C [N s/mm] xx {C[0, 0] / 1e3:.4g} xy {C[0, 1] / 1e3:.4g} "
                     f"yx {C[1, 0] / 1e3:.4g} yy {C[1, 1] / 1e3:.4g}")
    return lines, data


def _transient(f):
    g = f["transient"]
    t, x = g["time_s"][:], g["displacement_m"][:]
    a = g.attrs
    late = t >= t[-1] / 2
    amp = np.max(np.abs(x[late] - x[late].mean(axis=0)), axis=0) if late.any() else np.full(2, np.nan)
    settled = bool(a["settled"]) if "settled" in a else None
    lines = [f"{t[-1]:.4g} s simulated ({a.get('method', '')}, {int(len(t))} samples); "
             f"vibration amplitude over the last half x {amp[0] * 1e6:.4g} um, y {amp[1] * 1e6:.4g} um"
             + (" (NOT SETTLED: not a steady amplitude)" if settled is False else "")]
    data = {"duration_s": float(t[-1]), "amplitude_m": amp.tolist()}
    bearings = list(g.get("bearings", {}))
    lines += _transient_settling(a, data, bearings)
    fr = g["spectrum/frequency_hz"][:] if "spectrum" in g else np.zeros(0)
    if len(fr) > 1:
        A = g["spectrum/amplitude_m"][:]
        k = int(np.argmax(np.max(A, axis=1)[1:])) + 1
        df = float(fr[1] - fr[0])
        lines.append(f"  dominant line {with_resolution(fr[k], df / 2, 'Hz')}, {np.max(A[k]) * 1e6:.4g} um"
                     + (" (of a response that has NOT SETTLED)" if settled is False else ""))
        data["dominant_hz"] = float(fr[k])
    elif "spectrum" in g:
        lines.append("  no spectrum: not enough steady data")
    if "poincare" in g and "periodicity" in g["poincare"].attrs:
        lines.append("  " + _poincare_words(g["poincare"].attrs, bearings))
        data["poincare_periodicity"] = str(g["poincare"].attrs["periodicity"])
    for key in ("roller_pass_frequency_hz", "cage_frequency_hz"):
        if key in a:
            data[key] = float(a[key])
    if "roller_pass_frequency_hz" in a:
        lines.append(f"  roller pass {float(a['roller_pass_frequency_hz']):.2f} Hz, cage {float(a['cage_frequency_hz']):.2f} Hz")
    return lines, data


def _transient_settling(a, data: dict, bearings: list[str]) -> list[str]:
    """What the file says of the steady part: settled or not, and the spectrum's resolution."""
    if "settling_note" not in a:
        return []
    note = str(a["settling_note"]).replace("not settled:", "NOT SETTLED:", 1)
    head = f"  steady part from {float(a['settle_s']):.4g} s"
    dur = float(a.get("steady_duration_s", 0.0))
    if dur > 0 and "frequency_resolution_hz" in a:
        head += f" ({dur:.4g} s long, spectrum bin {float(a['frequency_resolution_hz']):.3g} Hz)"
        data["frequency_resolution_hz"] = float(a["frequency_resolution_hz"])
    data["settled"] = bool(a["settled"])
    data["steady_duration_s"] = dur
    unresolved = str(a.get("unresolved_frequencies", ""))
    data["unresolved_frequencies"] = [u for u in unresolved.split(", ") if u]
    out = [f"{head}: {note}"]
    if a.get("resolution_note", ""):
        note = readable_keys(str(a["resolution_note"]), bearings)
        out.append("  " + note.replace("window too short", "WINDOW TOO SHORT", 1))
    return out


def _poincare_words(p, bearings: list[str]) -> str:
    """The primary Poincare set's periodicity, with its tolerance, from its group's attributes."""
    label, n = str(p["periodicity"]), int(p.get("classified_points", 0))
    rel = float(p.get("relative_tolerance", np.nan))
    tol = f"tolerance {float(p['tolerance_m']):.3g} m" + (f" = {100 * rel:.2g} % of the orbit" if np.isfinite(rel)
                                                           else "")
    sampling = str(p.get("sampling", ""))
    if sampling.startswith("once per "):
        sampling = "once per " + frequency_label(sampling[len("once per "):], bearings)
    s = f"Poincare {sampling}: {label}"
    if label.startswith("period-"):
        k = int(p["period"])
        ext = float(p.get("orbit_extent_m", 0.0))
        within = (f"all within {100 * float(p['spread_m']) / ext:.2g} % of the orbit size of their mean"
                  if k == 1 and ext > 0 else f"on {k} places")
        return s + f" ({n} points, {within}; {tol})"
    if n:
        return s + f" ({int(p['distinct_points'])} distinct places among {n} points; {tol})"
    return s


def _chatter(f):
    g = f["chatter"]
    a = g.attrs
    lines = [f"{a['process']}; FRF from {a['frf_source']}" + (" recomputed at every speed" if a.get("frf_at_each_speed")
                                                              else "")]
    lines.append(f"  method: {a.get('method_selection') or str(a['method']).replace('_', ' ')}")
    data: dict[str, Any] = {"method": str(a["method"])}
    if "method" in g:
        used = [str(m) for m in g["method"].asstr()[:]]
        counts = {m: used.count(m) for m in dict.fromkeys(used)}
        if len(counts) > 1:
            lines.append("  limits from " + ", ".join(f"{m.replace('_', ' ')} at {k} speed(s)" for m, k in counts.items()))
    if "minimum_limit_depth_m" in a:
        d, s = float(a["minimum_limit_depth_m"]), float(a["minimum_at_speed_rpm"])
        lines.append(f"  minimum limit depth {d * 1e3:.3g} mm at {s:,.0f} rpm")
        data.update(minimum_limit_depth_m=d, minimum_at_speed_rpm=s)
    if int(a.get("capped_speeds", 0)):
        lines.append(f"  {int(a['capped_speeds'])} speed(s) stable up to the depth cap "
                     f"{float(a['depth_cap_m']) * 1e3:.3g} mm (the largest depth searched; no limit below it): "
                     f"{a.get('capped_speeds_rpm', '')}")
    if "recommended_speed_rpm" in a:
        n, tol = float(a["recommended_speed_rpm"]), float(a["recommended_speed_tolerance_rpm"])
        dep, peak = float(a["recommended_depth_m"]), float(a["pocket_peak_depth_m"])
        lines.append(f"  recommended: {n:,.0f} rpm +- {tol:,.0f} rpm at up to {dep * 1e3:.3g} mm (stability pocket "
                     f"{float(a['pocket_speed_min_rpm']):,.0f}-{float(a['pocket_speed_max_rpm']):,.0f} rpm, where the "
                     f"limit stays at or above {float(a['pocket_level']):.0%} of the pocket's "
                     f"{'>= ' if bool(a['pocket_capped']) else ''}{peak * 1e3:.3g} mm)")
        if int(a.get("pocket_grid_speeds", 3)) < 3:
            lines.append(f"    (no pocket holds 3 or more grid speeds; this one {int(a['pocket_grid_speeds'])}: refine the "
                         "speed grid around it before relying on it)")
        data.update(recommended_speed_rpm=n, recommended_depth_m=dep, recommended_speed_tolerance_rpm=tol)
    elif "recommendation" in a:
        lines.append(f"  recommended: {a['recommendation']}")
    for name in g.get("simulation", {}):
        s = g["simulation"][name].attrs
        state = "stable" if s["stable"] else f"CHATTER at {float(s['chatter_frequency_hz']):.0f} Hz"
        basis = str(s["verdict"]).partition(": ")[2] if "verdict" in s else ""
        lines.append(f"  simulation {float(s['speed_rpm']):g} rpm, {float(s['depth_m']) * 1e3:g} mm: {state}"
                     + (f" ({basis})" if basis else ""))
    return lines, data


SUMMARIES: dict[str, Callable] = {
    "static": _static, "modal": _modal, "campbell": _campbell, "frf": _frf, "unbalance": _unbalance,
    "thermal": _thermal, "coefficients": _coefficients, "transient": _transient, "chatter": _chatter,
    "bearing": _bearing, "dtrb": _dtrb, "contact": _contact,
}
