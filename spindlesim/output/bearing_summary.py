"""Terminal summaries of the bearings' files: thermal.h5, coefficients.h5, bearing.h5, dtrb.h5, contact.h5."""

from __future__ import annotations

import numpy as np

from .numbers import clean, g as _g
from .summary import scalar


def _per_bearing(f, group: str, fields: list[tuple[str, str, float, str]]):
    g = f[group]
    lines, data = [], {}
    for name in g:
        b = g[name]
        row = {k: float(np.asarray(b[k][()])) for k, *_ in fields if k in b}
        data[name] = row
        lines.append(f"  {name:10s} " + "  ".join(f"{lab} {row[k] * s:.4g}{u}" for k, lab, s, u in fields if k in row))
    return lines, data


def _deg(x: float) -> str:
    """An angle to 0.1 deg, never "-0.0"."""
    return f"{round(float(x), 1) + 0.0:.1f}"


def thermal(f):
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
        radial = g["tool_tip_radial_drift_m"][:] if "tool_tip_radial_drift_m" in g else None
        lines.append(f"thermal equilibrium at {len(sp)} speed(s), ambient {float(a['ambient_C']):g} C, "
                     f"{a['lubrication']}, motor load {float(a['motor_load_fraction']):g}")
        for i, s in enumerate(sp):
            motor = sum(heat[i, k] for k, n in enumerate(sources) if n.startswith("motor"))
            parts = [f"{n} {heat[i, sources.index('bearing:' + n)]:.0f} W, rings {inner[i, j]:.1f}/{outer[i, j]:.1f} C"
                     + _preload(thrust[i, j]) for j, n in enumerate(names) if f"bearing:{n}" in sources]
            tip = "" if not np.isfinite(drift[i]) else f"; tool tip {drift[i] * 1e6:+.1f} um axially"
            if radial is not None and np.isfinite(radial[i]).all():
                tip += f", x {radial[i, 0] * 1e6:+.2f} / y {radial[i, 1] * 1e6:+.2f} um radially"
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
        radial = w["tool_tip_radial_drift_m"][:] if "tool_tip_radial_drift_m" in w else None
        fr = w["natural_frequency_hz"][:]
        line = f"  warm-up over {t[-1] / 60:.0f} min ({len(t)} instants)"
        if np.isfinite(drift).any():
            line += f": tool tip axial drift {np.nanmin(drift) * 1e6:+.1f} .. {np.nanmax(drift) * 1e6:+.1f} um"
        if radial is not None and np.isfinite(radial).all():
            change = np.hypot(*(radial - radial[0]).T)
            line += f", radial drift from the first instant up to {np.max(change) * 1e6:.2f} um"
        if fr.size and np.isfinite(fr[:, 0]).all():
            line += f"; first natural frequency {fr[0, 0]:.1f} -> {fr[-1, 0]:.1f} Hz"
        lines.append(line)
        data["warm_up_final_drift_m"] = float(drift[-1])
        if "chatter" in w:
            lines.extend(_warm_up_depth(w["chatter"], t, data))
    return lines, data



def _warm_up_depth(c, t, data) -> list[str]:
    """The stable depth of cut at the running speed through a warm-up: cold, at the end of the last cutting
    step, the lowest, and the instants not computed."""
    dm, rpm = c["limit_depth_m"][:], c["speed_rpm"][:]
    capped = c["capped"][:].astype(bool) if "capped" in c else np.zeros(len(dm), bool)
    method = str(c.attrs.get("method", "")).split(" (")[0]
    lines = []

    def at(i: int) -> str:
        return f"{dm[i] * 1e3:.3g} mm at {rpm[i]:,.0f} rpm ({t[i] / 60:.0f} min)"

    ok = np.flatnonzero(np.isfinite(dm))
    if len(ok):
        k = int(ok[np.argmin(dm[ok])])
        lines.append(f"  stable depth of cut at the running speed ({method}): {at(ok[0])} -> {at(ok[-1])}; "
                     f"lowest {at(k)}")
        data["warm_up_limit_depth_m"] = [float(v) for v in dm]
    if capped.any():
        lines.append(f"  stable up to the depth cap at {int(capped.sum())} instant(s)")
    missing = int(np.sum(~np.isfinite(dm) & ~capped & (rpm > 0)))
    if missing:
        lines.append(f"  stable depth of cut NOT COMPUTED at {missing} of {len(dm)} instants "
                     f"(thermal.h5: warm_up/chatter, attribute not_computed)")
    return lines


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
    return [f"thermal equilibrium at {scalar(f['thermal'].attrs['speed_rpm']):g} rpm:"] + lines, data


