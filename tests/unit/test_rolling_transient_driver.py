"""The transient engine's driver: sampling, Poincare instants, exact solutions, incomplete runs."""

from dataclasses import dataclass, field

import numpy as np
import pytest

from spindlesim.analysis.transient.engine import Perturbation, TransientSettings, simulate
from spindlesim.analysis.transient.fixed_step import plan_steps
from spindlesim.analysis.transient.spectrum import amplitude_spectrum, distinct_points, poincare_times
from spindlesim.bearings.base import RADIAL, BearingBase
from spindlesim.bearings.linear.bearing import LinearBearing
from spindlesim.model.rig import journal_rotor

W = 2 * np.pi * 50.0  # 50 Hz oscillator
M = 0.6
A = 1e-6


def oscillator_rotor(bearing=None, rpm=3000.0):
    """A journal of 0.6 kg on an isotropic spring of natural frequency 50 Hz (= the shaft speed)."""
    b = bearing or LinearBearing("spring", 0, np.array([0.0]), np.array([np.eye(2) * M * W ** 2]), np.zeros((1, 2, 2)))
    return journal_rotor((b,), M, 0.0, (0.0, 0.0), rpm)


def settings(method, **kw):
    # released from x = A (a static force K A) with y' = A w: a circular whirl of radius A at 50 Hz
    return TransientSettings(0.5, method=method, settle_s=0.1, sample_rate_hz=2000,
                             perturbation=Perturbation(0, A * M * W ** 2), initial_velocity=((1, A * W),), **kw)


# exact solution x = A cos(w t), y = A sin(w t).  RK4 with h = 1e-4 s: phase error ~ T w (h w)^4 / 120 = 1.3e-6 A;
# Newmark (trapezoidal) at h = 2.5e-5 s: period elongation (h w)^2 / 12 = 5.1e-6 (Hughes 1987, ch. 9), i.e. a
# phase lag of 0.5 s x w x 5.1e-6 = 8.1e-4 rad: 8.1e-10 m at A = 1 um
@pytest.mark.parametrize("method, kw, tol", [
    ("DOP853", dict(rtol=1e-11), 1e-13),
    ("rk4", dict(step_s=1e-4), 3e-12),
    ("newmark", dict(step_s=2.5e-5), 9e-10)])
def test_sampling_spectrum_and_poincare_of_an_exact_solution(method, kw, tol):
    res = simulate(oscillator_rotor(), settings(method, **kw))
    assert res.complete and res.reason == ""
    assert res.time_s[0] == 0 and res.time_s[-1] == pytest.approx(0.5)
    assert np.allclose(np.diff(res.time_s), 1 / 2000)
    assert res.displacement_m[:, 0] == pytest.approx(A * np.cos(W * res.time_s), abs=tol)
    assert res.displacement_m[:, 1] == pytest.approx(A * np.sin(W * res.time_s), abs=tol)
    assert res.spectrum.dominant_frequency_hz(0) == pytest.approx(50.0, abs=res.spectrum.resolution_hz)
    # once per revolution (20 ms at 3000 rpm) from the settle time: the circle orbit maps to one point
    p = res.poincare_set("revolution")
    assert np.allclose(np.diff(p.time_s), 0.02)
    assert distinct_points(p.xy_m, 10 * tol) == 1
    assert p.xy_m[0] == pytest.approx([A, 0.0], abs=tol)
    # the engine says so: period-1, and settled (the undamped 50 Hz mode rings, but the response is periodic)
    assert p.periodicity.label == "period-1" and p.periodicity.points == p.time_s.size == 21
    assert p.periodicity.spread_m <= 2 * tol and p.periodicity.extent_m == pytest.approx(2 * A, rel=1e-3)
    assert res.settling.settled and "periodic" in res.settling.note


@dataclass(frozen=True)
class Sabotage(BearingBase):
    """The spring above, which raises KeyboardInterrupt or returns NaN after t_fail."""

    t_fail: float
    fail: str
    name: str = "sabotage"
    node: int = 0
    dof_names: tuple = RADIAL

    def force_and_tangent(self, q, v, t=0.0, speed=0.0, angle=None):
        if t > self.t_fail:
            if self.fail == "interrupt":
                raise KeyboardInterrupt
            return np.full(2, np.nan), np.eye(2), np.zeros((2, 2))
        K = np.eye(2) * M * W ** 2
        return -K @ q, K, np.zeros((2, 2))

    def linearized(self, speed, static_load=None, start=None):
        return np.eye(2) * M * W ** 2, np.zeros((2, 2))


