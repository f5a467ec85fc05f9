"""Figures of the chatter results (matplotlib Figure API, no pyplot state, no files written).

Each function returns a :class:`matplotlib.figure.Figure`; saving is the caller's business.
Plots only draw what the results hold; they compute no physics (the FRF figure evaluates a
state-space model on its own frequency grid).
"""

from __future__ import annotations

import textwrap
from typing import TYPE_CHECKING, Sequence

import numpy as np

from .frf import DIRECTIONS, ToolPointFrf
from .pockets import Pocket
from .process import METHOD_TITLES
from .results import LobeDiagram, SimulationResult
from .tool import ToolPoint

__all__ = ["lobe_diagram_figure", "frf_figure", "stability_map_figure", "simulation_figure"]

if TYPE_CHECKING:
    from matplotlib.figure import Figure

_KIND_STYLE = {"hopf": ("C0", "-"), "flip": ("C3", "-"), "fold": ("C2", "-"), "": ("C0", "-")}


def lobe_diagram_figure(diagram: LobeDiagram, title: str | None = None, show_lobes: bool = True,
                        simulations: Sequence[SimulationResult] = (), depth_max_mm: float | None = None,
                        recommendation: Pocket | None = None) -> Figure:
    """Limit depth [mm] against speed [rpm]; stable region shaded, lobe numbers at each lobe's minimum;
    below it the chatter frequency at the limit (points; each lobe's as thin lines), as CutPro and MetalMax show.

    Flip (period-doubling) parts of a semi-discretization boundary are drawn in red; speeds stable up
    to the depth cap are marked at the cap; the recommended pocket is drawn as its speed interval at
    its depth with the recommended speed.  Simulated points: o stable, x chatter (in the legend).  A
    limit found at one speed between speeds without one is drawn as a point.
    """
    fig = _figure(9.0, 7.0, layout=None)
    ax, ax_f = fig.subplots(2, 1, sharex=True, height_ratios=[3, 1.3],
                            gridspec_kw=_margins(fig, 1.0, 0.25, 0.75, 0.6, 0.2, 0.0, rows=2, cols=1))
    n = diagram.speed_rpm
    lim = 1e3 * diagram.limit_depth_m
    capped = np.asarray(diagram.capped, bool) & ~np.isfinite(lim)
    cap_mm = 1e3 * diagram.depth_cap_m if np.isfinite(diagram.depth_cap_m) else np.nan
    tops = [np.nanmax(lim) if np.any(np.isfinite(lim)) else 1.0] + ([cap_mm] if capped.any() else [])
    top = depth_max_mm or 1.12 * max(tops)
    ax.fill_between(n, 0.0, np.where(np.isfinite(lim), lim, top), color="C2", alpha=0.18, lw=0,
                    label="stable")
    if show_lobes and diagram.method != "semi_discretization":
        for k, c in enumerate(diagram.lobes):
            ax.plot(c.speed_rpm, 1e3 * c.limit_depth_m, color="0.6", lw=0.7, label=None if k else "each lobe")
            ax_f.plot(c.speed_rpm, c.chatter_frequency_hz, color="0.6", lw=0.7)
    ax.plot(n, lim, color="C0", lw=1.8, label="limit depth")
    _isolated_points(ax, n, lim)
    kinds = diagram.boundary_kind if len(diagram.boundary_kind) == len(n) else np.full(len(n), "hopf")
    for kd in ("flip", "fold"):
        if np.any(kinds == kd):
            mark = (kinds == kd) | np.r_[kinds[1:] == kd, False] | np.r_[False, kinds[:-1] == kd]
            ax.plot(n, np.where(mark, lim, np.nan), color=_KIND_STYLE[kd][0], lw=1.8,
                    label=f"limit depth ({'period doubling' if kd == 'flip' else kd})")
    if capped.any():
        ax.plot(n[capped], np.full(capped.sum(), cap_mm), "^", color="C2", ms=4,
                label=f"stable up to the depth cap {cap_mm:.3g} mm")
    if recommendation is not None:
        r = recommendation
        ax.plot([r.speed_min_rpm, r.speed_max_rpm], [1e3 * r.depth_m] * 2, color="k", lw=1.2)
        ax.plot([r.speed_rpm], [1e3 * r.depth_m], "*", color="k", ms=11,
                label=f"recommended {r.speed_rpm:,.0f} +- {r.tolerance_rpm:,.0f} rpm, {1e3 * r.depth_m:.3g} mm")
    placed: list[float] = []
    span = n[-1] - n[0] if len(n) > 1 else 1.0
    for c in sorted(diagram.lobes, key=lambda c: c.lobe):
        d = 1e3 * c.limit_depth_m
        if np.all(np.isnan(d)):
            continue
        i = int(np.nanargmin(d))
        interior = 0 < i < len(d) - 1 or len(d) == 1
        if d[i] <= top and interior and all(abs(c.speed_rpm[i] - x) > 0.03 * span for x in placed):
            placed.append(c.speed_rpm[i])
            ax.annotate(str(c.lobe), (c.speed_rpm[i], d[i]), textcoords="offset points", xytext=(0, -11),
                        ha="center", fontsize="x-small", color="C3" if c.kind == "flip" else "k")
    for stable in (True, False):
        sims = [s for s in simulations if bool(s.stable) == stable]
        if sims:
            ax.plot([s.speed_rpm for s in sims], [1e3 * s.depth_m for s in sims], "o" if stable else "x",
                    color="k" if stable else "C3", mfc="none", ms=7, ls="none",
                    label=f"simulation: {'stable' if stable else 'chatter'}")
    fc = np.where(np.isfinite(lim), diagram.chatter_frequency_hz, np.nan)
    ax_f.plot(n, fc, ".", color="C0", ms=4, gid="at-limit")  # points: the limit jumps between modes
    if np.isfinite(fc).any():  # the frequencies at the limit; other lobes' frequencies only where they fall in it
        lo, hi = float(np.nanmin(fc)), float(np.nanmax(fc))
        pad = 0.15 * max(hi - lo, 0.05 * hi)
        ax_f.set_ylim(lo - pad, hi + pad)
    ax_f.set_ylabel("chatter\nfrequency [Hz]")
    ax_f.grid(True, alpha=0.3)
    ax_f.set_xlabel("spindle speed [rpm]")
    ax.set_xlim(n[0], n[-1])
    ax.set_ylim(0.0, top)
    ax.set_ylabel("limit depth of cut [mm]")
    used = list(dict.fromkeys(str(m) for m in diagram.method_per_speed)) or [diagram.method]
    ax.set_title(title or f"{diagram.process}\n{METHOD_TITLES.get(used[0], used[0]) if len(used) == 1 else 'mixed: ' + ', '.join(u.replace('_', ' ') for u in used)}"
                 + (" (FRF at every speed)" if diagram.frf_at_each_speed else ""), fontsize="medium")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="upper left", fontsize="small")
    return fig


