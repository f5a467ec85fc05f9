"""Pockets the speed grid does not resolve, solved again on a finer grid (spindlesim/chatter/refine.py).

The "solver" here is a made-up envelope evaluated exactly at any speed, so the refined diagram can be
checked against the function itself: a deep, narrow pocket that falls between two grid speeds of a
50 rpm grid must be found and recommended on computed limits, and a pocket that the interpolation made
look deep but is not must lose the recommendation to the resolved one.
"""

import numpy as np
import pytest

from spindlesim.chatter import LobeDiagram, best_pocket, stability_pockets
from spindlesim.chatter.pockets import MIN_GRID_SPEEDS
from spindlesim.chatter.refine import POINTS, refine_pockets, unresolved_deeper
from spindlesim.chatter.results import LobeCurve

COARSE = np.arange(1000.0, 2001.0, 50.0)


def _broad(n):  # a resolved pocket: 1.5 at 1,200 rpm, flanks 0.002 per rpm
    return np.maximum(1.0, 1.5 - 0.002 * np.abs(n - 1200.0))


def _cusp(n, centre=1712.0, height=5.0, slope=0.02):  # a narrow pocket off the grid
    return np.maximum(1.0, height - slope * np.abs(n - centre))


def _solver(envelope, calls):
    def solve(speeds):
        speeds = np.asarray(speeds, float)
        calls.append(speeds)
        lim = envelope(speeds)
        lobe = LobeCurve(1, speeds, lim, np.full(len(speeds), 900.0), "hopf")
        return LobeDiagram(speeds, lim, np.full(len(speeds), 900.0), (lobe,), "semi_discretization", "test",
                           boundary_kind=np.full(len(speeds), "hopf"))
    return solve


def test_a_deep_pocket_between_grid_speeds_is_solved_and_recommended():
    """Cusp to 5 at 1,712 rpm (grid neighbours 4.76 at 1,700 and 3.24 at 1,750): one grid speed holds
    it, so on the grid the broad 1.5 pocket would be recommended.  After refinement the cusp holds
    >= 3 computed speeds, its limits equal the envelope at every speed, and it is recommended with a
    peak within 1 % of the true 5 and the pocket's 90 % depth (4.5, held over +-25 rpm, wider than
    +-1 % of the speed)."""
    env = lambda n: np.maximum(_broad(n), _cusp(n))  # noqa: E731
    calls = []
    solve = _solver(env, calls)
    coarse = solve(COARSE)
    before = best_pocket(stability_pockets(coarse))
    assert before.peak_speed_rpm == pytest.approx(1200.0)
    todo = unresolved_deeper(stability_pockets(coarse))
    assert [p.peak_speed_rpm for p in todo] == [1700.0]

    refined = refine_pockets(coarse, solve)
    assert len(calls) >= 2 and all(len(c) <= POINTS for c in calls[1:])
    assert np.all(np.diff(refined.speed_rpm) > 0)
    assert set(COARSE) <= set(refined.speed_rpm.tolist())
    np.testing.assert_allclose(refined.limit_depth_m, env(refined.speed_rpm), rtol=0, atol=1e-12)
    np.testing.assert_allclose(refined.lobes[0].limit_depth_m, refined.limit_depth_m)
    assert (refined.boundary_kind == "hopf").all() and len(refined.method_per_speed) == len(refined.speed_rpm)
    assert any("speeds added" in n for n in refined.notes)

    best = best_pocket(stability_pockets(refined))
    assert best.grid_speeds >= MIN_GRID_SPEEDS
    assert abs(best.peak_speed_rpm - 1712.0) < 10.0
    assert best.peak_depth_m == pytest.approx(5.0, rel=0.01)
    assert best.depth_m == pytest.approx(0.9 * best.peak_depth_m) and best.depth_m > 4.45
    assert best.speed_min_rpm <= 1712.0 * 0.99 + 1.0 and best.speed_max_rpm >= 1712.0 * 1.01 - 1.0


