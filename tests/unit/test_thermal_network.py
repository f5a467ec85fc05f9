"""Thermal network library (issue 22): construction checks, nonlinear solves, errors, the spindle builder."""

from __future__ import annotations

import math

import numpy as np
import pytest

from spindlesim.model.thermal_example import milling_spindle_layout
from spindlesim.thermal.network import Advection, Conductance, Network, Node, ThermalConvergenceError
from spindlesim.thermal.spindle_network import BearingContacts, BearingHeat, build_spindle_network
from spindlesim.thermal.transient import StepProfile, solve_transient


def _rod(n=6):
    nodes = tuple(Node(f"n{i}", 100.0) for i in range(n)) + (Node("amb", fixed_C=20.0),)
    links = tuple(Conductance(f"n{i}", f"n{i + 1}", 5.0) for i in range(n - 1)) + (Conductance(f"n{n - 1}", "amb", 1.0),)
    return Network(nodes, links)


def test_construction_errors_name_the_culprit():
    with pytest.raises(ValueError, match="duplicate node names"):
        Network((Node("a"), Node("a", fixed_C=0.0)))
    with pytest.raises(ValueError, match="unknown node 'c'"):
        Network((Node("a"), Node("b", fixed_C=0.0)), (Conductance("a", "c", 1.0),))
    with pytest.raises(ValueError, match=r"without a heat path to any boundary node: \['c'\]"):
        Network((Node("a"), Node("b", fixed_C=0.0), Node("c")), (Conductance("a", "b", 1.0),))
    with pytest.raises(ValueError, match="flows into boundary node"):
        Network((Node("a"), Node("b", fixed_C=0.0)), (Conductance("a", "b", 1.0),), (Advection("a", "b", 1.0),))
    with pytest.raises(ValueError, match="coolant flow not conserved at 'w'"):
        Network((Node("in", fixed_C=0.0), Node("w"), Node("x")), (), (Advection("in", "w", 2.0), Advection("w", "x", 1.0)))
    with pytest.raises(ValueError, match="boundary nodes"):
        _rod().solve_steady({"amb": 1.0})
    with pytest.raises(KeyError, match="no conductance named 'zz'"):
        _rod().solve_steady({"n0": 1.0}, conductances={"zz": 1.0})


def test_overrides_and_boundary_values():
    net = _rod()
    s1 = net.solve_steady({"n0": 10.0})
    assert s1["n5"] == pytest.approx(30.0)                              # 10 W through 1 W/K
    s2 = net.solve_steady({"n0": 10.0}, conductances={"n5--amb": 2.0}, boundary={"amb": 25.0})
    assert s2["n5"] == pytest.approx(30.0) and s2["n0"] == pytest.approx(s1["n0"] - 5.0 + 5.0 - 0.0 + 0.0)
    assert s2["n0"] - s2["n5"] == pytest.approx(s1["n0"] - s1["n5"])   # same flow through the rod


def test_picard_and_newton_agree_on_a_nonlinear_network():
    """Radiation-like conductance G(T) = 0.05 (1 + (T - 20)/50) and a source that falls with T."""
    net = _rod()

    def g(T):
        return {"n5--amb": 0.05 * (1.0 + (T[5] - 20.0) / 50.0)}

    def q(T):
        return {"n0": 40.0 * (1.0 - 0.002 * (T[0] - 20.0))}

    p = net.solve_steady(q, conductances=g, tol_K=1e-10, relaxation=0.3, max_iter=400)
    n = net.solve_steady(q, conductances=g, method="newton", tol_K=1e-10)
    assert np.max(np.abs(p.temperatures_C - n.temperatures_C)) < 1e-8
    assert n.iterations < p.iterations
    bal = net.heat_flows(n.temperatures_C, q, conductances=g)
    assert bal.relative_imbalance < 1e-9


def test_convergence_error_says_what_and_where():
    net = _rod()

    def g(T):   # a conductance that oscillates with temperature: no fixed point for Picard
        return {"n5--amb": 2.0 if T[5] > 60.0 else 0.5}

    with pytest.raises(ThermalConvergenceError, match=r"picard, 7 iterations.*at node 'n\d'.*tolerance 1e-08 K"):
        net.solve_steady({"n0": 60.0}, conductances=g, max_iter=7)


def test_zero_capacity_node_needs_implicit_euler():
    net = Network((Node("a", 10.0), Node("m"), Node("amb", fixed_C=0.0)),
                  (Conductance("a", "m", 1.0), Conductance("m", "amb", 1.0)))
    with pytest.raises(ValueError, match=r"heat capacity > 0.*\['m'\]"):
        solve_transient(net, 10.0, 100.0)
    r = solve_transient(net, 10.0, 200.0, method="implicit_euler", dt_s=0.5)
    # a-m-amb: tau = C R = 10 * 2 = 20 s; implicit Euler at h = 0.5 s: (1 + h/tau)^-n
    assert r["a"][-1] == pytest.approx(10.0 * (1 + 0.5 / 20.0) ** -400, rel=1e-9)
    assert r["m"][-1] == pytest.approx(0.5 * r["a"][-1], rel=1e-12)