def coefficients(f):
    g = f["coefficients"]
    lines, data = [f"bearing coefficients at {scalar(g.attrs['speed_rpm']):g} rpm (x, y):"], {}
    for name in g:
        K, C = g[name]["K_N_m"][:], g[name]["C_Ns_m"][:]
        data[name] = {"K_N_m": K.tolist(), "C_Ns_m": C.tolist()}
        lines.append(f"  {name:10s} K [N/um] xx {K[0, 0] / 1e6:.4g} xy {K[0, 1] / 1e6:.4g} yx {K[1, 0] / 1e6:.4g} "
                     f"yy {K[1, 1] / 1e6:.4g}   C [N s/mm] xx {C[0, 0] / 1e3:.4g} xy {C[0, 1] / 1e3:.4g} "
                     f"yx {C[1, 0] / 1e3:.4g} yy {C[1, 1] / 1e3:.4g}")
    return lines, data


def _stiffness_lines(K) -> list[str]:
    d = np.diag(np.asarray(K, float))
    names = ("Kxx", "Kyy", "Kzz", "Ktx", "Kty")[: len(d)]
    return ["  stiffness " + ", ".join(f"{n} {v / (1e6 if k < 3 else 1.0):.4g}{' N/um' if k < 3 else ' N m/rad'}"
                                       for k, (n, v) in enumerate(zip(names, d)))]


def bearing(f):
    g = f["bearing"]
    a = g.attrs
    lines = [str(a.get("operating_point", ""))]
    d = g["displacement"][()]
    held = set(str(a.get("held_dofs", "")).split(", ")) - {""}
    dofs, loads = ("x", "y", "z", "theta_x", "theta_y"), ("Fx", "Fy", "Fz", "Mx", "My")
    shown = [v * s if abs(v * s) >= 5e-5 else 0.0 for v, s in zip(d, (1e6,) * 3 + (1e3,) * 2)]  # round-off: 0
    lines.append("  displacement " + ", ".join(f"{n} {v:.4g} {'um' if k < 3 else 'mrad'}" + (" (held)" if n in held
                                               else "") for k, (n, v) in enumerate(zip(dofs, shown))))
    data = {"displacement": d.tolist()}
    if held:
        H = g["holding_load"][()]
        H = np.where(np.abs(H) > 1e-9 * max(1.0, float(np.max(np.abs(H)))), H, 0.0)
        lines.append("  holding load " + ", ".join(f"{m} {H[k]:.4g} {'N' if k < 3 else 'N m'}"
                                                   for k, (n, m) in enumerate(zip(dofs, loads)) if n in held)
                     + " (what holds the held DOFs; the bearing carries the load plus this)")
        data["holding_load"] = H.tolist()
    K = g["stiffness"][()]
    lines += _stiffness_lines(K)
    Qi, Qo, p = g["element_load_inner_N"][()], g["element_load_N"][()], g["max_pressure_Pa"][()]
    ai, ao = g["contact_angle_inner_deg"][()], g["contact_angle_outer_deg"][()]
    lines.append(f"  largest contact loads {Qi.max():.4g} N inner, {Qo.max():.4g} N outer; contact pressure "
                 f"{p.max() * 1e-9:.3g} GPa; contact angles {_deg(ai.min())}-{_deg(ai.max())} deg inner, "
                 f"{_deg(ao.min())}-{_deg(ao.max())} deg outer")
    data.update({"stiffness_diagonal": np.diag(K).tolist(), "max_element_load_N": float(Qo.max()),
                 "max_element_load_inner_N": float(Qi.max()), "max_pressure_Pa": float(p.max())})
    c, used, model = g["race_control_criterion"][()], g["race_control_used"][()], str(a.get("model", ""))
    count = {"outer": int(np.sum(c == 1)), "inner": int(np.sum(c == -1)), "either": int(np.sum(c == 0))}
    if model == "auto":
        model = f"per ball: outer at {int(np.sum(used == 1))}, inner at {int(np.sum(used == -1))}, shared at " \
                f"{int(np.sum(used == 0))}"
    lines.append(f"  race control {model}{' (model auto)' if a.get('model_setting') == 'auto' else ''}; Jones' "
                 f"criterion: outer race at {count['outer']}, inner race at {count['inner']}, either at "
                 f"{count['either']} of {c.size} balls")
    n_cut, ei, eo = int(a["truncated_contacts"]), g["edge_angle_inner_deg"][()], g["edge_angle_outer_deg"][()]
    lines.append(f"  contact ellipses reach {ei.max():.3g} deg inner, {eo.max():.3g} deg outer; shoulders at "
                 f"{float(a['shoulder_angle_inner_deg']):.3g} / {float(a['shoulder_angle_outer_deg']):.3g} deg"
                 + (f": TRUNCATED at {n_cut} contact(s)" if n_cut else ""))
    data.update(race_control_criterion=count, truncated_contacts=n_cut)
    warnings = str(a["truncation_warning"]).split(" | ") if "truncation_warning" in a else []
    lines += [f"  WARNING: {m}" for m in warnings + ([str(a["tilt_warning"])] if "tilt_warning" in a else [])]
    if "tilt_warning" in a:
        data["tilt_held_displacement"] = g["tilt_held/displacement"][()].tolist()
    if "operating_clearance_m" in g:
        c, dc = float(g["operating_clearance_m"][()]), float(g["clearance_change_m"][()])
        line = f"  at temperature: operating clearance {c * 1e6:.4g} um ({dc * 1e6:+.4g} um from growth)"
        if "preload_N" in g:
            pre = g["preload_N"][()]
            line += f", preload {', '.join(f'{v:.4g}' for v in pre)} N per row (no external load)"
        lost = [s for s in ("inner", "outer") if int(a.get(f"{s}_fit_lost", 0))]
        if lost:
            line += "; FIT LOST: " + ", ".join(f"{s} ring" for s in lost)
        lines.append(line)
        data.update(operating_clearance_m=c, clearance_change_m=dc)
    if "life_L10_Mrev" in g:
        L = float(g["life_L10_Mrev"][()])
        speed = float(a.get("speed_rpm", 0.0))
        lines.append(f"  basic rating life L10 {L:.4g} million rev" + (f" = {L * 1e6 / speed / 60:.4g} h" if speed else ""))
        data["life_L10_Mrev"] = L
    return lines, data


