"""Terminal summaries of the rotor analyses' results (static.h5, modal.h5, campbell.h5, frf.h5, unbalance.h5 are
written from the same results): StaticResult, ModalResult, CampbellStudy, FrfResult, UnbalanceResult.

Each summary reads the frozen result its analysis returned (``fn(result) -> (lines, data)``), never a file or the
deck: critical speeds, amplification factors, separation margins (CampbellResult.crossings: API 684 AF and SM
computed once, in analysis/resonance.py) and the stability threshold (CampbellResult.first_unstable) are the
analysis's; a summary only prints them.  A Campbell study that stopped partway is summarised on the speeds it
solved (output/summary.py puts the INCOMPLETE line first).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .numbers import clean, g as _g


#: references of the noise floor when nothing loads the rotor: 1e-9 of them (1 pm, 1 uN) print 0
ABSOLUTE_M = 1e-3
ABSOLUTE_N = 1e3


def static(r):
    """StaticResult: the loads, the static stiffness (at the asked node, at the tool tip) and the deflection
    there, each bearing's reaction; values below the solution's noise print 0."""
    speed = float(r.speed_rpm)
    lines, data = [], {"speed_rpm": speed}
    F = np.asarray(r.applied_force_N, float)
    load = f"Fx {_g(F[0])} N, Fy {_g(F[1])} N"
    if r.axial_displacement_m is not None:  # a model with the axial DOF
        load += f", Fz {_g(float(r.applied_axial_force_N))} N"
    grav = float(r.gravity_m_s2)
    what = f", gravity {grav:g} m/s2 included" if grav else ", no gravity"
    lines.append(f"at {speed:g} rpm under the applied loads{what}: {load}")
    data["applied_force_N"] = F.tolist()
    # deflections below 1e-9 of the largest (and below 1 pm, when nothing loads the rotor) print 0
    disp_all = np.asarray(r.displacement_m, float)
    noise = max(float(np.max(np.abs(disp_all), initial=0.0)), ABSOLUTE_M)
    k, node, dof = float(r.static_stiffness_N_m), int(r.stiffness_node) + 1, str(r.stiffness_dof)
    disp = clean(disp_all[node - 1], noise)
    lines.append(f"static stiffness at node {node} {dof}: {k / 1e6:.4g} N/um; deflection there "
                 f"x {_g(disp[0] * 1e6)} um, y {_g(disp[1] * 1e6)} um")
    data.update(stiffness_N_m=k, stiffness_node=node, deflection_m=disp.tolist())
    if r.tool_tip_node is not None:
        lines.append(_tool_tip_line(r, disp_all, noise, data))
    lines += _reactions(r, F, data)
    return lines, data


def _tool_tip_line(r, disp_all: np.ndarray, noise: float, data: dict) -> str:
    """The tool tip's static stiffness in each direction and its deflection (``data`` gains them)."""
    tip = int(r.tool_tip_node) + 1
    ks = {str(d): float(v) for d, v in (r.tool_tip_stiffness_N_m or {}).items()}
    disp = clean(disp_all[tip - 1], noise)
    words = [f"{'axial' if d == 'z' else 'radial'} {d} {v / 1e6:.4g}" for d, v in ks.items()]
    data.update(tool_tip_node=tip, tool_tip_stiffness_N_m=ks)
    return (f"tool tip (node {tip}) static stiffness: {', '.join(words)} N/um; deflection there "
            f"x {_g(disp[0] * 1e6)} um, y {_g(disp[1] * 1e6)} um")


def _reactions(r, F: np.ndarray, data: dict) -> list[str]:
    """Each bearing's reaction on the shaft (below the noise of the largest force: 0); a damper has none."""
    names = [str(n) for n in r.bearing_names]
    forces = np.asarray(r.bearing_force_N, float)
    data["bearing_force_N"] = {n: fb.tolist() for n, fb in zip(names, forces)}
    shown = clean(forces, max(float(np.max(np.abs(forces), initial=0.0)), float(np.max(np.abs(F), initial=0.0)),
                              ABSOLUTE_N))
    dampers = [str(n) for n in r.damping_only]
    lines = [f"  bearing {n:12s} reaction " + ", ".join(f"{_g(v):>10s}" for v in np.ravel(fb)[:5]) + " N"
             for n, fb in zip(names, shown) if n not in dampers]
    if dampers:
        lines.append(f"  {', '.join(dampers)}: damping only (no stiffness, no static reaction)")
    return lines