def test_an_interpolated_pocket_that_is_shallow_loses_the_recommendation():
    """A one-speed spike to 5 at 1,700 rpm on the grid whose true envelope is a needle (1.2 wide at
    the grid speed only, flanks 1 per rpm): the refined speeds around it find 1.0, the spike stays one
    grid speed, and the resolved broad pocket at 1,200 rpm is recommended."""
    def env(n):
        n = np.asarray(n, float)
        return np.maximum(_broad(n), np.maximum(1.0, 5.0 - 1.0 * np.abs(n - 1700.0)))
    refined = refine_pockets(_solver(env, [])(COARSE), _solver(env, []))
    assert len(refined.speed_rpm) > len(COARSE)
    assert best_pocket(stability_pockets(refined)).peak_speed_rpm == pytest.approx(1200.0)


def test_nothing_to_refine_returns_the_same_diagram():
    calls = []
    solve = _solver(_broad, calls)
    coarse = solve(COARSE)
    assert refine_pockets(coarse, solve) is coarse and len(calls) == 1


def test_merged_fills_lobes_one_side_lacks_and_takes_the_smaller_cap():
    a = _solver(_broad, [])(COARSE)
    extra = np.array([1025.0, 1975.0])
    lim = np.array([np.nan, 2.0])
    b = LobeDiagram(extra, lim, np.full(2, 800.0), (LobeCurve(2, extra, lim, np.full(2, 800.0), "flip"),),
                    "semi_discretization", "test", capped=np.array([True, False]), depth_cap_m=3.0)
    m = a.merged(b, "two more")
    assert m.speed_rpm[1] == 1025.0 and m.speed_rpm[-2] == 1975.0 and m.notes[-1] == "two more"
    assert m.capped.sum() == 1 and m.capped[1] and m.depth_cap_m == 3.0
    kinds = {(c.kind, c.lobe): c for c in m.lobes}
    assert np.isnan(kinds[("flip", 2)].limit_depth_m[0]) and kinds[("flip", 2)].limit_depth_m[-2] == 2.0
    assert np.isnan(kinds[("hopf", 1)].limit_depth_m[1])


def test_run_chatter_refines_with_a_model_per_speed():
    """The driver with one tool-point model per speed (as from the rotor) and ``more`` for the added
    speeds.  Full slot, 4 teeth (zero order, exact there), two-mode tool: on a 700 rpm grid the deepest
    pocket sits at one grid speed (14,100 rpm, 0.702 mm interpolated); on a 10 rpm grid it peaks at
    0.733 mm at 14,170 rpm and keeps 0.639 mm over 13,955-14,238 rpm.  After refinement the driver
    recommends it on computed limits, every diagram speed has its tool, and the added speeds were asked
    for through ``more``."""
    from spindlesim.chatter import MillingProcess, Mode, ToolPointModel, ToolSeries, run_chatter, stability_lobes
    from spindlesim.chatter.section import ChatterSpec

    tool = ToolPointModel.from_modes([Mode("x", 922.0, 0.011, 1.34e6), Mode("y", 1010.0, 0.02, 2.0e6)])
    slot = MillingProcess(4, 20e-3, 20e-3, "down", 6e8, 1 / 3)
    grid = np.arange(5000.0, 20001.0, 700.0)
    asked = []

    def tools_at(speeds):
        asked.append(np.asarray(speeds))
        return [tool] * len(speeds)

    spec = ChatterSpec(slot, grid, "auto", "rotor", None, True)
    result = run_chatter(spec, ToolSeries(grid, (tool,) * len(grid), tools_at))
    assert asked and len(result.diagram.speed_rpm) == len(grid) + sum(len(a) for a in asked)
    assert np.array_equal(result.tool.speeds_rpm, result.diagram.speed_rpm)
    assert len(result.tool.tools) == len(result.diagram.speed_rpm)
    fine = stability_lobes(slot, tool, np.arange(13900.0, 14300.0, 2.0))
    assert result.recommendation.peak_depth_m == pytest.approx(np.nanmax(fine.limit_depth_m), rel=0.02)
    assert abs(result.recommendation.peak_speed_rpm - 14170.0) < 30.0
    assert result.recommendation.grid_speeds >= MIN_GRID_SPEEDS
    unrefined = run_chatter(spec, [tool] * len(grid))  # a list (a series without more): the grid as given
    assert len(unrefined.diagram.speed_rpm) == len(grid) and unrefined.recommendation.grid_speeds == 1
