"""Seed 000's flexible-race bearing (internal DOFs): static equilibrium through the one static solver,
conservation, the contract.  Long runs (roller-pass lines) are in tests/validation."""

import dataclasses

import numpy as np
import pytest

from spindlesim.analysis.operating import operating_state
from spindlesim.analysis.transient.engine import TransientSettings, integrate, prepare, stability_step
from spindlesim.bearings.base import Bearing
from spindlesim.bearings.roller.contact_force import CompliantContact
from spindlesim.bearings.roller.bearing import FlexibleRaceBearing
from spindlesim.bearings.roller.flexible_race import HousingSupport
from spindlesim.bearings.roller.kinematics import CageKinematics
from spindlesim.bearings.roller.outer_race import SegmentedRing
from spindlesim.contact.hertz import palmgren_stiffness
from spindlesim.model.rig import journal_rotor

KIN = CageKinematics(18.738e-3, 28.262e-3, 4.762e-3)  # seed 000 Table 1
K_CONTACT = palmgren_stiffness(6.35e-3) * 2 ** (10 / 9)  # per contact, as the deck builder makes it
RPM = np.pi / 30


def bearing(rollers=8, E=208e9, damped=False, mu=0.0, rocking=False) -> FlexibleRaceBearing:
    ring = SegmentedRing(12, 0.5 * (14.131e-3 + 16e-3), 1.869e-3, 6.35e-3, E, 7850.0)
    rc = CompliantContact(K_CONTACT, 10 / 9, 1.8e9 if damped else 0.0, 1.0, 1.0, mu)
    hc = CompliantContact(1e9, 1.0, 170.0 if damped else 0.0, 1.0, 0.0, mu)
    hs = HousingSupport(hc, rocking_arc_m=2 * np.pi * 16e-3 / 12 if rocking else 0.0)
    return FlexibleRaceBearing("b", 0, KIN, rollers, ring, rc, hs, 6.35e-3)


def rotor(rollers=8, rpm=0.0, load=6.0, **kw):
    return journal_rotor((bearing(rollers, **kw),), 0.6, 200.0, (0.0, -load), rpm)


def _contacts(b, st):
    pos = b.absolute(np.concatenate([st.q, st.internal[0]]))
    return b.contact_state(pos, np.zeros_like(pos), st.speed_rad_s, 0.0)


def test_static_equilibrium_balances_the_load():
    r = rotor()
    st = operating_state(r)
    b = st.bearings[0]
    x = np.concatenate([st.q, st.internal[0]])
    f = b.generalized_force(b.absolute(x), np.zeros_like(x), 0.0, 0.0)
    assert np.max(np.abs(f[2:])) < 1e-6  # rollers and race segments in equilibrium
    assert f[:2] == pytest.approx([0.0, 6.0], abs=1e-6)  # the bearing carries the 6 N load
    cs = _contacts(b, st)
    assert np.all(cs["Q_out"] >= 0) and np.count_nonzero(cs["Q_out"] > 0.1) == 3
    # inner contacts carry the load; outer contacts pass it on to the race and housing
    assert np.sum(cs["Q_in"][:, None] * cs["n_in"], axis=0) == pytest.approx([0.0, -6.0], abs=1e-5)
    assert np.sum(cs["Q_out"][:, None] * cs["f"], axis=0) == pytest.approx([0.0, -6.0], abs=1e-5)
    # measured: the 12-segment race concentrates the load, Q_max Z / F_r = 4.73 (rigid races: 4.08)
    assert cs["Q_out"].max() * 8 / 6.0 > 4.08


@pytest.mark.parametrize("rollers", [5, 12])
def test_static_equilibrium_with_centrifugal_load(rollers):
    # at 5000 rpm every roller is pressed on the outer race at least by m r omega_c^2 (0.455 N here)
    st = operating_state(rotor(rollers=rollers, rpm=5000.0))
    b = st.bearings[0]
    cs = _contacts(b, st)
    r = b.roller_reference_radius_m + st.internal[0][:rollers]
    fc = b.roller_mass_kg * r * (KIN.cage_ratio * 5000 * RPM) ** 2
    assert fc == pytest.approx(0.455, abs=0.002)
    assert np.all(cs["Q_out"] >= fc * (1 - 1e-6))
    assert np.sum(cs["Q_in"][:, None] * cs["n_in"], axis=0) == pytest.approx([0.0, -6.0], abs=1e-5)


def _energy(p, traj, b, load):
    """Kinetic + bearing + load potential energy along a trajectory (zero speed)."""
    m = np.diag(p.system.M)
    ke = 0.5 * np.sum(m * traj.v ** 2, axis=1)
    pe = np.array([b.potential_energy_J(b.absolute(x), 0.0) for x in traj.x])
    return ke + pe + load * traj.x[:, 1]


@pytest.mark.slow
def test_energy_conserved_without_damping_and_friction():
    r = dataclasses.replace(rotor(rollers=5), ground_damping_Ns_m=0.0)
    b = r.bearings[0]
    drift = []
    for rtol in (1e-5, 1e-7):
        s = TransientSettings(3e-4, method="DOP853", rtol=rtol, sample_rate_hz=1e5, chunks=1,
                              initial_velocity=((0, 1e-4), (1, -2e-4)))
        p = prepare(r, s)
        traj = integrate(p, s)
        assert traj.complete
        e = _energy(p, traj, b, 6.0)
        drift.append(np.max(np.abs(e - e[0])) / (0.5 * 0.6 * (1e-4 ** 2 + 2e-4 ** 2)))
    assert drift[1] < drift[0]
    assert drift[1] < 1e-3


