"""Terminal summaries of the bearings' results: the fluid-film bearings' thermal equilibrium and coefficients
(``FilmBearings``; thermal.h5, coefficients.h5), a ball bearing (``BallStudy``; bearing.h5), a DTRB
(``DtrbStudy``; dtrb.h5), a contact (``ContactResult``; contact.h5).  Each reads the analysis's result, not its
file, and prints what the file holds (a spindle's thermal model: thermal_summary.py)."""

from __future__ import annotations

import math

import numpy as np

from .numbers import clean, g as _g

#: rad/s per rpm (the dtrb writer's)
RPM = math.pi / 30.0


def _per_bearing(study, fields: list[tuple[str, str, float, str]]):
    """A line and a row of ``fields`` (quantity, label, scale, unit) per bearing of a ``FilmBearings``, by name;
    the quantities a bearing's model does not give (``not_computed``) left out."""
    lines, data = [], {}
    for name, r in study.by_name():
        absent = r.not_computed()
        row = {k: r.quantity(k) for k, *_ in fields if k not in absent}
        data[name] = row
        lines.append(f"  {name:10s} " + "  ".join(f"{lab} {row[k] * s:.4g}{u}" for k, lab, s, u in fields if k in row))
    return lines, data


def _deg(x: float) -> str:
    """An angle to 0.1 deg, never "-0.0"."""
    return f"{round(float(x), 1) + 0.0:.1f}"


def thermal(study):
    """The fluid-film bearings' thermal equilibrium, bearing by bearing (``study``: their ``FilmBearings``)."""
    fields = [("temperature_mean_C", "T_mean", 1.0, " C"), ("temperature_out_C", "T_out", 1.0, " C"),
              ("eccentricity_ratio", "eps", 1.0, ""), ("min_film_m", "h_min", 1e6, " um"),
              ("power_loss_W", "loss", 1.0, " W"), ("heat_to_housing_W", "to housing", 1.0, " W")]
    from ..bearings.fluidfilm.viscosity import OIL_MAX_C

    lines, data = _per_bearing(study, fields)
    iso = [n for n, r in study.by_name() if r.not_computed()]
    if iso:
        lines.append(f"  {', '.join(iso)}: isoviscous film, no heat balance (the oil has no density and specific heat)")
    hot = [n for n, row in data.items() if row.get("temperature_mean_C", 0.0) > OIL_MAX_C]
    if hot:
        lines.append(f"  WARNING: {', '.join(hot)} above {OIL_MAX_C:g} C mean film temperature (beyond a mineral "
                     "oil's usable range)")
    return [f"thermal equilibrium at {study.speed_rpm:g} rpm:"] + lines, data


def coefficients(study):
    """Each fluid-film bearing's stiffness and damping at its thermal equilibrium (``study``: ``FilmBearings``)."""
    lines, data = [f"bearing coefficients at {study.speed_rpm:g} rpm (x, y):"], {}
    for name, r in study.by_name():
        K, C = np.asarray(r.film.K_N_m, float), np.asarray(r.film.C_Ns_m, float)
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


def bearing(study):
    """A ball bearing (set) under its load (``study``: its ``BallStudy``)."""
    res = study.run
    st = res.state
    lines = [res.title()]
    d = np.asarray(st.displacement, float)
    held = set(res.held.names) - {""}
    dofs, loads = ("x", "y", "z", "theta_x", "theta_y"), ("Fx", "Fy", "Fz", "Mx", "My")
    shown = [v * s if abs(v * s) >= 5e-5 else 0.0 for v, s in zip(d, (1e6,) * 3 + (1e3,) * 2)]  # round-off: 0
    lines.append("  displacement " + ", ".join(f"{n} {v:.4g} {'um' if k < 3 else 'mrad'}" + (" (held)" if n in held
                                               else "") for k, (n, v) in enumerate(zip(dofs, shown))))
    data = {"displacement": d.tolist()}
    if held:
        H = np.asarray(st.holding_load, float)
        H = np.where(np.abs(H) > 1e-9 * max(1.0, float(np.max(np.abs(H)))), H, 0.0)
        lines.append("  holding load " + ", ".join(f"{m} {H[k]:.4g} {'N' if k < 3 else 'N m'}"
                                                   for k, (n, m) in enumerate(zip(dofs, loads)) if n in held)
                     + " (what holds the held DOFs; the bearing carries the load plus this)")
        data["holding_load"] = H.tolist()
    K = np.asarray(st.stiffness, float)
    lines += _stiffness_lines(K)
    lines += _ball_lines(res, data)
    lines += _at_temperature_lines(study.at, data)
    L = _life(st.life_L10_iso281_Mrev)
    speed = res.speed_rad_s * 30 / math.pi
    lines.append(f"  basic rating life L10 {L:.4g} million rev" + (f" = {L * 1e6 / speed / 60:.4g} h" if speed else ""))
    data["life_L10_Mrev"] = L
    return lines, data


