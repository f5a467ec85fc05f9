"""Steps per tooth period: a floor of 20 inside a short cut, and the error control.

At 5 % radial immersion a tooth cuts for 14.4 % of the tooth period (2 teeth).  The old rule,
30 points per chatter wave at 1.2 f_n (at least 30 steps, multiples of 10), gave 60 steps per period
at 18,000 rpm and 50 at 22,000 rpm, 7 to 9 of them in the cut (6 at 25,000 rpm).  The floor,
ceil(20 / 0.144) = 140 rounded up to the step ladder, 150, puts at least 20 steps in the cut.
"""

import numpy as np
import pytest

from spindlesim.chatter import MillingProcess, Mode, ToolPointModel, stability_lobes
from spindlesim.chatter.sd_lobes import STEPS_IN_CUT

FN, ZETA, MT = 922.0, 0.011, 0.03993
TOOL = ToolPointModel.from_modes([Mode("x", FN, ZETA, MT * (2 * np.pi * FN) ** 2)])
LOW = MillingProcess(2, 20e-3, 1e-3, "down", 6e8, 1 / 3)


@pytest.mark.parametrize("speed, kind", [(18000.0, "flip"), (22000.0, "hopf")])
def test_step_floor_converges_at_low_immersion(speed, kind):
    """Default steps against 960 steps per period (138 in the cut), error control off so that the
    floor alone is tested.  Measured: 150 steps +0.09 % (flip, 18,000 rpm) and +0.01 % (Hopf,
    22,000 rpm); the old rule's 60 and 50 steps +0.57 % and +0.10 %; 40 steps (5.7 in the cut)
    +1.1 % and +0.15 %."""
    assert LOW.cut_fraction == pytest.approx(np.arccos(0.9) / np.pi)  # 0.1436
    bracket = {"depths_m": [0.8e-3, 2.3e-3], "rtol": 1e-9, "error_tol": np.inf}
    default = stability_lobes(LOW, TOOL, [speed], "semi_discretization", **bracket)
    m = int(default.stability_map.steps_per_period[0])
    assert m * LOW.cut_fraction >= STEPS_IN_CUT
    fine = stability_lobes(LOW, TOOL, [speed], "semi_discretization", steps=960, **bracket)
    old = stability_lobes(LOW, TOOL, [speed], "semi_discretization", steps=50, **bracket)
    assert default.boundary_kind[0] == fine.boundary_kind[0] == kind
    err = default.limit_depth_m[0] / fine.limit_depth_m[0] - 1
    assert abs(err) < 3e-3
    assert abs(old.limit_depth_m[0] / fine.limit_depth_m[0] - 1) > 2 * abs(err)


def test_error_control_refines_a_steep_flank():
    """Slotting, 2 teeth, 14,000 rpm: the boundary sits on a steep flank where rho crosses 1 at a
    shallow angle, so its depth is sensitive to the step.  The default 12 points per chatter wave give 30
    steps and put it 13 % high (2.426 mm against 2.140 mm converged, 800 steps).  The error estimate (rho at
    half the steps) flags it: with the extrapolation (default) the speed is solved again with 150 steps and
    extrapolated, -0.013 %; without it, until the estimated error is below 0.5 %: 270 steps, +0.12 % (30 points
    per wave, the default before the extrapolation: 230 steps, +0.16 %)."""
    slot = MillingProcess(2, 20e-3, 20e-3, "down", 6e8, 1 / 3)
    plain = stability_lobes(slot, TOOL, [14000.0], "semi_discretization", error_tol=np.inf)
    ctrl = stability_lobes(slot, TOOL, [14000.0], "semi_discretization")
    noex = stability_lobes(slot, TOOL, [14000.0], "semi_discretization", extrapolate=False)
    conv = stability_lobes(slot, TOOL, [14000.0], "semi_discretization", steps=800, depths_m=[1.8e-3, 2.5e-3],
                           rtol=1e-8)
    assert plain.steps_per_period[0] < ctrl.steps_per_period[0] < noex.steps_per_period[0]
    assert plain.limit_depth_m[0] / conv.limit_depth_m[0] - 1 > 0.05
    assert abs(ctrl.limit_depth_m[0] / conv.limit_depth_m[0] - 1) < 1e-3
    assert abs(noex.limit_depth_m[0] / conv.limit_depth_m[0] - 1) < 4e-3
