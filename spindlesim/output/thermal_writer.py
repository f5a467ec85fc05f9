"""thermal.h5 of a spindle's thermal model: group /spindle_thermal (speeds) and /spindle_thermal/warm_up.

Dimensions: ``speed_rpm`` (the speeds solved, ascending), ``node`` (the thermal network's node names),
``source`` (heat sources: bearing:<name>, motor:stator, motor:rotor), ``bearing`` (ball-bearing sets),
``row`` (1-based ball rows; NaN where a set has fewer), ``boundary`` (where the heat goes: ambient, the
coolant inlet), and in the warm-up ``time_s`` and ``mode``.  docs/output-format.md.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .hdf5 import Data, RunInfo, labels, write_h5


@dataclass(frozen=True)
class ThermalTable:
    """What the figures draw, as plain arrays (sent to the figure process): along ``x`` (speeds [rpm] or
    times [s]), per bearing its rings' temperatures [degC] and its largest row thrust [N], the motor's,
    the tool tip's axial and radial (x, y) drift [m],
    the speed at each point, the natural frequencies [Hz] and the minimum
    stable depth of cut [m] (warm-up)."""

    x: np.ndarray
    speed_rpm: np.ndarray
    bearings: tuple[str, ...]
    inner_C: np.ndarray  # [x, bearing]
    outer_C: np.ndarray
    preload_N: np.ndarray  # [x, bearing]
    motor_rotor_C: np.ndarray | None
    motor_stator_C: np.ndarray | None
    drift_m: np.ndarray
    frequency_hz: np.ndarray | None = None
    runaway_rpm: float | None = None
    depth_m: np.ndarray | None = None  # warm-up with a chatter section: the stable depth at each speed
    radial_m: np.ndarray | None = None  # [x, 2] the tool tip's radial drift x, y
    limit_rpm: tuple[float, float] | None = None  # the speed limit (highest stable, lowest running away)


def tabulate(states, bearings, frequency_hz=None, runaway_rpm=None, in_time: bool = False,
             depth_m=None, limit_rpm=None) -> ThermalTable:
    x = np.array([s.time_s if in_time else s.speed_rpm for s in states], float)
    motor = "motor:rotor" in states[0].temperatures_C if states else False
    return ThermalTable(
        x, np.array([s.speed_rpm for s in states], float), tuple(bearings),
        np.array([[s.parts_C[b].inner_ring_C for b in bearings] for s in states]).reshape(len(states), len(bearings)),
        np.array([[s.parts_C[b].outer_ring_C for b in bearings] for s in states]).reshape(len(states), len(bearings)),
        np.array([[_max_thrust(s.bearings.get(b)) for b in bearings]
                  for s in states]).reshape(len(states), len(bearings)),
        np.array([s.temperatures_C["motor:rotor"] for s in states]) if motor else None,
        np.array([s.temperatures_C["motor:stator"] for s in states]) if motor else None,
        np.array([np.nan if s.tool_tip_axial_drift_m is None else s.tool_tip_axial_drift_m for s in states], float),
        None if frequency_hz is None else np.asarray(frequency_hz, float), runaway_rpm,
        None if depth_m is None else np.asarray(depth_m, float), _radial(states),
        None if limit_rpm is None else (float(limit_rpm[0]), float(limit_rpm[1])))


_THRUST = "axial load each row carries (its operating preload; NaN: a bearing without rows' thrust)"
_ANGLE = "mean over the rolling elements of the row (a DTRB: its cone and cup angles)"


def _radial(states) -> np.ndarray:
    """The tool tip's radial drift (x, y) [m] of each state, NaN without a tool."""
    return np.array([(np.nan, np.nan) if s.tool_tip_radial_m is None else s.tool_tip_radial_m for s in states],
                    float).reshape(len(states), 2)


def _max_thrust(report) -> float:
    """The largest row thrust of a bearing's heat report (NaN: none, or a bearing without rows' thrust)."""
    t = None if report is None else report.row_thrust_N
    return float(np.nanmax(t)) if t is not None and len(t) else np.nan