def _ball_lines(res, data: dict) -> list[str]:
    """The balls at the state: contact loads, pressure and angles, race control, truncation; the warnings."""
    st = res.state
    K = np.asarray(st.stiffness, float)
    Qi, Qo = np.asarray(st.element_load_inner_N, float), np.asarray(st.element_load_outer_N, float)
    p = np.maximum(st.max_pressure_inner_Pa, st.max_pressure_outer_Pa)
    ai, ao = np.asarray(st.contact_angle_inner_deg, float), np.asarray(st.contact_angle_outer_deg, float)
    lines = [f"  largest contact loads {Qi.max():.4g} N inner, {Qo.max():.4g} N outer; contact pressure "
             f"{p.max() * 1e-9:.3g} GPa; contact angles {_deg(ai.min())}-{_deg(ai.max())} deg inner, "
             f"{_deg(ao.min())}-{_deg(ao.max())} deg outer"]
    data.update({"stiffness_diagonal": np.diag(K).tolist(), "max_element_load_N": float(Qo.max()),
                 "max_element_load_inner_N": float(Qi.max()), "max_pressure_Pa": float(p.max())})
    c, used, model = np.asarray(st.race_control, np.int8), np.asarray(st.race_used, np.int8), str(st.model)
    count = {"outer": int(np.sum(c == 1)), "inner": int(np.sum(c == -1)), "either": int(np.sum(c == 0))}
    if model == "auto":
        model = f"per ball: outer at {int(np.sum(used == 1))}, inner at {int(np.sum(used == -1))}, shared at " \
                f"{int(np.sum(used == 0))}"
    lines.append(f"  race control {model}{' (model auto)' if res.model_setting == 'auto' else ''}; Jones' "
                 f"criterion: outer race at {count['outer']}, inner race at {count['inner']}, either at "
                 f"{count['either']} of {c.size} balls")
    sh = res.bearing.shoulders
    n_cut = int(st.truncated_contacts)
    ei, eo = np.asarray(st.edge_angle_inner_deg, float), np.asarray(st.edge_angle_outer_deg, float)
    lines.append(f"  contact ellipses reach {ei.max():.3g} deg inner, {eo.max():.3g} deg outer; shoulders at "
                 f"{math.degrees(sh.inner_angle_rad):.3g} / {math.degrees(sh.outer_angle_rad):.3g} deg"
                 + (f": TRUNCATED at {n_cut} contact(s)" if n_cut else ""))
    data.update(race_control_criterion=count, truncated_contacts=n_cut)
    tc = res.tilt_check
    lines += [f"  WARNING: {m}" for m in list(res.truncation) + ([tc.message] if tc is not None else [])]
    if tc is not None:
        data["tilt_held_displacement"] = np.asarray(tc.held_state.displacement, float).tolist()
    return lines


def _at_temperature_lines(at, data: dict) -> list[str]:
    """The bearing at the deck's temperatures: operating clearance, preload without load, a lost fit ([]: none)."""
    if at is None:
        return []
    c, dc = at.operating_clearance_m, at.clearance_change_m
    line = f"  at temperature: operating clearance {c * 1e6:.4g} um ({dc * 1e6:+.4g} um from growth)"
    if at.preload_N is not None:
        pre = np.asarray(at.preload_N, float)
        line += f", preload {', '.join(f'{v:.4g}' for v in pre)} N per row (no external load)"
    lost = [s for s, fit in at.fits() if int(fit.lost)]
    if lost:
        line += "; FIT LOST: " + ", ".join(f"{s} ring" for s in lost)
    data.update(operating_clearance_m=c, clearance_change_m=dc)
    return [line]


def _life(value) -> float:
    """A rating life: None (not applicable) and inf (no load) are NaN, as bearing.h5 holds them."""
    v = float("nan") if value is None else float(value)
    return v if math.isfinite(v) else float("nan")


def dtrb(study):
    """A DTRB's equilibrium under the load (``study``: its ``DtrbStudy``)."""
    st = study.state
    K = np.asarray(st.stiffness, float)
    Q = np.asarray(st.outer_load_N, float)
    load = clean(study.load)
    words = [f"{n} {_g(v)} {'N' if k < 3 else 'N m'}"
             for k, (n, v) in enumerate(zip(("Fx", "Fy", "Fz", "Mx", "My"), load)) if v != 0.0]
    lines = [f"load {', '.join(words) or 'none'} at {study.speed_rad_s / RPM:.0f} rpm, "
             f"preload {float(study.preload_m) * 1e6:.3g} um"]
    lines += _stiffness_lines(K)
    lines.append(f"  largest roller load {Q.max():.4g} N; loaded rollers {int(np.sum(Q > 0))} of {Q.size}")
    return lines, {"stiffness_diagonal": np.diag(K).tolist(), "max_roller_load_N": float(Q.max())}


def contact(res):
    """The contact's peak pressure, area and approach (``res``: its ``ContactResult``)."""
    p, area = float(res.max_pressure_Pa), float(res.area_m2)
    lines = [f"load {float(res.load_N):.4g} N: maximum pressure {p * 1e-9:.4g} GPa, contact area {area * 1e6:.4g} mm2, "
             f"approach {float(res.approach_m) * 1e6:.4g} um"
             + ("; EDGE STRESS (pressure singular at the roller end)" if res.edge_singular else "")]
    return lines, {"max_pressure_Pa": p, "area_m2": area, "approach_m": float(res.approach_m)}
