"""Short result summaries for the terminal, read back from the files a run wrote.

A summary is built from the HDF5 file, not from the solver's objects, so what a user reads on the
terminal (or a script reads with ``--json``) is what the file holds.  One function per file name
(:data:`SUMMARIES`); each returns ``(lines, data)``: a few text lines and the same numbers as a
JSON-able dict.  Engineering conventions used here:

* amplification factor AF = 1 / (2 zeta) of the mode at a critical speed, and the separation
  margin API 684 asks for when AF > 2.5: min(16 %, 17 (1 - 1/(AF - 1.5)) %) for a critical speed
  below the operating speed, min(26 %, 10 + 17 (1 - 1/(AF - 1.5)) %) above it (API RP 684,
  2nd ed., SP6.8.2.10); AF <= 2.5 needs no margin (critically damped);
* the stability threshold is the lowest speed at which a mode's damping ratio turns negative.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Callable

import numpy as np

API684_AF = 2.5


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


def required_separation_margin(af: float, below: bool) -> float:
    """API 684 separation margin [fraction] for a critical speed with amplification factor ``af``
    below (``below``) or above the operating speed; 0 when AF <= 2.5."""
    if not np.isfinite(af) or af <= API684_AF:
        return 0.0
    base = 17.0 * (1.0 - 1.0 / (af - 1.5))
    return (min(16.0, base) if below else min(26.0, 10.0 + base)) / 100.0


def _f(x) -> float:
    return float(np.asarray(x))


def _static(f):
    g = f["static"]
    a = g.attrs
    lines, data = [], {"speed_rpm": _f(a["speed_rpm"])}
    F = g["applied_force_N"][:]
    load = f"Fx {F[0]:.4g} N, Fy {F[1]:.4g} N"
    if "applied_axial_force_N" in g:
        load += f", Fz {_f(g['applied_axial_force_N'][()]):.4g} N"
    lines.append(f"at {data['speed_rpm']:g} rpm under the applied loads (gravity included): {load}")
    data["applied_force_N"] = F.tolist()
    if "static_stiffness_N_m" in g:
        k = _f(g["static_stiffness_N_m"][()])
        node, dof = int(a["stiffness_node"]), str(a["stiffness_dof"])
        i = node - 1
        disp = g["displacement_m"][i]
        lines.append(f"static stiffness at node {node} {dof}: {k / 1e6:.4g} N/um; deflection there "
                     f"x {disp[0] * 1e6:.4g} um, y {disp[1] * 1e6:.4g} um")
        data.update(stiffness_N_m=k, stiffness_node=node, deflection_m=disp.tolist())
    if "tool_tip_stiffness_N_m" in g:
        tip = int(a["tool_tip_node"])
        ks = dict(zip(g["tip_dof"][:].astype(str), g["tool_tip_stiffness_N_m"][:]))
        disp = g["displacement_m"][tip - 1]
        words = [f"{'axial' if d == 'z' else 'radial'} {d} {v / 1e6:.4g}" for d, v in ks.items()]
        lines.append(f"tool tip (node {tip}) static stiffness: {', '.join(words)} N/um; deflection there "
                     f"x {disp[0] * 1e6:.4g} um, y {disp[1] * 1e6:.4g} um")
        data.update(tool_tip_node=tip, tool_tip_stiffness_N_m={d: float(v) for d, v in ks.items()})
    names = [str(n) for n in g["bearing_name"][:].astype(str)]
    forces = g["bearing_force_N"][:]
    data["bearing_force_N"] = {n: fb.tolist() for n, fb in zip(names, forces)}
    for n, fb in zip(names, forces):
        lines.append(f"  bearing {n:12s} reaction " + ", ".join(f"{v:10.4g}" for v in np.ravel(fb)[:5]) + " N")
    return lines, data


def _modal(f):
    g = f["modal"]
    fr, z, ld = g["frequency_hz"][:], g["damping_ratio"][:], g["log_dec"][:]
    wh = g["whirl"][:].astype(str)
    lines = [f"modes at {_f(g.attrs['speed_rpm']):g} rpm:", "   #  frequency Hz  damping ratio   log dec  whirl"]
    for k, (a, b, c, w) in enumerate(zip(fr, z, ld, wh)):
        lines.append(f"  {k + 1:2d}  {a:12.2f}  {b:13.4f}  {c:8.4f}  {w}" + ("   UNSTABLE" if b < 0 else ""))
    data = {"speed_rpm": _f(g.attrs["speed_rpm"]), "frequency_hz": fr.tolist(), "damping_ratio": z.tolist(),
            "log_dec": ld.tolist(), "whirl": wh.tolist()}
    return lines, data


def _campbell(f):
    g = f["campbell"]
    sp, fr, z = g["speed_rpm"][:], g["frequency_hz"][:], g["damping_ratio"][:]
    wh = g["whirl"][:].astype(str)
    op = _deck_speed(f)
    lines = [f"{len(sp)} speeds {sp[0]:g}-{sp[-1]:g} rpm, {fr.shape[1]} modes ({g.attrs.get('model', '')})"]
    crit = []
    for s, k in zip(g["critical_speed_rpm"][:], g["critical_mode"][:]):
        zk = float(np.interp(s, sp, z[:, int(k)]))
        af = 1.0 / (2.0 * zk) if zk > 0 else np.inf
        entry = {"speed_rpm": float(s), "mode": int(k) + 1, "amplification_factor": af}
        text = f"  critical speed {s:9.0f} rpm (mode {int(k) + 1}), AF {af:.3g}"
        if op:
            below = s < op
            need = required_separation_margin(af, below)
            have = abs(op - s) / s
            entry.update(separation_margin=have, required_margin=need, meets_api684=bool(have >= need))
            text += (f", separation from {op:g} rpm {100 * have:.1f} % (API 684 asks {100 * need:.1f} %"
                     f"{'' if have >= need else ': NOT MET'})")
        crit.append(entry)
        lines.append(text)
    if not crit:
        lines.append("  no critical speed (1x crossing of a forward mode with AF >= 2.5) in the range")
    unstable = np.argwhere(z < 0)
    threshold = None
    if unstable.size:
        i, k = unstable[np.argmin(sp[unstable[:, 0]])]
        threshold = {"speed_rpm": float(sp[i]), "mode": int(k) + 1, "frequency_hz": float(fr[i, k]),
                     "whirl": str(wh[i, k])}
        lines.append(f"  UNSTABLE from {sp[i]:g} rpm: mode {k + 1} ({wh[i, k]}, {fr[i, k]:.1f} Hz) has negative damping")
    else:
        lines.append("  every tracked mode is stable over the range")
    return lines, {"critical_speeds": crit, "stability_threshold": threshold, "operating_speed_rpm": op}


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
    peaks = [i for i in range(1, len(mag) - 1) if mag[i] >= mag[i - 1] and mag[i] > mag[i + 1]]
    peaks = sorted(peaks, key=lambda i: -mag[i])[:4]
    lines = [f"node {int(a['output_node'])} {a['output_dof']} / node {int(a['input_node'])} {a['input_dof']} at "
             f"{_f(a['speed_rpm']):g} rpm; static-end compliance {mag[0] * 1e6:.4g} um/N"]
    data = {"peaks": []}
    for i in sorted(peaks, key=lambda i: fr[i]):
        lines.append(f"  peak {fr[i]:9.1f} Hz  |H| {mag[i] * 1e6:.4g} um/N  dynamic stiffness {1e-6 / mag[i]:.4g} N/um")
        data["peaks"].append({"frequency_hz": float(fr[i]), "receptance_m_N": float(mag[i]),
                              "dynamic_stiffness_N_m": float(1 / mag[i])})
    if "tool_point" in g:
        H = g["tool_point/receptance_m_N"][:]
        re = H[:, 0, 0].real
        i = int(np.argmin(re))
        lines.append(f"  tool point: most negative real part of H_xx {re[i] * 1e6:.4g} um/N at {fr[i]:.1f} Hz")
        data["tool_point_min_real_m_N"] = float(re[i])
    return lines, data


def _unbalance(f):
    g = f["unbalance"]
    a = g.attrs
    node, dof = int(a["output_node"]), str(a["output_dof"])
    r = g["response_m"][:, node - 1, 0 if dof == "x" else 1]
    sp = g["speed_rpm"][:]
    i = int(np.argmax(np.abs(r)))
    lines = [f"peak response at node {node} {dof}: {abs(r[i]) * 1e6:.4g} um at {sp[i]:g} rpm "
             f"(unbalance {float(a['unbalance_kg_m']) * 1e6:g} g mm at node {int(a['unbalance_node'])})"]
    return lines, {"peak_m": float(abs(r[i])), "peak_speed_rpm": float(sp[i])}


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
    fields = [("temperature_mean_C", "T_mean", 1.0, " C"), ("temperature_out_C", "T_out", 1.0, " C"),
              ("eccentricity_ratio", "eps", 1.0, ""), ("min_film_m", "h_min", 1e6, " um"),
              ("power_loss_W", "loss", 1.0, " W"), ("heat_to_housing_W", "to housing", 1.0, " W")]
    from ..bearings.fluidfilm.viscosity import OIL_MAX_C

    lines, data = _per_bearing(f, "thermal", fields)
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
    lines = [f"{t[-1]:.4g} s simulated ({a.get('method', '')}, {int(len(t))} samples); "
             f"vibration amplitude over the last half x {amp[0] * 1e6:.4g} um, y {amp[1] * 1e6:.4g} um"]
    data = {"duration_s": float(t[-1]), "amplitude_m": amp.tolist()}
    fr = g["spectrum/frequency_hz"][:] if "spectrum" in g else np.zeros(0)
    if len(fr) > 1:
        A = g["spectrum/amplitude_m"][:]
        k = int(np.argmax(np.max(A, axis=1)[1:])) + 1
        lines.append(f"  dominant line {fr[k]:.2f} Hz, {np.max(A[k]) * 1e6:.4g} um")
        data["dominant_hz"] = float(fr[k])
    elif "spectrum" in g:
        lines.append("  no spectrum: not enough steady data")
    for key in ("roller_pass_frequency_hz", "cage_frequency_hz"):
        if key in a:
            data[key] = float(a[key])
    if "roller_pass_frequency_hz" in a:
        lines.append(f"  roller pass {float(a['roller_pass_frequency_hz']):.2f} Hz, cage {float(a['cage_frequency_hz']):.2f} Hz")
    return lines, data


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


def _stiffness_lines(K) -> list[str]:
    d = np.diag(np.asarray(K, float))
    names = ("Kxx", "Kyy", "Kzz", "Ktx", "Kty")[: len(d)]
    return ["  stiffness " + ", ".join(f"{n} {v / (1e6 if k < 3 else 1.0):.4g}{' N/um' if k < 3 else ' N m/rad'}"
                                       for k, (n, v) in enumerate(zip(names, d)))]


def _bearing(f):
    g = f["bearing"]
    a = g.attrs
    lines = [str(a.get("operating_point", ""))]
    K = g["stiffness"][()]
    lines += _stiffness_lines(K)
    Q = g["element_load_N"][()]
    p = g["max_pressure_Pa"][()]
    lines.append(f"  largest ball load {Q.max():.4g} N, contact pressure {p.max() * 1e-9:.3g} GPa; "
                 f"contact angles {g['contact_angle_inner_deg'][()].min():.1f}-{g['contact_angle_inner_deg'][()].max():.1f} deg (inner)")
    data = {"stiffness_diagonal": np.diag(K).tolist(), "max_element_load_N": float(Q.max()),
            "max_pressure_Pa": float(p.max())}
    if "life_L10_Mrev" in g:
        L = float(g["life_L10_Mrev"][()])
        speed = float(a.get("speed_rpm", 0.0))
        lines.append(f"  basic rating life L10 {L:.4g} million rev" + (f" = {L * 1e6 / speed / 60:.4g} h" if speed else ""))
        data["life_L10_Mrev"] = L
    return lines, data


def _dtrb(f):
    g = f["dtrb"]
    K = g["stiffness"][()]
    Q = g["roller_load_N"][()]
    lines = [f"load {np.array2string(np.asarray(g.attrs['applied_load']), precision=4, separator=', ')} "
             f"(N, N m) at {float(g.attrs['speed_rpm']):.0f} rpm, preload {float(g.attrs['preload_m']) * 1e6:.3g} um"]
    lines += _stiffness_lines(K)
    lines.append(f"  largest roller load {Q.max():.4g} N; loaded rollers {int(np.sum(Q > 0))} of {Q.size}")
    return lines, {"stiffness_diagonal": np.diag(K).tolist(), "max_roller_load_N": float(Q.max())}


def _contact(f):
    a = f["contact"].attrs
    p, area = float(a["max_pressure_Pa"]), float(a["area_m2"])
    lines = [f"load {float(a['load_N']):.4g} N: maximum pressure {p * 1e-9:.4g} GPa, contact area {area * 1e6:.4g} mm2, "
             f"approach {float(a['approach_m']) * 1e6:.4g} um"
             + ("; EDGE STRESS (pressure singular at the roller end)" if a.get("edge_singular") else "")]
    return lines, {"max_pressure_Pa": p, "area_m2": area, "approach_m": float(a["approach_m"])}


SUMMARIES: dict[str, Callable] = {
    "static": _static, "modal": _modal, "campbell": _campbell, "frf": _frf, "unbalance": _unbalance,
    "thermal": _thermal, "coefficients": _coefficients, "transient": _transient, "chatter": _chatter,
    "bearing": _bearing, "dtrb": _dtrb, "contact": _contact,
}
