"""Turning: Tlusty's regenerative theory with the oriented FRF against closed forms.

Single-degree-of-freedom tool along the feed (chip-thickness) direction, stiffness k, damping
ratio zeta, G(w) = 1 / (k (1 - r^2 + 2 j zeta r)):

* Re G is smallest, -1 / (4 k zeta (1 + zeta)), at r = 1 + zeta, hence
  b_lim,min = 2 k zeta (1 + zeta) / (Ks cos beta) (force angle beta: G_or = cos(beta) G);
* lobe k at that chatter frequency runs at n = 60 f_c / (k + eps / 2 pi) with
  eps = 2 pi - 2 arctan(Re G / Im G) (Schmitz and Smith, Machining Dynamics, ch. 4).
"""

import numpy as np
import pytest
from scipy.optimize import brentq

from spindlesim.chatter import (Mode, ToolPointModel, TurningProcess, oriented_frf, stability_lobes,
                                turning_parametric_lobes)

K, ZETA, FN, KS = 2.0e7, 0.03, 500.0, 2000e6  # N/m, -, Hz, N/m^2 (2000 N/mm^2)


def _G(f):
    r = np.asarray(f) / FN
    return 1.0 / (K * (1 - r**2 + 2j * ZETA * r))


def _eps_schmitz(G):
    return 2 * np.pi - 2 * np.arctan(G.real / G.imag)


def _closed_form_limit(speed_rpm, beta=0.0):
    """Smallest b over the lobes at one speed: roots of w T - eps(w) = 2 pi k for r > 1."""
    T = 60.0 / speed_rpm
    best = (np.inf, np.nan)
    wn = 2 * np.pi * FN
    k0 = max(0, int(np.floor(wn * T / (2 * np.pi) - 1)))
    for k in range(k0, k0 + 40):
        g = lambda w: w * T - _eps_schmitz(_G(w / (2 * np.pi))) - 2 * np.pi * k  # noqa: E731
        lo, hi = wn * (1 + 1e-9), wn * 50
        if g(lo) >= 0 or g(hi) <= 0:
            continue
        w = brentq(g, lo, hi, xtol=1e-12, rtol=1e-14)
        b = -1.0 / (2 * KS * np.cos(beta) * _G(w / (2 * np.pi)).real)
        if b < best[0]:
            best = (b, w / (2 * np.pi))
    return best


@pytest.mark.parametrize("beta_deg", [0.0, 70.0])
def test_sdof_minimum_limit_and_lobe_speeds(beta_deg):
    beta = np.deg2rad(beta_deg)
    tool = ToolPointModel.from_modes([Mode("x", FN, ZETA, K)])
    proc = TurningProcess(KS, beta)
    b_min = 2 * K * ZETA * (1 + ZETA) / (KS * np.cos(beta))
    fc = FN * (1 + ZETA)
    eps = _eps_schmitz(_G(fc))
    speeds = np.array([60 * fc / (k + eps / (2 * np.pi)) for k in range(5)])  # lobe minima
    d = stability_lobes(proc, tool, speeds)
    assert d.method == "oriented_frf"
    assert np.allclose(d.limit_depth_m, b_min, rtol=5e-3)
    assert np.allclose(d.chatter_frequency_hz, fc, rtol=5e-3)
    assert [c.lobe for c in d.lobes][:5] == [0, 1, 2, 3, 4]
    # the parametric lobes have their minimum at those speeds
    for c in turning_parametric_lobes(proc, tool, range(5)):
        i = int(np.argmin(c.limit_depth_m))
        assert c.limit_depth_m[i] == pytest.approx(b_min, rel=5e-3)
        assert c.speed_rpm[i] == pytest.approx(speeds[c.lobe], rel=5e-3)


def test_envelope_against_closed_form_at_any_speed():
    tool = ToolPointModel.from_modes([Mode("x", FN, ZETA, K)])
    proc = TurningProcess(KS, 0.0)
    speeds = np.linspace(3000.0, 40000.0, 47)
    d = stability_lobes(proc, tool, speeds)
    ref = np.array([_closed_form_limit(n) for n in speeds])
    assert np.allclose(d.limit_depth_m, ref[:, 0], rtol=5e-3)
    assert np.allclose(d.chatter_frequency_hz, ref[:, 1], rtol=5e-3)
    assert np.max(np.abs(d.limit_depth_m / ref[:, 0] - 1)) < 1e-3  # in fact much closer


