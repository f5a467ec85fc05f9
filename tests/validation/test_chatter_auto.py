"""`method: auto` and the default depth search against an independent semi-discretization.

Reference: tests/validation/sd_reference.py, a first-order semi-discretization written from Insperger
and Stepan (IJNME 61 (2004) 117-141; Semi-Discretization for Time-Delay Systems, Springer 2011), with
its own time grid (k steps in the cut, the free flight in one exact step), Richardson-extrapolated
from k and 2 k steps; it shares no code with spindlesim.

Cases (the issue's): the single-DOF milling benchmark of Insperger and Stepan (after Insperger, Mann,
Stepan and Bayly, IJMTM 43 (2003) 25-34): flexible along the feed, f_n 922 Hz, zeta 0.011,
m 0.03993 kg (k = 1.340e6 N/m), Kt 6e8 N/m^2, Kn 2e8 N/m^2, 20 mm cutter, 2 teeth, at 5 %, 50 % and
100 % radial immersion, up and down milling; and a 2-DOF 4-tooth cutter (x 600 Hz, zeta 0.03,
1.5e7 N/m; y 660 Hz, zeta 0.025, 1.8e7 N/m; Kt 8e8, Kn 2.4e8 N/m^2, 16 mm, half immersion).

Before this change `auto` took the zero-order solution at radial immersion >= 30 %, where it is too
high: on the grids below the zero-order limit exceeds the reference by up to +102 % at half immersion
down milling (14,750 rpm: 5.50 mm against 2.72 mm; at 17,750 rpm 2.00 against 0.93 mm, a flip lobe),
+14 % up milling, +16 % slotting (the issue's finer grid: +47 %) and +87 % for the 4-tooth cutter
down milling (18,750 rpm: 5.96 against 3.18 mm); at 5 % immersion by +106 % (up) and +282 % (down).
`auto` now runs the semi-discretization wherever the directional matrix is not constant: it lies
between -0.2 % and +0.4 % of the reference at every speed of every case (docs/validation.md).
"""

import numpy as np
import pytest

from spindlesim.chatter import MillingProcess, Mode, ToolPointModel, stability_lobes

from .sd_reference import MillingReference

FN, ZETA, MT = 922.0, 0.011, 0.03993
K1 = MT * (2 * np.pi * FN) ** 2
ONE = {"fn_hz": FN, "zeta": ZETA, "k_N_m": K1}
TWO = {"fn_hz": [600.0, 660.0], "zeta": [0.03, 0.025], "k_N_m": [1.5e7, 1.8e7]}
SPEEDS_1 = np.arange(7750.0, 25000.0, 1750.0)  # 10 speeds; 17,750 rpm is the flip point
SPEEDS_2 = np.arange(6250.0, 20001.0, 1250.0)[::2]  # 6 speeds up to 18,750 rpm


def _tool(par) -> ToolPointModel:
    f, z, k = (np.atleast_1d(par[key]) for key in ("fn_hz", "zeta", "k_N_m"))
    return ToolPointModel.from_modes([Mode(d, *v) for d, v in zip("xy", zip(f, z, k))])


CASES = {  # teeth, a/D, mode, Kt [N/m^2], Kn [N/m^2], tool, diameter [m], speeds [rpm]
    "1dof-5%-up": (2, 0.05, "up", 6e8, 2e8, ONE, 20e-3, SPEEDS_1),
    "1dof-5%-down": (2, 0.05, "down", 6e8, 2e8, ONE, 20e-3, SPEEDS_1),
    "1dof-50%-up": (2, 0.5, "up", 6e8, 2e8, ONE, 20e-3, SPEEDS_1),
    "1dof-50%-down": (2, 0.5, "down", 6e8, 2e8, ONE, 20e-3, SPEEDS_1),
    "1dof-slot": (2, 1.0, "down", 6e8, 2e8, ONE, 20e-3, SPEEDS_1),
    "2dof-4t-50%-up": (4, 0.5, "up", 8e8, 2.4e8, TWO, 16e-3, SPEEDS_2),
    "2dof-4t-50%-down": (4, 0.5, "down", 8e8, 2.4e8, TWO, 16e-3, SPEEDS_2),
}