def _isolated_points(ax, x: np.ndarray, y: np.ndarray) -> None:
    """Finite values without a finite neighbour (a line through them draws nothing) as points."""
    ok = np.isfinite(y)
    alone = ok & ~np.r_[False, ok[:-1]] & ~np.r_[ok[1:], False]
    if alone.any():
        ax.plot(x[alone], y[alone], ".", color="C0", ms=5, gid="isolated")


def frf_figure(tool: ToolPoint, terms: Sequence[str] = ("xx", "yy"),
               title: str | None = None) -> Figure:
    """Real and imaginary parts (left) and magnitude and phase (right) of the chosen terms [m/N -> um/N];
    xx solid, yy dashed, cross terms dotted (equal xx and yy stay readable); the frequency axis ends 30 %
    above the highest peak of a direct term that reaches a tenth of the largest one (the modes that can
    chatter), not at the end of the FRF's grid."""
    frf = tool.frf()
    fig = _figure(10.0, 6.0, layout=None)
    (a_re, a_mag), (a_im, a_ph) = fig.subplots(2, 2, sharex=True,
                                               gridspec_kw=_margins(fig, 0.9, 0.2, 0.5, 0.6, 0.25, 0.95, 2, 2))
    end = modes_of_interest_hz(frf)
    shown = frf.frequency_hz <= end  # drawn up to the axis' end only, so the magnitude axis fits what is seen
    f = frf.frequency_hz[shown]
    styles = {"xx": ("C0", "-", 1.6), "yy": ("C1", "--", 1.2)}
    for t in terms:
        i, j = DIRECTIONS.index(t[0]), DIRECTIONS.index(t[1])
        h = 1e6 * frf.H[shown, i, j]
        if not np.any(h):
            continue
        color, ls, lw = styles.get(t, ("C2", ":", 1.2))
        style = dict(color=color, ls=ls, lw=lw, label=t)
        a_re.plot(f, h.real, **style)
        a_im.plot(f, h.imag, **style)
        a_mag.semilogy(f, np.abs(h), **style)
        a_ph.plot(f, np.rad2deg(np.angle(h)), **style)
    a_re.set_xlim(f[0], end)
    a_re.set_ylabel("real [um/N]")
    a_im.set_ylabel("imaginary [um/N]")
    a_mag.set_ylabel("magnitude [um/N]")
    a_ph.set_ylabel("phase [deg] (wrapped)")
    a_ph.set_ylim(-180, 180)
    a_ph.set_yticks([-180, -90, 0, 90, 180])
    for a in (a_im, a_ph):
        a.set_xlabel("frequency [Hz]")
    for a in (a_re, a_im, a_mag, a_ph):
        a.grid(True, alpha=0.3)
    a_re.legend(fontsize="small")
    fig.suptitle(title or f"tool-point FRF ({frf.source or 'unnamed'})", fontsize="medium")
    return fig


