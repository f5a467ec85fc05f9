"""Terminal summaries of the bearings' files: thermal.h5 of the fluid-film bearings, coefficients.h5, bearing.h5,
dtrb.h5, contact.h5 (a spindle's thermal model: thermal_summary.py)."""

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
    """The fluid-film bearings' thermal equilibrium, bearing by bearing."""
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