def _reference(case, speeds, a_max):
    N, imm, mode, kt, kn, par, D, _ = CASES[case]
    ref = MillingReference(N, imm, mode, kt, kn, **par)
    out = np.array([ref.limit(s, a, k=40, grid=50) for s, a in zip(speeds, a_max)])
    return out[:, 0], out[:, 1]


@pytest.mark.slow
@pytest.mark.parametrize("case", list(CASES))
def test_auto_is_never_more_than_2_percent_above_the_reference(case):
    """Measured, auto / reference - 1 over the speeds: 1-DOF 5 % up -0.17 .. +0.38 %, 5 % down
    -0.21 .. +0.28 %, 50 % up +0.20 .. +0.33 %, 50 % down +0.06 .. +0.28 %, slot -0.07 .. +0.42 %;
    2-DOF 4 teeth 50 % up -0.12 .. +0.11 %, down 0.00 .. +0.23 %.  The reference's own error bound
    |a_80 - a_40| is below 0.6 % of its value except at one slotting speed on a steep flank (2.6 %);
    the test allows it on top of the 2 %."""
    N, imm, mode, kt, kn, par, D, speeds = CASES[case]
    p = MillingProcess(N, D, imm * D, mode, kt, kn / kt)
    auto = stability_lobes(p, _tool(par), speeds)
    assert auto.method == "semi_discretization" and set(auto.method_per_speed) == {"semi_discretization"}
    zoa = stability_lobes(p, _tool(par), speeds, "zero_order").limit_depth_m
    lim = auto.limit_depth_m
    a_max = 1.25 * np.where(np.isfinite(lim), np.maximum(lim, zoa), auto.depth_cap_m)
    ref, bound = _reference(case, speeds, a_max)
    found = np.isfinite(lim)
    assert np.all(np.isfinite(ref[found])), "the reference finds a boundary wherever auto does"
    excess = lim[found] / ref[found] - 1
    assert np.all(excess <= 0.02 + bound[found] / ref[found]), (speeds[found], excess)
    assert np.all(excess >= -0.02 - bound[found] / ref[found])  # and not needlessly low
    # a capped speed (stable up to the cap) must be stable up to the cap by the reference too
    assert np.all(~np.isfinite(ref[~found]) | (ref[~found] >= 0.98 * auto.depth_cap_m))


def test_zero_order_where_exact_and_refused_where_it_overpromises():
    """auto keeps the zero-order solution only for a constant directional matrix (4-tooth slot:
    the reference agrees to 0.2 %); at half immersion, 2 teeth, down milling it was 115 % too high
    at 17,750 rpm (2.00 mm against the reference's 0.93 mm, a period-doubling lobe)."""
    slot4 = MillingProcess(4, 20e-3, 20e-3, "down", 6e8, 1 / 3)
    speeds = np.array([9000.0, 17750.0])
    d = stability_lobes(slot4, _tool(ONE), speeds)
    assert d.method == "zero_order" and "constant" in d.selection
    ref = MillingReference(4, 1.0, "down", 6e8, 2e8, **ONE)
    for s, a in zip(speeds, d.limit_depth_m):
        r, bound = ref.limit(s, 1.5 * a, k=30, grid=30)
        assert abs(a / r - 1) < 3e-3 + bound / r
    half = MillingProcess(2, 20e-3, 10e-3, "down", 6e8, 1 / 3)
    zoa = stability_lobes(half, _tool(ONE), [17750.0], "zero_order").limit_depth_m[0]
    auto = stability_lobes(half, _tool(ONE), [17750.0])
    r, _ = MillingReference(2, 0.5, "down", 6e8, 2e8, **ONE).limit(17750.0, 2.5e-3, k=30, grid=40)
    assert zoa / r - 1 > 1.0  # the zero-order limit is more than twice the reference's
    assert auto.boundary_kind[0] == "flip" and abs(auto.limit_depth_m[0] / r - 1) < 0.01
