"""DTRB figures (matplotlib object API, no pyplot): polar load distribution, stiffness sweeps.

Plots only draw results; nothing here computes physics.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Sequence

import numpy as np

from .results import DtrbState, DtrbSweep

if TYPE_CHECKING:
    from matplotlib.figure import Figure

ROW_STYLE = (("tab:blue", "row 1 (Z < 0)"), ("tab:red", "row 2 (Z > 0)"))


def _figure(w: float, h: float) -> Figure:
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(w, h), layout="constrained")
    FigureCanvasAgg(fig)
    return fig


def plot_load_distribution(states: Sequence[tuple[str, DtrbState]]) -> Figure:
    """Cup load Q_o of every roller against its azimuth, one polar panel per state (seed 001 Figs. 9, 11);
    each title counts the rollers the cone (inner ring) loads in each row: at speed an unloaded roller
    still presses on the cup with its centrifugal force, so the cup curve is closed even where it is not
    loaded.  The radial tick labels sit at the azimuth with the smallest loads."""
    from matplotlib.ticker import MaxNLocator

    n = max(1, len(states))
    cols = min(3, n)
    rows = (n + cols - 1) // cols
    fig = _figure(4.2 * cols, 4.3 * rows)
    for i, (title, st) in enumerate(states):
        ax = fig.add_subplot(rows, cols, i + 1, projection="polar")
        for row, (color, label) in enumerate(ROW_STYLE):
            psi = np.append(st.psi_rad[row], st.psi_rad[row][0])
            q = np.append(st.outer_load_N[row], st.outer_load_N[row][0])
            ax.plot(psi, q, "-o", color=color, ms=3, lw=1.2, label=label)
        loaded = st.loaded_rollers()
        per_row = [np.size(st.outer_load_N[r]) for r in range(2)]
        ax.set_title(f"{title}\nrollers the cone loads: row 1 {loaded[0]} of {per_row[0]}, "
                     f"row 2 {loaded[1]} of {per_row[1]}", fontsize=9)  # the rest press on the cup at speed only
        ax.set_rlabel_position(quiet_azimuth_deg(st))
        ax.yaxis.set_major_locator(MaxNLocator(4))
        ax.tick_params(labelsize=7)
        if i == 0:
            ax.legend(loc="lower left", bbox_to_anchor=(-0.15, -0.15), fontsize=7)
    fig.suptitle("Roller load Q_o [N] on the cup against azimuth psi (X at 0 deg)", fontsize=10)
    return fig


def quiet_azimuth_deg(st: DtrbState) -> float:
    """The azimuth [deg] where the larger of the two rows' loads is smallest, among the oblique ones (a
    horizontal radius runs its labels together): the radial tick labels go there, off the curves."""
    grid = np.linspace(0.0, 2 * np.pi, 72, endpoint=False)
    grid = grid[np.abs(np.sin(grid)) >= 0.6]
    top = np.zeros_like(grid)
    for row in range(2):
        psi, q = np.asarray(st.psi_rad[row], float), np.asarray(st.outer_load_N[row], float)
        order = np.argsort(np.mod(psi, 2 * np.pi))
        top = np.maximum(top, np.interp(grid, np.mod(psi, 2 * np.pi)[order], q[order], period=2 * np.pi))
    return float(np.degrees(grid[int(np.argmin(top))]))


def plot_stiffness_sweep(sweep: DtrbSweep, components: Sequence[tuple[int, int, str]], x_scale: float,
                         x_label: str, title: str) -> Figure:
    """Direct stiffness terms over the swept parameter, with the number of loaded rollers per row."""
    fig = _figure(5.0 * len(components), 4.6)
    x = sweep.values * x_scale
    for i, (a, b, name) in enumerate(components):
        ax = fig.add_subplot(1, len(components), i + 1)
        ax.plot(x, sweep.stiffness[:, a, b] / 1e6, "k-", marker="o", ms=2.5, lw=1.4, label=f"{name} (each point solved)")
        ax.set_xlabel(x_label)
        ax.set_ylabel(f"{name} [N/um]")
        ax.grid(True, alpha=0.3)
        tw = ax.twinx()
        for row, (color, label) in enumerate(ROW_STYLE):
            tw.step(x, sweep.loaded_rollers[:, row], where="mid", color=color, lw=0.9, alpha=0.7,
                    label=f"loaded rollers, {label}")
        tw.set_ylabel("loaded rollers")
        tw.set_ylim(0, 1.1 * max(1, sweep.loaded_rollers.max()))
        partial = (sweep.loaded_rollers < sweep.loaded_rollers.max()).any(axis=1)
        if partial.any():
            ax.axvspan(x[partial].min(), x[partial].max(), color="0.85", alpha=0.5, lw=0,
                       label="unloaded rollers present")
        h1, l1 = ax.get_legend_handles_labels()
        h2, l2 = tw.get_legend_handles_labels()
        # under the axes, never over the curves
        ax.legend(h1 + h2, l1 + l2, fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.16), ncols=2,
                  frameon=False)
    fig.suptitle(title, fontsize=10)
    return fig