def test_compiled_rk4_conserves_energy_at_fourth_order():
    # measured drift over 2 ms / kick energy at h0 (stability step, 1.41 us), h0/2, h0/4, h0/8:
    # 9.7e-3, 2.3e-3, 1.6e-4, 1.0e-5 (RK4 damps the 200 kHz segment modes at h0, then order 4)
    r = dataclasses.replace(rotor(rollers=5, rocking=True), ground_damping_Ns_m=0.0)
    b = r.bearings[0]
    s0 = TransientSettings(2e-3, method="rk4", initial_velocity=((0, 1e-4), (1, -2e-4)), sample_rate_hz=1e4)
    p0 = prepare(r, s0)
    h0 = stability_step(p0.system, p0.x0, p0.v0)
    assert 1e-6 < h0 < 2e-6 and p0.plan.step_s <= 1e-6  # the default: min(1 us, the stability limit)
    drift = []
    for h in (h0 / 4, h0 / 8):
        s = dataclasses.replace(s0, step_s=h)
        p = prepare(r, s)
        traj = integrate(p, s)
        e = _energy(p, traj, b, 6.0)
        drift.append(np.max(np.abs(e - e[0])) / (0.5 * 0.6 * (1e-4 ** 2 + 2e-4 ** 2)))
    assert drift[0] / drift[1] > 10
    assert drift[1] < 3e-5


def test_satisfies_the_contract():
    b = bearing(rollers=12, damped=True, mu=0.05)
    assert isinstance(b, Bearing)
    f = b.frequencies_hz(5000 * RPM)
    assert f["cage"] == pytest.approx(33.22, abs=0.005)  # REFERENCES.md
    assert f["roller_pass"] == pytest.approx(398.7, abs=0.05)
    n = 2 + 12 + 36
    assert b.internal_mass.size == n - 2
    q = np.zeros(n)
    fq, K, C = b.force_and_tangent(q, np.zeros(n), 0.0, 5000 * RPM)
    assert fq.shape == (n,) and K.shape == C.shape == (n, n)
    out = b.outputs(q, np.zeros(n), 0.0, 5000 * RPM)
    assert out["roller_load_N"][0].shape == (12,) and out["race_deflection_m"][0].shape == (12,)
    # the compiled force is the numpy reference (round-off: race forces are differences of ~100 N)
    rng = np.random.default_rng(1)
    for _ in range(20):
        x = rng.normal(size=n) * 1e-7
        v = rng.normal(size=n) * 1e-4
        ref = b.generalized_force(b.absolute(x), v, 5000 * RPM, 0.37)
        assert np.max(np.abs(b.force(x, v, 0.0, 5000 * RPM, 0.37) - ref)) <= 1e-9 * np.max(np.abs(ref))
    # roller spin with no slip: the outer contact point of a roller is at rest (pure rolling)
    w = 5000 * RPM
    wc = KIN.cage_ratio * w
    spin = wc - KIN.spin_ratio * w
    assert b.roller_reference_radius_m * wc + spin * b.roller_radius_m == pytest.approx(0.0, abs=1e-9)


def test_compiled_force_keeps_its_digits_for_tiny_race_displacements():
    # a race segment moved by 1e-14 m (1e-12 of its radius): the housing and beam forces are linear there,
    # so doubling the displacement doubles the change of force; lengths differenced directly (|p| - R_m)
    # keep only ~1e-4 of such a change (the rounding of R_m is 3.5e-18 m)
    b = bearing(rollers=8)
    n = b.n_pos
    k = 2 + 8  # first race DOF: segment 0 (x, y, rotation)
    phi = b.ring.phi[0]
    zero = np.zeros(n)
    f0 = b.force(zero, zero, 0.0, 0.0, 0.0)
    df = []
    for u in (1e-14, 2e-14):
        q = zero.copy()
        q[k], q[k + 1] = u * np.cos(phi + 0.3), u * np.sin(phi + 0.3)  # radial and tangential parts
        df.append(b.force(q, zero, 0.0, 0.0, 0.0) - f0)
    big = np.abs(df[1]) > 1e-6 * np.abs(df[1]).max()
    assert np.count_nonzero(big) >= 6  # the segment and its two beams' neighbours
    assert np.max(np.abs(df[1][big] / df[0][big] - 2.0)) < 1e-6


def test_rig_steps_the_flexible_race_at_its_stability_limit_and_the_rigid_race_at_1_us():
    # the flexible race's step is bound by its ~200 kHz segment modes (about 1.4 us), not by the accuracy
    # of the kHz response: seed 000's rig steps there; the rigid race keeps 1 us (issue 4)
    from spindlesim.deck.transient import TransientSection
    from spindlesim.runs.transient import rig_setup

    rotor_f, s = rig_setup(TransientSection(model="flexible_race"), {"duration_s": 0.01})
    p = prepare(rotor_f, s)
    h0 = stability_step(p.system, p.x0, p.v0)
    assert 1e-6 < h0 < 2e-6 and 0.95 * h0 < p.plan.step_s <= h0
    rotor_r, s = rig_setup(TransientSection(model="rigid_race"), {"duration_s": 0.01})
    assert 0.95e-6 < prepare(rotor_r, s).plan.step_s <= 1e-6
