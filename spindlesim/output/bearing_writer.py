"""bearing.h5 of a ball bearing (set) under a load (docs/output-format.md, "Ball bearing: bearing.h5").

    /bearing/displacement [dof], reaction, load, holding_load [load], stiffness [load, dof]
    /bearing/element_load_N ... [row, element]       per ball: loads, contact angles, race control, truncation
    /bearing/life_L10_Mrev, life_L10r_Mrev             ISO 281 and ISO/TS 16281 (NaN: none)
    /bearing/tilt_held/...                              the state with the tilt held at 0 (a free tilt warned of)
    /bearing/operating_clearance_m ...                  at the deck's temperatures, fits and speed
    /bearing/sweeps/<name>/...                          preload, load and speed sweeps

Dimensions: string coordinates ``dof`` (x .. theta_y) and ``load`` (Fx .. My), ``row`` and ``element``
(1-based), ``semi_axis`` (a, b), and a sweep's own variable.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from .hdf5 import DOF5_UNITS, LOAD5_UNITS, STIFFNESS5_UNITS, Data, RunInfo, five_dof, labels, write_h5

if TYPE_CHECKING:
    from ..bearings.ball.study import AtTemperature


LIFE_NOTE = ("NaN where there is none: ISO 281 factors not tabulated for the contact angle, or no equivalent "
             "load (unbounded life)")
K_NOTE = "K[load, dof] = -dF/dq (N/m, N/rad, N m/m, N m/rad: see component_units)"


def _life(v) -> np.ndarray:
    """A rating life for the file: None (not applicable) and inf (no load) become the NaN fill."""
    a = np.array(np.nan if v is None else v, dtype=float)
    return np.where(np.isfinite(a), a, np.nan)


QO_NOTE = "outer-race contact load Q_o"
QI_NOTE = "inner-race contact load Q_i (Q_o - Q_i: about the centrifugal force at speed)"
RACE_NOTE = ("Jones' race-control criterion at the ball's state: 1 only outer-race control possible "
             "(M_so > M_si cos(a_i - a_o)), -1 only inner-race control, 0 either (M_s = (3/8) Q a E(k))")
USED_NOTE = ("race control the ball was solved with: 1 outer (the couple on the outer contact), -1 inner, 0 shared "
             "(model full; under model auto a ball the criterion sends back and forth)")
EDGE_NOTE = "angle the contact ellipse reaches on the thrust side of the groove: a + asin(a_H / (f D))"
CUT_NOTE = "1: a loaded contact whose ellipse runs over the shoulder (edge stress), 0: not"


def _ball_datasets(base: str, rec, dims: tuple[str, ...]) -> dict:
    """Per-ball datasets shared by the state and the sweep groups (``rec``: a BallState or a BallSweep)."""
    return {
        f"{base}/element_load_N": Data(rec.element_load_outer_N, "N", dims, QO_NOTE + " (= element_load_outer_N)"),
        f"{base}/element_load_outer_N": Data(rec.element_load_outer_N, "N", dims, QO_NOTE),
        f"{base}/element_load_inner_N": Data(rec.element_load_inner_N, "N", dims, QI_NOTE),
        f"{base}/contact_angle_inner_deg": Data(rec.contact_angle_inner_deg, "degree", dims,
                                                "inner contact angle, in the row's thrust direction"),
        f"{base}/contact_angle_outer_deg": Data(rec.contact_angle_outer_deg, "degree", dims,
                                                "outer contact angle, in the row's thrust direction"),
        f"{base}/centrifugal_force_N": Data(rec.centrifugal_force_N, "N", dims,
                                            "centrifugal force of the ball, m (d_m / 2) w_c^2"),
        f"{base}/gyroscopic_moment_Nm": Data(
            rec.gyroscopic_moment_Nm, "N m", dims, "gyroscopic moment J w_R w_c sin(beta) of the ball, carried by "
            "the friction of the controlling race (both contacts for model full)"),
        f"{base}/race_control_criterion": Data(np.asarray(rec.race_control, np.int8), "1", dims, RACE_NOTE),
        f"{base}/race_control_used": Data(np.asarray(rec.race_used, np.int8), "1", dims, USED_NOTE),
        f"{base}/edge_angle_inner_deg": Data(rec.edge_angle_inner_deg, "degree", dims, EDGE_NOTE),
        f"{base}/edge_angle_outer_deg": Data(rec.edge_angle_outer_deg, "degree", dims, EDGE_NOTE),
        f"{base}/truncated_inner": Data(np.asarray(rec.truncated_inner, np.uint8), "1", dims, CUT_NOTE),
        f"{base}/truncated_outer": Data(np.asarray(rec.truncated_outer, np.uint8), "1", dims, CUT_NOTE),
    }


def _state_datasets(base: str, st) -> dict:
    re, rep = ("row", "element"), ("row", "element", "semi_axis")
    return {
        f"{base}/displacement": Data(st.displacement, "", ("dof",), "inner-ring displacement",
                                     component_units=DOF5_UNITS),
        f"{base}/reaction": Data(st.reaction, "", ("load",), "force on the shaft", component_units=LOAD5_UNITS),
        f"{base}/load": Data(st.load, "", ("load",), "load on the bearing: the deck's load plus the holding load",
                             component_units=LOAD5_UNITS),
        f"{base}/holding_load": Data(st.holding_load, "", ("load",), "load that holds the held DOFs at their "
                                     "displacement (0 at free DOFs)", component_units=LOAD5_UNITS),
        f"{base}/stiffness": Data(st.stiffness, "", ("load", "dof"), K_NOTE, component_units=STIFFNESS5_UNITS),
        **_ball_datasets(base, st, re),
        f"{base}/max_pressure_Pa": Data(np.maximum(st.max_pressure_inner_Pa, st.max_pressure_outer_Pa), "Pa", re,
                                        "the larger of the inner and outer contacts"),
        f"{base}/max_pressure_inner_Pa": (st.max_pressure_inner_Pa, "Pa", re),
        f"{base}/max_pressure_outer_Pa": (st.max_pressure_outer_Pa, "Pa", re),
        f"{base}/semi_axes_inner_m": Data(st.semi_axes_inner_m, "m", rep, "a across rolling, b along rolling"),
        f"{base}/semi_axes_outer_m": Data(st.semi_axes_outer_m, "m", rep, "a across rolling, b along rolling"),
        f"{base}/row_axial_load_N": (st.row_axial_load_N, "N", ("row",)),
        f"{base}/spin_moment_inner_Nm": Data(st.spin_moment_inner_Nm, "N m", re, "(3/8) Q a E(k): spin moment "
                                             "of the inner contact in full slip per unit friction coefficient"),
        f"{base}/spin_moment_outer_Nm": Data(st.spin_moment_outer_Nm, "N m", re, "(3/8) Q a E(k) of the outer "
                                             "contact"),
        f"{base}/spin_roll_inner": Data(st.spin_roll_inner, "1", re, "|spin| / roll of the ball on the inner race "
                                        "(0 under inner-race control)"),
        f"{base}/spin_roll_outer": Data(st.spin_roll_outer, "1", re, "|spin| / roll on the outer race (0 under "
                                        "outer-race control)"),
        f"{base}/traction_ratio": Data(np.where(np.isfinite(st.traction_ratio), st.traction_ratio, np.nan), "1", re,
                                       "friction force / normal load the gyroscopic couple needs at its contact; "
                                       "NaN: that contact unloaded", fill_nan=True),
        f"{base}/life_L10_Mrev": Data(_life(st.life_L10_iso281_Mrev), "megarevolution", (),
                                      "ISO 281 basic rating life; " + LIFE_NOTE, fill_nan=True),
        f"{base}/life_L10r_Mrev": Data(_life(st.life_L10r_iso16281_Mrev), "megarevolution", (),
                                       "ISO/TS 16281 reference rating life; " + LIFE_NOTE, fill_nan=True),
        **five_dof(base), **labels(base, "semi_axis", ("a", "b")),
    }


def _growth_datasets(base: str, at: AtTemperature) -> tuple[dict, dict]:
    """What the bearing's temperatures and fits made of it (datasets and attributes of ``base``)."""
    gr = at.growth
    data = {
        f"{base}/operating_clearance_m": Data(
            np.array(at.operating_clearance_m), "m", (),
            "diametral clearance at the deck's temperatures, fits and speed (< 0: interference)"),
        f"{base}/operating_clearance_at_rest_m": Data(np.array(gr.clearance_m), "m", (),
                                                      "diametral clearance at the deck's temperatures and fits, at rest"),
        f"{base}/clearance_change_m": Data(np.array(at.clearance_change_m), "m", (),
                                           "operating clearance minus the clearance as made (deck value)"),
        f"{base}/preload_offset_m": Data(at.row_offsets_m, "m", ("row",),
                                         "axial groove-centre offset c_k of each row at temperature (position preload)"),
        f"{base}/preload_offset_change_m": Data(np.asarray(gr.row_offset_change_m, float), "m", ("row",),
                                                "change of c_k from growth (> 0: more preload)"),
    }
    if at.preload_N is not None:
        data[f"{base}/preload_N"] = Data(np.asarray(at.preload_N, float), "N", ("row",), "thrust each row carries "
                                         "with no external load, at the deck's temperatures, fits and speed")
    fits = {}
    for side, fit in at.fits():
        data[f"{base}/{side}_fit_interference_m"] = Data(np.array(fit.interference_m), "m", (),
                                                         "effective diametral interference (<= 0: fit lost)")
        data[f"{base}/{side}_fit_pressure_Pa"] = Data(np.array(fit.pressure_Pa), "Pa", ())
        fits[f"{side}_fit_lost"] = int(fit.lost)
    return data, fits