def _rows(states, bearings) -> int:
    return max((len(s.bearings[b].row_thrust_N) for s in states for b in bearings
                if b in s.bearings and s.bearings[b].row_thrust_N is not None), default=1)


def _per_bearing(states, bearings, rows, field) -> np.ndarray:
    out = np.full((len(states), len(bearings), rows), np.nan)
    for i, s in enumerate(states):
        for j, b in enumerate(bearings):
            v = getattr(s.bearings.get(b), field, None) if b in s.bearings else None
            if v is not None:
                out[i, j, :len(v)] = v
    return out


def _common(g: str, states, bearings, nodes, sources, boundaries, axis: str) -> dict:
    """The datasets every series has, along ``axis`` (speed_rpm or time_s)."""
    rows = _rows(states, bearings)
    dims = (axis,)
    T = np.array([[s.temperatures_C[n] for n in nodes] for s in states])
    heat = np.array([[s.heat_W.get(src, 0.0) for src in sources] for s in states])
    parts = {p: np.array([[getattr(s.parts_C[b], f"{p}_C") for b in bearings] for s in states])
             for p in ("inner_ring", "outer_ring", "rolling_elements")}
    drift = np.array([np.nan if s.tool_tip_axial_drift_m is None else s.tool_tip_axial_drift_m for s in states])
    K = {}
    for i, s in enumerate(states):
        for j, b in enumerate(bearings):
            k = next(kb for (kb, _), bb in zip(s.operating.coefficients, s.operating.bearings) if bb.name == b)
            K.setdefault("radial", np.full((len(states), len(bearings)), np.nan))[i, j] = k[0, 0]
            if k.shape[0] >= 3:
                K.setdefault("axial", np.full((len(states), len(bearings)), np.nan))[i, j] = k[2, 2]
    data = {
        f"{g}/temperature_C": Data(T, "degC", dims + ("node",)),
        f"{g}/heat_W": Data(heat, "W", dims + ("source",), "heat generated by each source"),
        f"{g}/removed_W": Data(np.array([[(s.removed_W or {}).get(b, 0.0) for b in boundaries] for s in states]),
                               "W", dims + ("boundary",), "heat carried away to each boundary"),
        f"{g}/stored_W": Data(np.array([s.stored_W for s in states]), "W", dims,
                              "generated - removed: 0 at a steady state, the heat warming the parts in a warm-up"),
        f"{g}/row_thrust_N": Data(_per_bearing(states, bearings, rows, "row_thrust_N"), "N", dims + ("bearing", "row"),
                                  _THRUST, fill_nan=True),
        f"{g}/contact_angle_inner_deg": Data(_per_bearing(states, bearings, rows, "contact_angle_inner_deg"), "degree",
                                             dims + ("bearing", "row"), _ANGLE, fill_nan=True),
        f"{g}/contact_angle_outer_deg": Data(_per_bearing(states, bearings, rows, "contact_angle_outer_deg"), "degree",
                                             dims + ("bearing", "row"), _ANGLE, fill_nan=True),
        f"{g}/axial_offset_m": Data(np.array([[s.axial_offsets_m[b] for b in bearings] for s in states]), "m",
                                    dims + ("bearing",), "growth of the shaft minus that of the housing from the "
                                    "housing's front face to the bearing"),
        f"{g}/tool_tip_axial_drift_m": Data(drift, "m", dims, "axial position change of the tool tip against the "
                                            "housing's front face (NaN: no tool or no axial DOF)", fill_nan=True),
        f"{g}/tool_tip_radial_drift_m": Data(_radial(states), "m", dims + ("dof",), "the tool tip's radial "
                                             "position (x, y) against the cold, unloaded spindle's axis: its static "
                                             "deflection at the state (NaN: no tool)", fill_nan=True),
        **labels(g, "dof", ("x", "y")),
        **{f"{g}/{p}_C": Data(v, "degC", dims + ("bearing",)) for p, v in parts.items()},
        **{f"{g}/bearing_stiffness_{k}_N_m": Data(v, "N/m", dims + ("bearing",), f"{k} stiffness of the set at its "
                                                  "operating point", fill_nan=True) for k, v in K.items()},
        **labels(g, "node", nodes), **labels(g, "source", sources), **labels(g, "bearing", bearings),
        **labels(g, "boundary", boundaries),
        f"{g}/row": (np.arange(1, rows + 1), "1", ("row",)),
    }
    return data


