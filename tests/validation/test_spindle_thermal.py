"""The spindle's thermal loop (issue 22): heat -> temperatures -> growth -> preload -> heat, on the milling
spindle deck (decks/milling_spindle.yaml, section spindle_thermal).

Checks written here, each against something independent of the loop:

* the axial offsets of the bearing seats and the tool tip's drift at a uniform temperature: hand integrals
  (alpha_s - alpha_h) dT (z - z_h) and alpha_s dT (z_tip - z_h);
* energy: at the thermal equilibrium the heat generated (bearings, motor) leaves through the coolant and the
  ambient (1e-6 of it with a tight loop tolerance);
* the trends the issue names: a position-preloaded pair's preload rises faster with speed when the
  temperatures follow than with centrifugal force alone; a spring preload holds its thrust; hybrid
  (Si3N4) balls raise the preload less than steel ones; the end of a long warm-up at one speed is the
  steady state there;
* a runaway says which bearing and which speed;
* a warm-up's speed step on both of its sides, the side before equal to a warm-up that ends there.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest
import yaml

from spindlesim.analysis.operating import operating_state
from spindlesim.analysis.spindle_thermal import SpindleThermal, ThermalRunawayError
from spindlesim.deck import DeckError, parse_deck
from spindlesim.model.build import build_rotor
from spindlesim.model.thermal import build_spindle_thermal

DECK = Path(__file__).parents[2] / "decks" / "milling_spindle.yaml"


def _deck(change=None) -> dict:
    d = yaml.safe_load(DECK.read_text())
    if change is not None:
        change(d)
    return d


def _thermal(d: dict) -> SpindleThermal:
    deck = parse_deck(yaml.safe_dump(d), "mill.yaml").deck
    rotor = build_rotor(deck)
    return SpindleThermal(rotor, build_spindle_thermal(deck, rotor))


@pytest.fixture(scope="module")
def spindle() -> SpindleThermal:
    return _thermal(_deck())


def _front_thrust(state) -> float:
    return float(np.max(state.bearings["front"].row_thrust_N))


def test_axial_offsets_and_tool_tip_drift_at_a_uniform_temperature():
    """Every node at 50 C (reference 20 C), a cast-iron housing (10.5e-6 1/K) on the steel shaft
    (11.5e-6): each seat's offset is (alpha_s - alpha_h) 30 K (z_k - z_h), 0.99 um at the front pair (52.5 mm)
    and 11.1 um at the rear (390 mm); the tip's growth alpha_s 30 K (z_tip - z_h) = -55.2 um beyond its
    elastic displacement (z_h = 20 mm the housing's front face; the tool tip at -140 mm)."""
    def cast_iron(d):
        d["spindle_thermal"]["housing"]["material"] = {"thermal_expansion_1_K": 10.5e-6}

    spindle = _thermal(_deck(cast_iron))
    T = {n: 50.0 for n in spindle._names}
    a_s, a_h = spindle.model.shaft_expansion_1_K, spindle.model.housing_expansion_1_K
    assert (a_s, a_h) == (11.5e-6, 10.5e-6)
    off = spindle.offsets(T)
    for name, z in (("front", 0.0525), ("rear", 0.390)):
        assert off[name] == pytest.approx((a_s - a_h) * 30.0 * (z - 0.020), rel=1e-12, abs=1e-15)
    st = operating_state(spindle.rotor_at(T)[0], 0.0, spindle.shaft)
    tip = spindle.rotor.tool_tip
    elastic = float(st.q[spindle.rotor.dofs.index(tip, "z")])
    z_tip = float(spindle.rotor.node_z_m[tip])
    assert z_tip == pytest.approx(-0.140)
    assert spindle._tip_drift(T, st) - elastic == pytest.approx(a_s * 30.0 * (z_tip - 0.020), rel=1e-12)


def test_heat_generated_leaves_through_coolant_and_ambient(spindle):
    s = _tight(spindle).steady(8000.0)
    generated = s.total_heat_W
    assert generated > 100.0
    assert sum(s.removed_W.values()) == pytest.approx(generated, rel=1e-6)
    assert abs(s.stored_W) < 1e-6 * generated
    assert set(s.removed_W) == {"ambient", "jacket:inlet"}


def _tight(spindle):
    import dataclasses

    return SpindleThermal(spindle.rotor, dataclasses.replace(spindle.model, tolerance_K=1e-7), spindle.shaft)


def test_position_preload_rises_faster_with_temperature_than_with_speed_alone(spindle):
    """Front pair (position preload 15 um): from 4000 to 12,000 rpm its largest row thrust rises with
    centrifugal force alone (bearings cold: 327 -> 592 N) and about twice as much when the rings take their
    temperatures (576 -> 1106 N; 3.4 x before each ring's seat straddled both shaft and housing segments at its
    node: the inner ring had been tied to the segment on the motor's side, which runs warmer)."""
    cold = {}
    for rpm in (4000.0, 12000.0):
        st = operating_state(spindle.rotor, rpm, spindle.shaft)
        front = next(b for b in st.bearings if b.name == "front")
        cold[rpm] = float(np.max(front.solve(st.load_of("front"), rpm * np.pi / 30).row_axial_load_N))
    warm = {rpm: _front_thrust(spindle.steady(rpm)) for rpm in (4000.0, 12000.0)}
    rise_cold, rise_warm = cold[12000.0] - cold[4000.0], warm[12000.0] - warm[4000.0]
    assert rise_cold > 0
    assert rise_warm > 1.5 * rise_cold


def test_spring_preload_holds_its_thrust(spindle):
    """The rear pair's floating row carries its 300 N spring force at every speed and temperature."""
    for rpm in (4000.0, 12000.0):
        thrust = spindle.steady(rpm).bearings["rear"].row_thrust_N
        assert np.max(thrust) == pytest.approx(300.0, rel=1e-9)


def test_hybrid_balls_raise_the_preload_less_than_steel_ones(spindle):
    """Silicon nitride grows about a quarter as much as steel (3.2e-6 against 11.5e-6 1/K): at 6000 rpm the
    hybrid front pair's preload (and its heat) stays below the all-steel pair's."""
    steel = _thermal(_deck(lambda d: d["bearings"][0].pop("ball_material")))
    hybrid_state, steel_state = spindle.steady(6000.0), steel.steady(6000.0)
    assert _front_thrust(hybrid_state) < _front_thrust(steel_state)
    assert hybrid_state.heat_W["bearing:front"] < steel_state.heat_W["bearing:front"]


@pytest.mark.slow
def test_a_long_warm_up_at_one_speed_ends_in_the_steady_state(spindle):
    steady = spindle.steady(8000.0)
    end = spindle.warm_up((0.0,), (8000.0,), 40 * 3600.0, samples=3)[-1]
    for name in ("bearing:front:inner", "bearing:front:outer", "bearing:rear:inner", "motor:stator", "housing[5]"):
        assert end.temperatures_C[name] == pytest.approx(steady.temperatures_C[name], abs=0.05), name
    assert _front_thrust(end) == pytest.approx(_front_thrust(steady), rel=2e-3)


def test_a_runaway_names_the_bearing_and_the_speed(spindle):
    with pytest.raises(ThermalRunawayError, match=re.escape("thermal runaway of bearing 'front' at 20000 rpm")):
        spindle.steady(20000.0)


@pytest.mark.parametrize("where,value,expect", [
    ("cooling_jacket.flow_l_min", 0.0, "flow_l_min"),
    ("motor.efficiency", 1.2, "efficiency"),
    ("housing.material.conductivity_W_mK", -5.0, "conductivity_W_mK"),
])
def test_bad_thermal_input_is_a_located_deck_error(where, value, expect):
    d = _deck()
    node = d["spindle_thermal"]
    keys = where.split(".")
    for k in keys[:-1]:
        node = node.setdefault(k, {})
    node[keys[-1]] = value
    with pytest.raises(DeckError) as exc:
        parse_deck(yaml.safe_dump(d), "mill.yaml")
    text = str(exc.value.issues[0])
    assert text.startswith("mill.yaml:") and expect in text


def test_prescribed_temperatures_and_the_thermal_section_exclude_each_other():
    d = _deck()
    d["bearings"][0]["temperatures_C"] = {"inner_ring": 40, "outer_ring": 30, "rolling_elements": 35}
    with pytest.raises(DeckError) as exc:
        parse_deck(yaml.safe_dump(d), "mill.yaml")
    assert any("bearings[0].temperatures_C" in str(i) and "exclude each other" in str(i) for i in exc.value.issues)


def test_a_speed_sweep_starts_from_its_neighbours_extrapolated(spindle):
    """Operating points solve each speed's loop from the nearest speed's temperatures extrapolated linearly
    from the next nearest: the same equilibrium as a start from the ambient (within a few loop tolerances,
    0.01 K each) in fewer passes than a start from the nearest speed alone."""
    from spindlesim.analysis.points import OperatingPoints

    points = OperatingPoints(spindle.rotor, spindle.model)
    for rpm in (4000.0, 6000.0):
        points.thermal_state(rpm)
    swept = points.thermal_state(8000.0)
    cold = spindle.steady(8000.0)
    nearest = spindle.steady(8000.0, start=points.thermal_state(6000.0))
    for name in ("bearing:front:inner", "bearing:front:outer", "bearing:rear:inner", "motor:stator"):
        assert swept.temperatures_C[name] == pytest.approx(cold.temperatures_C[name], abs=0.05), name
    assert _front_thrust(swept) == pytest.approx(_front_thrust(cold), rel=2e-3)
    assert swept.iterations < nearest.iterations < cold.iterations


def test_radial_drift_is_the_tips_deflection_and_zero_without_loads(spindle):
    """Item 6's radial drift: the tool tip's static deflection (x, y) at the state, the one the static analysis
    gives on the bearings at those temperatures; the network is axisymmetric, so with no load and no gravity the
    tip stays on the axis (0 to round-off) while it still drifts axially by the shaft's growth."""
    from spindlesim.analysis.static import solve_static

    s = spindle.steady(4000.0)
    tip = spindle.rotor.tool_tip
    warm_rotor = spindle.rotor_at(s.temperatures_C)[0]
    ref = solve_static(warm_rotor, speed_rpm=4000.0)
    assert s.tool_tip_radial_m == pytest.approx(tuple(ref.displacement_m[tip]), rel=1e-6, abs=1e-12)
    assert abs(s.tool_tip_radial_m[0]) > 1e-7  # the deck's loads deflect it (about 1.6 um in x)

    def unloaded(d):
        d.pop("loads", None)
        d["operating"]["gravity"] = False

    free = _thermal(_deck(unloaded)).steady(4000.0)
    assert max(abs(v) for v in free.tool_tip_radial_m) < 1e-12
    assert abs(free.tool_tip_axial_drift_m) > 5e-6


def test_a_speed_step_is_reported_on_both_sides_at_the_deck_speeds(spindle):
    """A step inside the warm-up comes twice at its instant, the same temperatures (they do not jump), first at the
    speed before the step, then at the speed after it, each the deck's number (no rad/s round trip).  The side
    before is what a warm-up that ends there at the first speed reports: an independent run (no step in it)."""
    steps = spindle.warm_up((0.0, 600.0), (4000.0, 12000.0), 1200.0, samples=2)
    assert [s.time_s for s in steps] == [0.0, 600.0, 600.0, 1200.0]
    assert [s.speed_rpm for s in steps] == [4000.0, 4000.0, 12000.0, 12000.0]
    before, after = steps[1], steps[2]
    assert before.temperatures_C == after.temperatures_C
    alone = spindle.warm_up((0.0,), (4000.0,), 600.0, samples=2)[-1]
    assert alone.speed_rpm == 4000.0
    for name, t in alone.temperatures_C.items():
        assert before.temperatures_C[name] == pytest.approx(t, abs=1e-6), name
    assert _front_thrust(before) == pytest.approx(_front_thrust(alone), rel=1e-9)
    # the heat jumps with the speed at the step (the front pair's friction grows with it)
    assert after.heat_W["bearing:front"] > 2.0 * before.heat_W["bearing:front"]
