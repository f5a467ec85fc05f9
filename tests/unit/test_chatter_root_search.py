"""The limit depth's refinement follows the multiplier that turns unstable.

A nearly undamped mode holds the spectral radius a hair below 1 (here 1 - 2e-6) from zero depth up to where
the chatter mode overtakes it, so rho(a) - 1 is flat on the stable side of each bracket and a regula falsi on
it degenerates to bisection.  Interpolating on the modulus of the multiplier nearest the unstable one finds
the same roots (the side a trial depth replaces is still decided by rho) in far fewer evaluations.
"""

import numpy as np
import pytest

import spindlesim.chatter.sd_lobes as sd_lobes
from spindlesim.chatter import MillingProcess, Mode, ToolPointModel

FN, ZETA, MT = 922.0, 0.011, 0.03993
K1 = MT * (2 * np.pi * FN) ** 2
# x: the chatter mode of the Insperger-Stepan benchmark; y: 40 Hz, damping 1e-6, stiff enough that the cut
# hardly moves it (its multiplier stays at exp(-zeta w tau) = 1 - 2e-6 or so at every depth)
FLAT = Mode("y", 40.0, 1e-6, 1e12)
TOOL = ToolPointModel.from_modes([Mode("x", FN, ZETA, K1), FLAT])
PROCESS = MillingProcess(2, 20e-3, 5e-3, "down", 6e8, 1 / 3)
SPEEDS = np.linspace(9000.0, 21000.0, 7)


class _Counting:
    def __init__(self, prob):
        self.prob, self.evaluations = prob, 0

    def multipliers(self, s_idx, depth):
        self.evaluations += len(np.atleast_1d(s_idx))
        return self.prob.multipliers(s_idx, depth)


def _brackets():
    prob = sd_lobes._Grouped(PROCESS, [TOOL], SPEEDS, np.full(len(SPEEDS), 60), 1)
    depths = np.linspace(0.1e-3, 4e-3, 40)
    mu = np.stack([prob.multipliers(np.arange(len(SPEEDS)), np.full(len(SPEEDS), a)) for a in depths], axis=1)
    rho = np.abs(mu[..., 0])
    j = np.argmax(rho >= 1.0, axis=1)
    assert np.all(rho[np.arange(len(SPEEDS)), j] >= 1.0) and np.all(j > 0)
    s = np.arange(len(SPEEDS))
    return prob, depths, rho, mu, j, s


def test_below_the_limit_the_spectral_radius_is_the_flat_mode():
    _, _, rho, _, j, s = _brackets()
    below = rho[s, j - 1]
    assert np.all(below < 1.0) and np.all(below > 1.0 - 1e-4)  # held by the undamped mode, not the chatter mode


def test_following_the_unstable_multiplier_gives_the_same_roots_in_fewer_evaluations():
    prob, depths, rho, mu, j, s = _brackets()
    lo, hi = depths[j - 1], depths[j]
    f_lo, f_hi = rho[s, j - 1] - 1.0, rho[s, j] - 1.0
    plain, followed = _Counting(prob), _Counting(prob)
    a_plain, _ = sd_lobes._itp(plain, s, lo, hi, f_lo, f_hi, 1e-4)
    a_followed, slope = sd_lobes._itp(followed, s, lo, hi, f_lo, f_hi, 1e-4, mu[s, j - 1], mu[s, j, 0])
    np.testing.assert_allclose(a_followed, a_plain, rtol=1e-4)  # the search's tolerance, the default rtol
    # at the roots the spectral radius is 1 (to what a depth tolerance of 1e-4 leaves of it)
    np.testing.assert_allclose(prob.spectral_radius(s, a_followed), 1.0, atol=1e-4 * np.max(slope * a_followed))
    # 32 against 55 evaluations for the 7 speeds (the milling deck's diagram: 1269 against 2647 for 263 speeds)
    assert followed.evaluations <= 0.7 * plain.evaluations, (followed.evaluations, plain.evaluations)
    assert np.all(slope > 0)


@pytest.mark.parametrize("missing", ["lower", "upper"])
def test_without_the_multipliers_it_falls_back_to_rho(missing):
    """An island's bracket (found by maximising rho between grid depths) has no multipliers at its ends: the
    refinement then interpolates on rho itself, as before, and still converges."""
    prob, depths, rho, mu, j, s = _brackets()
    lo, hi = depths[j - 1], depths[j]
    M_lo = np.full_like(mu[s, j - 1], np.nan) if missing == "lower" else mu[s, j - 1]
    mu_hi = np.full_like(mu[s, j, 0], np.nan) if missing == "upper" else mu[s, j, 0]
    a, _ = sd_lobes._itp(prob, s, lo, hi, rho[s, j - 1] - 1.0, rho[s, j] - 1.0, 1e-6, M_lo, mu_hi)
    ref, _ = sd_lobes._itp(prob, s, lo, hi, rho[s, j - 1] - 1.0, rho[s, j] - 1.0, 1e-6)
    np.testing.assert_allclose(a, ref, rtol=1e-6)


class _Bump:
    """rho(a) = base(a) + a narrow bump at A0 that reaches above 1 between two grid depths (an island)."""

    A0, WIDTH = 1.05e-3, 0.04e-3

    def __init__(self, base, height):
        self.base, self.height, self.calls = base, height, 0
        self.speeds = np.array([10000.0])

    def spectral_radius(self, s_idx, depth):
        self.calls += len(np.atleast_1d(s_idx))
        a = np.asarray(depth, float)
        return self.base(a) + self.height * np.exp(-(((a - self.A0) / self.WIDTH) ** 2))


