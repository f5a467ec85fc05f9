"""Time-domain simulation against the lobe diagrams.

Points 10 % below the boundary are stable and 10 % above chatter, at several speeds; the
simulated chatter frequency is the diagram's within one FFT bin; while the motion is linear the
Poincare distances shrink by the monodromy's spectral radius per tooth period.
"""

import numpy as np
import pytest

from spindlesim.chatter import MillingProcess, Mode, ToolPointModel, TurningProcess, simulate, stability_lobes
from spindlesim.chatter.semi_discretization import spectral_radius

TOOL = ToolPointModel.from_modes([Mode("x", 922.0, 0.011, 0.03993 * (2 * np.pi * 922.0) ** 2)])
SLOT2 = MillingProcess(2, 20e-3, 20e-3, "down", 6e8, 1 / 3, feed_per_tooth_m=5e-5)  # Insperger-Stepan example


def _check(process, tool, diagram, periods):
    for s, a, fc in zip(diagram.speed_rpm, diagram.limit_depth_m, diagram.chatter_frequency_hz):
        below = simulate(process, tool, s, 0.9 * a, tooth_periods=periods)
        above = simulate(process, tool, s, 1.1 * a, tooth_periods=periods)
        assert below.stable, f"{s} rpm, 0.9 x {a * 1e3:.4f} mm: growth {below.growth_per_period:.4f}"
        assert not above.stable, f"{s} rpm, 1.1 x {a * 1e3:.4f} mm: growth {above.growth_per_period:.4f}"
        assert np.isnan(below.chatter_frequency_hz)
        assert abs(above.chatter_frequency_hz - fc) <= above.fft_bin_hz, (s, above.chatter_frequency_hz, fc)


def test_milling_slot_semi_discretization_boundary():
    speeds = np.array([6000.0, 10000.0, 16000.0, 17000.0])
    sd = stability_lobes(SLOT2, TOOL, speeds, "semi_discretization", depth_max_m=1.5e-3, n_depths=16)
    assert np.all(np.isfinite(sd.limit_depth_m))
    _check(SLOT2, TOOL, sd, 400)


def test_milling_low_immersion_flip_and_hopf():
    p = MillingProcess(2, 20e-3, 1e-3, "down", 6e8, 1 / 3, feed_per_tooth_m=5e-5)
    sd = stability_lobes(p, TOOL, [17500.0, 18000.0, 22000.0], "semi_discretization", depth_max_m=4e-3, n_depths=16)
    assert list(sd.boundary_kind) == ["flip", "flip", "hopf"]
    _check(p, TOOL, sd, 400)


def test_milling_two_directions_half_immersion():
    """x and y flexible, 4 teeth, half immersion up milling: zero-order and SD within 2 %, both
    confirmed by the simulation."""
    tool = ToolPointModel.from_modes([Mode("x", 600.0, 0.03, 1.5e7), Mode("y", 660.0, 0.025, 1.8e7)])
    p = MillingProcess(4, 16e-3, 8e-3, "up", 800e6, 0.3, feed_per_tooth_m=5e-5)
    speeds = [7000.0, 12000.0, 16000.0]
    sd = stability_lobes(p, tool, speeds, "semi_discretization", depth_max_m=6e-3, n_depths=16)
    zoa = stability_lobes(p, tool, speeds, "zero_order")
    assert np.allclose(zoa.limit_depth_m, sd.limit_depth_m, rtol=0.02)
    _check(p, tool, sd, 400)


def test_milling_with_helix():
    """30 deg helix (16 axial slices in both the semi-discretization and the simulation)."""
    tool = ToolPointModel.from_modes([Mode("x", 600.0, 0.03, 3e6), Mode("y", 660.0, 0.025, 3.6e6)])
    p = MillingProcess(3, 16e-3, 4e-3, "down", 800e6, 0.3, helix_rad=np.deg2rad(30.0), feed_per_tooth_m=5e-5)
    sd = stability_lobes(p, tool, [8000.0, 11000.0, 14000.0], "semi_discretization", depth_max_m=8e-3, n_depths=16)
    straight = stability_lobes(MillingProcess(3, 16e-3, 4e-3, "down", 800e6, 0.3), tool, [11000.0],
                               "semi_discretization", depth_max_m=8e-3, n_depths=16)
    assert sd.limit_depth_m[1] > 1.01 * straight.limit_depth_m[0]  # the helix matters here
    _check(p, tool, sd, 400)


def test_turning_oriented_frf_boundary():
    tool = ToolPointModel.from_modes([Mode("x", 500.0, 0.03, 2e7), Mode("y", 700.0, 0.04, 3e7)])
    p = TurningProcess(2000e6, np.deg2rad(30.0), np.deg2rad(20.0))
    d = stability_lobes(p, tool, [9000.0, 14000.0])
    _check(p, tool, d, 200)


def test_linear_decay_matches_spectral_radius():
    for s, a in ((10100.0, 0.28e-3), (16000.0, 0.25e-3)):
        rho = spectral_radius(SLOT2, TOOL, s, a, steps=120)
        sim = simulate(SLOT2, TOOL, s, a, tooth_periods=300)
        assert sim.stable
        assert sim.growth_per_period == pytest.approx(rho, abs=3e-3)
        assert sim.out_of_cut_fraction < 0.05
