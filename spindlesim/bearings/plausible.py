"""Plausibility checks the bearing families share: values that are valid but most likely a unit mistake.

Each check appends ``(key path, message)`` to a list; a family's ``plausibility(entry, at)`` (its row of
``BEARING_TYPES``, ``bearings/types.py``) returns those of one ``bearings:`` entry at the path ``at``, and
``spindlesim/deck/plausibility.py`` locates them as warnings.  The thresholds are conservative on purpose (no
shipped deck triggers any of them); each message names what the value would be in the unit the user probably
meant.
"""

from __future__ import annotations

from typing import Any

Found = list[tuple[tuple[Any, ...], str]]

#: a dimension under a ``_mm`` key below this [mm] looks like metres
MIN_DIMENSION_MM = 1.0
#: a radial clearance above this fraction of the diameter looks like micrometres given as mm
MAX_CLEARANCE_RATIO = 0.01
#: a bearing stiffness below this [N/m] looks like N/mm or N/um
MIN_STIFFNESS_N_M = 1e5
#: damping time constant C/K [s] outside these bounds looks like another unit of damping
DAMPING_TIME_S = (1e-9, 1.0)
#: a fit below this magnitude [um] (but not 0) looks like millimetres written under a _um key
MIN_FIT_UM = 0.1
#: an expansion coefficient above this [1/K] is beyond the metals of a spindle (aluminium 23e-6)
MAX_EXPANSION_1_K = 3e-5
#: beta [s] of a rolling bearing's C = beta K outside these (10 x Kraemer's range) looks like another unit
ROLLING_DAMPING_S = (2.5e-7, 2.5e-4)


def metres(entry: Any, path: tuple[Any, ...], keys: tuple[str, ...], bad: Found) -> None:
    """A dimension under a ``_mm`` key below :data:`MIN_DIMENSION_MM` (metres?)."""
    for key in keys:
        v = getattr(entry, key, None)
        if v is not None and 0 < v < MIN_DIMENSION_MM:
            bad.append((path + (key,), f"{key} {v:g} is less than {MIN_DIMENSION_MM:g} mm: was it given in metres? "
                                       f"({v:g} m = {v * 1e3:g} mm)"))


def clearance(value_mm: float, diameter_mm: float, key: str, of: str, path: tuple[Any, ...], bad: Found,
              hint: str) -> None:
    """A clearance ``value_mm`` over :data:`MAX_CLEARANCE_RATIO` of the diameter ``of`` (micrometres?)."""
    if diameter_mm >= MIN_DIMENSION_MM and value_mm > MAX_CLEARANCE_RATIO * diameter_mm:
        bad.append((path + (key,), f"{key} {value_mm:g} is {100 * value_mm / diameter_mm:.3g} % of {of} (over "
                                   f"{100 * MAX_CLEARANCE_RATIO:g} %): was it given in micrometres?{hint}"))


def stiffness(K: list[list[float]], path: tuple[Any, ...], bad: Found) -> bool:
    """A direct stiffness above 0 and below :data:`MIN_STIFFNESS_N_M` (N/mm or N/um?); False when found."""
    for i in range(2):
        k = abs(K[i][i])
        if 0 < k < MIN_STIFFNESS_N_M:  # exactly 0: a damper-only element (decks/seed001_dtrb_rotor.yaml)
            bad.append((path + (i, i), f"stiffness {K[i][i]:g} N/m is below {MIN_STIFFNESS_N_M:g} N/m: was it "
                                       f"given in N/mm or N/um? ({K[i][i]:g} N/um = {K[i][i] * 1e6:g} N/m)"))
            return False
    return True


def damping(K: list[list[float]], C: list[list[float]] | None, path: tuple[Any, ...], bad: Found) -> None:
    """A damping whose ratio C/K to the stiffness lies outside :data:`DAMPING_TIME_S` (another unit?)."""
    if C is None:
        return
    lo, hi = DAMPING_TIME_S
    for i in range(2):
        k, c = abs(K[i][i]), abs(C[i][i])
        if k > 0 and c > 0 and not lo <= c / k <= hi:
            bad.append((path + (i, i), f"damping {C[i][i]:g} N s/m with stiffness {K[i][i]:g} N/m gives C/K = "
                                       f"{c / k:.3g} s, outside {lo:g} .. {hi:g} s: is the damping in N s/m?"))
            return


def rolling_damping(entry: Any, at: tuple[Any, ...], bad: Found) -> None:
    """A rolling bearing's stiffness-proportional damping beta far outside Kraemer's range (ms or us?)."""
    d = getattr(entry, "damping", None)
    beta = None if d is None else d.stiffness_proportional_s
    lo, hi = ROLLING_DAMPING_S
    if beta and not lo <= beta <= hi:
        bad.append((at + ("damping", "stiffness_proportional_s"),
                    f"stiffness_proportional_s {beta:g} s is more than 10 times outside the 0.25e-5 .. 2.5e-5 s of "
                    "rolling bearings (Kraemer 1993): was it given in ms or us? (1.0e-5 s is the default)"))


def fits_and_expansions(entry: Any, where: tuple[Any, ...], bad: Found) -> None:
    """A ball bearing's fit (``fits_um``) above 0 and below :data:`MIN_FIT_UM` (millimetres?), an expansion
    coefficient of its materials above :data:`MAX_EXPANSION_1_K`."""
    fits = getattr(entry, "fits_um", None)
    if fits is not None:
        for key in ("shaft", "housing"):
            v = getattr(fits, key)
            if 0.0 < abs(v) < MIN_FIT_UM:
                bad.append((where + ("fits_um", key), f"a fit of {v:g} um is below {MIN_FIT_UM:g} um: was it given "
                                                      f"in millimetres? ({v:g} mm = {v * 1e3:g} um)"))
    mats = [("material",), ("ball_material",)]
    if getattr(entry, "mounting", None) is not None:
        mats += [("mounting", "shaft_material"), ("mounting", "housing_material")]
    for path in mats:
        m = entry
        for k in path:
            m = getattr(m, k, None)
        e = getattr(m, "thermal_expansion_1_K", None)
        if e is not None and e > MAX_EXPANSION_1_K:
            bad.append((where + path + ("thermal_expansion_1_K",),
                        f"{e:g} 1/K is above {MAX_EXPANSION_1_K:g} 1/K (steel 11.5e-6, aluminium 23e-6): is it "
                        "the coefficient in 1/K?"))