def _sweep_datasets(base: str, sw) -> dict:
    unit = {"speed_rpm": "rpm", "fx_N": "N", "fy_N": "N", "fz_N": "N", "mx_Nm": "N m", "my_Nm": "N m"}
    n = sw.name
    per_ball = (n, "row", "element")
    return {
        f"{base}/{n}": (sw.values, unit.get(n, "um" if n.endswith("_um") else "N"), (n,)),
        f"{base}/stiffness": Data(sw.stiffness, "", (n, "load", "dof"), K_NOTE, component_units=STIFFNESS5_UNITS),
        f"{base}/displacement": Data(sw.displacement, "", (n, "dof"), "inner-ring displacement",
                                     component_units=DOF5_UNITS),
        f"{base}/load": Data(sw.load, "", (n, "load"), "load on the bearing: the deck's load plus the holding load",
                             component_units=LOAD5_UNITS),
        f"{base}/holding_load": Data(sw.holding_load, "", (n, "load"), "load that holds the held DOFs (0 at free "
                                     "DOFs)", component_units=LOAD5_UNITS),
        f"{base}/race_control_model": Data(np.array(sw.model, dtype=object), "1", (n,),
                                           "race control of the ball equilibria at each point (model auto: chosen "
                                           "per point by Jones' criterion)"),
        **_ball_datasets(base, sw, per_ball),
        f"{base}/row_axial_load_N": (sw.row_axial_load_N, "N", (n, "row")),
        f"{base}/max_pressure_Pa": Data(np.maximum(sw.max_pressure_inner_Pa, sw.max_pressure_outer_Pa), "Pa",
                                        per_ball, "the larger of the inner and outer contacts"),
        f"{base}/life_L10_Mrev": Data(_life(sw.life_L10_iso281_Mrev), "megarevolution", (n,),
                                      "ISO 281 basic rating life; " + LIFE_NOTE, fill_nan=True),
        f"{base}/life_L10r_Mrev": Data(_life(sw.life_L10r_iso16281_Mrev), "megarevolution", (n,),
                                       "ISO/TS 16281 reference rating life; " + LIFE_NOTE, fill_nan=True),
        **five_dof(base),
    }


