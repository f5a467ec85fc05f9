"""Thermal network against closed forms (issue 22; docs/validation.md "Spindle thermal network")."""

from __future__ import annotations

import math

import numpy as np
import pytest

from spindlesim.thermal.conduction import axial_conductance, cylindrical_shell_resistance
from spindlesim.thermal.network import Advection, Conductance, Network, Node
from spindlesim.thermal.transient import StepProfile, solve_transient


def test_composite_cylinder_wall_series_resistances():
    """Incropera sec. 3.3.1: q = (T_inf,1 - T_inf,4) / [1/(h1 2 pi r1 L) + sum ln(r_i+1/r_i)/(2 pi k_i L)
    + 1/(h4 2 pi r4 L)].  Three layers (steel, insulation, aluminium), fluid inside and air outside;
    the network has a node at each interface."""
    L, r = 2.0, [0.05, 0.06, 0.09, 0.095]
    k = [45.0, 0.05, 200.0]
    h_in, h_out, t_in, t_out = 800.0, 12.0, 180.0, 15.0
    R = [1.0 / (h_in * 2 * math.pi * r[0] * L)] + [cylindrical_shell_resistance(r[i], r[i + 1], L, k[i]) for i in range(3)] \
        + [1.0 / (h_out * 2 * math.pi * r[3] * L)]
    q_exact = (t_in - t_out) / sum(R)
    hand = (t_in - t_out) / (1 / (800 * 2 * math.pi * 0.05 * 2) + math.log(1.2) / (2 * math.pi * 45 * 2)
                             + math.log(1.5) / (2 * math.pi * 0.05 * 2) + math.log(0.095 / 0.09) / (2 * math.pi * 200 * 2)
                             + 1 / (12 * 2 * math.pi * 0.095 * 2))
    assert q_exact == pytest.approx(hand, rel=1e-14)
    names = ["s0", "s1", "s2", "s3"]
    net = Network(tuple(Node(n) for n in names) + (Node("in", fixed_C=t_in), Node("out", fixed_C=t_out)),
                  (Conductance("in", "s0", 1 / R[0]), Conductance("s0", "s1", 1 / R[1]), Conductance("s1", "s2", 1 / R[2]),
                   Conductance("s2", "s3", 1 / R[3]), Conductance("s3", "out", 1 / R[4])))
    s = net.solve_steady()
    bal = net.heat_flows(s.temperatures_C)
    assert -bal.removed_W["in"] == pytest.approx(q_exact, rel=1e-12)
    assert bal.removed_W["out"] == pytest.approx(q_exact, rel=1e-12)
    # interface temperature from the closed form
    assert s["s2"] == pytest.approx(t_in - q_exact * sum(R[:3]), rel=1e-12)


def _fin_network(n: int, L: float, d: float, k: float, h: float, tb: float, tinf: float) -> tuple[Network, float]:
    A, P = math.pi * d * d / 4, math.pi * d
    dx = L / n
    nodes = [Node(f"x{i}") for i in range(n)] + [Node("base", fixed_C=tb), Node("air", fixed_C=tinf)]
    links = [Conductance("base", "x0", axial_conductance(0.5 * dx, A, k))]
    links += [Conductance(f"x{i}", f"x{i + 1}", axial_conductance(dx, A, k)) for i in range(n - 1)]
    links += [Conductance(f"x{i}", "air", h * P * dx) for i in range(n)]
    return Network(tuple(nodes), tuple(links)), math.sqrt(h * P * k * A)


def test_fin_converges_to_tanh_second_order():
    """Pin fin, adiabatic tip (Incropera eq. 3.81): q_f = sqrt(h P k A) theta_b tanh(mL), m^2 = hP/(kA);
    efficiency tanh(mL)/(mL).  Copper rod d 5 mm, L 100 mm, k 398, h 100 W/m2K: mL = 1.42.  The
    network of n cells (node at each cell centre) converges at second order in 1/n."""
    L, d, k, h, tb, tinf = 0.1, 0.005, 398.0, 100.0, 100.0, 25.0
    m = math.sqrt(h * math.pi * d / (k * math.pi * d * d / 4))
    errors = []
    for n in (5, 10, 20, 40, 80):
        net, M = _fin_network(n, L, d, k, h, tb, tinf)
        s = net.solve_steady()
        q = -net.heat_flows(s.temperatures_C).removed_W["base"]
        exact = M * (tb - tinf) * math.tanh(m * L)
        errors.append(abs(q / exact - 1.0))
        eff = q / (h * math.pi * d * L * (tb - tinf))
        assert eff == pytest.approx(math.tanh(m * L) / (m * L), rel=errors[-1] * 1.01)
    rates = [math.log2(a / b) for a, b in zip(errors, errors[1:])]
    assert errors[-1] < 5e-5   # 4.4e-5 at 80 cells
    assert all(1.95 < p < 2.05 for p in rates), rates


