"""Sweeps over preload, load and speed, the standalone run of a section, and the figures."""

import ast
import inspect
import math

import numpy as np
import pytest
from matplotlib.figure import Figure

from spindlesim.bearings.ball import plots
from spindlesim.bearings.ball.sweeps import load_sweep, preload_sweep, run, speed_sweep

from .test_ball_section import RPM, bearing, default_section


def small_section(**changes):
    sweeps = {"preload": {"start": 0.0, "stop": 30.0, "count": 4},
              "load": {"component": "fz_N", "start": -2000.0, "stop": 2000.0, "count": 3},
              "speed_rpm": {"start": 0.0, "stop": 20000.0, "count": 5}}
    return default_section(sweeps=sweeps, **changes)


def test_run_of_a_section_and_its_figures():
    r = run(small_section())
    assert set(r.sweeps) == {"preload", "load", "speed"}
    sp = r.sweeps["speed"]
    assert sp.name == "speed_rpm" and sp.values.tolist() == [0.0, 5000.0, 10000.0, 15000.0, 20000.0]
    assert sp.stiffness.shape == (5, 5, 5) and sp.contact_angle_outer_deg.shape == (5, 2, 18)
    assert np.allclose(sp.load, [1000.0, 0.0, 0.0, 0.0, 0.0])
    pre = r.sweeps["preload"]
    assert pre.name == "preload_axial_um" and pre.values[-1] == pytest.approx(30.0)
    assert np.all(np.diff(pre.stiffness[:, 0, 0]) > 0)  # radial stiffness grows with preload
    ld = r.sweeps["load"]
    assert ld.name == "fz_N" and ld.row_axial_load_N[0, 1] > ld.row_axial_load_N[0, 0]
    assert r.state.speed_rpm == pytest.approx(12000.0)
    figs = plots.figures(r)
    assert set(figs) == {"ball_load_distribution", "ball_contact_ellipses", "ball_stiffness_vs_preload",
                         "ball_stiffness_vs_speed", "ball_contact_angles_vs_speed"}
    for name, fig in figs.items():
        assert isinstance(fig, Figure)
        title = fig._suptitle.get_text()
        assert "position preload 21 um" in title or "preload" in name, name
    assert "12000 rpm" in figs["ball_load_distribution"]._suptitle.get_text()
    assert "Fx 1000 N" in figs["ball_stiffness_vs_speed"]._suptitle.get_text()


def test_sweep_functions_directly():
    b = bearing(preload={"kind": "spring", "axial_N": 200.0})
    sw = preload_sweep(b, [100.0, 300.0], np.zeros(5), 1000 * RPM)
    assert sw.name == "preload_axial_N" and np.allclose(sw.row_axial_load_N, [[100.0, 100.0], [300.0, 300.0]])
    sw = load_sweep(b, 3, [0.0, 20.0], np.array([500.0, 0, 0, 0, 0]))
    assert sw.name == "mx_Nm" and sw.load[1, 3] == 20.0
    sw = speed_sweep(b, np.array([0.0, 10000.0]) * RPM, np.zeros(5))
    assert sw.values.tolist() == pytest.approx([0.0, 10000.0])
    fig = plots.plot_contact_angles_vs_speed(sw)
    assert "spring preload 200 N" in fig._suptitle.get_text()
    fig = plots.plot_load_distribution(b.solve(np.array([800.0, 0.0, 0.0, 0.0, 0.0]), 3000 * RPM))
    assert "Fx 800 N, 3000 rpm" in fig._suptitle.get_text()


def test_plots_use_the_object_api_only():
    tree = ast.parse(inspect.getsource(plots))
    names = {a.name for n in ast.walk(tree) if isinstance(n, (ast.Import, ast.ImportFrom)) for a in n.names}
    mods = {n.module for n in ast.walk(tree) if isinstance(n, ast.ImportFrom)}
    assert "matplotlib.pyplot" not in names | mods and "pyplot" not in names
    assert not any(m and m.startswith("spindlesim.output") for m in mods)


def test_rows_that_coincide_stay_distinguishable_and_the_angle_legend_says_mean():
    """A DB pair under a radial load: both rows carry the same, their lines lie on top of each other
    (issue 23: "ball pair rows distinguishable when they coincide", "mean over the balls" in the legend)."""
    b = bearing()
    sw = speed_sweep(b, np.array([0.0, 5000.0, 10000.0]) * RPM, np.array([1000.0, 0, 0, 0, 0]))
    np.testing.assert_allclose(sw.contact_angle_inner_deg[:, 0], sw.contact_angle_inner_deg[:, 1], rtol=1e-6)
    fig = plots.plot_contact_angles_vs_speed(sw)
    ax = fig.axes[0]
    rows = {ln.get_label(): ln for ln in ax.get_lines()}
    one, two = rows["inner, row 1"], rows["inner, row 2"]
    assert (one.get_linewidth(), one.get_marker()) != (two.get_linewidth(), two.get_marker())
    assert two.get_zorder() > one.get_zorder() and one.get_linewidth() > two.get_linewidth()  # the thin one on top
    assert "mean over the balls" in ax.get_legend().get_title().get_text()
