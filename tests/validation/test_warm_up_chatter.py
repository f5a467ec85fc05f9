"""The minimum stable depth of cut through a warm-up (spindlesim/analysis/warm_up_chatter.py), milling
spindle deck.

* At the first instant the spindle is at the temperature of its cold assembly (ambient = reference =
  20 C): no part has grown, so the tool-point FRF and the minimum depth are those of the rotor without
  any thermal model at that speed, built and solved independently here (to 1e-9).
* The minimum over the speeds is the envelope's: no speed of an independent zero-order diagram at that
  state lies below it, and it is attained at the speed reported.
* Warmer bearings change it: 10 min at 4,000 rpm then 20 min at 12,000 rpm warm the front inner rings
  above 30 C, the preload and the stiffness rise, and the minimum moves by more than 1 % from the cold one
  (through the deck's 2 h warm-up it goes 0.567 -> 0.75 -> 0.53 mm, docs/validation.md).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from spindlesim.analysis.points import OperatingPoints
from spindlesim.analysis.tool_point import tool_point_model
from spindlesim.analysis.warm_up_chatter import minimum_depth_through
from spindlesim.chatter import build_chatter, zero_order_lobes
from spindlesim.deck import load_deck
from spindlesim.model.thermal import build_spindle_thermal

DECK = Path(__file__).parents[2] / "decks" / "milling_spindle.yaml"
SPEEDS = np.linspace(6000.0, 24000.0, 61)


@pytest.fixture(scope="module")
def case():
    loaded = load_deck(DECK)
    cold = OperatingPoints(loaded_rotor(loaded))
    warm = OperatingPoints(cold.rotor, build_spindle_thermal(loaded.deck, cold.rotor))
    spec = build_chatter(loaded.deck.chatter, DECK.parent)
    instants = warm.thermal.warm_up((0.0, 600.0), (4000.0, 12000.0), 1800.0, samples=4)
    return cold, warm, spec, instants


def loaded_rotor(loaded):
    from spindlesim.model.build import build_rotor

    return build_rotor(loaded.deck)


def test_the_cold_instant_is_the_rotor_without_a_thermal_model(case):
    cold, warm, spec, instants = case
    assert instants[0].time_s == 0.0 and instants[0].speed_rpm == pytest.approx(4000.0)
    md = minimum_depth_through(warm, instants[:1], spec.process, SPEEDS)
    ref = zero_order_lobes(spec.process, tool_point_model(cold, 4000.0), SPEEDS)
    i = int(np.nanargmin(ref.limit_depth_m))
    assert md.depth_m[0] == pytest.approx(ref.limit_depth_m[i], rel=1e-9)
    assert md.speed_rpm[0] == SPEEDS[i]
    assert md.chatter_frequency_hz[0] == pytest.approx(ref.chatter_frequency_hz[i], rel=1e-9)
    assert "zero order" in md.method


def test_the_minimum_is_the_envelope_at_every_instant_and_moves_as_the_spindle_warms(case):
    cold, warm, spec, instants = case
    md = minimum_depth_through(warm, instants, spec.process, SPEEDS)
    assert len(md.depth_m) == len(instants) and np.isfinite(md.depth_m).all()
    last = instants[-1]
    assert last.temperatures_C["bearing:front:inner"] > 30.0  # warmed up
    sysm = warm.system(last.operating)
    from spindlesim.analysis.tool_point import point_dofs, state_space

    tip = point_dofs(warm.rotor, None)[1]
    ref = zero_order_lobes(spec.process, state_space(sysm, np.eye(sysm.size)[:, tip]), SPEEDS)
    assert np.nanmin(ref.limit_depth_m) == pytest.approx(md.depth_m[-1], rel=1e-12)
    assert ref.limit_at(md.speed_rpm[-1]) == pytest.approx(md.depth_m[-1], rel=1e-12)
    assert abs(md.depth_m[-1] / md.depth_m[0] - 1.0) > 0.01
