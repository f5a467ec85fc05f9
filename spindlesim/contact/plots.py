"""Figures of a contact result (matplotlib Figure API, no pyplot state).

Plots only draw what :class:`~spindlesim.contact.result.ContactResult` holds; they
compute no physics.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from .result import ContactResult

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["pressure_map_figure", "roller_profile_figure"]


def pressure_map_figure(result: ContactResult, title: str = "Contact pressure") -> Figure:
    """Colour map of p(x, y) [GPa] with the maximum marked; axes in mm."""
    fig = _figure(8.0, 4.0)
    ax = fig.add_subplot()
    x_mm, y_mm = 1e3 * result.x_m, 1e3 * result.y_m
    p = result.pressure_Pa / 1e9
    vmax, label = None, "pressure [GPa]"
    if result.edge_singular and p.shape[1] > 8:
        # colour scale from the interior: the end cells hold grid-dependent singular values
        vmax = 1.25 * float(p[:, 2:-2].max())
        label = "pressure [GPa]\n(scale clipped: edge values\ngrid-dependent)"
    mesh = ax.pcolormesh(y_mm, x_mm, p, shading="nearest", cmap="viridis", vmin=0.0, vmax=vmax)
    cb = fig.colorbar(mesh, ax=ax)
    cb.set_label(label)
    xm, ym = result.max_location_m
    ax.plot([1e3 * ym], [1e3 * xm], "r+", ms=10,
            label=f"max {result.max_pressure_Pa / 1e9:.3f} GPa"
            + (" (edge singularity)" if result.edge_singular else ""))
    ax.set_xlabel("y along roller [mm]")
    ax.set_ylabel("x across contact [mm]")
    load = f"{result.load_N:,.0f}" if abs(result.load_N) >= 1000 else f"{result.load_N:.4g}"  # 10,000 N, not 1e+04
    ax.set_title(f"{title}: load {load} N")
    ax.legend(loc="upper right", fontsize="small")
    return fig


def roller_profile_figure(result: ContactResult) -> Figure:
    """Centre-line pressure [GPa] and contact half-width [mm] along the roller."""
    fig = _figure(8.0, 5.5)
    ax1, ax2 = fig.subplots(2, 1, sharex=True)
    y_mm = 1e3 * result.y_m
    ax1.plot(y_mm, result.centreline_pressure_Pa / 1e9, label="x = 0")
    ax1.plot(y_mm, result.pressure_Pa.max(axis=0) / 1e9, "--", label="max over x")
    ax1.set_ylabel("pressure [GPa]")
    ax1.legend(fontsize="small")
    if result.edge_singular:
        ax1.set_title("edge values are grid-dependent (edge singularity)", fontsize="small")
    ax2.plot(y_mm, 1e3 * result.half_width_m)
    ax2.set_ylabel("half-width [mm]")
    ax2.set_xlabel("y along roller [mm]")
    ax2.set_ylim(bottom=0.0)
    for ax in (ax1, ax2):
        ax.grid(True, alpha=0.3)
    return fig


def _figure(width_in: float, height_in: float) -> Figure:
    """A constrained-layout figure; matplotlib is imported here, not when the module is."""
    from matplotlib.figure import Figure

    return Figure(figsize=(width_in, height_in), layout="constrained")
