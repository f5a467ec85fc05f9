"""Modal fit of measured FRFs: known modal parameters recovered from noisy synthetic tap tests."""

import numpy as np
import pytest

from spindlesim.chatter import Mode, ToolPointFrf, ToolPointModel, fit_tool_point_model
from spindlesim.chatter.modal_fit import fit_direction, noise_level

TRUE = [Mode("x", 650.0, 0.035, 2.2e7), Mode("x", 1450.0, 0.02, 4.0e7),
        Mode("y", 720.0, 0.03, 2.6e7), Mode("y", 1600.0, 0.025, 5.0e7)]


def _noisy(noise: float, seed: int = 7) -> ToolPointFrf:
    model = ToolPointModel.from_modes(TRUE)
    f = np.arange(100.0, 3000.0, 1.0)
    H = model.receptance(2 * np.pi * f)
    rng = np.random.default_rng(seed)
    peak = np.abs(H).max()
    for i in range(2):
        H[:, i, i] += noise * peak * (rng.standard_normal(len(f)) + 1j * rng.standard_normal(len(f))) / np.sqrt(2)
    return ToolPointFrf(f, H, "synthetic tap test")


def test_exact_frf_is_fitted_exactly():
    fit = fit_tool_point_model(_noisy(0.0))
    for a, b in zip(TRUE, fit.modes):
        assert b.direction == a.direction
        assert b.frequency_hz == pytest.approx(a.frequency_hz, rel=1e-8)
        assert b.damping_ratio == pytest.approx(a.damping_ratio, rel=1e-6)
        assert b.stiffness_N_m == pytest.approx(a.stiffness_N_m, rel=1e-6)


@pytest.mark.parametrize("noise", [0.01, 0.02])
def test_noisy_frf_recovers_modal_parameters(noise):
    """Complex Gaussian noise of 1 % and 2 % of the peak on every sample (1 Hz resolution).

    Tolerances: frequency 0.1 %, damping ratio 5 %, modal stiffness 3 %.
    """
    frf = _noisy(noise)
    fit = fit_tool_point_model(frf)
    assert len(fit.modes) == 4
    for a, b in zip(TRUE, fit.modes):
        assert b.frequency_hz == pytest.approx(a.frequency_hz, rel=1e-3)
        assert b.damping_ratio == pytest.approx(a.damping_ratio, rel=0.05)
        assert b.stiffness_N_m == pytest.approx(a.stiffness_N_m, rel=0.03)
    # fitted model follows the clean FRF closely at the resonances (what the lobes depend on)
    clean = ToolPointModel.from_modes(TRUE)
    w = 2 * np.pi * np.array([650.0, 672.0, 720.0, 745.0])
    ref = clean.receptance(w)
    assert np.allclose(fit.model.receptance(w), ref, rtol=0.05, atol=0.02 * np.abs(ref).max())
    assert noise_level(frf.H[:, 0, 0]) == pytest.approx(noise * np.abs(frf.H).max(), rel=0.15)


def test_fit_one_direction_band_and_mode_count():
    frf = _noisy(0.005)
    fit = fit_direction(frf.frequency_hz, frf.H[:, 1, 1], "y", n_modes=1, band_hz=(500.0, 1000.0))
    assert len(fit.modes) == 1
    assert fit.modes[0].frequency_hz == pytest.approx(720.0, rel=2e-3)
    # the 1600 Hz mode outside the band is absorbed by the upper residual
    assert fit.upper_residual_m_N > 0
