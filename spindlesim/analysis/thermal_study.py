"""What ``spindlesim thermal`` computes on a spindle with a thermal model, as one frozen result.

:func:`thermal_study`: the thermal equilibrium at each speed from the lowest up (a speed that runs away ends the
list: the arrangement's speed limit, bisected to 2 %); with a warm-up, the spindle through its speed steps from
cold, with the rotor's first natural frequencies and, given ``depth_through``, the stable depth of cut at each
instant's speed.  A part that fails (an instant's modes or lobes) is NaN with its reason in ``missing``; a Ctrl-C
stops the study where it is and the result keeps what was computed (``interrupted`` says where).
"""

from __future__ import annotations

import logging
from dataclasses import dataclass
from typing import Callable, Sequence

import numpy as np

from .modal import modal_from_matrices
from .spindle_thermal import ThermalRunawayError, ThermalState, speed_limit

log = logging.getLogger(__name__)

#: natural frequencies reported through a warm-up
WARM_UP_MODES = 4
#: what a failing part of the study raises (its value is NaN, its reason kept)
PART_ERRORS = (np.linalg.LinAlgError, ArithmeticError, ValueError)


@dataclass(frozen=True)
class WarmUp:
    """The spindle at the instants of a warm-up: its states, the rotor's first natural frequencies [time, mode]
    and the stable depth of cut at each instant's speed (``warm_up_chatter.StableDepth``; None without a chatter
    section taking its FRF from the rotor)."""

    states: tuple[ThermalState, ...]
    frequency_hz: np.ndarray
    stable_depth: object | None = None


@dataclass(frozen=True)
class ThermalSetting:
    """What the model of a study sets and its summary names: the ambient temperature [degC], the lubrication
    ("method, lubricant"), the motor's load fraction and the ball-bearing sets of the model, in its order."""

    ambient_C: float = float("nan")
    lubrication: str = ""
    motor_load_fraction: float = float("nan")
    bearings: tuple[str, ...] = ()


def setting_of(model) -> ThermalSetting:
    """The :class:`ThermalSetting` of a ``SpindleThermalModel``."""
    return ThermalSetting(model.layout.ambient_C, lubrication_label(model), model.load_fraction,
                          tuple(model.bearings))


def lubrication_label(model) -> str:
    """The lubrication of a ``SpindleThermalModel`` as "method, lubricant" (thermal.h5's ``lubrication``)."""
    return f"{model.lubrication.method}, {getattr(model.lubrication.lubricant, 'name', '')}"


@dataclass(frozen=True)
class ThermalStudy:
    """The equilibria at ascending speeds, the runaway that ended the list ((rpm, message) or None), the speed
    limit (highest stable, lowest running away) [rpm], the warm-up, the parts not computed, where a Ctrl-C
    stopped the study ("" : it was not), and what the model set (``setting``)."""

    states: tuple[ThermalState, ...]
    runaway: tuple[float, str] | None = None
    limit_rpm: tuple[float, float] | None = None
    warm_up: WarmUp | None = None
    missing: tuple[str, ...] = ()
    interrupted: str = ""
    setting: ThermalSetting = ThermalSetting()

    # ---- named results (the optimiser's, the report's) --------------------------------------------------
    @property
    def thermal_speed_limit_rpm(self) -> float:
        """The highest speed found stable; inf when no speed of the list ran away."""
        if self.limit_rpm is not None:
            return float(self.limit_rpm[0])
        return float("inf") if self.runaway is None else float("nan")

    @property
    def max_bearing_temperature_C(self) -> float:
        """The hottest bearing part over the equilibria."""
        return max((max(p.inner_ring_C, p.outer_ring_C, p.rolling_elements_C) for s in self.states for p in s.parts_C.values()),
                   default=float("nan"))

    @property
    def bearing_heat_W(self) -> float:
        """The bearings' heat at the highest speed solved."""
        if not self.states:
            return float("nan")
        return float(sum(v for k, v in self.states[-1].heat_W.items() if k.startswith("bearing:")))


def thermal_study(points, speeds_rpm: Sequence[float], warm_up=None,
                  depth_through: Callable | None = None,
                  progress: Callable[[int, int], None] | None = None, quiet: bool = False) -> ThermalStudy:
    """The module note's study on ``points`` (operating points with a steady thermal model); ``warm_up`` the
    model's ``WarmUpSpec`` (or None), ``depth_through(points, instants)`` the stable depth of cut through it;
    ``quiet``: the runaway that ends the list is logged as information, not as a warning (another analysis
    asking for the speed limit)."""
    thermal = points.thermal
    setting = setting_of(thermal.model) if thermal is not None else ThermalSetting()
    speeds = list(speeds_rpm)
    total = len(speeds) + (1 if warm_up is not None else 0)
    states: list[ThermalState] = []
    runaway = limit = None
    missing: list[str] = []
    where = ""
    try:
        for k, rpm in enumerate(speeds):
            where = f"at the equilibrium of {rpm:g} rpm"
            try:
                states.append(points.thermal_state(rpm))
            except ThermalRunawayError as exc:
                runaway = (rpm, str(exc))
                log.log(logging.INFO if quiet else logging.WARNING, "%s", exc)
                break
            if progress is not None:
                progress(k + 1, total)
        if runaway is not None and states:  # the speed limit of the arrangement, to 2 %
            where = "in the search of the speed limit"
            limit = speed_limit(thermal, states[-1], runaway[0])
            log.info("thermal speed limit between %.0f and %.0f rpm", *limit)
        warm = None
        if warm_up is not None:
            where = "in the warm-up"
            warm, runaway = _warm_up(points, warm_up, depth_through, runaway, missing)
            if progress is not None:
                progress(total, total)
    except KeyboardInterrupt:
        log.warning("thermal: interrupted by the user %s", where)
        return ThermalStudy(tuple(states), runaway, limit, None, tuple(missing), f"interrupted by the user {where}",
                            setting)
    return ThermalStudy(tuple(states), runaway, limit, warm, tuple(missing), setting=setting)


def _warm_up(points, w, depth_through, runaway, missing: list[str]):
    try:
        instants = points.thermal.warm_up(w.times_s, w.speeds_rpm, w.duration_s, w.samples)
    except ThermalRunawayError as exc:
        return None, runaway or (float("nan"), f"warm-up: {exc}")
    if not instants:
        return None, runaway
    r = points.rotor
    freqs = []
    for ts in instants:
        f = np.full(WARM_UP_MODES, np.nan)
        try:
            m = modal_from_matrices(points.system(ts.operating), r.dofs, r.node_z_m, WARM_UP_MODES, ts.speed_rpm)
            f[:len(m.frequency_hz)] = m.frequency_hz
        except PART_ERRORS as exc:
            missing.append(f"warm-up natural frequencies at {ts.time_s / 60.0:.1f} min ({ts.speed_rpm:g} rpm) "
                           f"failed: {exc}")
        freqs.append(f)
    depth = None
    if depth_through is not None:
        try:
            depth = depth_through(points, instants)
        except PART_ERRORS as exc:
            missing.append(f"warm-up stable depth of cut failed: {exc}")
        if depth is not None:
            missing.extend(f"warm-up stable depth of cut: {m}" for m in depth.failures)
    return WarmUp(instants, np.array(freqs), depth), runaway
