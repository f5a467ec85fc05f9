"""The stable depth of cut through a warm-up (spindlesim/analysis/warm_up_chatter.py), milling spindle deck:
at each instant the limit depth at the instant's own speed, by the chatter section's method (here the
semi-discretization), with the tool-point FRF of that instant.

* At the first instant the spindle is at the temperature of its cold assembly (ambient = reference =
  20 C): no part has grown, so the depth is that of the rotor without any thermal model at that speed,
  built and solved independently here (to 1e-9).
* One spindle, one number (issue 35, item 3): at the end of a step long enough for the spindle to settle
  (8 h at 12,000 rpm; its slowest time constants are tens of minutes) the depth equals the one the
  chatter diagram's method gives at 12,000 rpm with the tool-point FRF of that speed's thermal equilibrium,
  as `spindlesim chatter` builds it (measured 4.8e-7 apart; asserted within 1e-4), while the cold
  spindle's differs by 34 % (3.58 against 2.68 mm).
* Warmer bearings change it: 10 min at 4,000 rpm then 20 min at 12,000 rpm warm the front inner rings
  above 30 C and the depth at 12,000 rpm moves by more than 1 % from its value at the start of the step.
* An instant at rest cuts nothing: NaN, and not counted as a failure.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from spindlesim.analysis.points import OperatingPoints
from spindlesim.analysis.tool_point import tool_point_model
from spindlesim.analysis.warm_up_chatter import stable_depth_through
from spindlesim.chatter import build_chatter, stability_lobes
from spindlesim.deck import load_deck
from spindlesim.model.build import build_rotor
from spindlesim.model.thermal import build_spindle_thermal

DECK = Path(__file__).parents[2] / "decks" / "milling_spindle.yaml"


@pytest.fixture(scope="module")
def case():
    loaded = load_deck(DECK)
    cold = OperatingPoints(build_rotor(loaded.deck))
    warm = OperatingPoints(cold.rotor, build_spindle_thermal(loaded.deck, cold.rotor))
    spec = build_chatter(loaded.deck.chatter, DECK.parent)
    return cold, warm, spec


def _depth(spec, points, states):
    return stable_depth_through(points, states, spec.process, spec.method, spec.method_options)


def test_the_cold_instant_is_the_rotor_without_a_thermal_model(case):
    cold, warm, spec = case
    instants = warm.thermal.warm_up((0.0,), (4000.0,), 60.0, samples=2)
    assert instants[0].time_s == 0.0 and instants[0].speed_rpm == pytest.approx(4000.0)
    sd = _depth(spec, warm, instants[:1])
    ref = stability_lobes(spec.process, tool_point_model(cold, 4000.0), [4000.0], spec.method,
                          **dict(spec.method_options))
    assert ref.method == "semi_discretization"
    assert sd.depth_m[0] == pytest.approx(ref.limit_depth_m[0], rel=1e-9)
    assert sd.chatter_frequency_hz[0] == pytest.approx(ref.chatter_frequency_hz[0], rel=1e-9)
    assert sd.speed_rpm[0] == 4000.0 and "semi-discretization" in sd.method


def test_a_settled_step_gives_the_number_of_the_chatter_diagram(case):
    cold, warm, spec = case
    instants = warm.thermal.warm_up((0.0,), (12000.0,), 8 * 3600.0, samples=3)
    sd = _depth(spec, warm, instants[-1:])
    steady = OperatingPoints(cold.rotor, build_spindle_thermal(load_deck(DECK).deck, cold.rotor))  # equilibria
    ref = stability_lobes(spec.process, tool_point_model(steady, 12000.0), [12000.0], spec.method,
                          **dict(spec.method_options))
    assert sd.depth_m[0] == pytest.approx(ref.limit_depth_m[0], rel=1e-4)
    # not trivially: the cold spindle's depth at that speed differs by more than that
    cold_ref = stability_lobes(spec.process, tool_point_model(cold, 12000.0), [12000.0], spec.method,
                               **dict(spec.method_options))
    assert abs(cold_ref.limit_depth_m[0] / ref.limit_depth_m[0] - 1.0) > 0.1


def test_the_depth_moves_as_the_spindle_warms_and_is_nan_at_rest(case):
    cold, warm, spec = case
    instants = warm.thermal.warm_up((0.0, 600.0, 1800.0), (4000.0, 12000.0, 0.0), 2400.0, samples=5)
    sd = _depth(spec, warm, instants)
    moving = [k for k, ts in enumerate(instants) if ts.speed_rpm > 0]
    at_rest = [k for k, ts in enumerate(instants) if ts.speed_rpm == 0]
    assert at_rest and np.isnan(sd.depth_m[at_rest]).all() and not sd.failures
    assert np.isfinite(sd.depth_m[moving]).all()
    on_12k = [k for k in moving if abs(instants[k].speed_rpm - 12000.0) < 1e-6]
    first, last = on_12k[0], on_12k[-1]
    assert instants[last].temperatures_C["bearing:front:inner"] > 30.0  # warmed up
    assert abs(sd.depth_m[last] / sd.depth_m[first] - 1.0) > 0.01
