"""Milling: zero-order (Altintas and Budak 1995) and semi-discretization (Insperger and Stepan).

Tool: the single-degree-of-freedom milling example of Insperger and Stepan (Int. J. Numer. Meth.
Engng 61 (2004) 117-141, after Insperger, Mann, Stepan and Bayly, IJMTM 43 (2003) 25-34; also
Ding et al. 2010): flexible in the feed direction x, f_n = 922 Hz, zeta = 0.011,
m = 0.03993 kg; Kt = 6e8 N/m^2, Kn = 2e8 N/m^2; down milling.

* Full immersion, 4 teeth: two teeth always cut at phi and phi + 90 deg, so the directional
  matrix is constant and the zero-order solution is exact; the semi-discretization (default 30
  points per chatter wave) must agree within 2 % (1.5 % at the steepest lobe flank, 0.2 %
  median).  With the example's 2 teeth the matrix fluctuates by 3x its mean (one tooth in cut)
  and the two differ by 5 to 45 % (benchmarks/bench_chatter.py); the time-domain simulation
  sides with the semi-discretization (tests/validation/test_chatter_simulation.py).
* a/D = 0.05, 2 teeth: period-doubling (flip) islands around 18000 rpm that the zero-order
  solution cannot show; second-order convergence of the semi-discretization in the step.
"""

import numpy as np
import pytest

from spindlesim.chatter import MillingProcess, Mode, ToolPointModel, simulate, stability_lobes

FN, ZETA, MT = 922.0, 0.011, 0.03993
K = MT * (2 * np.pi * FN) ** 2  # 1.340e6 N/m
KT, KN = 6e8, 2e8
TOOL = ToolPointModel.from_modes([Mode("x", FN, ZETA, K)])


def test_zero_order_slot_closed_form():
    """Slot, x only: K0_xx = -N Kn / 4, so a_min = 8 k zeta (1 + zeta) / (N Kn) at the lobe minima."""
    for N in (2, 4):
        p = MillingProcess(N, 20e-3, 20e-3, "down", KT, KN / KT)
        assert p.mean_directional()[0, 0] == pytest.approx(-N * KN / 4, rel=1e-12)
        fc = FN * (1 + ZETA)
        r = 1 + ZETA
        G = 1 / (K * (1 - r**2 + 2j * ZETA * r))
        eps = 2 * np.pi - 2 * np.arctan(G.real / G.imag)
        speeds = np.array([60 * fc / (N * (k + eps / (2 * np.pi))) for k in range(4)])
        d = stability_lobes(p, TOOL, speeds, "zero_order")
        assert np.allclose(d.limit_depth_m, 8 * K * ZETA * (1 + ZETA) / (N * KN), rtol=5e-3)
        assert np.allclose(d.chatter_frequency_hz, fc, rtol=5e-3)


def test_zero_order_and_semi_discretization_agree_at_full_immersion():
    p = MillingProcess(4, 20e-3, 20e-3, "down", KT, KN / KT)
    speeds = np.linspace(5000.0, 25000.0, 21)
    zoa = stability_lobes(p, TOOL, speeds, "zero_order")
    sd = stability_lobes(p, TOOL, speeds, "semi_discretization", depth_max_m=1.2e-3, n_depths=12)
    both = np.isfinite(sd.limit_depth_m)
    assert both.sum() >= 15
    assert np.all(zoa.limit_depth_m[~both] > 1.0e-3)  # SD NaN only above its depth range
    err = np.abs(sd.limit_depth_m[both] / zoa.limit_depth_m[both] - 1)
    assert err.max() < 0.02
    assert np.allclose(sd.chatter_frequency_hz[both], zoa.chatter_frequency_hz[both], rtol=1e-3)
    assert set(sd.boundary_kind[both]) == {"hopf"}


def test_low_immersion_flip_islands_missed_by_zero_order():
    p = MillingProcess(2, 20e-3, 1e-3, "down", KT, KN / KT)  # a/D = 0.05
    speeds = np.arange(15000.0, 19001.0, 500.0)
    zoa = stability_lobes(p, TOOL, speeds, "zero_order")
    sd = stability_lobes(p, TOOL, speeds, "semi_discretization", depth_max_m=6e-3, n_depths=30)
    flip = sd.boundary_kind == "flip"
    assert flip.sum() >= 5
    tau = 60.0 / (2 * speeds[flip])
    waves = sd.chatter_frequency_hz[flip] * tau
    assert np.allclose(waves - np.floor(waves), 0.5, atol=1e-6)  # period doubling: f = (j + 1/2) / tau
    i = int(np.flatnonzero(speeds == 18000.0)[0])
    assert sd.boundary_kind[i] == "flip"
    assert sd.limit_depth_m[i] < 0.35 * zoa.limit_depth_m[i]  # 1.30 mm against 4.96 mm
    assert sd.chatter_frequency_hz[i] == pytest.approx(900.0, abs=1e-6)
    assert np.all(sd.limit_depth_m[flip] < 0.6 * zoa.limit_depth_m[flip])
    # the time-domain simulation at 2 mm, 18000 rpm (stable for the zero-order solution) chatters
    # with period two: the Poincare points alternate between two clusters
    sim = simulate(p, TOOL, 18000.0, 2.0e-3, tooth_periods=300)
    assert not sim.stable
    P = sim.poincare_m[-40:, 0]
    assert np.abs(P[2:] - P[:-2]).max() < 0.05 * np.abs(P[1:] - P[:-1]).max()
    assert sim.chatter_frequency_hz == pytest.approx(900.0, abs=sim.fft_bin_hz)


@pytest.mark.parametrize("speed, order, kind", [(18000.0, 1, "flip"), (22000.0, 1, "hopf"), (22000.0, 0, "hopf")])
def test_semi_discretization_converges_second_order(speed, order, kind):
    """Limit depth for m = 16 ... 128 steps per tooth period against m = 512: error ~ m^-2."""
    p = MillingProcess(2, 20e-3, 1e-3, "down", KT, KN / KT)
    a = {}
    for m in (16, 32, 64, 128, 512):
        d = stability_lobes(p, TOOL, [speed], "semi_discretization", steps=m, order=order,
                            depths_m=[1.0e-3, 2.3e-3], rtol=1e-10)
        assert d.boundary_kind[0] == kind
        a[m] = d.limit_depth_m[0]
    steps = np.array([16, 32, 64, 128])
    err = np.array([abs(a[m] / a[512] - 1) for m in steps])
    slope = -np.polyfit(np.log(steps), np.log(err), 1)[0]
    assert slope > 1.8  # 2.1 to 2.2 observed
    assert err[-1] < 2e-3
