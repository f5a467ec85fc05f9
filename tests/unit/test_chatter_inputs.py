"""Tool-point inputs: modes, sampled FRFs, the state-space model and the processes' force models."""

import numpy as np
import pytest

from spindlesim.chatter import MillingProcess, Mode, ToolPointFrf, ToolPointModel, TurningProcess
from spindlesim.chatter.process import _antiderivative
from spindlesim.chatter.tool import ToolSeries, as_state_space, for_simulation, tool_series

MODES = [Mode("x", 650.0, 0.035, 2.2e7), Mode("x", 1450.0, 0.02, 4.0e7), Mode("y", 720.0, 0.03, 2.6e7)]


def test_state_space_from_modes_reproduces_the_modal_receptance():
    model = ToolPointModel.from_modes(MODES)
    f = np.linspace(10.0, 3000.0, 500)
    H = model.frf(f).H
    hx = MODES[0].receptance(f) + MODES[1].receptance(f)
    hy = MODES[2].receptance(f)
    assert np.allclose(H[:, 0, 0], hx, rtol=1e-10, atol=0)
    assert np.allclose(H[:, 1, 1], hy, rtol=1e-10, atol=0)
    assert np.all(H[:, 0, 1] == 0) and np.all(H[:, 1, 0] == 0)
    # static compliance = sum 1/k
    assert model.receptance(np.array([0.0]))[0, 0, 0].real == pytest.approx(1 / 2.2e7 + 1 / 4e7, rel=1e-12)


def test_modes_summary_and_grid():
    model = ToolPointModel.from_modes(MODES)
    summ = model.modes()
    assert [round(s.frequency_hz, 6) for s in summ] == [650.0, 720.0, 1450.0]
    assert summ[0].damping_ratio == pytest.approx(0.035, rel=1e-10)
    grid = model.frequency_grid()
    assert np.all(np.diff(grid) > 0)
    near = grid[np.abs(grid - 650 * 1.035) < 650 * 0.035]
    assert len(near) > 50  # clustered on the resonance


def test_eigen_and_direct_frf_paths_agree():
    model = ToolPointModel.from_modes(MODES)
    w = 2 * np.pi * np.linspace(100, 2000, 37)
    direct = np.array([model.C @ np.linalg.solve(1j * wk * np.eye(6) - model.A, model.B) for wk in w])
    assert np.allclose(model.receptance(w), direct, rtol=1e-10, atol=1e-20)


def test_general_abc_and_truncation():
    rng = np.random.default_rng(3)
    base = ToolPointModel.from_modes(MODES + [Mode("y", 9000.0, 0.02, 5e8)])
    T = rng.standard_normal((8, 8)) + 4 * np.eye(8)  # any state basis
    Ti = np.linalg.inv(T)
    general = ToolPointModel(Ti @ base.A @ T, Ti @ base.B, base.C @ T, "general")
    w = 2 * np.pi * np.array([300.0, 650.0, 1450.0])
    assert np.allclose(general.receptance(w), base.receptance(w), rtol=1e-8)
    trunc = general.truncated(3000.0)
    assert trunc.A.shape == (6, 6)
    assert np.allclose(trunc.receptance(w)[:, 0, 0], base.receptance(w)[:, 0, 0], rtol=1e-8)


def test_frf_validation_and_interpolation():
    f = np.array([1.0, 2.0, 3.0])
    H = np.zeros((3, 2, 2), complex)
    with pytest.raises(ValueError, match="increasing"):
        ToolPointFrf(np.array([1.0, 3.0, 2.0]), H)
    with pytest.raises(ValueError, match="shape"):
        ToolPointFrf(f, np.zeros((3, 2), complex))
    H[:, 0, 0] = [1 + 1j, 3 + 1j, 5 - 1j]
    frf = ToolPointFrf(f, H)
    assert frf.interpolated(np.array([1.5])).H[0, 0, 0] == pytest.approx(2 + 1j)
    with pytest.raises(ValueError):
        Mode("z", 100.0, 0.01, 1e6)
    with pytest.raises(ValueError):
        Mode("x", 100.0, 1.5, 1e6)


def test_tool_series_forms():
    """One tool at every speed, one per speed (looked up by the speed, not by position or the nearest), and a
    callable computed at each speed and at speeds added later."""
    model = ToolPointModel.from_modes(MODES)
    other = ToolPointModel.from_modes([Mode("x", 500.0, 0.02, 1e6)])
    speeds = np.array([1000.0, 2000.0])
    const = tool_series(model, speeds)
    assert not const.speed_dependent and const.along(speeds) == [model, model] and const.tool_at(1234.0) is model
    assert const.at([5.0]) is const and const.extendable
    asked = []
    computed = tool_series(lambda n: asked.append(n) or model, speeds)
    assert computed.speed_dependent and asked == [1000.0, 2000.0] and computed.tool_at(1500.0) is model
    assert asked[-1] == 1500.0 and computed.tool_at(2000.0) is model and asked[-1] == 1500.0
    with pytest.raises(ValueError, match="2 speeds"):
        tool_series([model], speeds)
    listed = tool_series([model, other], speeds)
    assert listed.along([2000.0, 1000.0]) == [other, model] and not listed.extendable
    with pytest.raises(ValueError, match="no tool at 1900 rpm"):
        listed.tool_at(1900.0)
    assert listed.near(1900.0) is other and listed.near(1000.0) is model  # a check off the grid: the nearest
    joined = listed.joined(ToolSeries(np.array([1500.0]), (model,)))
    assert joined.at([1000.0, 1500.0, 2000.0]).tools == (model, model, other)
    assert tool_series(listed, [7.0]) is listed
    assert as_state_space(model) is model and model.state_space is model


