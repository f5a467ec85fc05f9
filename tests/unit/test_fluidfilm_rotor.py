"""Fluid-film bearings inside the rotor analyses (issue 3 item 5)."""

import numpy as np
import pytest

from spindlesim.analysis.campbell import solve_campbell
from spindlesim.analysis.static import solve_static
from spindlesim.deck import default_deck, parse_deck
from spindlesim.analysis.operating import operating_state
from spindlesim.model.build import build_rotor


def _deck_without_loads():
    text = default_deck("spindle").text
    text = text.replace("    load_N: 400\n", "").replace("    load_N: 300\n", "")
    text = text.replace("  gravity: false", "  gravity: true")
    return parse_deck(text, "noload.yaml").deck


def test_bearing_loads_from_static_equilibrium():
    rotor = build_rotor(_deck_without_loads())
    st = operating_state(rotor)
    loads = {b.name: w for b, w in zip(st.bearings, st.loads)}
    total = sum(v for v in loads.values())
    weight = st.shaft.gravity_unit[rotor.dofs.component("y")].sum() * 9.80665  # the rotor weight, along -y
    assert weight < -100  # 14.9 kg of shaft
    # the shaft presses the bearings down with its weight plus the 1 N nose load sideways
    assert total[1] == pytest.approx(weight, rel=1e-6)
    assert total[0] == pytest.approx(1.0, rel=1e-6)
    # the static analysis uses those loads and its reactions balance weight and the 1 N nose load
    st = solve_static(rotor)
    np.testing.assert_allclose(st.bearing_force_N.sum(axis=0) + st.applied_force_N, 0, atol=1e-6)
    # each bearing's coefficients are those at its own load
    k_front, _ = rotor.bearings[0].linearized(rotor.speed_rad_s, loads["front"])
    k_heavy, _ = rotor.bearings[0].linearized(rotor.speed_rad_s, 3 * loads["front"])
    assert not np.allclose(k_front, k_heavy, rtol=1e-2)


def test_campbell_recomputes_bearings_at_every_speed():
    rotor = build_rotor(default_deck("spindle").deck)
    k_low, _ = rotor.bearings[0].linearized(1000 * np.pi / 30)
    k_high, _ = rotor.bearings[0].linearized(8000 * np.pi / 30)
    assert np.abs(k_high - k_low).max() > 0.05 * np.abs(k_low).max()  # coefficients depend on speed
    c = solve_campbell(rotor, np.array([1000.0, 8000.0]), 4)
    assert np.all(np.isfinite(c.frequency_hz))
    assert not np.allclose(c.frequency_hz[0], c.frequency_hz[1], rtol=1e-3)


def test_zero_speed_is_reported_not_a_traceback():
    rotor = build_rotor(default_deck("spindle").deck, speed_rpm=0.0)
    with pytest.raises(ValueError, match="positive speed"):
        solve_static(rotor)