def modal(r):
    """ModalResult: a table of the modes at its speed (frequency, damping ratio, log dec, whirl)."""
    fr, z, ld = (np.asarray(v, float) for v in (r.frequency_hz, r.damping_ratio, r.log_dec))
    wh = [str(w) for w in r.whirl]
    speed = float(r.speed_rpm)
    lines = [f"modes at {speed:g} rpm:", "   #  frequency Hz  damping ratio   log dec  whirl"]
    for k, (a, b, c, w) in enumerate(zip(fr, z, ld, wh)):
        lines.append(f"  {k + 1:2d}  {a:12.2f}  {b:13.3g}  {c:8.3g}  {w}" + ("   UNSTABLE" if b < 0 else ""))
    data = {"speed_rpm": speed, "frequency_hz": fr.tolist(), "damping_ratio": z.tolist(),
            "log_dec": ld.tolist(), "whirl": wh}
    return lines, data


def campbell(study):
    """CampbellStudy: its diagram's (``hot``) crossings judged by API 684, its critical speeds and its stability
    threshold, against the spindle's operating speed (``operating_rpm``)."""
    r = study.hot
    sp, fr = np.asarray(r.speed_rpm, float), np.asarray(r.frequency_hz, float)
    wh = np.asarray(r.whirl).astype(str)
    lines = [f"{len(sp)} speeds {sp[0]:g}-{sp[-1]:g} rpm, {fr.shape[1]} modes ({r.model})"]
    crossings = _crossing_rows(r.crossings) if r.crossings is not None else []
    if r.crossings is not None:
        lines += _crossing_lines(r.crossings, crossings)
        crit = [c for c in crossings if c["order"] == 1.0 and c["critical"] and c["whirl"] != "backward"]
    else:  # a diagram without its crossings: its critical speeds only
        crit = [{"speed_rpm": float(s), "mode": int(k) + 1} for s, k in zip(r.critical_speeds_rpm, r.critical_modes)]
    if crit:
        lines.append("  critical speeds (1x, AF >= 2.5, not backward): "
                     + ", ".join(f"{c['speed_rpm']:.0f} rpm (mode {c['mode']})" for c in crit))
    else:
        lines.append("  no critical speed (1x crossing with AF >= 2.5 of a mode other than backward) in the range")
    threshold = None
    if r.first_unstable is not None:  # the analysis's stability threshold: (speed, mode) indices
        i, k = r.first_unstable
        threshold = {"speed_rpm": float(sp[i]), "mode": k + 1, "frequency_hz": float(fr[i, k]),
                     "whirl": str(wh[i, k])}
        lines.append(f"  UNSTABLE from {sp[i]:g} rpm: mode {k + 1} ({wh[i, k]}, {fr[i, k]:.1f} Hz) has negative damping")
    else:
        lines.append("  every tracked mode is stable over the range")
    op = None if study.operating_rpm is None else float(study.operating_rpm)
    return lines, {"critical_speeds": crit, "crossings": crossings, "stability_threshold": threshold,
                   "operating_speed_rpm": op}


def _crossing_lines(c, rows: list[dict]) -> list[str]:
    """The operating range API 684 measures from and a table of the crossings ``rows`` of Crossings ``c``."""
    lines = []
    orders = ", ".join(f"{n:g}x" for n in np.asarray(c.orders, float))
    if c.min_operating_rpm is not None:
        lo, hi = float(c.min_operating_rpm), float(c.max_continuous_rpm)
        where = f"{lo:g} rpm" if lo == hi else f"{lo:g}-{hi:g} rpm"
        lines.append(f"  operating speed {where}; API 684 separation margins from it")
    if rows:
        lines.append(f"  crossings of {orders} with the tracked modes (AF = 1/(2 zeta), API 684 critical when "
                     ">= 2.5):")
        lines.append("     speed rpm  order  mode  whirl      freq Hz          AF  margin req  margin  API 684")
        lines += [_crossing_line(row) for row in rows]
    else:
        lines.append(f"  no crossing of {orders} with a tracked mode in the range")
    return lines


def _crossing_rows(c) -> list[dict]:
    """The crossings of a Crossings (analysis.resonance) as rows, modes 1-based (as campbell.h5 numbers them)."""
    cols = {"speed_rpm": c.speed_rpm, "order": c.order, "mode": np.asarray(c.mode) + 1,
            "frequency_hz": c.frequency_hz, "damping_ratio": c.damping_ratio,
            "amplification_factor": c.amplification_factor, "required_separation_margin": c.required_margin,
            "separation_margin": c.separation_margin}
    crit, meets = np.asarray(c.critical, bool), np.asarray(c.meets_api684, bool)
    rows = []
    for j in range(len(c.speed_rpm)):
        row = {k: (int(v[j]) if k == "mode" else _finite(v[j])) for k, v in cols.items()}
        row.update(whirl=str(c.whirl[j]), critical=bool(crit[j]), meets_api684=bool(meets[j]))
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


