"""Figures of the tool library: every tool's tip receptance, and every tool's lobes (one colour per tool)."""

from __future__ import annotations

import numpy as np

from .figures import new_figure


def receptance_figure(library, title: str = ""):
    """|H_xx| (solid) and |H_yy| (dashed) at each tool's tip, and Re H_xx (the part that sets the chatter limit)."""
    fig = new_figure(10.0, 6.5)
    a_mag, a_re = fig.subplots(2, 1, sharex=True)
    f = library.frequency_hz
    for k, t in enumerate(library.tools):
        c = f"C{k % 10}"
        a_mag.semilogy(f, 1e6 * np.abs(t.receptance_m_N[:, 0, 0]), color=c, lw=1.4,
                       label=f"{t.name} ({1e3 * t.nose_to_tip_m:.0f} mm, {t.mass_kg:.2f} kg)")
        a_mag.semilogy(f, 1e6 * np.abs(t.receptance_m_N[:, 1, 1]), color=c, lw=0.9, ls="--")
        a_re.plot(f, 1e6 * t.receptance_m_N[:, 0, 0].real, color=c, lw=1.2)
    a_mag.set_ylabel("|H| at the tip [um/N]\n(xx solid, yy dashed)")
    a_re.set_ylabel("Re H_xx [um/N]")
    a_re.set_xlabel("frequency [Hz]")
    for a in (a_mag, a_re):
        a.grid(True, alpha=0.3)
    a_mag.legend(fontsize="small", loc="upper left", ncol=2 if len(library.tools) > 5 else 1)
    fig.suptitle(f"{title}\ntool library at {library.speed_rpm:g} rpm (receptance coupling at node "
                 f"{library.nose_node})" if title else f"tool library at {library.speed_rpm:g} rpm", fontsize="medium")
    return fig


def lobes_figure(lobes, title: str = ""):
    """Each tool's limit depth over speed, its minimum marked (x) and its recommended speed (o)."""
    fig = new_figure(10.0, 5.5)
    ax = fig.subplots()
    for k, lb in enumerate(lobes):
        c = f"C{k % 10}"
        ax.plot(lb.speed_rpm, 1e3 * lb.limit_depth_m, color=c, lw=1.3,
                label=f"{lb.name}: min {1e3 * lb.min_depth_m:.3g} mm")
        ax.plot([lb.min_speed_rpm], [1e3 * lb.min_depth_m], "x", color=c, ms=7)
        if np.isfinite(lb.recommended_speed_rpm):
            ax.plot([lb.recommended_speed_rpm], [1e3 * lb.recommended_depth_m], "o", color=c, ms=6, mfc="none")
    top = max(float(np.nanmax(1e3 * lb.limit_depth_m)) for lb in lobes if np.isfinite(lb.limit_depth_m).any())
    ax.set_ylim(0.0, 1.05 * top)
    ax.set_xlabel("spindle speed [rpm]")
    ax.set_ylabel("limit depth of cut [mm]")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize="small", loc="upper left")
    ax.set_title(f"{title}\nlobes of every tool ({lobes[0].method}); x minimum, o recommended" if title else
                 f"lobes of every tool ({lobes[0].method})", fontsize="medium")
    return fig