@pytest.mark.parametrize("method", ["BDF", "Radau"])
def test_lumped_capacity_decay(method):
    """RC decay: T(t) = T_inf + (T0 - T_inf) exp(-t / RC), to 1e-6 of (T0 - T_inf) over five time constants."""
    C, G, T0, Tinf = 4600.0, 2.3, 80.0, 20.0
    net = Network((Node("body", C), Node("air", fixed_C=Tinf)), (Conductance("body", "air", G),))
    t = np.linspace(0.0, 5 * C / G, 41)
    r = solve_transient(net, T0, t[-1], t_eval=t, method=method, rtol=1e-10, atol=1e-10)
    exact = Tinf + (T0 - Tinf) * np.exp(-r.times_s * G / C)
    assert np.max(np.abs(r["body"] - exact)) / (T0 - Tinf) < 1e-6


def test_implicit_euler_is_first_order():
    C, G, T0, Tinf = 1000.0, 1.0, 80.0, 20.0
    net = Network((Node("body", C), Node("air", fixed_C=Tinf)), (Conductance("body", "air", G),))
    tend = C / G
    err = []
    for dt in (100.0, 50.0, 25.0, 12.5):
        r = solve_transient(net, T0, tend, method="implicit_euler", dt_s=dt)
        err.append(abs(r["body"][-1] - (Tinf + (T0 - Tinf) * math.exp(-1.0))))
    rates = [math.log2(a / b) for a, b in zip(err, err[1:])]
    assert all(0.9 < p < 1.1 for p in rates), rates


def _coolant_network():
    """Two solid bodies, one heated, cooled by ambient air and by a three-node coolant stream."""
    nodes = (Node("a", 900.0), Node("b", 1500.0), Node("w0", 60.0), Node("w1", 60.0), Node("w2", 60.0),
             Node("air", fixed_C=22.0), Node("inlet", fixed_C=18.0))
    links = (Conductance("a", "b", 3.0), Conductance("b", "air", 0.4), Conductance("a", "air", 0.2),
             Conductance("w0", "b", 5.0), Conductance("w1", "b", 5.0), Conductance("w2", "a", 4.0))
    adv = (Advection("inlet", "w0", 50.0), Advection("w0", "w1", 50.0), Advection("w1", "w2", 50.0))
    return Network(nodes, links, adv)


def test_steady_energy_balance():
    """Generated = removed (air + coolant m c_p (T_out - T_in)) to 1e-9 relative."""
    net = _coolant_network()
    q = {"a": 350.0, "b": 120.0}
    s = net.solve_steady(q)
    bal = net.heat_flows(s.temperatures_C, q)
    assert bal.generated_W == 470.0
    assert bal.relative_imbalance < 1e-9
    assert bal.removed_W["inlet"] == pytest.approx(50.0 * (s["w2"] - 18.0), rel=1e-12)


def test_warm_up_ends_at_the_steady_state_and_stores_what_it_does_not_remove():
    net = _coolant_network()
    q = {"a": 350.0, "b": 120.0}
    s = net.solve_steady(q)
    r = solve_transient(net, 20.0, 40 * 3600.0, sources=q, rtol=1e-10, atol=1e-10)
    assert np.max(np.abs(r.final_C - s.temperatures_C)) < 1e-6
    # implicit Euler: the discrete balance C (T_n+1 - T_n) = h (Q - removed)_n+1 holds to rounding
    prof = StepProfile((0.0, 900.0, 2400.0), (1.0, 2.5, 0.5))
    ie = solve_transient(net, 20.0, 3600.0, sources=lambda t, T: {"a": 350.0 * prof(t), "b": 120.0},
                         breakpoints=prof.breakpoints, method="implicit_euler", dt_s=20.0)
    stored, net_heat = ie.stored_J(), ie.net_heat_J("right")
    assert abs(stored[-1] - net_heat[-1]) < 1e-9 * np.max(np.abs(stored))
    # BDF with the same profile: trapezoid over a fine output, to the integration tolerance
    bdf = solve_transient(net, 20.0, 3600.0, sources=lambda t, T: {"a": 350.0 * prof(t), "b": 120.0},
                          breakpoints=prof.breakpoints, t_eval=np.linspace(0, 3600, 3601), rtol=1e-9, atol=1e-9)
    assert bdf.net_heat_J()[-1] == pytest.approx(bdf.stored_J()[-1], rel=1e-5)
    assert np.max(np.abs(bdf.final_C - ie.final_C)) < 0.1   # first-order IE at 20 s steps: 0.067 K
