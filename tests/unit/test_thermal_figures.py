"""Issue 35, items 3 and 5: thermal_speeds.png states the speed limit the summary states (the bisected one, not
the first speed of the list that ran away), and the inner and outer rings are told apart in the legend."""

from __future__ import annotations

import numpy as np

from spindlesim.output.thermal_plots import speeds_figure
from spindlesim.output.thermal_writer import ThermalTable


def _table(limit):
    x = np.array([4000.0, 8000.0, 12000.0, 16000.0])
    T = np.column_stack([30 + x / 500, 28 + x / 600])
    return ThermalTable(x, x, ("front", "rear"), T, T - 5, np.column_stack([500 + x / 20, 300 + 0 * x]), None, None,
                        np.full(4, np.nan), runaway_rpm=20000.0, limit_rpm=limit)


def _texts(fig):
    return [t.get_text() for ax in fig.axes for t in ax.texts]


def test_the_figure_marks_the_bisected_limit_the_summary_states():
    fig = speeds_figure(_table((18000.0, 18250.0)))
    assert any("stable up to 18000 rpm, runs away from 18250 rpm" in t for t in _texts(fig))
    assert not any("20000" in t for t in _texts(fig))
    lines = [ln.get_xdata()[0] for ax in fig.axes for ln in ax.lines  # the vertical lines
             if len(ln.get_xdata()) == 2 and ln.get_xdata()[0] == ln.get_xdata()[1]]
    assert lines and all(v == 18250.0 for v in lines)


def test_without_a_bisection_the_first_runaway_speed_is_marked():
    fig = speeds_figure(_table(None))
    assert any("thermal runaway at 20000 rpm" in t for t in _texts(fig))


def test_inner_and_outer_rings_differ_in_style_in_the_legend():
    fig = speeds_figure(_table((18000.0, 18250.0)))
    handles = {t.get_text(): h for h, t in zip(fig.axes[0].get_legend().legend_handles, fig.axes[0].get_legend().texts)}
    inner, outer = handles["front: inner ring"], handles["front: outer ring"]
    assert inner.get_linestyle() != outer.get_linestyle()
    assert inner.get_marker() != outer.get_marker() and outer.get_markerfacecolor() == "white"