def write_spindle_thermal(path: Path, run: RunInfo, model, study) -> Path:
    """``study``: an :class:`~spindlesim.analysis.thermal_study.ThermalStudy` of ``model``."""
    from ..analysis.thermal_study import lubrication_label

    g = "/spindle_thermal"
    series, warm = study, study.warm_up
    all_states = tuple(series.states) + (tuple(warm.states) if warm is not None else ())
    first = all_states[0] if all_states else None
    nodes = tuple(first.temperatures_C) if first is not None else ()
    bearings = tuple(model.bearings)
    sources = tuple(sorted({k for s in all_states for k in s.heat_W}))
    boundaries = tuple(sorted({k for s in all_states for k in (s.removed_W or {})}))
    data: dict = {}
    attrs: dict = {g: {"ambient_C": model.layout.ambient_C, "reference_C": model.reference_C,
                       "lubrication": lubrication_label(model),
                       "motor_load_fraction": model.load_fraction, "tolerance_K": model.tolerance_K}}
    if series.states:
        data[f"{g}/speed_rpm"] = (np.array([s.speed_rpm for s in series.states]), "rpm", ("speed_rpm",))
        data[f"{g}/iterations"] = (np.array([s.iterations for s in series.states]), "1", ("speed_rpm",))
        data.update(_common(g, series.states, bearings, nodes, sources, boundaries, "speed_rpm"))
    if series.runaway is not None:
        rpm, message = series.runaway
        if np.isfinite(rpm):
            attrs[g]["runaway_speed_rpm"] = float(rpm)
        attrs[g]["runaway"] = message
    if series.limit_rpm is not None:
        attrs[g]["speed_limit_rpm"] = np.asarray(series.limit_rpm, float)
    if warm is not None:
        w = f"{g}/warm_up"
        data[f"{w}/time_s"] = (np.array([s.time_s for s in warm.states]), "s", ("time_s",))
        data[f"{w}/speed_rpm"] = Data(np.array([s.speed_rpm for s in warm.states]), "rpm", ("time_s",))
        data[f"{w}/natural_frequency_hz"] = Data(warm.frequency_hz, "Hz", ("time_s", "mode"),
                                                 "first damped natural frequencies of the rotor on its bearings at "
                                                 "the temperatures of that instant", fill_nan=True)
        data.update(_common(w, warm.states, bearings, nodes, sources, boundaries, "time_s"))
        sd = warm.stable_depth
        if sd is not None:
            c, t = f"{w}/chatter", ("time_s",)
            data[f"{c}/time_s"] = (np.array([s.time_s for s in warm.states]), "s", t)
            data[f"{c}/limit_depth_m"] = Data(sd.depth_m, "m", t, "limit depth of cut at the instant's speed with the "
                                              "tool-point FRF of that instant; NaN at rest (speed 0), where stable up "
                                              "to the depth cap (capped 1) or not computed", fill_nan=True)
            data[f"{c}/speed_rpm"] = Data(sd.speed_rpm, "rpm", t, "the instant's speed")
            data[f"{c}/chatter_frequency_hz"] = Data(sd.chatter_frequency_hz, "Hz", t, "chatter frequency at the "
                                                     "limit", fill_nan=True)
            data[f"{c}/capped"] = Data(np.asarray(sd.capped, np.int8), "1", t, "1: stable up to the depth cap")
            data[f"{c}/depth_cap_m"] = Data(sd.depth_cap_m, "m", t, "the largest depth searched", fill_nan=True)
            attrs[c] = {"method": sd.method}
            if sd.failures:
                attrs[c]["not_computed"] = "; ".join(sd.failures)
    return write_h5(path, run, data, attrs)
