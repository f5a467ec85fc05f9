"""Figures are returned as matplotlib Figure objects (no pyplot)."""

import sys

import numpy as np
from matplotlib.figure import Figure

from spindlesim.chatter import MillingProcess, Mode, ToolPointModel, simulate, stability_lobes
from spindlesim.chatter import plots


def test_all_figures():
    tool = ToolPointModel.from_modes([Mode("x", 922.0, 0.011, 1.34e6), Mode("y", 1000.0, 0.02, 2e6)])
    p = MillingProcess(2, 20e-3, 1e-3, "down", 6e8, 1 / 3)
    speeds = np.linspace(15000, 20000, 6)
    sd = stability_lobes(p, tool, speeds, "semi_discretization", n_depths=8, steps=30, stability_map=True)
    zo = stability_lobes(p, tool, speeds, "zero_order")
    sim = simulate(p, tool, 18000, 1e-3, tooth_periods=40)
    figs = [plots.lobe_diagram_figure(sd, simulations=[sim]), plots.lobe_diagram_figure(zo),
            plots.stability_map_figure(sd), plots.frf_figure(tool), plots.frf_figure(tool.frf(), terms=("xx",)),
            plots.simulation_figure(sim)]
    for f in figs:
        assert isinstance(f, Figure)
        f.canvas.draw()  # renders without pyplot (Agg canvas of the Figure itself)
    assert "matplotlib.pyplot" not in sys.modules or not hasattr(plots, "plt")


def test_simulation_title_states_what_the_verdict_rests_on():
    """A cut whose Poincare distances have not decayed is chatter even when the fitted growth per tooth
    period is just below one; the title used to read "chatter (growth per period 0.9998)", which
    contradicts itself.  It now gives the criterion's numbers: the decay ratio and the growth."""
    from dataclasses import replace

    tool = ToolPointModel.from_modes([Mode("x", 922.0, 0.011, 1.34e6)])
    sim = simulate(MillingProcess(2, 20e-3, 20e-3, "down", 6e8, 1 / 3), tool, 10000, 1e-4, tooth_periods=60)
    cases = [(replace(sim, stable=False, growth_per_period=0.9998, decay_ratio=0.85, chatter_frequency_hz=930.0),
              ("CHATTER", "not decaying", "0.85", "0.9998")),
             (replace(sim, stable=False, growth_per_period=0.9995, decay_ratio=0.02, chatter_frequency_hz=930.0),
              ("CHATTER", "does not decay", "0.9995", "< 0.999")),
             (replace(sim, stable=True, growth_per_period=0.95, decay_ratio=0.003), ("STABLE", "0.9500", "< 0.999")),
             (replace(sim, stable=True, growth_per_period=1.2, decay_ratio=1e-8), ("STABLE", "died out"))]
    for s, words in cases:
        title = plots.simulation_figure(s)._suptitle.get_text()
        for w in words:
            assert w in title, (w, title)
    assert sim.verdict.startswith("stable") == sim.stable


# Lobe diagrams and tool-point FRFs read at a glance (issue 23, section 5)

def _small_case():
    tool = ToolPointModel.from_modes([Mode("x", 922.0, 0.011, 1.34e6), Mode("y", 1000.0, 0.02, 2e6)])
    p = MillingProcess(2, 20e-3, 1e-3, "down", 6e8, 1 / 3)
    return tool, p


def test_lobe_diagram_has_a_chatter_frequency_panel_and_legends_for_lobes_and_simulations():
    from dataclasses import replace

    tool, p = _small_case()
    zo = stability_lobes(p, tool, np.linspace(15000, 20000, 41), "zero_order")
    sim = simulate(p, tool, 18000, 1e-3, tooth_periods=40)
    fig = plots.lobe_diagram_figure(zo, simulations=[sim, replace(sim, stable=not sim.stable, speed_rpm=16000.0)])
    ax, ax_f = fig.axes[:2]
    assert ax_f.get_ylabel().replace("\n", " ") == "chatter frequency [Hz]"
    assert ax_f.get_xlabel() == "spindle speed [rpm]" and ax.get_shared_x_axes().joined(ax, ax_f)
    at_limit = next(ln for ln in ax_f.get_lines() if ln.get_gid() == "at-limit")
    np.testing.assert_array_equal(at_limit.get_ydata(), zo.chatter_frequency_hz)
    assert len([ln for ln in ax_f.get_lines() if ln.get_color() == "0.6"]) == len(zo.lobes)  # each lobe's too
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert {"each lobe", "simulation: stable", "simulation: chatter"} <= set(labels), labels


def test_a_limit_between_gaps_is_drawn_as_a_point():
    from dataclasses import replace

    tool, p = _small_case()
    zo = stability_lobes(p, tool, np.linspace(15000, 20000, 11), "zero_order")
    lim = zo.limit_depth_m.copy()
    lim[[3, 5]] = np.nan  # speed 4 alone between two speeds without a limit
    fig = plots.lobe_diagram_figure(replace(zo, limit_depth_m=lim))
    dots = [ln for ln in fig.axes[0].get_lines() if ln.get_gid() == "isolated"]
    assert len(dots) == 1 and list(dots[0].get_xdata()) == [zo.speed_rpm[4]]
    assert list(dots[0].get_ydata()) == [1e3 * lim[4]]


def test_tool_point_frf_axis_ends_above_the_modes_and_xx_yy_differ_in_style():
    tool, _ = _small_case()
    wide = tool.frf(np.linspace(1.0, 37500.0, 7500))  # a grid far past the modes
    fig = plots.frf_figure(wide, terms=("xx", "yy", "xy"))
    a_re = fig.axes[0]
    assert 1000.0 < a_re.get_xlim()[1] <= 1.3 * 1000.0 * 1.01  # the 1000 Hz mode, not 37.5 kHz
    styles = {ln.get_label(): ln.get_linestyle() for ln in a_re.get_lines()}
    assert styles["xx"] == "-" and styles["yy"] == "--"  # xy of this uncoupled tool is zero: not drawn
