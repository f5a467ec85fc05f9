"""Plausibility checks: values that are valid but most likely a unit mistake.

Each check returns ``(key path, message)``; the loader locates them as warnings
(``file:line:col: key: warning: ...``, the exit code unchanged) and ``--strict`` makes them
errors.  The thresholds are conservative on purpose: no shipped deck triggers any of them
(tests/unit/test_deck_plausibility.py), and each names what the value would be in the unit
the user probably meant.

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

Found = list[tuple[tuple[Any, ...], str]]

#: a dimension under a ``_mm`` key below this [mm] looks like metres
MIN_DIMENSION_MM = 1.0
#: a shaft density below this [kg/m3] looks like g/cm3
MIN_DENSITY_KG_M3 = 500.0
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


def _ball_growth(b: Any, where: tuple[Any, ...], bad: Found) -> None:
    fits = getattr(b, "fits_um", None)
    if fits is not None:
        for key in ("shaft", "housing"):
            v = getattr(fits, key)
            if 0.0 < abs(v) < MIN_FIT_UM:
                bad.append((where + ("fits_um", key), f"a fit of {v:g} um is below {MIN_FIT_UM:g} um: was it given "
                                                      f"in millimetres? ({v:g} mm = {v * 1e3:g} um)"))
    mats = [("material",), ("ball_material",)]
    if getattr(b, "mounting", None) is not None:
        mats += [("mounting", "shaft_material"), ("mounting", "housing_material")]
    for path in mats:
        m = b
        for k in path:
            m = getattr(m, k, None)
        e = getattr(m, "thermal_expansion_1_K", None)
        if e is not None and e > MAX_EXPANSION_1_K:
            bad.append((where + path + ("thermal_expansion_1_K",),
                        f"{e:g} 1/K is above {MAX_EXPANSION_1_K:g} 1/K (steel 11.5e-6, aluminium 23e-6): is it "
                        "the coefficient in 1/K?"))


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


def _metres(entry: Any, path: tuple[Any, ...], keys: tuple[str, ...], bad: Found) -> None:
    for key in keys:
        v = getattr(entry, key, None)
        if v is not None and 0 < v < MIN_DIMENSION_MM:
            bad.append((path + (key,), f"{key} {v:g} is less than {MIN_DIMENSION_MM:g} mm: was it given in metres? "
                                       f"({v:g} m = {v * 1e3:g} mm)"))


def _stiffness(K: list[list[float]], path: tuple[Any, ...], bad: Found) -> bool:
    for i in range(2):
        k = abs(K[i][i])
        if 0 < k < MIN_STIFFNESS_N_M:  # exactly 0: a damper-only element (decks/seed001_dtrb_rotor.yaml)
            bad.append((path + (i, i), f"stiffness {K[i][i]:g} N/m is below {MIN_STIFFNESS_N_M:g} N/m: was it "
                                       f"given in N/mm or N/um? ({K[i][i]:g} N/um = {K[i][i] * 1e6:g} N/m)"))
            return False
    return True


def _damping(K: list[list[float]], C: list[list[float]] | None, path: tuple[Any, ...], bad: Found) -> None:
    if C is None:
        return
    lo, hi = DAMPING_TIME_S
    for i in range(2):
        k, c = abs(K[i][i]), abs(C[i][i])
        if k > 0 and c > 0 and not lo <= c / k <= hi:
            bad.append((path + (i, i), f"damping {C[i][i]:g} N s/m with stiffness {K[i][i]:g} N/m gives C/K = "
                                       f"{c / k:.3g} s, outside {lo:g} .. {hi:g} s: is the damping in N s/m?"))
            return


def _linear(b: Any, at: tuple[Any, ...], bad: Found) -> None:
    if b.K_N_m is not None:
        if _stiffness(b.K_N_m, at + ("K_N_m",), bad):
            _damping(b.K_N_m, b.C_Ns_m, at + ("C_Ns_m",), bad)
    if b.table is not None:
        for j, K in enumerate(b.table.K_N_m):
            if not _stiffness(K, at + ("table", "K_N_m", j), bad):
                break
            _damping(K, b.table.C_Ns_m[j], at + ("table", "C_Ns_m", j), bad)


def _rolling_damping(b: Any, at: tuple[Any, ...], bad: Found) -> None:
    damping = getattr(b, "damping", None)
    beta = None if damping is None else damping.stiffness_proportional_s
    lo, hi = ROLLING_DAMPING_S
    if beta and not lo <= beta <= hi:
        bad.append((at + ("damping", "stiffness_proportional_s"),
                    f"stiffness_proportional_s {beta:g} s is more than 10 times outside the 0.25e-5 .. 2.5e-5 s of "
                    "rolling bearings (Kraemer 1993): was it given in ms or us? (1.0e-5 s is the default)"))


def _bearing(b: Any, at: tuple[Any, ...], bad: Found) -> None:
    kind = b.type
    if kind in ("roller", "ball", "dtrb"):
        _rolling_damping(b, at, bad)
    if kind == "linear":
        _linear(b, at, bad)
    elif kind in ("three_lobe", "plain"):
        _metres(b, at, ("diameter_mm", "width_mm"), bad)
        if b.diameter_mm >= MIN_DIMENSION_MM and b.clearance_mm > MAX_CLEARANCE_RATIO * b.diameter_mm:
            bad.append((at + ("clearance_mm",),
                        f"clearance_mm {b.clearance_mm:g} is {100 * b.clearance_mm / b.diameter_mm:.3g} % of the "
                        f"journal diameter (over {100 * MAX_CLEARANCE_RATIO:g} %): was it given in micrometres? "
                        f"({b.clearance_mm:g} um = {b.clearance_mm * 1e-3:g} mm)"))
    elif kind == "roller":
        _metres(b, at, ("inner_raceway_diameter_mm", "outer_raceway_diameter_mm"), bad)
        d = b.inner_raceway_diameter_mm
        if d >= MIN_DIMENSION_MM and b.radial_clearance_mm > MAX_CLEARANCE_RATIO * d:
            bad.append((at + ("radial_clearance_mm",),
                        f"radial_clearance_mm {b.radial_clearance_mm:g} is {100 * b.radial_clearance_mm / d:.3g} % "
                        f"of the inner raceway diameter (over {100 * MAX_CLEARANCE_RATIO:g} %): was it given in "
                        "micrometres?"))
    elif kind == "ball":
        _metres(b, at, ("pitch_diameter_mm", "ball_diameter_mm"), bad)
    elif kind == "dtrb":
        _metres(b.geometry, at + ("geometry",), ("pitch_diameter_mm", "large_end_diameter_mm"), bad)


def plausibility_warnings(d: Any) -> Found:
    """(key path, message) of every likely unit mistake in a valid deck ``d``."""
    bad: Found = []
    if d.shaft is not None:
        _rows(d.shaft.elements, ("shaft", "elements"), bad)
    for i, b in enumerate(d.bearings):
        _bearing(b, ("bearings", i), bad)
        if getattr(b, "type", None) == "ball":
            _ball_growth(b, ("bearings", i), bad)
    if getattr(d, "bearing", None) is not None:
        _ball_growth(d.bearing, ("bearing",), bad)
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
        _metres(br, ("transient", "bearing"), ("inner_raceway_diameter_mm", "outer_raceway_diameter_mm"), bad)
    return bad
