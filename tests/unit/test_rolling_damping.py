"""Damping of the rolling bearings (issue 30 item 4): C = beta K on the whole tangent of ball sets, DTRBs and
rigid-race roller bearings; flexible-race bearings keep their contacts' own damping; the deck key."""

from pathlib import Path

import numpy as np
import pytest

from spindlesim.bearings.damping import DEFAULT_STIFFNESS_PROPORTIONAL_S
from spindlesim.bearings.types import BEARING_TYPES
from spindlesim.deck import DeckError, load_deck, parse_deck
from spindlesim.model.build import build_rotor

MILLING = str(Path(__file__).parents[2] / "decks" / "milling_spindle.yaml")
RPM = np.pi / 30.0


def _milling_bearings(text=None):
    loaded = load_deck(MILLING) if text is None else parse_deck(text)
    return {b.name: b for b in build_rotor(loaded.deck).bearings}


def _entry(kind, **keys):
    return BEARING_TYPES[kind].entry.model_validate({"type": kind, "name": "b", "node": 1, **keys})


def test_ball_set_damping_is_beta_times_its_stiffness_at_the_state():
    front = _milling_bearings()["front"]
    assert front.damping_s == DEFAULT_STIFFNESS_PROPORTIONAL_S == 1.0e-5
    load = np.array([150.0, -80.0, 40.0, 2.0, -3.0])
    K, C = front.linearized(18000 * RPM, load)
    assert np.abs(C - 1.0e-5 * K).max() <= 1e-15 * np.abs(C).max()
    assert C[2, 2] > 0 and C[3, 3] > 0  # axial and tilt damped, not only x and y
    # the nonlinear reaction: f(q, v) = f(q, 0) - beta K_t v, C_t = beta K_t = -df/dv
    q = np.array([1e-6, -2e-6, 0.5e-6, 1e-5, -2e-5])
    v = np.array([1e-3, -2e-3, 5e-4, 3e-2, 1e-2])
    f0, K0, C0 = front.force_and_tangent(q, np.zeros(5), 0.0, 18000 * RPM)
    f1, K1, C1 = front.force_and_tangent(q, v, 0.0, 18000 * RPM)
    assert np.array_equal(K0, K1) and np.array_equal(C0, C1)
    assert np.abs(C1 - 1.0e-5 * K1).max() <= 1e-15 * np.abs(C1).max()
    assert np.allclose(f1, f0 - C1 @ v, rtol=0, atol=1e-12 * np.abs(f0).max())


def test_spring_preloaded_set_damps_what_its_condensed_stiffness_holds():
    rear = _milling_bearings()["rear"]  # the floating row's axial DOF is condensed out of K, so out of C too
    K, C = rear.linearized(18000 * RPM, np.array([50.0, -60.0, 0.0, 0.0, 0.0]))
    assert np.array_equal(C, 1.0e-5 * K) and C[0, 0] > 0.0


def test_zero_beta_gives_the_old_undamped_bearings():
    text = open(MILLING).read().replace(
        "    preload: {kind: position, axial_um: 15.0}\n",
        "    preload: {kind: position, axial_um: 15.0}\n    damping: {stiffness_proportional_s: 0}\n")
    front = _milling_bearings(text)["front"]
    assert front.damping_s == 0.0
    K, C = front.linearized(18000 * RPM, np.array([150.0, -80.0, 40.0, 0.0, 0.0]))
    assert np.all(C == 0.0) and np.abs(K).max() > 1e7
    f, _, Ct = front.force_and_tangent(np.full(5, 1e-7), np.full(5, 1e-2), 0.0, 0.0)
    assert np.all(Ct == 0.0)
    assert np.array_equal(f, front.force_and_tangent(np.full(5, 1e-7), np.zeros(5), 0.0, 0.0)[0])


def test_dtrb_and_rigid_race_damping():
    geo = {"rollers_per_row": 20, "cup_angle_deg": 15.64, "pitch_diameter_mm": 70.0, "large_end_diameter_mm": 10.0,
           "roller_length_mm": 14.0, "large_end_offset_mm": 18.0, "crown_radius_mm": 2680.0, "slices": 20}
    for dofs in (5, 2):
        e = _entry("dtrb", geometry=geo, preload_um=20.0, dofs=dofs, damping={"stiffness_proportional_s": 2e-5})
        b = BEARING_TYPES["dtrb"].build(e)
        K, C = b.linearized(3000 * RPM, np.array([0.0, -2000.0, 1000.0, 0.0, 0.0])[:dofs])
        assert K.shape == (dofs, dofs) and np.array_equal(C, 2e-5 * K)
        q, v = np.full(dofs, 1e-6), np.full(dofs, 1e-3)
        f0, _, _ = b.force_and_tangent(q, np.zeros(dofs), 0.0, 0.0)
        f1, K1, C1 = b.force_and_tangent(q, v, 0.0, 0.0)
        assert np.array_equal(C1, 2e-5 * K1) and np.allclose(f1, f0 - C1 @ v, rtol=1e-12)
    r = BEARING_TYPES["roller"].build(_entry("roller", rollers=12, model="rigid_race"))
    assert r.damping_s == DEFAULT_STIFFNESS_PROPORTIONAL_S
    K, C = r.linearized(3000 * RPM, np.array([0.0, -500.0]))
    assert np.array_equal(C, 1e-5 * K)
    off = BEARING_TYPES["roller"].build(_entry("roller", rollers=12, damping={"stiffness_proportional_s": 0.0}))
    assert np.all(off.linearized(3000 * RPM, np.array([0.0, -500.0]))[1] == 0.0)