def test_oriented_frf_directional_factors_schmitz_smith():
    """Modes at angles alpha_r from the feed direction: G_or = sum cos(beta - alpha_r) cos(alpha_r) G_r."""
    f = np.linspace(100.0, 1500.0, 200)
    modes = [(np.deg2rad(30.0), 2e7, 500.0, 0.03), (np.deg2rad(-60.0), 3e7, 700.0, 0.04)]
    H = np.zeros((len(f), 2, 2), complex)
    ref = np.zeros(len(f), complex)
    beta = np.deg2rad(70.0)
    for a, k, fn, z in modes:
        u = np.array([np.cos(a), np.sin(a)])
        g = Mode("x", fn, z, k).receptance(f)
        H += g[:, None, None] * np.outer(u, u)
        ref += np.cos(beta - a) * np.cos(a) * g
    assert np.allclose(oriented_frf(TurningProcess(KS, beta), H), ref, rtol=1e-12)
    # the feed direction rotates the whole picture
    rot = TurningProcess(KS, beta, feed_direction_rad=np.deg2rad(30.0))
    ref_rot = sum(np.cos(beta - (a - np.deg2rad(30))) * np.cos(a - np.deg2rad(30)) * Mode("x", fn, z, k).receptance(f)
                  for a, k, fn, z in modes)
    assert np.allclose(oriented_frf(rot, H), ref_rot, rtol=1e-12)


def test_measured_frf_and_model_give_the_same_lobes():
    tool = ToolPointModel.from_modes([Mode("x", FN, ZETA, K), Mode("y", 650.0, 0.04, 3e7)])
    proc = TurningProcess(KS, np.deg2rad(60.0), np.deg2rad(20.0))
    speeds = np.linspace(4000.0, 20000.0, 60)
    a = stability_lobes(proc, tool, speeds)
    frf = tool.frf(np.arange(200.0, 1500.0, 0.25))  # a "measured" FRF at 0.25 Hz resolution
    b = stability_lobes(proc, frf, speeds)
    assert np.allclose(a.limit_depth_m, b.limit_depth_m, rtol=2e-3)


def test_frf_at_each_speed():
    """A tool that softens with speed: each speed is solved on its own FRF."""
    proc = TurningProcess(KS, 0.0)
    speeds = np.linspace(5000.0, 30000.0, 11)

    def tool(n):
        return ToolPointModel.from_modes([Mode("x", FN * (1 - 0.1 * (n / 30000) ** 2), ZETA, K)])

    d = stability_lobes(proc, tool, speeds)
    assert d.frf_at_each_speed
    single = [stability_lobes(proc, tool(n), [n]).limit_depth_m[0] for n in speeds]
    assert np.allclose(d.limit_depth_m, single, rtol=1e-12)
    fixed = stability_lobes(proc, tool(0.0), speeds)
    assert not np.allclose(d.limit_depth_m, fixed.limit_depth_m, rtol=1e-2)


def test_semi_discretization_converges_to_tlusty_for_turning():
    """Constant-coefficient delay equation: the SD boundary tends to the exact one (second order).
    Error control off (error_tol=inf): the plain discretisation at the given points per wave."""
    tool = ToolPointModel.from_modes([Mode("x", FN, ZETA, K), Mode("y", 700.0, 0.04, 3e7)])
    proc = TurningProcess(KS, np.deg2rad(30.0), np.deg2rad(20.0))
    speeds = np.array([9000.0, 14000.0, 26000.0])
    exact = stability_lobes(proc, tool, speeds)
    errs = []
    for ppw in (10.0, 20.0, 40.0):
        sd = stability_lobes(proc, tool, speeds, "semi_discretization", points_per_wave=ppw, n_depths=12,
                             depth_max_m=3 * np.nanmax(exact.limit_depth_m), error_tol=np.inf)
        errs.append(np.max(np.abs(sd.limit_depth_m / exact.limit_depth_m - 1)))
    assert errs[-1] < 5e-3
    assert errs[0] / errs[1] > 3.0 and errs[1] / errs[2] > 3.0  # ~ 4 per halving of the step