def test_step_profile_and_breakpoints():
    p = StepProfile((0.0, 10.0, 25.0), (1.0, 3.0, 2.0))
    assert [p(0.0), p(9.999), p(10.0), p(30.0)] == [1.0, 1.0, 3.0, 2.0]
    assert p.breakpoints == (10.0, 25.0)
    net = Network((Node("a", 10.0), Node("amb", fixed_C=0.0)), (Conductance("a", "amb", 1.0),))
    seen = []
    r = solve_transient(net, 0.0, 30.0, sources=lambda t, T: (seen.append(t), {"a": p(t)})[1],
                        breakpoints=p.breakpoints)
    # no evaluation of the first segment saw the second step's value at t = 10 (left limit)
    assert r.times_s.tolist().count(10.0) == 2 and r.times_s.tolist().count(25.0) == 2
    # exact piecewise solution
    T = 0.0
    for a, b, v in ((0.0, 10.0, 1.0), (10.0, 25.0, 3.0), (25.0, 30.0, 2.0)):
        T = v + (T - v) * math.exp(-(b - a) / 10.0)
    assert r["a"][-1] == pytest.approx(T, rel=1e-4)


@pytest.fixture(scope="module")
def spindle():
    return build_spindle_network(milling_spindle_layout())


HEAT = {"front": BearingHeat(108.0, 24.0, 108.0), "rear": BearingHeat(54.0, 12.0, 54.0)}


def test_spindle_nodes_and_energy_balance(spindle):
    names = spindle.network.names
    for n in ("shaft[3]", "bearing:front:inner", "bearing:front:balls", "bearing:rear:outer", "housing[2]",
              "jacket:coolant[1]", "motor:stator", "motor:rotor", "ambient", "jacket:inlet"):
        assert n in names
    w = 18000 * math.pi / 30
    s = spindle.steady(w, HEAT, load_fraction=0.3, tol_K=1e-10)
    src = spindle.sources(HEAT, spindle.motor_losses(w, load_fraction=0.3))
    bal = spindle.network.heat_flows(s.temperatures_C, src, conductances=spindle.conductances(w, s.temperatures_C))
    assert bal.generated_W == pytest.approx(360.0 + spindle.motor_losses(w, load_fraction=0.3).total_W)
    assert bal.relative_imbalance < 1e-9
    assert bal.removed_W["jacket:inlet"] > 0.8 * bal.generated_W   # the jacket takes most of it
    # hotter with more bearing heat; the front inner ring runs hotter than its outer ring
    hot = spindle.steady(w, {k: BearingHeat(2 * v.inner_W, 2 * v.balls_W, 2 * v.outer_W) for k, v in HEAT.items()},
                         load_fraction=0.3)
    assert hot["bearing:front:inner"] > s["bearing:front:inner"] > s["bearing:front:outer"]


def test_spindle_heat_callable_and_contacts(spindle):
    """Bearing heat that depends on the temperatures (the coupling's signature) converges; heavier
    contacts conduct better: the contact part of the ring-to-balls conductance goes as the ellipse's size,
    Q^(1/3) (eight times the load, twice the conductance), beside the rings' free faces, which do not
    depend on the load."""
    w = 12000 * math.pi / 30

    def heat(T):
        rise = T["bearing:front:inner"] - T["bearing:front:outer"]
        return {"front": BearingHeat(80.0 + 0.5 * rise, 10.0, 80.0), "rear": BearingHeat(40.0, 5.0, 40.0)}

    s = spindle.steady(w, heat)
    assert s.iterations > 1
    light = spindle.conductances(w, contacts={"front": BearingContacts(50.0, 50.0)})
    heavy = spindle.conductances(w, contacts={"front": BearingContacts(400.0, 400.0)})
    front = next(b for b in spindle.layout.bearings if b.name == "front")
    faces = spindle._ring_faces(front, w)[0]
    assert faces > 0
    assert heavy["bearing:front:inner--balls"] - faces == pytest.approx(
        2 * (light["bearing:front:inner--balls"] - faces), rel=1e-9)


def test_spindle_warm_up_reaches_the_steady_state(spindle):
    w = 15000 * math.pi / 30
    s = spindle.steady(w, HEAT, load_fraction=0.2, tol_K=1e-10)
    r = spindle.warm_up(w, 30 * 3600.0, HEAT, load_fraction=0.2, update_K=0.0, rtol=1e-9, atol=1e-9)
    assert np.max(np.abs(r.final_C - s.temperatures_C)) < 1e-6
    prof = StepProfile((0.0, 1800.0, 3600.0), (6000 * math.pi / 30, 18000 * math.pi / 30, 0.0))
    r2 = spindle.warm_up(prof, 5400.0, HEAT, t_eval=np.linspace(0, 5400, 91))
    front = r2["bearing:front:inner"]
    k1, k2 = np.searchsorted(r2.times_s, 1800.0), np.searchsorted(r2.times_s, 3600.0)
    # warmer than cold at both steps (the bearings' heat is held here; at the higher speed the motor's iron
    # losses are held above its base speed and the rotating surfaces cool better, so no order between them)
    assert min(front[k1], front[k2]) > front[0] + 10.0 and front[0] == 20.0