def test_rigid_race_compiled_force_carries_the_same_damping():
    from spindlesim.bearings.roller import rigid_race_kernel
    from spindlesim.bearings.roller.bearing import Waviness

    r = BEARING_TYPES["roller"].build(_entry("roller", rollers=12, model="rigid_race", radial_clearance_mm=0.0005,
                                             waviness=[{"surface": "outer", "waves": 8, "amplitude_um": 0.3}]))
    c = r.compiled()
    out = np.zeros(2)
    for q, v, t in ((np.array([2e-6, -3e-6]), np.array([0.01, -0.02]), 1.3e-3),
                    (np.array([-1e-6, 2e-6]), np.array([-0.005, 0.003]), 4.1e-2)):
        rigid_race_kernel.force(c.floats, 0, c.ints, 0, q, v, t, 523.6, 523.6 * t, out)
        ref = r.force_and_tangent(q, v, t, 523.6)[0]
        assert out == pytest.approx(ref, rel=1e-12, abs=1e-9)
        assert np.abs(ref - r.force_and_tangent(q, np.zeros(2), t, 523.6)[0]).max() > 1.0  # damping acts
    assert Waviness  # imported for the entry's model


def test_flexible_race_keeps_its_contact_damping_and_refuses_the_key():
    with pytest.raises(ValueError, match="flexible_race model is damped by its roller and housing contacts"):
        _entry("roller", model="flexible_race", damping={"stiffness_proportional_s": 1e-5})
    b = BEARING_TYPES["roller"].build(_entry("roller", rollers=12, model="flexible_race"))
    K, C = b.linearized(30000 * RPM, np.array([0.0, -500.0]))  # decks/validation/roller_rotor.yaml's speed
    # seed 000 eq. 30's contact damping condensed to the node: positive, of order 1e-6 s times K
    assert C[0, 0] > 0 and C[1, 1] > 0
    assert 1e-7 < C[1, 1] / K[1, 1] < 1e-5


@pytest.mark.parametrize("value, message", [(-1e-5, "must be >= 0"), (0.1, "must be <= 0.001")])
def test_bad_beta_is_a_located_deck_error(value, message):
    text = open(MILLING).read().replace(
        "    preload: {kind: spring, axial_N: 300.0}\n",
        f"    preload: {{kind: spring, axial_N: 300.0}}\n    damping: {{stiffness_proportional_s: {value}}}\n")
    with pytest.raises(DeckError) as exc:
        parse_deck(text, "milling.yaml")
    line = text.splitlines().index(f"    damping: {{stiffness_proportional_s: {value}}}") + 1
    assert f"milling.yaml:{line}:" in str(exc.value)
    assert "bearings[1].damping.stiffness_proportional_s" in str(exc.value) and message in str(exc.value)


def test_a_beta_far_outside_the_literature_range_is_a_plausibility_warning():
    from spindlesim.deck.plausibility import plausibility_warnings

    base = open(MILLING).read()
    assert not [w for w in plausibility_warnings(parse_deck(base).deck) if "damping" in str(w[0])]
    for beta, warned in ((1e-5, False), (2e-4, False), (1e-3, True), (1e-8, True), (0.0, False)):
        text = base.replace("    preload: {kind: spring, axial_N: 300.0}\n",
                            f"    preload: {{kind: spring, axial_N: 300.0}}\n    damping: {{stiffness_proportional_s: {beta}}}\n")
        found = [w for w in plausibility_warnings(parse_deck(text).deck)
                 if w[0] == ("bearings", 1, "damping", "stiffness_proportional_s")]
        assert bool(found) == warned, (beta, found)


def test_a_time_integration_holds_the_damping_of_its_operating_point():
    """at_operating_point(..., transient=True): C = beta K of the operating point, held (a linear damper),
    in the Python force and in the rigid race's compiled force."""
    from spindlesim.bearings.roller import rigid_race_kernel

    W = 18000 * RPM
    front = _milling_bearings()["front"]
    load = np.array([150.0, -80.0, 40.0, 0.0, 0.0])
    frozen = front.at_operating_point(W, load, transient=True)
    C_op = front.linearized(W, load)[1]
    q, v = np.full(5, 2e-7), np.array([1e-3, -2e-3, 5e-4, 3e-2, 1e-2])
    f0 = frozen.force_and_tangent(q, np.zeros(5), 0.0, W)[0]
    f1, _, C1 = frozen.force_and_tangent(q, v, 0.0, W)
    assert np.array_equal(C1, C_op) and np.allclose(f1, f0 - C_op @ v, rtol=0, atol=1e-12 * np.abs(f0).max())
    assert front.at_operating_point(W, load) is front
    r = BEARING_TYPES["roller"].build(_entry("roller", rollers=12, model="rigid_race"))
    rf = r.at_operating_point(3000 * RPM, np.array([0.0, -500.0]), transient=True)
    C_op = r.linearized(3000 * RPM, np.array([0.0, -500.0]))[1]
    c, out = rf.compiled(), np.zeros(2)
    qr, vr = np.array([1e-6, -3e-6]), np.array([0.01, -0.02])
    rigid_race_kernel.force(c.floats, 0, c.ints, 0, qr, vr, 1e-3, 314.0, 0.314, out)
    ref, _, Cr = rf.force_and_tangent(qr, vr, 1e-3, 314.0)
    assert np.array_equal(Cr, C_op) and out == pytest.approx(ref, rel=1e-12, abs=1e-9)
    assert np.allclose(ref, rf.force_and_tangent(qr, np.zeros(2), 1e-3, 314.0)[0] - C_op @ vr, rtol=1e-13)