def modes_of_interest_hz(frf: ToolPointFrf) -> float:
    """The end of an FRF figure's frequency axis: 1.3 x the highest local peak of |H_xx| or |H_yy| that
    reaches a tenth of the largest, at most the grid's end."""
    f = frf.frequency_hz
    mag = np.abs(np.stack([frf.H[:, k, k] for k in range(frf.H.shape[1])], axis=1)).max(axis=1)
    if len(f) < 3 or not np.any(mag > 0):
        return float(f[-1])
    peak = np.r_[False, (mag[1:-1] >= mag[:-2]) & (mag[1:-1] > mag[2:]), False]
    big = peak & (mag >= 0.1 * mag.max())
    return float(min(f[-1], 1.3 * f[big].max())) if big.any() else float(f[-1])


def stability_map_figure(diagram: LobeDiagram, title: str | None = None) -> Figure:
    """The stability margin 1 - rho (rho: spectral radius of the monodromy matrix) over speed x depth on a log
    colour scale where stable, red where unstable, hatched grey above the first crossing (not evaluated there); the
    rho = 1 contour and the boundary.  (On a diverging scale centred on rho = 1 the lightly damped modes of a rotor
    keep rho within 1e-3 of 1 everywhere and the map came out white.)"""
    from matplotlib.colors import ListedColormap, LogNorm

    smap = diagram.stability_map
    if smap is None:
        raise ValueError(f"the {diagram.method} diagram has no stability map (semi-discretization only)")
    fig = _figure(9.0, 5.0)
    ax = fig.add_subplot()
    d_mm = 1e3 * smap.depth_m
    rho = np.asarray(smap.spectral_radius, float).T  # NaN: not evaluated (above the first crossing)
    ax.set_facecolor("0.88")  # what is not drawn: not evaluated
    ax.fill_between([smap.speed_rpm[0], smap.speed_rpm[-1]], 0, d_mm[-1], facecolor="none", edgecolor="0.7",
                    hatch="//", lw=0, label="not evaluated (above the first crossing)", zorder=0)
    margin = np.ma.masked_where(~(rho < 1.0), 1.0 - np.where(np.isfinite(rho), rho, 0.0))
    floor = max(float(margin.min()) if margin.count() else 1e-6, 1e-6)
    mesh = ax.pcolormesh(smap.speed_rpm, d_mm, margin, shading="nearest", cmap="viridis",
                         norm=LogNorm(vmin=floor, vmax=max(1.0, 10 * floor)), zorder=1)
    fig.colorbar(mesh, ax=ax).set_label("stability margin 1 - rho (log)")
    unstable = np.ma.masked_where(~(rho >= 1.0), np.ones_like(rho))
    ax.pcolormesh(smap.speed_rpm, d_mm, unstable, shading="nearest", cmap=ListedColormap(["tab:red"]), zorder=1)
    ax.fill_between([], [], [], color="tab:red", label="unstable (rho >= 1)")
    if len(smap.speed_rpm) > 1 and len(d_mm) > 1 and np.all(np.isfinite(rho)) and np.any(rho >= 1.0):
        ax.contour(smap.speed_rpm, d_mm, rho, levels=[1.0], colors="k", linewidths=0.8)
    ax.plot(diagram.speed_rpm, 1e3 * diagram.limit_depth_m, "k.", ms=3, label="first crossing (refined)", zorder=2)
    ax.set_xlabel("spindle speed [rpm]")
    ax.set_ylabel("depth of cut [mm]")
    ax.set_ylim(0.0, d_mm[-1])
    ax.set_xlim(smap.speed_rpm[0], smap.speed_rpm[-1])
    ax.set_title(title or f"{diagram.process}\nsemi-discretization, order {smap.order}", fontsize="medium")
    ax.legend(loc="upper left", fontsize="small")
    return fig


