"""Seed 000's flexible-race model in time: roller-pass line, step and segment convergence, static limit.

References:
- roller-pass frequency N f_cage with f_cage = 0.39868 x 83.33 Hz = 33.22 Hz at 5000 rpm (seed 000 eq. 3,
  REFERENCES.md): 166.1 / 265.8 / 398.7 Hz for 5 / 8 / 12 rollers; seed 000 sec. 5 reports the dominant
  FFT line of the shaft there;
- Stribeck / Sjovall quasi-static distribution (Harris, Rolling Bearing Analysis, ch. 7): the limit of a
  slowly loaded bearing with rigid races, Q_max ~ 4.08 F_r / Z for line contact at zero clearance.
All runs use the embedded default deck (seed 000 Table 1: 6 N, 0.2 N s/mm, 5000 rpm, 12 segments).
"""

import dataclasses

import numpy as np
import pytest

from spindlesim.analysis.operating import operating_state
from spindlesim.analysis.transient.engine import TransientSettings, simulate
from spindlesim.analysis.transient.spectrum import distinct_points, poincare_spread
from spindlesim.analysis.transient.system import Excitation, TimeLoad
from spindlesim.bearings.roller.load_distribution import static_load_distribution
from spindlesim.bearings.roller.section import RollerOuterRace
from spindlesim.deck.transient import TransientSection
from spindlesim.model.rig import rig_rotor


def flexible(rollers, segments=12, **kw):
    """The rig of the embedded default deck with seed 000's flexible race (a journal rotor)."""
    return rig_rotor(TransientSection(model="flexible_race", outer_race=RollerOuterRace(segments=segments), **kw),
                     rollers=rollers)


def band(res, channel, harmonic):
    """Largest spectral amplitude within 1.5 bins of harmonic x N f_cage."""
    f = res.spectrum.frequency_hz
    sel = np.abs(f - harmonic * res.frequencies_hz["bearing.roller_pass"]) <= 1.5 * res.spectrum.resolution_hz
    return float(res.spectrum.amplitude[sel, channel].max())


@pytest.mark.slow
@pytest.mark.parametrize("rollers, f_rp_ref, channels", [(5, 166.1, (0, 1)), (8, 265.8, (0, 1)), (12, 398.7, (0,))])
def test_dominant_line_at_roller_pass_frequency(rollers, f_rp_ref, channels):
    res = simulate(flexible(rollers), TransientSettings(0.3, method="rk4", settle_s=0.1))
    assert res.complete, res.reason
    assert res.frequencies_hz["bearing.roller_pass"] == pytest.approx(f_rp_ref, abs=0.05)
    df = res.spectrum.resolution_hz
    assert df == pytest.approx(5.0, rel=0.2)
    for ch in channels:  # x: horizontal, across the load; y: along the load
        assert res.spectrum.dominant_frequency_hz(ch, fmin_hz=10.0) == pytest.approx(f_rp_ref, abs=df)
    # zero clearance, loaded: period-1 on the Poincare map sampled every 1/(N f_cage)
    steady = res.displacement_m[res.time_s >= res.settle_s]
    ptp = np.ptp(steady, axis=0).max()
    pc = res.poincare_set("bearing.roller_pass")
    assert poincare_spread(pc.xy_m) < 1e-3 * ptp
    assert distinct_points(pc.xy_m, 1e-2 * ptp) == 1
    # rollers pass their load to the race
    Q = res.bearing_outputs[0]["roller_load_N"][0][res.time_s >= res.settle_s]
    assert Q.min() >= 0 and Q.max() > 6.0 / rollers


@pytest.mark.slow
def test_response_converges_as_the_step_shrinks():
    rotor = flexible(8)
    runs = [simulate(rotor, TransientSettings(0.15, method="rk4", settle_s=0.05, step_s=h)) for h in (1e-6, 0.5e-6)]
    assert runs[1].step_s < 0.6 * runs[0].step_s
    for ch in (0, 1):
        a = [band(r, ch, 1) for r in runs]
        assert a[0] == pytest.approx(a[1], rel=0.01)
    assert np.max(np.abs(runs[0].displacement_m - runs[1].displacement_m)) < 0.01 * np.ptp(runs[1].displacement_m)


def test_slowly_loaded_shaft_reaches_the_static_solution():
    # 0 rpm, the 6 N load ramped over 20 ms, then held: the roller loads settle on the static equilibrium
    loaded = flexible(8, speed_rpm=0.0)
    free = dataclasses.replace(loaded, loads=())
    ramp = Excitation(loads=(TimeLoad(1, -6.0, "ramp", t_on_s=0.02),))
    res = simulate(free, TransientSettings(0.06, method="rk4", settle_s=0.05, excitation=ramp))
    assert res.complete, res.reason
    st = operating_state(loaded)  # the one static solver, with the load from the start
    b = st.bearings[0]
    x = np.concatenate([st.q, st.internal[0]])
    q_static = b.outputs(x, np.zeros_like(x), 0.0, 0.0)["roller_load_N"][0]
    q_end = res.bearing_outputs[0]["roller_load_N"][0][-1]
    assert q_end == pytest.approx(q_static, abs=0.01 * q_static.max())
    # forces balance the load: the bearing's force on the shaft = 6 N upwards
    assert res.bearing_force_N[0][-1] == pytest.approx([0.0, 6.0], abs=0.06)


# measured Q (N) of the loaded rollers, default race: 2.108 / 3.019 / 2.108 (+ 0.002 at the edges);
# Stribeck: 2.0805 / 3.0578 / 2.0805 (Q_max Z / F_r 4.03 against 4.08); race and housing x1000: 1e-5
@pytest.mark.parametrize("stiffen, tol", [(1.0, 0.02), (1e3, 1e-4)])
def test_static_distribution_tends_to_stribeck_as_the_race_stiffens(stiffen, tol):
    rotor = flexible(8, speed_rpm=0.0)
    base = rotor.bearings[0]
    ring = dataclasses.replace(base.ring, youngs_modulus_Pa=base.ring.youngs_modulus_Pa * stiffen)
    hc = dataclasses.replace(base.housing.contact, stiffness=base.housing.contact.stiffness * stiffen)
    b = dataclasses.replace(base, ring=ring, housing=dataclasses.replace(base.housing, contact=hc))
    st = operating_state(dataclasses.replace(rotor, bearings=(b,)))
    x = np.concatenate([st.q, st.internal[0]])
    q = st.bearings[0].outputs(x, np.zeros_like(x), 0.0, 0.0)["roller_load_N"][0]
    # Stribeck with the series stiffness of the two contacts (K = k_c / 2^n), same roller angles
    K = b.roller_contact.stiffness / 2 ** b.roller_contact.exponent
    ref = static_load_distribution(K, b.roller_contact.exponent, 8, 6.0, phase_rad=b.cage_phase_rad + np.pi / 2).load_N
    assert ref.max() * 8 / 6.0 == pytest.approx(4.08, abs=0.01)
    assert q == pytest.approx(ref, abs=tol * ref.max())