def frf(r):
    """FrfResult: the static compliance, every mode in range with the peak of |H| nearest to it, and, with a tool,
    the most negative real part of the tool point's H_xx (what limits a chatter-free depth)."""
    fr, h = np.asarray(r.frequency_hz, float), np.asarray(r.receptance_m_N)
    mag = np.abs(h)
    head = (f"response at node {int(r.output_node)} {r.output_dof} / force at node {int(r.input_node)} "
            f"{r.input_dof}, {float(r.speed_rpm):g} rpm; ")
    data: dict[str, Any] = {"peaks": []}
    if r.static_compliance_m_N is not None:
        c0 = float(r.static_compliance_m_N)
        head += f"static compliance (0 Hz, K^-1) {c0 * 1e6:.4g} um/N"
        data["static_compliance_m_N"] = c0
    else:
        head += f"|H| at {fr[0]:g} Hz {mag[0] * 1e6:.4g} um/N (no static compliance in the file)"
    lines = [head]
    if r.added is not None:
        n_add = int(np.sum(r.added))
        lines.append(f"  {len(fr) - n_add} frequencies of the deck's grid + {n_add} added around the modes in range")
    local = [i for i in range(1, len(mag) - 1) if mag[i] >= mag[i - 1] and mag[i] > mag[i + 1]]
    if r.modes is not None:
        lines += _peaks_of_modes(r.modes, fr, mag, local, data["peaks"])
    else:  # no modes: the local maxima of |H|
        for i in local:
            lines.append(f"  peak {fr[i]:9.1f} Hz  |H| {mag[i] * 1e6:.4g} um/N  dynamic stiffness "
                         f"{1e-6 / mag[i]:.4g} N/um")
            data["peaks"].append({"frequency_hz": float(fr[i]), "receptance_m_N": float(mag[i]),
                                  "dynamic_stiffness_N_m": float(1 / mag[i])})
    if r.tool_point is not None:
        re, ft = np.asarray(r.tool_point.H)[:, 0, 0].real, np.asarray(r.tool_point.frequency_hz, float)
        i = int(np.argmin(re))
        lines.append(f"  tool point: most negative real part of H_xx {re[i] * 1e6:.4g} um/N at {ft[i]:.1f} Hz")
        data["tool_point_min_real_m_N"] = float(re[i])
    return lines, data


def _peaks_of_modes(m, fr: np.ndarray, mag: np.ndarray, local: list[int], peaks: list) -> list[str]:
    """Every mode of ModesInRange ``m`` in the grid's range, with the local peak of |H| nearest to it within its
    band f_n (1 +- 3 zeta), in order of frequency (``peaks`` gains each peak and its modes)."""
    lo, hi = fr[0], fr[-1]
    by_peak: dict[int, list[str]] = {}
    unseen: list[tuple[float, str]] = []
    for fd, fn, zk, wk in zip(m.frequency_hz, m.undamped_frequency_hz, m.damping_ratio, m.whirl):
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
    for i in sorted(by_peak):
        peaks.append({"frequency_hz": float(fr[i]), "receptance_m_N": float(mag[i]),
                      "dynamic_stiffness_N_m": float(1 / mag[i]), "modes": by_peak[i]})
    return [text for _, text in sorted(rows + unseen)]


def unbalance(r):
    """UnbalanceResult: the peak response at the output over the sweep (0-peak and peak-to-peak) and, at each 1x
    crossing in range, the response peak near it with its API 684 amplification factors."""
    node, dof = int(r.output_node), str(r.output_dof)
    resp = np.asarray(r.response_m)[:, node - 1, 0 if dof == "x" else 1]
    sp = np.asarray(r.speed_rpm, float)
    i = int(np.argmax(np.abs(resp)))
    kind = r.amplitude  # the phasor modulus: 0-peak
    amp = abs(resp[i])
    lines = [f"peak response at node {node} {dof}: {amp * 1e6:.4g} um {kind} ({2 * amp * 1e6:.4g} um peak-to-peak) at "
             f"{sp[i]:.6g} rpm (unbalance {float(r.unbalance_kg_m) * 1e6:g} g mm at node {int(r.unbalance_node)})"]
    data: dict[str, Any] = {"peak_m": float(amp), "peak_to_peak_m": float(2 * amp), "peak_speed_rpm": float(sp[i]),
                            "amplitude": kind}
    if r.added is not None:
        n_add = int(np.sum(r.added))
        lines.append(f"  {len(sp) - n_add} speeds of the deck's grid + {n_add} added around the 1x crossings")
    if r.resonances is not None:
        rows = _crossing_rows(r.resonances.crossings)
        lines += _resonance_lines(r.resonances, rows, kind)
        data["resonances"] = rows
    return lines, data


def _resonance_lines(res, rows: list[dict], kind: str) -> list[str]:
    """One line per 1x crossing (``rows`` gain its response peak and half-power AF): UnbalanceResonances ``res``."""
    lines = []
    for row, ps, pa, af in zip(rows, res.peak_speed_rpm, res.peak_amplitude_m, res.half_power_af):
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
    return lines
