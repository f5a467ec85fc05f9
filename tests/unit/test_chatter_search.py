"""The lobes without the stability map: brackets continued from the neighbouring speeds
(spindlesim/chatter/sd_search.py) against the march over the depth grid (the map), on the textbook cases.

The two must find the same first crossing of rho = 1 at every speed, to the search tolerance (rtol 1e-4 on
each side: 2e-4 between them), including the period-doubling (flip) islands of low radial immersion, the
steep flanks of slotting and a two-mode, four-tooth cutter; and the continued brackets must cost well under
half the march's evaluations.  Measured (121 speeds 5,000-25,000 rpm, 1-DOF benchmark of Insperger and
Stepan; 91 speeds for the 2-DOF cutter): largest difference 9.3e-5 (5 % down, 47 flip speeds), 9.4e-5 (5 %
up), 8.2e-5 (10 % down), 9.0e-5 (50 % down), 1.4e-4 (slot), 1.5e-4 (2-DOF); evaluations 1,383 against 3,504,
1,333 / 5,845, 1,350 / 3,527, 1,379 / 3,809, 1,605 / 7,144, 1,113 / 2,238.
"""

import logging

import numpy as np
import pytest

import spindlesim.chatter.semi_discretization as sd
from spindlesim.chatter import MillingProcess, Mode, ToolPointModel, stability_lobes

FN, ZETA, MT = 922.0, 0.011, 0.03993
ONE = ToolPointModel.from_modes([Mode("x", FN, ZETA, MT * (2 * np.pi * FN) ** 2)])
TWO = ToolPointModel.from_modes([Mode("x", 600.0, 0.03, 1.5e7), Mode("y", 660.0, 0.025, 1.8e7)])
CASES = {
    "5%-down": (MillingProcess(2, 20e-3, 1e-3, "down", 6e8, 1 / 3), ONE, np.linspace(14000, 24000, 41)),
    "5%-up": (MillingProcess(2, 20e-3, 1e-3, "up", 6e8, 1 / 3), ONE, np.linspace(14000, 24000, 41)),
    "slot": (MillingProcess(2, 20e-3, 20e-3, "down", 6e8, 1 / 3), ONE, np.linspace(8000, 24000, 41)),
    "2dof-4t": (MillingProcess(4, 16e-3, 8e-3, "down", 8e8, 0.3), TWO, np.linspace(6000, 20000, 29)),
}


@pytest.fixture
def evaluations(monkeypatch):
    monkeypatch.setenv("SPINDLESIM_SD_PROCESSES", "0")  # every evaluation in this process, where it is counted
    count = [0]
    orig = sd.SdProblem.multipliers

    def counted(self, s_idx, depth):
        count[0] += len(np.atleast_1d(s_idx))
        return orig(self, s_idx, depth)

    monkeypatch.setattr(sd.SdProblem, "multipliers", counted)
    return count


@pytest.mark.parametrize("case", list(CASES))
def test_continued_brackets_find_the_marchs_limits_with_fewer_evaluations(case, evaluations, caplog):
    p, tool, speeds = CASES[case]
    caplog.set_level(logging.WARNING)
    search = stability_lobes(p, tool, speeds, "semi_discretization")
    n_search = evaluations[0]
    march = stability_lobes(p, tool, speeds, "semi_discretization", stability_map=True)
    n_march = evaluations[0] - n_search
    assert search.stability_map is None and march.stability_map is not None
    a, b = search.limit_depth_m, march.limit_depth_m
    assert np.array_equal(np.isnan(a), np.isnan(b))
    assert np.allclose(a, b, rtol=2e-4, equal_nan=True), np.nanmax(np.abs(a / b - 1))
    assert list(search.boundary_kind) == list(march.boundary_kind)
    assert np.array_equal(search.steps_per_period, march.steps_per_period)
    if case.startswith("5%"):
        assert np.count_nonzero(search.boundary_kind == "flip") >= 10  # the islands are there, and found
    assert n_search < 0.6 * n_march, (n_search, n_march)


def test_an_island_below_the_continued_bracket_is_found(monkeypatch):
    """5 % down milling at 18,250 rpm, 150 steps: unstable from 1.15 to 4.0 mm (a closed period-doubling
    region), stable again up to 7.8 mm.  From a guess of 6 mm the bracket closes around 7.8 mm; the probes below
    it find the region and its lower edge.  Without the probes the search would return the upper boundary."""
    from spindlesim.chatter import sd_search
    from spindlesim.chatter.sd_lobes import _Grouped

    p, tool, _ = CASES["5%-down"]
    speeds = np.array([18250.0])
    ref = stability_lobes(p, tool, speeds, "semi_discretization", stability_map=True, extrapolate=False,
                          error_tol=np.inf, steps=150)
    prob = _Grouped(p, [tool], speeds, np.array([150]), 1)
    rho0 = np.exp(np.max(np.linalg.eigvals(tool.A).real) * p.tooth_period_s(speeds))
    got = sd_search.continued_limits(prob, np.array([6e-3]), 0.2, rho0, 1e-4, 0.9)
    assert ref.boundary_kind[0] == got["kind"][0] == "flip"
    assert 1.1e-3 < got["limit"][0] < 1.2e-3
    assert got["limit"][0] == pytest.approx(ref.limit_depth_m[0], rel=2e-4)
    monkeypatch.setattr(sd_search, "PROBES", ())
    blind = sd_search.continued_limits(prob, np.array([6e-3]), 0.2, rho0, 1e-4, 0.9)
    assert blind["limit"][0] > 7e-3