def simulation_figure(sim: SimulationResult, title: str | None = None, periods_shown: int = 30) -> Figure:
    """Time history, spectrum (tooth-passing harmonics dotted, chatter frequency marked) and Poincare section."""
    fig = _figure(11.0, 8.2)
    active_dirs = [i for i in range(len(DIRECTIONS)) if np.any(sim.displacement_m[:, i])]
    gs = fig.add_gridspec(1 + max(1, len(active_dirs)), 2, height_ratios=[1.0] * max(1, len(active_dirs)) + [1.6])
    t_ms = 1e3 * sim.time_s
    # x and y each in a panel of its own (on one axis the one drawn last hid the other)
    ax_t = None
    for row, i in enumerate(active_dirs or [0]):
        ax_t = fig.add_subplot(gs[row, :], sharex=ax_t)
        ax_t.plot(t_ms, 1e6 * sim.displacement_m[:, i], lw=0.6, color=f"C{i}")
        ax_t.set_ylabel(f"{DIRECTIONS[i]} [um]")
        ax_t.grid(True, alpha=0.3)
    ax_t.set_xlabel("time [ms]")
    ax_f = fig.add_subplot(gs[-1, 0])
    ax_p = fig.add_subplot(gs[-1, 1])
    ax_f.semilogy(sim.spectrum_frequency_hz, 1e6 * np.maximum(sim.spectrum_amplitude_m, 1e-30), lw=0.7)
    fmax = sim.spectrum_frequency_hz[-1]
    if np.isfinite(sim.chatter_frequency_hz):
        ax_f.axvline(sim.chatter_frequency_hz, color="C3", lw=0.8, label=f"chatter {sim.chatter_frequency_hz:.1f} Hz")
        fmax = min(fmax, 4 * sim.chatter_frequency_hz)
    else:
        fmax = min(fmax, 12 * sim.tooth_frequency_hz)
    for k in range(1, int(fmax / sim.tooth_frequency_hz) + 1):
        ax_f.axvline(k * sim.tooth_frequency_hz, color="0.6", lw=0.5, ls=":")
    ax_f.set_xlim(0, fmax)
    amp = sim.spectrum_amplitude_m[sim.spectrum_frequency_hz <= fmax]
    if np.any(amp > 0):
        ax_f.set_ylim(1e6 * amp.max() * 1e-5, 1e6 * amp.max() * 3)
    ax_f.set_xlabel("frequency [Hz]")
    ax_f.set_ylabel("amplitude [um]")
    if np.isfinite(sim.chatter_frequency_hz):
        ax_f.legend(fontsize="small", loc="upper right")
    ax_f.grid(True, alpha=0.3)
    m = sim.steps_per_period
    tail = sim.displacement_m[-periods_shown * m:]
    half = len(sim.poincare_m) // 2
    active = [i for i in range(2) if np.any(sim.displacement_m[:, i])]
    if len(active) == 1:  # one flexible direction: phase plane of that direction
        i = active[0]
        dt = sim.time_s[1] - sim.time_s[0]
        px, py = 1e6 * tail[:, i], 1e3 * np.gradient(tail[:, i], dt)
        qx, qy = 1e6 * sim.poincare_m[half:, i], 1e3 * sim.poincare_velocity_m_s[half:, i]
        labels = (f"{DIRECTIONS[i]} [um]", f"d{DIRECTIONS[i]}/dt [mm/s]")
    else:
        px, py = 1e6 * tail[:, 0], 1e6 * tail[:, 1]
        qx, qy = 1e6 * sim.poincare_m[half:, 0], 1e6 * sim.poincare_m[half:, 1]
        labels = ("x [um]", "y [um]")
    ax_p.plot(px, py, color="0.7", lw=0.5, label="trajectory")
    ax_p.plot(qx, qy, ".", color="C3", ms=4, label="once per tooth period")
    ax_p.set_xlabel(labels[0])
    ax_p.set_ylabel(labels[1])
    ax_p.legend(fontsize="small", loc="upper right")
    ax_p.grid(True, alpha=0.3)
    word, _, basis = sim.verdict.partition(": ")
    fig.suptitle(title or f"{sim.speed_rpm:.0f} rpm, depth {1e3 * sim.depth_m:.3g} mm: {word.upper()}\n"
                 + textwrap.fill(basis, 110), fontsize="medium")
    return fig


def _figure(width_in: float, height_in: float, layout: str | None = "constrained") -> Figure:
    """A constrained-layout figure (``layout=None``: none, the panels placed by :func:`_margins`); matplotlib is
    imported here, not when the module is."""
    from matplotlib.figure import Figure

    return Figure(figsize=(width_in, height_in), layout=layout)


def _margins(fig: Figure, left_in: float, right_in: float, top_in: float, bottom_in: float, hgap_in: float,
             wgap_in: float, rows: int, cols: int) -> dict:
    """The subplots' grid with margins and gaps in inches, for the figures drawn after every run (the
    constrained layout engine measures every tick label twice per save: half of these figures' time)."""
    w, h = fig.get_size_inches()
    panel_h = (h - top_in - bottom_in - (rows - 1) * hgap_in) / rows
    panel_w = (w - left_in - right_in - (cols - 1) * wgap_in) / cols
    return dict(left=left_in / w, right=1 - right_in / w, top=1 - top_in / h, bottom=bottom_in / h,
                hspace=hgap_in / panel_h, wspace=wgap_in / panel_w)
