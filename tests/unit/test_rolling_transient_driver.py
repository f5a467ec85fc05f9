"""Transient driver: sampling, Poincare instants, incomplete runs (interrupt, non-finite state)."""

from dataclasses import dataclass

import numpy as np
import pytest

from spindlesim.analysis.spectrum import amplitude_spectrum, distinct_points, poincare_times
from spindlesim.analysis.fixed_step import plan_steps
from spindlesim.analysis.transient import TransientSettings, run_transient


@dataclass(frozen=True)
class Oscillator:
    """x'' + w^2 x = 0 in x and y, with optional sabotage after t_fail."""

    w: float = 2 * np.pi * 50.0
    t_fail: float = np.inf
    fail: str = ""
    model_name: str = "test"
    rollers: int = 4
    cage_frequency_hz: float = 12.5  # roller pass 50 Hz = the oscillator: period-1 Poincare map
    n_state: int = 4

    @property
    def roller_pass_frequency_hz(self):
        return self.rollers * self.cage_frequency_hz

    def initial_state(self):
        return np.array([1e-6, 0.0, 0.0, 1e-6 * self.w])

    def rhs(self, t, s):
        if t > self.t_fail:
            if self.fail == "interrupt":
                raise KeyboardInterrupt
            return np.full(4, np.nan)
        return np.array([s[2], s[3], -self.w**2 * s[0], -self.w**2 * s[1]])

    def shaft_displacement(self, Y):
        return Y[:, 0:2]

    def roller_forces(self, t, Y):
        return np.zeros((len(t), self.rollers))

    def race_deflection(self, t, Y):
        return None


# RK4 with h = 1e-4 s: global phase error ~ T w (h w)^4 / 120 = 1.3e-6 of the 1e-6 m amplitude
@pytest.mark.parametrize("settings, tol", [
    (dict(method="DOP853", rtol=1e-10, atol=1e-18), 1e-13),
    (dict(method="RK4", step_s=1e-4), 3e-12)])
def test_sampling_spectrum_and_poincare_of_an_exact_solution(settings, tol):
    res = run_transient(Oscillator(), TransientSettings(0.5, settle_s=0.1, sample_rate_hz=2000, **settings))
    assert res.complete and res.reason == ""
    assert res.time_s[0] == 0 and res.time_s[-1] == pytest.approx(0.5)
    assert np.allclose(np.diff(res.time_s), 1 / 2000)
    w = 2 * np.pi * 50
    assert res.displacement_m[:, 0] == pytest.approx(1e-6 * np.cos(w * res.time_s), abs=tol)
    assert res.spectrum.dominant_frequency_hz(0) == pytest.approx(50.0, abs=res.spectrum.resolution_hz)
    # Poincare instants every 1/(N f_cage) = 20 ms from the settle time: the circle orbit maps to one point
    assert np.allclose(np.diff(res.poincare_time_s), 0.02)
    assert distinct_points(res.poincare_xy_m, 1e-10) == 1
    assert res.poincare_xy_m[0] == pytest.approx([1e-6, 0.0], abs=1e-12)


@pytest.mark.parametrize("method, fail, word", [
    ("DOP853", "interrupt", "interrupted"), ("DOP853", "nan", "step-size collapse"),
    ("RK4", "interrupt", "interrupted"), ("RK4", "nan", "non-finite")])
def test_failed_run_keeps_what_it_computed(method, fail, word):
    res = run_transient(Oscillator(t_fail=0.26, fail=fail),
                        TransientSettings(0.5, sample_rate_hz=1000, chunks=10, method=method, step_s=1e-4))
    assert not res.complete
    assert word in res.reason and res.reason
    assert 0.2 <= res.t_reached_s <= 0.3
    assert res.time_s.size > 0 and res.time_s[-1] <= 0.3
    assert np.all(np.isfinite(res.displacement_m))


def test_exact_stepping_plan():
    # 8 rollers at 5000 rpm: 1/f_rp = 3.7624 ms = 50 samples of 76 steps of 0.99 us
    plan = plan_steps(1.0, 1e-6, 50 * 265.787, 265.787)
    assert plan.samples_per_pass == 50 and plan.steps_per_sample == 76
    assert plan.step_s <= 1e-6 and plan.step_s * 76 * 50 == pytest.approx(1 / 265.787, rel=1e-12)
    assert plan.n_samples == int(1.0 * 50 * 265.787)
    # no roller pass (0 rpm): the grid alone
    plan = plan_steps(0.1, 3e-6, 2000.0, 0.0)
    assert plan.samples_per_pass == 0 and plan.step_s * plan.steps_per_sample == pytest.approx(5e-4)
    assert plan.n_samples == 200 and plan.step_s <= 3e-6


def test_spectrum_amplitude_and_poincare_times():
    fs, n = 1000.0, 1000
    t = np.arange(n) / fs
    sig = 3.0 * np.sin(2 * np.pi * 100 * t)  # on a bin
    sp = amplitude_spectrum(sig, fs)
    assert sp.amplitude[:, 0].max() == pytest.approx(3.0, rel=1e-9)
    assert sp.dominant_frequency_hz(0) == pytest.approx(100.0)
    assert poincare_times(0.1, 0.2, 0.025) == pytest.approx([0.1, 0.125, 0.15, 0.175, 0.2])