GRID = np.linspace(0.1e-3, 2e-3, 20)  # the island at 1.05 mm lies between the grid depths 1.0 and 1.1 mm


def _search(bump):
    rho = bump.spectral_radius(np.zeros(len(GRID), int), GRID)[None, :]
    rho0 = bump.spectral_radius(np.array([0]), np.array([1e-7]))
    bump.calls = 0
    first = np.array([int(np.argmax(rho[0] >= 1.0)) if np.any(rho[0] >= 1.0) else -1])
    return sd_lobes._brackets(bump, GRID, rho, rho0, first, 0.9)


def test_an_island_between_grid_depths_is_found_from_its_rise_on_the_grid():
    """rho 0.93 + a bump of 0.1 (peak 1.03 at 1.05 mm, 0.04 mm wide): the grid depth 1.0 mm sees 0.9481, its
    neighbours 0.9300: a rise of a quarter of the distance to 1, searched; the island bracketed."""
    bump = _Bump(lambda a: np.full_like(a, 0.93), 0.1)
    lo, hi, f_lo, f_hi = _search(bump)
    assert bump.calls > 0
    assert lo[0] < bump.A0 < 1.1e-3 and np.isfinite(hi[0]) and f_hi[0] >= 0.0 > f_lo[0]
    assert abs(hi[0] - bump.A0) < bump.WIDTH


def test_a_flat_mode_drifting_by_round_off_is_not_searched():
    """A nearly undamped mode: rho = 1 - 6.7e-5 drifting by 3e-8 over the grid (the milling deck's case), the
    first crossing at 1.6 mm: its local maxima rise 1e-4 of their distance to 1 and are not searched."""
    bump = _Bump(lambda a: np.where(a < 1.55e-3, 1 - 6.7e-5 + 3e-8 * np.sin(4e4 * a), 1.01), 0.0)
    lo, hi, _, _ = _search(bump)
    assert bump.calls == 0
    assert lo[0] == GRID[14] and hi[0] == GRID[15]  # the grid's own bracket


def test_interpolation_closes_the_bracket_in_fewer_evaluations(monkeypatch):
    """Inverse quadratic interpolation with a light truncation (ITP_KAPPA1 = 0.002 of the first width) against the
    method's usual regula falsi with kappa_1 = 0.2, whose first step is nearly a bisection: the same roots to
    the tolerance in fewer evaluations (here 23 against 35 for the 7 speeds; the milling deck: 2.9 against 4.4 a
    speed after the continued bracket)."""
    prob, depths, rho, mu, j, s = _brackets()
    lo, hi = depths[j - 1], depths[j]
    args = (s, lo, hi, rho[s, j - 1] - 1.0, rho[s, j] - 1.0, 1e-4, mu[s, j - 1], mu[s, j, 0])
    new = _Counting(prob)
    a_new, slope = sd_lobes._itp(new, *args)
    monkeypatch.setattr(sd_lobes, "ITP_KAPPA1", 0.2)
    monkeypatch.setattr(sd_lobes, "_interpolated", lambda a, b, c, fa, fb, fc: (b * fa - a * fb) / (fa - fb))
    old = _Counting(prob)
    a_old, _ = sd_lobes._itp(old, *args)
    np.testing.assert_allclose(a_new, a_old, rtol=1e-4)
    np.testing.assert_allclose(prob.spectral_radius(s, a_new), 1.0, atol=1e-4 * np.max(slope * a_new))
    assert new.evaluations <= 0.8 * old.evaluations, (new.evaluations, old.evaluations)


def test_the_slope_at_the_root_is_the_multipliers_not_rounding():
    """Full slot, 2 teeth, 17,600 rpm, 30 steps (tests/unit/test_chatter_search.py's case at its speed 24): from
    the continued search's bracket (0.339-0.565 mm) the interpolation converges on the root from below.  Without
    a step past the root the last bracket was 3.5e-13 m wide and d|mu|/da over it 314 /m, the multipliers'
    rounding; the derivative is 190 /m.  The slope feeds the error estimate and the extrapolation."""
    process = MillingProcess(2, 20e-3, 20e-3, "down", 6e8, 1 / 3)
    tool = ToolPointModel.from_modes([Mode("x", FN, ZETA, K1)])
    speeds = np.array([17600.0])
    prob = sd_lobes._Grouped(process, [tool], speeds, np.array([30]), 1)
    s = np.array([0])
    lo, hi = np.array([0.000339011109515516]), np.array([0.0005650185158591934])
    M_lo, M_hi = prob.multipliers(s, lo), prob.multipliers(s, hi)
    root, slope = sd_lobes._itp(prob, s, lo, hi, np.abs(M_lo[:, 0]) - 1, np.abs(M_hi[:, 0]) - 1, 1e-4, M_lo,
                                M_hi[:, 0])
    h = 1e-3 * root
    central = (prob.spectral_radius(s, root + h) - prob.spectral_radius(s, root - h)) / (2 * h)
    np.testing.assert_allclose(slope, central, rtol=0.01)
    np.testing.assert_allclose(prob.spectral_radius(s, root), 1.0, atol=float(1e-4 * slope[0] * root[0]))
