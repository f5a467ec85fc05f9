"""Stability pockets and the recommended speed (spindlesim/chatter/pockets.py), on made-up envelopes."""

import numpy as np
import pytest

from spindlesim.chatter import LobeDiagram, best_pocket, stability_pockets

SPEEDS = np.arange(1000.0, 2001.0, 10.0)


def _diagram(limit, capped=None, cap=np.nan, speeds=SPEEDS):
    n = len(limit)
    return LobeDiagram(speeds, np.asarray(limit, float), np.full(n, 900.0), (), "semi_discretization", "test",
                       capped=np.zeros(n, bool) if capped is None else capped, depth_cap_m=cap)


def _peak(center, height, slope, base=1.0):
    return np.maximum(base, height - slope * np.abs(SPEEDS - center))


def test_broad_pocket_at_90_percent_and_edges_are_not_pockets():
    """A peak of 2 with flanks of 0.01 per rpm: at 90 % (1.8) the interval is 1,480-1,520 rpm, wider
    than +-1 % of 1,500 rpm; the rising end of the range (3 at 2,000 rpm) is not a pocket."""
    lim = np.maximum(_peak(1500.0, 2.0, 0.01), 1.0 + 2.0 * np.clip(SPEEDS - 1800.0, 0, None) / 200.0)
    pockets = stability_pockets(_diagram(lim))
    assert len(pockets) == 1
    p = pockets[0]
    assert (p.peak_speed_rpm, p.peak_depth_m, p.level) == (1500.0, 2.0, pytest.approx(0.9))
    assert p.depth_m == pytest.approx(1.8) and p.speed_min_rpm == pytest.approx(1480.0)
    assert p.speed_max_rpm == pytest.approx(1520.0) and p.speed_rpm == pytest.approx(1500.0)
    assert p.tolerance_rpm == pytest.approx(20.0) and p.grid_speeds == 5
    assert best_pocket(pockets) is p


def test_sharp_pocket_gives_depth_for_one_percent_of_the_speed():
    """A sharp cusp (0.05 per rpm) holds 90 % of its peak over +-4 rpm only; its depth is lowered until
    the interval spans +-1 % (15 rpm): 2 - 0.75 = 1.25.  A broad lower pocket can then be deeper."""
    sharp = _peak(1500.0, 2.0, 0.05)
    p = stability_pockets(_diagram(sharp))[0]
    assert p.depth_m == pytest.approx(1.25, rel=1e-6) and p.tolerance_rpm == pytest.approx(15.0, rel=1e-6)
    assert p.level == pytest.approx(0.625, rel=1e-6)
    both = np.maximum(sharp, _peak(1200.0, 1.5, 0.002))
    best = best_pocket(stability_pockets(_diagram(both)))
    assert best.peak_speed_rpm == 1200.0 and best.depth_m == pytest.approx(1.35)


def test_capped_speeds_count_at_the_cap():
    lim = _peak(1500.0, 2.0, 0.01)
    capped = np.abs(SPEEDS - 1500.0) <= 20.0
    lim[capped] = np.nan
    p = best_pocket(stability_pockets(_diagram(lim, capped, cap=1.9)))
    assert p.capped and p.peak_depth_m == 1.9 and p.peak_speed_rpm == 1500.0
    assert p.speed_min_rpm < 1480.0 < 1520.0 < p.speed_max_rpm
    assert stability_pockets(_diagram(np.linspace(1.0, 2.0, len(SPEEDS)))) == ()


def test_a_pocket_between_two_grid_speeds_is_not_preferred():
    """On a 50 rpm grid a cusp to 5 at 1,700 rpm (neighbours 1) keeps +-1 % (17 rpm) between two grid
    speeds only: deeper, but resolved by one grid speed; a lower pocket spanning many grid speeds is
    recommended instead, the cusp only when alone."""
    coarse = np.arange(1000.0, 2001.0, 50.0)
    cusp = np.where(coarse == 1700.0, 5.0, 1.0)
    broad = np.maximum(1.0, 1.5 - 0.002 * np.abs(coarse - 1200.0))
    pockets = stability_pockets(_diagram(np.maximum(cusp, broad), speeds=coarse))
    assert pockets[0].peak_speed_rpm == 1700.0 and pockets[0].grid_speeds == 1
    assert best_pocket(pockets).peak_speed_rpm == 1200.0 and best_pocket(pockets).grid_speeds >= 3
    assert best_pocket(stability_pockets(_diagram(cusp, speeds=coarse))).peak_speed_rpm == 1700.0


def test_the_minimum_of_a_tie_is_at_the_lowest_speed():
    """Two speeds whose limits agree within the depth search's tolerance (1e-4; the milling deck's 23,910 and
    24,000 rpm straddle the bottom of a lobe and agree to 1e-5) are a tie: the lower speed is reported whichever
    of them the search makes smaller, and in any order."""
    a = 0.0007411547114381245
    for eps in (2.7e-16, 9.5e-6, 0.9e-4):
        for limits in ([2e-3, a, 3e-3, a * (1 - eps)], [2e-3, a * (1 - eps), 3e-3, a]):
            d = _diagram(limits, speeds=np.array([9000.0, 23910.0, 12000.0, 24000.0]))
            assert d.minimum[0] == 23910.0
            assert d.minimum[1] in (a, a * (1 - eps))
    d = _diagram([2e-3, a, a * (1 - 3e-4)], speeds=np.array([9000.0, 23910.0, 24000.0]))  # a real difference
    assert d.minimum == (24000.0, a * (1 - 3e-4))