@pytest.mark.parametrize("method, fail, word", [
    ("DOP853", "interrupt", "interrupted"), ("DOP853", "nan", "failed"),
    ("newmark", "interrupt", "interrupted"), ("newmark", "nan", "non-finite")])
def test_failed_run_keeps_what_it_computed(method, fail, word):
    res = simulate(oscillator_rotor(Sabotage(0.26, fail)),
                   TransientSettings(0.5, sample_rate_hz=1000, chunks=10, method=method, step_s=1e-4,
                                     perturbation=Perturbation(0, 1.0)))
    assert not res.complete
    assert word in res.reason and res.reason
    assert res.time_s.size > 0 and 0.2 <= res.time_s[-1] <= 0.3
    assert np.all(np.isfinite(res.displacement_m))


@dataclass(frozen=True)
class Flaky(Sabotage):
    """The spring, which fails (as a film whose Newton iterate went through the bore) at its first call after
    t_fail and works again at the next one; ``fail`` "always" keeps failing after t_fail."""

    calls: list = field(default_factory=list, hash=False, compare=False)

    def force_and_tangent(self, q, v, t=0.0, speed=0.0, angle=None):
        if t > self.t_fail and (self.fail == "always" or not self.calls):
            self.calls.append(t)
            from spindlesim.bearings.fluidfilm.reynolds import ReynoldsError

            raise ReynoldsError("journal touches the bore")
        K = np.eye(2) * M * W ** 2
        return -K @ q, K, np.zeros((2, 2))


@pytest.mark.parametrize("fail", ["once", "always"])
def test_newmark_step_failing_from_its_predictor_is_solved_again(fail):
    # once: the step is solved again from zero new acceleration and the run is the spring's; always: the run
    # stops with its reason and keeps what it computed (a film's error is the contract's ArithmeticError)
    res = simulate(oscillator_rotor(Flaky(0.26, fail)),
                   TransientSettings(0.5, sample_rate_hz=1e4, method="newmark", step_s=1e-4,
                                     perturbation=Perturbation(0, A * M * W ** 2)))
    if fail == "once":
        ref = simulate(oscillator_rotor(), TransientSettings(0.5, sample_rate_hz=1e4, method="newmark", step_s=1e-4,
                                                             perturbation=Perturbation(0, A * M * W ** 2)))
        assert res.complete and np.max(np.abs(res.displacement_m - ref.displacement_m)) < 1e-9 * A
        assert res.newton_iterations.max() > 40  # the step solved twice counts both
    else:
        assert not res.complete and "touches the bore" in res.reason and 0.2 <= res.time_s[-1] <= 0.3


def test_exact_stepping_plan():
    # 8 rollers at 5000 rpm: 1/f_rp = 3.7624 ms = 50 samples of 76 steps of 0.99 us
    plan, M_ = plan_steps(1.0, 1e-6, 50 * 265.787, 265.787)
    assert M_ == 50 and plan.steps_per_sample == 76
    assert plan.step_s <= 1e-6 and plan.step_s * 76 * 50 == pytest.approx(1 / 265.787, rel=1e-12)
    assert plan.n_samples == int(1.0 * 50 * 265.787)
    # no period (0 rpm): the grid alone
    plan, M_ = plan_steps(0.1, 3e-6, 2000.0, 0.0)
    assert M_ == 0 and plan.step_s * plan.steps_per_sample == pytest.approx(5e-4)
    assert plan.n_samples == 200 and plan.step_s <= 3e-6


def test_spectrum_amplitude_and_poincare_times():
    fs, n = 1000.0, 1000
    t = np.arange(n) / fs
    sig = 3.0 * np.sin(2 * np.pi * 100 * t)  # on a bin
    sp = amplitude_spectrum(sig, fs)
    assert sp.amplitude[:, 0].max() == pytest.approx(3.0, rel=1e-9)
    assert sp.dominant_frequency_hz(0) == pytest.approx(100.0)
    assert poincare_times(0.1, 0.2, 0.025) == pytest.approx([0.1, 0.125, 0.15, 0.175, 0.2])


