"""Named results: the numbers ``spindlesim optimize`` takes as objectives and constraints, one table.

Each name is one call into an existing analysis on the deck as written (``runs.common.RunContext``: the rotor at
its operating points, the thermal equilibrium where the deck's ``spindle_thermal.analyses`` asks for it), at the
deck's operating speed (``operating.speed_rpm``) unless the table says otherwise; nothing is computed here that an
analysis does not compute for its own command.  ``needs`` names what the deck must have (a located deck error
otherwise, before anything runs):

    rotor      a rotor (shaft or journal), operating and bearings that hold it (``require_rotor``)
    chatter    a ``chatter:`` section
    thermal    a ``spindle_thermal:`` section
    ball       a bearing of type ball (the ISO 281 rating life)
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Any, Callable

import numpy as np


@dataclass(frozen=True)
class NamedResult:
    name: str
    unit: str
    needs: tuple[str, ...]
    text: str  # what it is, for docs/deck-format.md and the summary
    compute: Callable[["Evaluation"], float]


class Evaluation:
    """One design's analyses, each run once on first use (the names asked share the rotor's states)."""

    def __init__(self, loaded: Any):
        from ..runs.common import RunContext

        self.loaded = loaded
        self.deck = loaded.deck
        self.ctx = RunContext(loaded)
        self._steady = None

    @property
    def speed_rpm(self) -> float:
        return float(self.deck.operating.speed_rpm)

    def steady_points(self):
        """Operating points at the spindle's thermal equilibrium (``spindle_thermal.analyses`` whatever it says,
        as ``spindlesim thermal`` solves them)."""
        if self._steady is None:
            from ..analysis.points import OperatingPoints
            from ..model.thermal import build_spindle_thermal

            points = self.ctx.points
            model = build_spindle_thermal(self.deck, points.rotor)
            self._steady = points if points.thermal is not None and model.analyses == "steady" else \
                OperatingPoints(points.rotor, dataclasses.replace(model, analyses="steady"), shaft=points.shaft)
        return self._steady

    def thermal_state(self):
        return self.steady_points().thermal_state(self.speed_rpm)


def _static_stiffness(ev: Evaluation) -> float:
    from ..analysis.static import solve_static

    at = ev.deck.static.stiffness_at
    return solve_static(ev.ctx.points, at.node - 1, at.dof, speed_rpm=ev.speed_rpm).static_stiffness_N_m


def _first_natural_frequency(ev: Evaluation) -> float:
    from ..analysis.modal import solve_modal

    d = ev.deck
    speed = d.modal.speed_rpm if d.modal.speed_rpm is not None else ev.speed_rpm
    f = solve_modal(ev.ctx.points, speed, n_modes=d.modal.modes).frequency_hz
    if not len(f):
        raise ArithmeticError("no underdamped mode")
    return float(f[0])


def _min_limit_depth(ev: Evaluation) -> float:
    from ..analysis.chatter_study import chatter_study
    from ..chatter import build_chatter
    from ..deck import deck_folder

    spec = build_chatter(ev.deck.chatter, deck_folder(ev.loaded))
    points = ev.ctx.points if spec.frf_source == "rotor" else None
    limit = ev.ctx.thermal_speed_limit() if getattr(ev.deck, "spindle_thermal", None) is not None else None
    st = chatter_study(spec, points, ev.speed_rpm, speed_limit_rpm=None if limit is None else limit[0])
    return 1e3 * st.min_limit_depth_m


def _thermal_speed_limit(ev: Evaluation) -> float:
    """The highest speed of ``spindle_thermal.speeds_rpm`` found stable, the runaway bisected to 2 %; when no
    speed of the list runs away, the highest speed of the list (a lower bound: extend the list)."""
    limit = ev.ctx.thermal_speed_limit()
    if limit is not None:
        return float(limit[0])
    from ..model.thermal import build_spindle_thermal

    speeds = build_spindle_thermal(ev.deck, ev.ctx.points.rotor).speeds_rpm
    return float(max(speeds)) if speeds else ev.speed_rpm


def _bearing_heat(ev: Evaluation) -> float:
    return float(sum(v for k, v in ev.thermal_state().heat_W.items() if k.startswith("bearing:")))


def _max_bearing_temperature(ev: Evaluation) -> float:
    parts = ev.thermal_state().parts_C.values()
    return float(max(max(p.inner_ring_C, p.outer_ring_C, p.rolling_elements_C) for p in parts))


def _tool_tip_drift(ev: Evaluation) -> float:
    drift = ev.thermal_state().tool_tip_axial_drift_m
    if drift is None:
        raise ValueError("no tool tip axial drift (the rotor has no tool section)")
    return 1e6 * float(drift)


def _min_l10(ev: Evaluation) -> float:
    """The smallest ISO 281 basic rating life of the deck's ball bearing sets under the loads the rotor puts on
    them at its static state of the operating speed [h]."""
    st = ev.ctx.points.state(ev.speed_rpm)
    rpm = ev.speed_rpm
    lives = []
    for b, load in zip(ev.ctx.points.rotor.bearings, st.loads):
        L = b.rating_life_Mrev(st.speed_rad_s, np.asarray(load, float))
        if L is not None:
            lives.append(float(L) * 1e6 / (60.0 * rpm) if rpm > 0 else float("inf"))
    if not lives:
        raise ValueError("no ball bearing has an ISO 281 rating life")
    return min(lives)


def _rotor_mass(ev: Evaluation) -> float:
    return ev.ctx.points.rotor.mass_kg


#: every named result; docs/deck-format.md ("optimize") shows this table
NAMED_RESULTS: dict[str, NamedResult] = {r.name: r for r in (
    NamedResult("static_stiffness_N_m", "N/m", ("rotor",),
                "static stiffness at `static.stiffness_at` (the static analysis)", _static_stiffness),
    NamedResult("first_natural_frequency_hz", "Hz", ("rotor",),
                "lowest damped natural frequency (the modal analysis, at `modal.speed_rpm` if given)",
                _first_natural_frequency),
    NamedResult("min_limit_depth_mm", "mm", ("chatter",),
                "smallest limiting depth of cut over the lobes' speeds (the chatter analysis; not smooth)",
                _min_limit_depth),
    NamedResult("thermal_speed_limit_rpm", "rpm", ("rotor", "thermal"),
                "highest speed of `spindle_thermal.speeds_rpm` without thermal runaway, bisected to 2 % (the "
                "thermal analysis); the list's highest speed when none runs away", _thermal_speed_limit),
    NamedResult("bearing_heat_W", "W", ("rotor", "thermal"),
                "the bearings' heat at thermal equilibrium (the thermal analysis)", _bearing_heat),
    NamedResult("max_bearing_temperature_C", "degC", ("rotor", "thermal"),
                "hottest bearing part (rings, rolling elements) at thermal equilibrium", _max_bearing_temperature),
    NamedResult("tool_tip_axial_drift_um", "um", ("rotor", "thermal"),
                "tool tip's axial drift at thermal equilibrium (ISO 230-3's)", _tool_tip_drift),
    NamedResult("min_l10_h", "h", ("rotor", "ball"),
                "smallest ISO 281 basic rating life of the ball bearing sets under their static loads", _min_l10),
    NamedResult("rotor_mass_kg", "kg", ("rotor",), "mass of shaft, tool, holder and disks", _rotor_mass),
)}


def missing_sections(loaded: Any, name: str) -> str:
    """What the deck lacks for ``name`` ("" : nothing)."""
    from ..deck.describe import bearing_entries

    d = loaded.deck
    lacks = []
    for need in NAMED_RESULTS[name].needs:
        if need == "rotor" and (d.operating is None or (d.shaft is None and d.journal is None) or not d.bearings):
            lacks.append("a rotor (shaft or journal), operating and bearings")
        elif need == "chatter" and getattr(d, "chatter", None) is None:
            lacks.append("a chatter section")
        elif need == "thermal" and getattr(d, "spindle_thermal", None) is None:
            lacks.append("a spindle_thermal section")
        elif need == "ball" and not bearing_entries(d, "ball"):
            lacks.append("a bearing of type ball")
    return " and ".join(lacks)


def evaluate_names(loaded: Any, names: tuple[str, ...]) -> dict[str, float]:
    """The named results ``names`` of the deck (an analysis that fails raises, as for its own command)."""
    ev = Evaluation(loaded)
    return {n: float(NAMED_RESULTS[n].compute(ev)) for n in names}
