"""Plots of fluid-film bearing results (matplotlib Figure API, no pyplot state).

- :func:`characteristics_figure`: eccentricity, attitude, friction and flows, stiffness
  and damping vs the Sommerfeld number (the content of seed 003 Figs. 1-4);
- :func:`pressure_figure`: film pressure over the unrolled bore.

Only plotting here: the data come from
:func:`spindlesim.bearings.fluidfilm.performance.characteristic_curves` and
:class:`spindlesim.bearings.fluidfilm.results.FilmResult`.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from spindlesim.bearings.fluidfilm.results import FilmResult

if TYPE_CHECKING:
    from matplotlib.figure import Figure


def _figure(w: float, h: float) -> Figure:
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(w, h), layout="constrained")
    FigureCanvasAgg(fig)
    return fig


def characteristics_figure(curves: dict, title: str = "", mark_S: float | None = None) -> Figure:
    """Four panels vs S (log axis): eps & flows, attitude & f/psi, k (on Cp), c (on Cp).

    ``mark_S`` draws a vertical line at an operating Sommerfeld number.  The legends sit under their
    panels' axis labels, off the curves (:func:`_legend_below`).
    """
    fig = _figure(11.0, 8.0)
    axs = fig.subplots(2, 2)
    S = curves["S"]
    a = axs[0, 0]
    a.semilogx(S, curves["eccentricity_ratio"], "k-", label="e / Cb")
    a.set_ylabel("eccentricity ratio e/Cb")
    a2 = a.twinx()
    a2.semilogx(S, curves["inlet_flow"], "b--", label="inlet Q/(R Cp N L)")
    a2.semilogx(S, curves["side_flow"], "b:", label="side Qs/(R Cp N L)")
    a2.set_ylabel("nondimensional flow")
    _legend_below(a, a.get_lines() + a2.get_lines(), 3)
    a.set_title("Eccentricity ratio and nondimensional oil flows (cf. seed 003 Fig. 1)", fontsize=9)
    b = axs[0, 1]
    b.semilogx(S, curves["attitude_angle_deg"], "k-")
    b.set_ylabel("attitude angle [deg]")
    b2 = b.twinx()
    b2.loglog(S, curves["friction_ratio"], "r--")
    b2.set_ylabel("f / psi", color="r")
    b.set_title("Attitude angle and friction coefficient / clearance ratio (Fig. 2)", fontsize=9)
    names = (("xx", 0, 0), ("xy", 0, 1), ("yx", 1, 0), ("yy", 1, 1))
    for ax, key, label in ((axs[1, 0], "k", "k = K Cp / W"), (axs[1, 1], "c", "c = B Cp omega / W")):
        M = curves[key]
        for nm, i, j in names:  # yx dashed: equal to xy (symmetric damping) it shows under it
            ax.semilogx(S, M[:, i, j], ls="--" if nm == "yx" else "-", label=f"{key}{nm}")
        ax.axhline(0.0, color="0.6", lw=0.5)
        ax.set_yscale("symlog", linthresh=1.0)  # k, c grow like 1/W: keep small S readable
        ax.set_ylabel(label + " (symlog)")
        _legend_below(ax, ax.get_lines()[:4], 4)
        ax.set_title(("Stiffness" if key == "k" else "Damping")
                     + " coefficients, x horizontal / y vertical (Figs. 3-4)", fontsize=9)
    for ax in axs.ravel():
        ax.set_xlabel("Sommerfeld number S = mu N D L / (psi^2 W), psi = 2 Cp / D")
        ax.grid(True, which="both", alpha=0.3)
        if mark_S is not None:
            ax.axvline(mark_S, color="m", lw=1)
    if title:
        fig.suptitle(title)
    return fig


def _legend_below(ax, lines, ncol: int) -> None:
    """One legend for ``lines`` under ``ax``'s x label (the layout engine makes room for it)."""
    ax.legend(lines, [ln.get_label() for ln in lines], loc="upper center", bbox_to_anchor=(0.5, -0.2), ncol=ncol,
              fontsize=8, frameon=False)


def pressure_figure(result: FilmResult, title: str = "") -> Figure:
    """Film pressure [MPa] over angle (from +x towards +y) and axial position."""
    fig = _figure(9.0, 4.5)
    ax = fig.subplots()
    th = np.degrees(result.node_theta_rad)
    z = result.node_z_m * 1e3
    p = result.pressure_Pa / 1e6
    # mirror the half width to show the whole bearing
    th2, z2, p2 = np.concatenate([th, th]), np.concatenate([z, -z]), np.concatenate([p, p])
    tc = ax.tricontourf(th2, z2, p2, levels=30, cmap="viridis")
    fig.colorbar(tc, ax=ax, label="pressure [MPa]")
    ax.set_xlabel("angle from +x towards +y (rotation direction) [deg]")
    ax.set_ylabel("axial position z [mm]")
    ax.set_xlim(0, 360)
    ttl = title or "Film pressure"
    ax.set_title(f"{ttl}: e/Cb = {result.eccentricity_ratio:.3f}, attitude "
                 f"{result.attitude_angle_deg:.1f} deg, p_max {p.max():.3g} MPa")
    load_deg = math.degrees(math.atan2(result.load_N[1], result.load_N[0])) % 360
    ax.axvline(load_deg, color="w", ls="--", lw=1, label=f"direction of the shaft's load on the bearing ({load_deg:.0f} deg)")
    ax.legend(loc="upper right", fontsize=8, framealpha=0.85)
    return fig
