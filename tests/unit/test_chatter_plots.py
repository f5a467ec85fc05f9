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
    sd = stability_lobes(p, tool, speeds, "semi_discretization", n_depths=8, steps=30)
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