def dtrb(f):
    g = f["dtrb"]
    K = g["stiffness"][()]
    Q = g["roller_load_N"][()]
    load = clean(g.attrs["applied_load"])
    words = [f"{n} {_g(v)} {'N' if k < 3 else 'N m'}"
             for k, (n, v) in enumerate(zip(("Fx", "Fy", "Fz", "Mx", "My"), load)) if v != 0.0]
    lines = [f"load {', '.join(words) or 'none'} at {float(g.attrs['speed_rpm']):.0f} rpm, "
             f"preload {float(g.attrs['preload_m']) * 1e6:.3g} um"]
    lines += _stiffness_lines(K)
    lines.append(f"  largest roller load {Q.max():.4g} N; loaded rollers {int(np.sum(Q > 0))} of {Q.size}")
    return lines, {"stiffness_diagonal": np.diag(K).tolist(), "max_roller_load_N": float(Q.max())}


def contact(f):
    a = f["contact"].attrs
    p, area = float(a["max_pressure_Pa"]), float(a["area_m2"])
    lines = [f"load {float(a['load_N']):.4g} N: maximum pressure {p * 1e-9:.4g} GPa, contact area {area * 1e6:.4g} mm2, "
             f"approach {float(a['approach_m']) * 1e6:.4g} um"
             + ("; EDGE STRESS (pressure singular at the roller end)" if a.get("edge_singular") else "")]
    return lines, {"max_pressure_Pa": p, "area_m2": area, "approach_m": float(a["approach_m"])}


def _preload(row_thrust) -> str:
    """", preload N N" of a bearing's rows' thrust; nothing for a bearing without one (a cylindrical roller)."""
    t = np.asarray(row_thrust, float)
    return f", preload {np.nanmax(t):.0f} N" if np.isfinite(t).any() else ""