def test_both_tool_points_implement_the_protocol():
    """The model and the sampled FRF answer the same questions: receptance at frequencies, the FRF on their own
    grid or given frequencies, the state space where there is one (a sampled FRF is fitted for it)."""
    model = ToolPointModel.from_modes(MODES)
    f = np.arange(100.0, 3000.0, 0.5)
    frf = model.frf(f)
    w = 2 * np.pi * np.array([700.0, 922.25, 1500.0])
    assert np.allclose(frf.receptance(w), model.receptance(w), rtol=2e-3)
    assert frf.frf() is frf and np.allclose(frf.frf(f[10:20]).H, frf.H[10:20])
    assert np.array_equal(model.frf().frequency_hz, model.frequency_grid())
    assert frf.state_space is None
    fitted = as_state_space(frf)
    assert fitted.state_space is fitted
    assert for_simulation(frf) is frf and for_simulation(model) is model
    with pytest.raises(ValueError, match="band"):
        frf.receptance(np.array([2 * np.pi * 5000.0]))


def test_milling_average_directional_factors_are_altintas_budak():
    """K0 = (N Kt / 4 pi) [alpha], alpha of Altintas and Budak (1995) / Altintas (2000) eq. 3.xx."""
    Kt, Kr, N = 700e6, 0.3, 3

    def alpha(st, ex):
        def a(p):
            return 0.5 * np.array([
                [np.cos(2 * p) - 2 * Kr * p + Kr * np.sin(2 * p), -np.sin(2 * p) - 2 * p + Kr * np.cos(2 * p)],
                [-np.sin(2 * p) + 2 * p + Kr * np.cos(2 * p), -np.cos(2 * p) - 2 * Kr * p - Kr * np.sin(2 * p)]])
        return a(ex) - a(st)

    for mode, ae in (("up", 4e-3), ("down", 4e-3), ("down", 20e-3), ("up", 13e-3)):
        p = MillingProcess(N, 20e-3, ae, mode, Kt, Kr)
        st, ex = p.entry_exit_rad
        assert np.allclose(p.mean_directional(), N * Kt / (4 * np.pi) * alpha(st, ex), rtol=1e-12, atol=1e-3)


def test_step_averages_and_cutting_tables_are_consistent_with_the_mean():
    p = MillingProcess(3, 16e-3, 5e-3, "down", 800e6, 0.35, feed_direction_rad=0.4)
    steps, depth = 360, 2e-3
    K = p.directional_steps(steps, depth)
    assert np.allclose(K.mean(axis=0), depth * p.mean_directional(), rtol=1e-10, atol=1e-6)
    tab = p.cutting_tables(steps, depth)
    lin = depth * np.einsum("ks,ksi,ksj->kij", tab.w, tab.force, tab.e)  # point values of K(t)
    assert np.allclose(lin.mean(axis=0), depth * p.mean_directional(), rtol=2e-2, atol=1e3)
    # a helix spreads the cut but keeps the average
    ph = MillingProcess(3, 16e-3, 5e-3, "down", 800e6, 0.35, helix_rad=np.deg2rad(30))
    Kh = ph.directional_steps(steps, depth)
    assert np.allclose(Kh.mean(axis=0), depth * ph.mean_directional(), rtol=1e-8, atol=1e-3)
    assert np.abs(Kh).max() < np.abs(ph.directional_steps(steps, 1e-9) / 1e-9 * depth).max()


def test_antiderivative_matches_quadrature():
    Kr = 0.4
    phi = np.linspace(0.3, 2.1, 20001)
    e = np.stack([np.sin(phi), np.cos(phi)], -1)
    f = np.stack([-np.cos(phi) - Kr * np.sin(phi), np.sin(phi) - Kr * np.cos(phi)], -1)
    M = np.einsum("ki,kj->kij", f, e)
    quad = np.trapezoid(M, phi, axis=0)
    I = _antiderivative(np.array([0.3, 2.1]), Kr)
    assert np.allclose(I[1] - I[0], quad, atol=1e-8)


def test_turning_force_model():
    p = TurningProcess(2000e6, np.deg2rad(70.0), np.deg2rad(30.0))
    f, g = p.feed_vector, p.force_vector
    assert np.degrees(np.arccos(f @ g)) == pytest.approx(70.0)
    assert np.allclose(p.mean_directional(), -2000e6 * np.outer(g, f))
    assert p.method_for("auto") == "oriented_frf"
    with pytest.raises(ValueError, match="does not apply"):
        p.method_for("zero_order")
    mill = MillingProcess(2, 20e-3, 1e-3, "down", 6e8, 1 / 3)
    assert mill.method_for("auto") == "semi_discretization"  # 5 %: interrupted cut
    # zero order only where the directional matrix is constant: a full slot with 4, 6, 8 teeth
    for teeth, ae, method in ((2, 10e-3, "semi_discretization"), (2, 20e-3, "semi_discretization"),
                              (3, 20e-3, "semi_discretization"), (8, 10e-3, "semi_discretization"),
                              (4, 20e-3, "zero_order"), (6, 20e-3, "zero_order"), (8, 20e-3, "zero_order")):
        assert MillingProcess(teeth, 20e-3, ae, "down", 6e8, 1 / 3).method_for("auto") == method, (teeth, ae)