def damped_oscillator_rotor(zeta, rpm):
    K = np.eye(2) * M * W ** 2
    b = LinearBearing("spring", 0, np.array([0.0]), np.array([K]), np.array([np.eye(2) * 2 * zeta * M * W]))
    return oscillator_rotor(b, rpm)


def test_free_decay_of_a_released_oscillator_is_not_settled():
    # released from x = A at 0 rpm with zeta = 0.02: x = A exp(-zeta w t) (cos w_d t + ...); the
    # steady part 0.1-0.5 s is a free vibration whose second half has exp(-zeta w 0.2 s) of the first's RMS
    zeta = 0.02
    res = simulate(damped_oscillator_rotor(zeta, 0.0),
                   TransientSettings(0.5, method="rk4", step_s=1e-4, settle_s=0.1, sample_rate_hz=2000,
                                     perturbation=Perturbation(0, A * M * W ** 2)))
    st = res.settling
    assert not st.settled and "decays" in st.note
    assert st.envelope_change == pytest.approx(np.exp(-zeta * W * 0.2) - 1.0, rel=0.01)
    n = int(np.sum(res.time_s >= 0.1 - 1e-12))  # 0.1 s to 0.5 s inclusive
    assert st.duration_s == pytest.approx(n / 2000) and st.resolution_hz == pytest.approx(2000 / n)


def test_undecayed_free_whirl_is_not_settled_and_the_outputs_say_so(tmp_path):
    # undamped 50 Hz whirl at 290 rpm: once per revolution (4.83 Hz) the point moves on by 10.34 turns
    # (not periodic), the linear mode at sqrt(k/m) = 50 Hz keeps all of its start amplitude and carries
    # the largest line.  Steady part 0.2 s: 5 Hz bins, the revolution is within 2 bins of 0 Hz.
    import h5py

    from spindlesim.output.hdf5 import RunInfo
    from spindlesim.analysis.transient.result import TransientStudy
    from spindlesim.output.summary import transient
    from spindlesim.output.transient_plots import orbit_figure, poincare_figure, spectrum_figure, time_figure
    from spindlesim.output.transient_writer import write_transient
    from tests.cli.test_transient_cli import _texts

    res = simulate(oscillator_rotor(rpm=290.0),
                   TransientSettings(0.4, method="rk4", step_s=1e-4, settle_s=0.2, sample_rate_hz=2000,
                                     perturbation=Perturbation(0, A * M * W ** 2), initial_velocity=((1, A * W),)))
    st = res.settling
    assert not st.settled and "free vibration" in st.note
    assert st.ringing_mode_hz == pytest.approx(50.0, rel=1e-6) and st.ringing_mode_decay == pytest.approx(1.0)
    n = int(np.sum(res.time_s >= 0.2 - 1e-12))
    assert st.resolution_hz == pytest.approx(res.sample_rate_hz / n)  # the rate is rounded to whole revolutions
    assert st.unresolved == (("revolution", pytest.approx(290 / 60)),)
    for fig in (time_figure(res), orbit_figure(res), spectrum_figure(res), poincare_figure(res)):
        assert "NOT SETTLED: the free vibration of the start has not died out" in _texts(fig)
    short = f"WINDOW TOO SHORT for {st.resolution_hz:.3g} Hz resolution: revolution (4.833 Hz)"
    assert short in _texts(spectrum_figure(res))

    path = write_transient(tmp_path / "transient.h5", RunInfo("deck", "<test>", "0" * 64), res)
    with h5py.File(path) as f:
        a = f["transient"].attrs
        t = f["transient/time_s"][()]
        n = int(np.sum(t >= a["settle_s"] - 1e-12))
        assert not a["settled"] and a["settling_note"] == st.note
        assert a["frequency_resolution_hz"] == pytest.approx(a["sample_rate_hz"] / n)
        assert a["steady_duration_s"] == pytest.approx(n / a["sample_rate_hz"])
        assert a["unresolved_frequencies"] == "revolution" and a["ringing_mode_hz"] == pytest.approx(50.0)
    lines, data = transient(TransientStudy(res))  # the summary reads the result, not the file
    text = "\n".join(lines)
    assert "NOT SETTLED: the free vibration" in text and short in text
    assert "(NOT SETTLED: not a steady amplitude)" in lines[0] and "has NOT SETTLED" in text
    assert data["settled"] is False and data["unresolved_frequencies"] == ["revolution"]
