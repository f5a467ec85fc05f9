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
