"""Plausibility checks: values that are valid but most likely a unit mistake.

Each check returns ``(key path, message)``; the loader locates them as warnings
(``file:line:col: key: warning: ...``, the exit code unchanged) and ``--strict`` makes them
errors.  The thresholds are conservative on purpose: no shipped deck triggers any of them
(tests/unit/test_deck_plausibility.py), and each names what the value would be in the unit
the user probably meant.  What a bearing entry is checked for is its family's (the ``plausibility`` of its
row in ``BEARING_TYPES``, with the shared checks of ``spindlesim/bearings/plausible.py``); the shaft, the tool
and the deck sections' checks are here.

* a shaft or bearing dimension under a ``_mm`` key below 1 mm (a 0.06 mm shaft: metres?);
* a shaft density below 500 kg/m3 (7.85: g/cm3?);
* a fluid-film clearance over 1 % of the journal diameter, a roller bearing's radial clearance
  over 1 % of its inner raceway diameter (micrometres written as millimetres?);
* a bearing or joint stiffness above 0 and below 1e5 N/m (N/mm or N/um written as N/m?);
* bearing damping whose ratio to the stiffness, C/K, is above 1 s or below 1e-9 s (a damping
  given in another unit than N s/m);
* a rolling bearing's stiffness-proportional damping beta (``damping.stiffness_proportional_s``) above 0 and
  more than 10 times outside Kraemer's 0.25e-5 .. 2.5e-5 s (milliseconds or microseconds given as seconds?);
* a ball bearing's fit (``fits_um``) above 0 and below 0.1 um in magnitude (millimetres given as
  micrometres?), a thermal expansion coefficient above 3e-5 1/K (more than any bearing metal).
"""

from __future__ import annotations

from typing import Any

from ..bearings.ball.section_thermal import growth_plausibility
from ..bearings.plausible import (DAMPING_TIME_S, MAX_CLEARANCE_RATIO, MAX_EXPANSION_1_K, MIN_DIMENSION_MM,  # noqa: F401
                                  MIN_FIT_UM, MIN_STIFFNESS_N_M, ROLLING_DAMPING_S, Found, metres)
from ..bearings.types import bearing_plausibility

#: a shaft density below this [kg/m3] looks like g/cm3
MIN_DENSITY_KG_M3 = 500.0


def _rows(rows: list[list[float]], where: tuple[Any, ...], bad: Found) -> None:
    for j, name in ((0, "outer_dia_mm"), (2, "length_mm")):
        small = [i for i, r in enumerate(rows) if r[j] < MIN_DIMENSION_MM]
        if small:
            i = small[0]
            more = f" ({len(small)} rows)" if len(small) > 1 else ""
            bad.append((where + (i, j), f"{name} {rows[i][j]:g} is less than {MIN_DIMENSION_MM:g} mm{more}: "
                                        f"was it given in metres? ({rows[i][j]:g} m = {rows[i][j] * 1e3:g} mm)"))
    small = [i for i, r in enumerate(rows) if r[3] < MIN_DENSITY_KG_M3]
    if small:
        i = small[0]
        bad.append((where + (i, 3), f"density_kg_m3 {rows[i][3]:g} is below {MIN_DENSITY_KG_M3:g} kg/m3: was it "
                                    f"given in g/cm3? ({rows[i][3]:g} g/cm3 = {rows[i][3] * 1e3:g} kg/m3)"))


def plausibility_warnings(d: Any) -> Found:
    """(key path, message) of every likely unit mistake in a valid deck ``d``."""
    bad: Found = []
    if d.shaft is not None:
        _rows(d.shaft.elements, ("shaft", "elements"), bad)
    for i, b in enumerate(d.bearings):
        bad += bearing_plausibility(b, ("bearings", i))
    if getattr(d, "bearing", None) is not None:
        bad += growth_plausibility(d.bearing, ("bearing",))
    tool = getattr(d, "tool", None)
    if tool is not None:
        for name in ("interface", "joint"):
            j = getattr(tool, name)
            if j is not None and 0 < j.translational_N_m < MIN_STIFFNESS_N_M:
                bad.append((("tool", name, "translational_N_m"),
                            f"stiffness {j.translational_N_m:g} N/m is below {MIN_STIFFNESS_N_M:g} N/m: was it "
                            "given in N/mm or N/um?"))
    if getattr(d, "transient", None) is not None:
        br = d.transient.bearing
        metres(br, ("transient", "bearing"), ("inner_raceway_diameter_mm", "outer_raceway_diameter_mm"), bad)
    return bad
