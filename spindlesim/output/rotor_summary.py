"""Terminal summaries of the rotor's files: static.h5, modal.h5, campbell.h5, frf.h5, unbalance.h5.

Critical speeds, amplification factors, separation margins (campbell.h5 /campbell/crossings: API 684 AF
and SM computed once, in analysis/resonance.py) and the stability threshold (/campbell ``first_unstable``,
``stable``) are the analysis's; a summary only prints them.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .numbers import clean, g as _g
from .summary import scalar


#: references of the noise floor when nothing loads the rotor: 1e-9 of them (1 pm, 1 uN) print 0
ABSOLUTE_M = 1e-3
ABSOLUTE_N = 1e3


def static(f):
    g = f["static"]
    a = g.attrs
    lines, data = [], {"speed_rpm": scalar(a["speed_rpm"])}
    F = g["applied_force_N"][:]
    load = f"Fx {_g(F[0])} N, Fy {_g(F[1])} N"
    if "applied_axial_force_N" in g:
        load += f", Fz {_g(scalar(g['applied_axial_force_N'][()]))} N"
    grav = a.get("gravity_m_s2")
    what = "" if grav is None else (f", gravity {scalar(grav):g} m/s2 included" if scalar(grav) else ", no gravity")
    lines.append(f"at {data['speed_rpm']:g} rpm under the applied loads{what}: {load}")
    data["applied_force_N"] = F.tolist()
    # deflections below 1e-9 of the largest (and below 1 pm, when nothing loads the rotor) print 0
    noise = max(float(np.max(np.abs(g["displacement_m"][:]), initial=0.0)), ABSOLUTE_M)
    if "static_stiffness_N_m" in g:
        k = scalar(g["static_stiffness_N_m"][()])
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
    shown = clean(forces, max(float(np.max(np.abs(forces), initial=0.0)), float(np.max(np.abs(F), initial=0.0)),
                              ABSOLUTE_N))
    dampers = [n.strip() for n in str(a.get("damping_only", "")).split(",") if n.strip()]
    for n, fb in zip(names, shown):  # below the noise of the largest force: 0
        if n in dampers:
            continue
        lines.append(f"  bearing {n:12s} reaction " + ", ".join(f"{_g(v):>10s}" for v in np.ravel(fb)[:5]) + " N")
    if dampers:
        lines.append(f"  {', '.join(dampers)}: damping only (no stiffness, no static reaction)")
    return lines, data


def modal(f):
    g = f["modal"]
    fr, z, ld = g["frequency_hz"][:], g["damping_ratio"][:], g["log_dec"][:]
    wh = g["whirl"][:].astype(str)
    lines = [f"modes at {scalar(g.attrs['speed_rpm']):g} rpm:", "   #  frequency Hz  damping ratio   log dec  whirl"]
    for k, (a, b, c, w) in enumerate(zip(fr, z, ld, wh)):
        lines.append(f"  {k + 1:2d}  {a:12.2f}  {b:13.3g}  {c:8.3g}  {w}" + ("   UNSTABLE" if b < 0 else ""))
    data = {"speed_rpm": scalar(g.attrs["speed_rpm"]), "frequency_hz": fr.tolist(), "damping_ratio": z.tolist(),
            "log_dec": ld.tolist(), "whirl": wh.tolist()}
    return lines, data


def campbell(f):
    g = f["campbell"]
    sp, fr = g["speed_rpm"][:], g["frequency_hz"][:]
    wh = g["whirl"][:].astype(str)
    op = float(g.attrs["operating_speed_rpm"]) if "operating_speed_rpm" in g.attrs else None
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
    threshold = None
    if "first_unstable" in g.attrs:  # the analysis's stability threshold: (speed, mode) indices
        i, k = (int(v) for v in g.attrs["first_unstable"])
        threshold = {"speed_rpm": float(sp[i]), "mode": k + 1, "frequency_hz": float(fr[i, k]),
                     "whirl": str(wh[i, k])}
        lines.append(f"  UNSTABLE from {sp[i]:g} rpm: mode {k + 1} ({wh[i, k]}, {fr[i, k]:.1f} Hz) has negative damping")
    elif g.attrs.get("stable", False):
        lines.append("  every tracked mode is stable over the range")
    else:  # a file from before the threshold was written
        lines.append("  stability threshold not in the file")
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


def frf(f):
    g = f["frf"]
    fr, h = g["frequency_hz"][:], g["receptance_m_N"][:]
    a = g.attrs
    mag = np.abs(h)
    head = (f"response at node {int(a['output_node'])} {a['output_dof']} / force at node {int(a['input_node'])} "
            f"{a['input_dof']}, {scalar(a['speed_rpm']):g} rpm; ")
    data: dict[str, Any] = {"peaks": []}
    if "static_compliance_m_N" in g:
        c0 = scalar(g["static_compliance_m_N"][()])
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


def unbalance(f):
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
