"""Rotor time integration: spectral peak = natural frequency, energy balance, nonlinear path = linear path."""

import numpy as np
import pytest

from spindlesim.analysis.modal import solve_modal
from spindlesim.analysis.rotor_transient import integrate, unbalance_force
from tests.rotor_helpers import disk_entry, isotropic_bearing, rotor_from, uniform_rows


def _rotor(speed=0.0, k=1e6, c=0.0):
    d, *_ = disk_entry(4, 7810, 0.28, 0.05, 0.07)
    body = uniform_rows(6, 1500.0, 50.0) + "disks:\n" + d + "bearings:\n" + isotropic_bearing("a", 1, k, c) + \
        isotropic_bearing("b", 7, k, c)
    return rotor_from(body, speed)


class LinearAsNonlinear:
    """A linear isotropic spring-damper given to the integrator through the nonlinear protocol."""

    dof_names = ("x", "y")

    def __init__(self, node, k, c):
        self.node, self.k, self.c = node, k, c

    def force_and_tangent(self, q, v, t):
        return -(self.k * q + self.c * v), self.k * np.eye(2), self.c * np.eye(2)


def test_free_vibration_peak_at_first_natural_frequency():
    rotor = _rotor()
    f1 = solve_modal(rotor, n_modes=1).frequency_hz[0]
    q0 = np.zeros(rotor.dofs.size)
    q0[rotor.dofs.index(3, "x")] = 1e-5
    dt = 1 / (f1 * 200)
    res = integrate(rotor, 40 / f1, dt, q0=q0, record_nodes=[3], include_static=False)
    x = res.displacement_m[:, 0, 0]
    spec = np.abs(np.fft.rfft(x * np.hanning(len(x))))
    freq = np.fft.rfftfreq(len(x), dt)
    peak = freq[np.argmax(spec[1:]) + 1]
    assert abs(peak - f1) <= freq[1]  # within one FFT bin
    # average-acceleration Newmark: a small period elongation only (~ (w dt)^2 / 12)
    assert abs(peak - f1) / f1 < 0.01


def test_energy_is_conserved_without_damping():
    rotor = _rotor()
    from spindlesim.fe.assembly import assemble_shaft, system_matrices

    sysm = system_matrices(rotor, assemble_shaft(rotor), 0.0)
    q0 = np.zeros(rotor.dofs.size)
    q0[rotor.dofs.index(3, "y")] = 1e-5
    res = integrate(rotor, 0.2, 2e-4, q0=q0, include_static=False)
    n = rotor.dofs.size
    q = res.displacement_m.reshape(len(res.time_s), n)
    v = np.gradient(q, res.time_s, axis=0)
    e0 = 0.5 * q0 @ sysm.K @ q0
    pot = 0.5 * np.einsum("ti,ij,tj->t", q, sysm.K, q)
    assert pot.max() <= e0 * (1 + 1e-9)  # never more potential energy than was put in
    assert np.isfinite(v).all()


def test_nonlinear_protocol_matches_linear_matrices():
    lin = _rotor(speed=3000.0, k=1e6, c=200.0)
    free = _rotor(speed=3000.0, k=0.0, c=0.0)
    unb = [unbalance_force(lin, 3, 1e-4)]
    a = integrate(lin, 0.1, 5e-4, forces=unb, record_nodes=[3])
    b = integrate(free, 0.1, 5e-4, forces=[unbalance_force(free, 3, 1e-4)], record_nodes=[3],
                  nonlinear=[LinearAsNonlinear(0, 1e6, 200.0), LinearAsNonlinear(6, 1e6, 200.0)])
    assert a.complete and b.complete
    np.testing.assert_allclose(b.displacement_m, a.displacement_m, rtol=1e-7, atol=1e-12)
    assert b.newton_iterations[1:].max() <= 3


class Exploding(LinearAsNonlinear):
    def force_and_tangent(self, q, v, t):
        if t > 0.01:
            return np.array([np.nan, 0.0]), np.eye(2), np.zeros((2, 2))
        return super().force_and_tangent(q, v, t)


def test_failed_run_returns_what_it_computed():
    rotor = _rotor(k=0.0)
    res = integrate(rotor, 0.05, 1e-3, nonlinear=[Exploding(0, 1e6, 0.0), LinearAsNonlinear(6, 1e6, 0.0)])
    assert not res.complete
    assert "non-finite" in res.reason
    assert 9 <= len(res.time_s) <= 12 and np.isfinite(res.displacement_m).all()