def _check_attrs(res) -> tuple[dict, dict]:
    """Attributes of /bearing for the held DOFs, the race control, the shoulders and the run's warnings, and
    the /bearing/tilt_held datasets."""
    b, st = res.bearing, res.state
    sh = b.shoulders
    attrs = {"held": res.held.label(), "held_dofs": ", ".join(res.held.names), "model_setting": res.model_setting,
             "shoulder_angle_inner_deg": math.degrees(sh.inner_angle_rad),
             "shoulder_angle_outer_deg": math.degrees(sh.outer_angle_rad),
             "shoulder_height_inner_m": sh.inner_height_m, "shoulder_height_outer_m": sh.outer_height_m,
             "shoulder_source": sh.source, "truncated_contacts": st.truncated_contacts}
    if res.truncation:
        attrs["truncation_warning"] = " | ".join(res.truncation)
    data = {}
    tc = res.tilt_check
    if tc is not None:
        attrs.update(tilt_warning=tc.message, free_tilt_rad=tc.tilt_rad)
        h = tc.held_state
        data = {
            "/bearing/tilt_held/displacement": Data(h.displacement, "", ("dof",), "inner-ring displacement with "
                                                    "the tilt held at 0, same load and speed",
                                                    component_units=DOF5_UNITS),
            "/bearing/tilt_held/holding_load": Data(h.holding_load, "", ("load",), "moment the shaft needs to hold "
                                                    "the tilt at 0", component_units=LOAD5_UNITS),
            **five_dof("/bearing/tilt_held"),
        }
    return attrs, data


def write_bearing(path: Path, run: RunInfo, res, at: AtTemperature | None = None) -> Path:
    """bearing.h5 of a ball-bearing run ``res`` (:func:`spindlesim.bearings.ball.sweeps.run`); ``at``: the
    bearing at the deck's temperatures and fits (None: the deck gives none)."""
    st = res.state
    data = _state_datasets("/bearing", st)
    for key, sw in res.sweeps.items():
        data.update(_sweep_datasets(f"/bearing/sweeps/{key}", sw))
    g = res.bearing.geometry
    attrs = {"/bearing": {"type": "ball", "name": res.bearing.name, "arrangement": g.arrangement, "rows": g.rows,
                          "balls": g.balls, "speed_rpm": res.speed_rad_s * 30 / math.pi,
                          "preload": res.bearing.preload.label(), "model": st.model,
                          "operating_point": res.title()}}
    more_attrs, more_data = _check_attrs(res)
    attrs["/bearing"].update(more_attrs)
    data.update(more_data)
    if at is not None:
        more, flags = _growth_datasets("/bearing", at)
        data.update(more)
        attrs["/bearing"].update(flags)
        attrs["/bearing"].update({f"temperature_{k}_C": v for k, v in at.temperatures_C.items()})
    return write_h5(path, run, data, attrs)
