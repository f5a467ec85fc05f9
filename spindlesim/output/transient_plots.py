"""Figures of a rotor transient (matplotlib Figure API, no pyplot state).  No physics here.

Every title states the operating point (node, speed, applied load, oil temperature, method) and,
for a run that stopped early, why.  Lengths are drawn in the unit that suits their size (um, nm),
about their steady mean (stated), so that a 1e-5 um vibration on a 0.02 um offset is readable.

A run holds up to millions of samples; a figure has some hundred pixel columns.  Time series are
drawn decimated to the axes' width at the saved resolution (:func:`column_extremes`: the minimum and
maximum of every pixel column, in time order, at most two points a column), which draws the same
picture as every sample.  The margins are fixed in inches (no layout engine, which measures every
label twice per save).  matplotlib is imported inside the functions: the command sends
:func:`for_figures` of its result to the figure process (``output.drawing``) and never imports it.
"""

from __future__ import annotations

import dataclasses
import math
import textwrap
from typing import TYPE_CHECKING

import numpy as np

from ..analysis.transient.result import TransientResult
from ..analysis.transient.spectrum import Spectrum, amplitude_spectrum
from .figures import new_figure
from .labels import bearing_label, frequency_label, readable_keys
from .numbers import with_resolution

if TYPE_CHECKING:
    from matplotlib.figure import Figure

UM = 1e6
#: resolution of the saved PNGs (``figures.save_figure``): the pixel columns of an axes
DPI = 110
#: characteristic frequencies whose harmonics are marked on the spectrum: rolling-element passes
PASS_SUFFIXES = ("roller_pass", "ball_pass_outer")
#: the spectra show this many dB below their peak (an amplitude ratio of 1e-5)
FLOOR_DB = 100.0
_PASS_COLORS = ("tab:red", "tab:green", "tab:purple", "tab:brown")
_LENGTH_UNITS = ((1e-3, "mm"), (1e-6, "um"), (1e-9, "nm"), (1e-12, "pm"))


def _speed_text(res: TransientResult) -> str:
    sp = res.speed_rpm
    if not sp.size:
        return ""
    return f"{sp[0]:.0f} rpm" if np.ptp(sp) < 1e-9 * max(abs(sp[0]), 1.0) else f"{sp[0]:.0f}-{sp[-1]:.0f} rpm"


def _title(res: TransientResult, what: str, operating: str = "", width_in: float | None = None,
           resolution: bool = False, settling: bool = True) -> str:
    """The figure title; it says when the run stopped early, when the steady part has not settled and
    (``resolution``) when it is too short for the frequencies named.  On a figure ``width_in`` inches
    wide the lines are wrapped to fit."""
    point = ", ".join(p for p in (_speed_text(res), operating) if p)
    s = f"{what}, node {res.record_node + 1}: {point} ({res.method})"
    if not res.complete:
        s += f"\nINCOMPLETE: {res.reason}"
    st = res.settling
    if settling and st is not None and not st.settled:
        s += "\n" + st.note.replace("not settled:", "NOT SETTLED:", 1)
    if resolution and st is not None and st.resolution_note:
        note = readable_keys(st.resolution_note, res.bearing_names)
        s += "\n" + note.replace("window too short", "WINDOW TOO SHORT", 1)
    if width_in is None:
        return s
    chars = max(30, int(13 * width_in))  # about 13 characters per inch at 9 pt
    return "\n".join(textwrap.fill(line, chars) for line in s.splitlines())


def _no_data(ax, text: str) -> None:
    ax.text(0.5, 0.5, text, ha="center", va="center", transform=ax.transAxes, color="0.3", wrap=True)
    ax.set_xticks([])
    ax.set_yticks([])


def column_extremes(x: np.ndarray, y: np.ndarray, columns: int) -> tuple[np.ndarray, np.ndarray]:
    """(x, y) reduced to the smallest and largest y of each of ``columns`` runs of consecutive samples
    (in sample order, at most 2 ``columns`` points): drawn as a line over that many pixel columns it
    looks like the whole series and holds its extremes.  Short series are returned as they are."""
    x, y = np.asarray(x), np.asarray(y)
    n = y.size
    if n <= 2 * columns:
        return x, y
    k = math.ceil(n / columns)
    m = math.ceil(n / k)
    pad = m * k - n
    blocks = np.concatenate([y, np.full(pad, y[-1])]).reshape(m, k)
    base = np.arange(m) * k
    lo, hi = base + blocks.argmin(axis=1), base + blocks.argmax(axis=1)
    idx = np.column_stack([np.minimum(lo, hi), np.maximum(lo, hi)]).ravel()
    idx = np.minimum(idx, n - 1)
    idx = idx[np.r_[True, idx[1:] != idx[:-1]]]
    return x[idx], y[idx]


def pixel_columns(ax) -> int:
    """Width of ``ax`` in pixels of the saved figure."""
    return max(16, int(math.ceil(ax.get_position().width * ax.figure.get_figwidth() * DPI)))


def _fixed(fig, title: str = "", left_in: float = 0.85, right_in: float = 0.25, bottom_in: float = 0.55,
           hgap_in: float = 0.75, wgap_in: float = 0.75, title_in: float = 0.3) -> None:
    """Margins and gaps in inches (the figure's suptitle lines above ``title_in`` per panel title)."""
    w, h = fig.get_size_inches()
    axes = [a for a in fig.axes if a.get_subplotspec() is not None]
    grid = axes[0].get_subplotspec().get_gridspec()
    top_in = title_in + 0.17 * (title.count("\n") + 1 if title else 0) + 0.1
    rows, cols = grid.nrows, grid.ncols
    ph = (h - top_in - bottom_in - (rows - 1) * hgap_in) / rows
    pw = (w - left_in - right_in - (cols - 1) * wgap_in) / cols
    fig.subplots_adjust(left=left_in / w, right=1 - right_in / w, top=1 - top_in / h, bottom=bottom_in / h,
                        hspace=hgap_in / ph if rows > 1 else 0.2, wspace=wgap_in / pw if cols > 1 else 0.2)


def for_figures(res: TransientResult) -> TransientResult:
    """``res`` without what no figure draws (every rotor DOF, the bearing forces): what a figure process
    is sent."""
    outputs = tuple({k: v for k, v in o.items() if k != "force" and np.ndim(v[0]) == 2} for o in res.bearing_outputs)
    return dataclasses.replace(res, rotor_displacement=np.zeros((0, 0)), bearing_force_N=(), bearing_outputs=outputs)


def length_unit(span_m: float) -> tuple[float, str]:
    """(metres per unit, unit) in which ``span_m`` reads between 1 and 1000."""
    for scale, name in _LENGTH_UNITS:
        if span_m >= scale:
            return scale, name
    return _LENGTH_UNITS[-1]


def time_unit(t_end_s: float) -> tuple[float, str]:
    """(factor from seconds, unit) of every time axis of a figure: ms for runs under 2 s, else s."""
    return (1e3, "ms") if t_end_s < 2.0 else (1.0, "s")


def _steady(res: TransientResult) -> np.ndarray:
    return res.time_s >= res.settle_s - 1e-12


def _revolution_hz(res: TransientResult) -> float:
    f = res.frequencies_hz.get("revolution", 0.0)
    return f if f > 0 else min((v for v in res.frequencies_hz.values() if v > 0), default=0.0)


def _window(res: TransientResult, revolutions: float = 4) -> np.ndarray:
    """The last few revolutions (at least 2 % of the run, at least 20 samples)."""
    t = res.time_s
    if not t.size:
        return t > 0
    f = _revolution_hz(res)
    total = t[-1] - t[0]
    span = max(revolutions / f if f > 0 else 0.1 * total, 0.02 * total, 20 / res.sample_rate_hz)
    return t >= t[-1] - span


def _envelope(t: np.ndarray, y: np.ndarray, period_s: float):
    """(t, min, max) of y over a sliding window of one ``period_s``: the whole run as a band."""
    if t.size < 8:
        return t, y, y
    k = 4 if period_s > 0 else 1  # windows of four quarter-period bins
    width = period_s / k if period_s > 0 else (t[-1] - t[0]) / 400
    bins = int(min(max((t[-1] - t[0]) / width, 1), t.size // 2, 20000))
    edges = np.linspace(0, t.size, bins + 1).astype(int)[:-1]
    lo, hi = np.minimum.reduceat(y, edges), np.maximum.reduceat(y, edges)
    if bins >= k > 1:
        n = bins - k + 1
        lo = np.min([lo[j:j + n] for j in range(k)], axis=0)
        hi = np.max([hi[j:j + n] for j in range(k)], axis=0)
        edges = edges[k // 2:k // 2 + n]
    return t[edges], lo, hi


def _band_columns(t: np.ndarray, lo: np.ndarray, hi: np.ndarray, columns: int):
    """A min-max band reduced to ``columns`` runs of points (the least lo and greatest hi of each)."""
    n = t.size
    if n <= columns:
        return t, lo, hi
    k = math.ceil(n / columns)
    starts = np.arange(0, n, k)
    return np.append(t[starts], t[-1]), np.append(np.minimum.reduceat(lo, starts), lo[-1]), \
        np.append(np.maximum.reduceat(hi, starts), hi[-1])


def time_figure(res: TransientResult, operating: str = "") -> Figure:
    """x and y at the record node: envelope of the whole run (top), the last revolutions (bottom),
    each about its steady mean in a unit that suits the vibration."""
    from matplotlib.ticker import MaxNLocator

    fig = new_figure(10, 6.5, layout=None)
    axes = fig.subplots(2, 2)
    title = _title(res, "Response", operating, 10)
    _fixed(fig, title)
    t = res.time_s
    if not t.size:
        for ax in axes.ravel():
            _no_data(ax, "no samples")
        return fig
    ref = _steady(res) if _steady(res).sum() >= 2 else np.ones(t.size, bool)
    w = _window(res)
    n_rev = (t[w][-1] - t[w][0]) * _revolution_hz(res)
    tf, tu = time_unit(float(t[-1]))
    for k, lab in enumerate(("x", "y")):
        d = res.displacement_m[:, k]
        mean = float(np.mean(d[ref]))
        scale, unit = length_unit(float(np.ptp(d)) or 1e-12)
        top, bottom = axes[0, k], axes[1, k]
        f_rev = _revolution_hz(res)
        te, lo, hi = _band_columns(*_envelope(t * tf, (d - mean) / scale, tf / f_rev if f_rev > 0 else 0.0),
                                   pixel_columns(top))
        top.fill_between(te, lo, hi, color="tab:blue" if k == 0 else "tab:orange", lw=0.3, alpha=0.7,
                         label="min-max over one revolution" if f_rev > 0 else "min-max envelope")
        settled = res.settling is None or res.settling.settled
        top.axvline(res.settle_s * tf, color="0.4" if settled else "tab:red", ls="--", lw=0.8,
                    label=f"steady part from {res.settle_s * tf:.3g} {tu}" + (
                        "" if res.settling is None else " (settled)" if settled else " (NOT SETTLED)"))
        if not res.complete:
            top.axvline(t[-1] * tf, color="tab:red", lw=1.0, label=f"run stopped at {t[-1] * tf:.4g} {tu}")
        top.set_title(f"{lab}, whole run (mean of the steady part {mean / scale:.4g} {unit})", fontsize=9)
        top.set_xlabel(f"time [{tu}]")
        top.set_ylabel(f"{lab} - mean [{unit}]")
        top.legend(fontsize=7, loc="upper right")
        bottom.plot(*column_extremes(t[w] * tf, (d[w] - mean) / scale, pixel_columns(bottom)), lw=1.0,
                    color="tab:blue" if k == 0 else "tab:orange")
        bottom.set_title(f"{lab}, last {n_rev:.0f} revolutions" if n_rev > 0 else f"{lab}, last samples", fontsize=9)
        bottom.set_xlabel(f"time [{tu}]")
        bottom.set_ylabel(f"{lab} - mean [{unit}]")
        for ax in (top, bottom):
            ax.grid(True, alpha=0.3)
            ax.yaxis.set_major_locator(MaxNLocator(6))
    fig.suptitle(title, fontsize=9)
    return fig


def orbit_figure(res: TransientResult, operating: str = "") -> Figure:
    """Orbit of the steady part about its centre, equal axes (what exists when the run stopped early)."""
    from matplotlib.ticker import MaxNLocator

    fig = new_figure(6.5, 6.5, layout=None)
    ax = fig.subplots()
    _fixed(fig, _title(res, "Orbit, steady part", operating, 6.5), left_in=0.9, bottom_in=0.6)
    steady = _steady(res)
    note = ""
    if steady.sum() < 2:
        if res.time_s.size < 4:
            _no_data(ax, "not enough steady data for an orbit")
            ax.set_title(_title(res, "Orbit", operating, 6.5), fontsize=9)
            return fig
        steady = np.arange(res.time_s.size) >= res.time_s.size // 2
        note = (f"run stopped at {res.time_s[-1]:.4g} s, before the steady part ({res.settle_s:.3g} s): "
                f"last half of the samples, start-up included")
    d = res.displacement_m[steady]
    centre = d.mean(axis=0)
    scale, unit = length_unit(float(max(np.ptp(d[:, 0]), np.ptp(d[:, 1]))) or 1e-12)
    rel = (d - centre) / scale
    ax.plot(rel[:, 0], rel[:, 1], lw=0.5, color="0.35", label="orbit")
    p = res.poincare[0] if res.poincare else None
    if p is not None and p.time_s.size:
        pp = (p.xy_m - centre) / scale
        ax.plot(pp[:, 0], pp[:, 1], "o", ms=3, color="tab:red", label=f"once per {frequency_label(p.name, res.bearing_names)}")
    ax.set_aspect("equal", adjustable="datalim")
    for axis in (ax.xaxis, ax.yaxis):
        axis.set_major_locator(MaxNLocator(6))
    # the centre in a unit of its own size, said once per axis (the orbit's unit is the axis')
    for set_label, name, c in ((ax.set_xlabel, "x", centre[0]), (ax.set_ylabel, "y", centre[1])):
        c_scale, c_unit = length_unit(abs(float(c)) or 1e-12)
        set_label(f"{name} - {name}_centre [{unit}]   ({name}_centre = {float(c) / c_scale:.4g} {c_unit})")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7, loc="upper right")
    if note:
        ax.text(0.02, 0.02, note, transform=ax.transAxes, fontsize=7, color="tab:red", va="bottom", wrap=True)
    ax.set_title(_title(res, "Orbit, steady part" if not note else "Orbit", operating, 6.5), fontsize=9)
    return fig


def _spectrum_of(res: TransientResult) -> tuple[Spectrum, str]:
    """The run's spectrum of the steady part or, for a run that stopped before it, of what exists."""
    if res.spectrum.frequency_hz.size:
        return res.spectrum, ""
    n = res.time_s.size
    if n < 16:
        return res.spectrum, ""
    part = np.arange(n) >= n // 2
    spec = amplitude_spectrum(res.displacement_m[part], res.sample_rate_hz)
    t = res.time_s[part]
    return spec, (f"run stopped at {res.time_s[-1]:.4g} s, before the steady part ({res.settle_s:.3g} s): spectrum of "
                  f"{t[0]:.4g}-{t[-1]:.4g} s, start-up transient included")


def pass_frequencies(res: TransientResult) -> dict[str, float]:
    """The rolling-element pass frequencies of the run (bearing.roller_pass, bearing.ball_pass_outer)."""
    return {k: v for k, v in res.frequencies_hz.items() if v > 0 and k.endswith(PASS_SUFFIXES)}


def spectrum_figure(res: TransientResult, modal_hz: np.ndarray | None = None, operating: str = "") -> Figure:
    """x and y amplitude spectra with every pass-frequency harmonic in range marked (h x), the
    revolution 1X and 2X, the linear modes and the dominant line."""
    fig = new_figure(10, 6.5, layout=None)
    ax = fig.subplots(2, 1, sharex=True)
    spec, note = _spectrum_of(res)
    _fixed(fig, _title(res, "Spectrum of the steady part", operating, 10, resolution=not note), hgap_in=0.3,
           title_in=0.15)
    f, A = spec.frequency_hz, spec.amplitude
    if not f.size:
        for a in ax:
            _no_data(a, "not enough steady data for a spectrum: the run stopped at "
                        f"{res.time_s[-1] if res.time_s.size else 0.0:.4g} s, the steady part starts at "
                        f"{res.settle_s:.3g} s")
        fig.suptitle(_title(res, "Spectrum", operating, 10), fontsize=9)
        return fig
    passes = pass_frequencies(res)
    rev = res.frequencies_hz.get("revolution", 0.0)
    modal = np.asarray(modal_hz, float) if modal_hz is not None else np.zeros(0)
    fmax = max([3.0 * v for v in passes.values()] + [3.0 * rev] + ([1.5 * float(np.max(modal[:2]))] if modal.size else []))
    fmax = min(f[-1], fmax) if fmax > 0 else f[-1]
    scale, unit = length_unit(float(np.max(A)) or 1e-12)
    for k, lab in enumerate(("x", "y")):
        a = ax[k]
        shown = f <= fmax
        a.semilogy(*column_extremes(f[shown], np.maximum(A[shown, k], 1e-30) / scale, pixel_columns(a)), lw=0.7,
                   color="tab:blue")
        sel = (f > 0) & (f <= fmax)
        i = int(np.argmax(np.where(sel, A[:, k], -1.0)))
        a.plot(f[i], A[i, k] / scale, "v", color="k", ms=6, gid=f"dominant:{lab}")
        a.annotate(f"{with_resolution(f[i], spec.resolution_hz / 2, 'Hz')}, {A[i, k] / scale:.3g} {unit}",
                   (f[i], A[i, k] / scale), xytext=(6, 4), textcoords="offset points", fontsize=7)
        for c, (name, fr) in zip(_PASS_COLORS, passes.items()):
            n = int(fmax / fr + 1e-9)
            every = max(1, math.ceil(n / 24))
            for h in range(1, n + 1):
                a.axvline(h * fr, color=c, ls=":", lw=0.9, gid=f"harmonic:{name}:{h}",
                          label=(f"{frequency_label(name, res.bearing_names)} {fr:.4g} Hz, harmonics 1..{n}"
                                 if h == 1 else None))
                if k == 0 and (h == 1 or h % every == 0):
                    a.text(h * fr, 1.0, f"{h}x", color=c, fontsize=6, ha="center", va="bottom",
                           transform=a.get_xaxis_transform())
        for h in (1, 2):
            if 0 < h * rev <= fmax:
                a.axvline(h * rev, color="0.3", ls="-.", lw=0.8, gid=f"revolution:{h}",
                          label=f"revolution 1X, 2X ({rev:.4g} Hz)" if h == 1 else None)
        for j, fm in enumerate(modal[(modal > 0) & (modal <= fmax)]):
            a.axvline(fm, color="tab:orange", ls="--", lw=0.8, label="linear modes" if j == 0 else None)
        a.set_ylabel(f"{lab} amplitude [{unit}]")
        peak = float(np.max(A[shown, k])) / scale
        if peak > 0:  # 100 dB below the peak: not the decades of the numerical floor
            a.set_ylim(peak * 10 ** -(FLOOR_DB / 20), peak * 3.0)
        a.grid(True, which="major", alpha=0.3)
    ax[1].legend(fontsize=7, loc="upper right")
    if note:
        ax[0].text(0.01, 0.03, note, transform=ax[0].transAxes, fontsize=7, color="tab:red")
    ax[1].set_xlim(0, fmax)
    ax[1].set_xlabel(f"frequency [Hz] (bin {spec.resolution_hz:.3g} Hz)")
    what = "Spectrum of the steady part" if not note else "Spectrum of the part computed"
    fig.suptitle(_title(res, what, operating, 10, resolution=not note), fontsize=9)
    return fig


def _points(n: int) -> str:
    return f"{n} point" + ("" if n == 1 else "s")


def _periodicity_text(p) -> str:
    """A Poincare set's periodicity in words, with its tolerance relative to the orbit."""
    q = p.periodicity
    scale, unit = length_unit(q.tolerance_m)
    tol = f"tolerance {q.tolerance_m / scale:.2g} {unit}"
    if math.isfinite(q.relative_tolerance):
        tol += f" ({100 * q.relative_tolerance:.2g} % of the orbit)"
    if q.kind == "period" and q.period == 1:
        share = f" ({100 * q.spread_m / q.extent_m:.2g} % of the orbit)" if q.extent_m > 0 else ""
        return f"all {_points(q.points)} within {q.spread_m / scale:.2g} {unit} of their mean{share}; {tol}"
    if q.kind == "period":
        return f"{_points(q.points)} on {q.period} places; {tol}"
    return f"{_points(q.points)}, {q.distinct} distinct; {tol}"


def poincare_figure(res: TransientResult, operating: str = "") -> Figure:
    """Every Poincare set: x against dx/dt about the steady mean, with what the analysis says of it
    (period-k, not periodic, too few points; a period-1 set is drawn as one point)."""
    from matplotlib.ticker import MaxNLocator

    sets = [p for p in res.poincare if p.time_s.size]
    ncol = min(max(len(sets), 1), 3)
    nrow = max(1, math.ceil(len(sets) / ncol))
    fig = new_figure(4.3 * ncol, 3.9 * nrow + 0.5, layout=None)
    axes = np.atleast_1d(fig.subplots(nrow, ncol)).ravel()
    _fixed(fig, _title(res, "Poincare maps", operating, 4.3 * ncol), left_in=0.8, hgap_in=1.25, wgap_in=0.8,
           title_in=0.75)
    if not sets:
        stop = res.time_s[-1] if res.time_s.size else 0.0
        _no_data(axes[0], "not enough steady data for a Poincare map:\n"
                 f"the run stopped at {stop:.4g} s,\nthe steady part starts at {res.settle_s:.3g} s")
        fig.suptitle(_title(res, "Poincare maps", operating, 4.3 * ncol), fontsize=9)
        return fig
    steady = _steady(res) if _steady(res).sum() >= 2 else np.ones(res.time_s.size, bool)
    x_all, v_all = res.displacement_m[steady, 0], res.velocity_m_s[steady, 0]
    x0, v0 = (float(x_all.mean()), float(v_all.mean())) if x_all.size else (0.0, 0.0)
    xs, xu = length_unit(float(np.ptp(x_all)) if x_all.size else 1e-12)
    vs, vu = length_unit(float(np.ptp(v_all)) if v_all.size else 1e-12)
    for ax, p in zip(axes, sets):
        q = p.periodicity
        x, v = (p.xy_m[:, 0] - x0) / xs, (p.v_m_s[:, 0] - v0) / vs
        if q is not None and q.kind == "period" and q.period == 1:
            ax.plot([x.mean()], [v.mean()], "o", ms=9, mfc="none", color="tab:red", gid="period-1")
            hx = max(0.5 * float(np.ptp(x_all)) / xs, 1e-9)
            hv = max(0.5 * float(np.ptp(v_all)) / vs, 1e-9)
            ax.set_xlim(x.mean() - hx, x.mean() + hx)
            ax.set_ylim(v.mean() - hv, v.mean() + hv)
        else:
            ax.plot(x, v, ".", ms=3)
        for axis in (ax.xaxis, ax.yaxis):
            axis.set_major_locator(MaxNLocator(5))
        ax.set_xlabel(f"x - mean [{xu}]")
        ax.set_ylabel(f"dx/dt - mean [{vu}/s]")
        label = "" if q is None else f"period-{q.period}" if q.periodic else q.kind
        words = "" if q is None else "\n" + textwrap.fill(_periodicity_text(p), 70)
        ax.set_title(f"once per {frequency_label(p.name, res.bearing_names)} ({p.frequency_hz:.4g} Hz): {label}{words}", fontsize=7.5,
                     color="tab:red" if q is not None and q.periodic else "black")
        ax.grid(True, alpha=0.3)
    for ax in axes[len(sets):]:
        ax.remove()
    fig.suptitle(_title(res, "Poincare maps", operating, 4.3 * ncol), fontsize=9)
    return fig


def _pretty(name: str, units: str) -> str:
    base = name[: -len(units) - 1] if units and name.endswith("_" + units) else name
    return base.replace("_", " ")


def bearing_output_figure(res: TransientResult, b: int, name: str, operating: str = "") -> Figure:
    """A per-element bearing output (e.g. roller loads): a map over the last revolutions (top) and three
    elements over the last two revolutions (bottom)."""
    from matplotlib.ticker import MaxNLocator

    values, units = res.bearing_outputs[b][name]
    fig = new_figure(10, 6.5, layout=None)
    ax = fig.subplots(2, 1)
    what = _pretty(name, units)
    if units == "m":  # a length in the unit that suits it (a race deflects by micrometres)
        scale, units = length_unit(float(np.max(np.abs(values), initial=0.0)) or 1e-12)
        values = values / scale
    who = bearing_label(res.bearing_names[b], res.bearing_names)
    title = _title(res, f"{who[0].upper()}{who[1:]}: {what}", operating, 10)
    _fixed(fig, title, hgap_in=0.85)
    t = res.time_s
    if not t.size:
        _no_data(ax[0], "no samples")
        return fig
    element = "roller" if "roller" in name else "ball" if "ball" in name else "race node" if "race" in name \
        else "element"
    V = values.reshape(len(t), -1)
    cage = min((v for k, v in res.frequencies_hz.items() if k.endswith(".cage") and v > 0), default=0.0)
    span = 6 / cage if cage > 0 else t[-1] - t[0]
    m = t >= t[-1] - span
    tf, tu = time_unit(float(t[-1]))
    im = ax[0].imshow(V[m].T, aspect="auto", origin="lower", cmap="viridis",
                      extent=(t[m][0] * tf, t[m][-1] * tf, 0.5, V.shape[1] + 0.5), interpolation="nearest")
    fig.colorbar(im, ax=ax[0], label=f"{what} [{units}]", fraction=0.05, pad=0.01)
    ax[0].set_xlabel(f"time [{tu}]")
    ax[0].set_ylabel(element)
    ax[0].yaxis.set_major_locator(MaxNLocator(integer=True, nbins=8))
    ax[0].set_title(f"every {element}" + (", last 6 cage revolutions" if cage > 0 and span < t[-1] - t[0] else ""),
                    fontsize=9)
    w = _window(res, 2)
    for j in range(min(V.shape[1], 3)):
        ax[1].plot(*column_extremes(t[w] * tf, V[w, j], pixel_columns(ax[1])), lw=1.0, label=f"{element} {j + 1}")
    ax[1].set_xlabel(f"time [{tu}]")
    ax[1].set_ylabel(f"{what} [{units}]")
    ax[1].set_title(f"{min(V.shape[1], 3)} {element}s, last 2 revolutions", fontsize=9)
    ax[1].legend(fontsize=7, loc="upper right")
    ax[1].grid(True, alpha=0.3)
    fig.suptitle(title, fontsize=9)
    return fig


def run_up_figure(res: TransientResult, peak_rpm: float | None = None, operating: str = "") -> Figure:
    """Response amplitude against the speed of a run-up (envelope of |x|, |y|)."""
    fig = new_figure(9, 5, layout=None)
    ax = fig.subplots()
    title = _title(res, "Run-up", operating, 9, settling=False)
    _fixed(fig, "", title_in=0.2 + 0.17 * (title.count("\n") + 1))
    if not res.time_s.size:
        _no_data(ax, "no samples")
        return fig
    scale, unit = length_unit(float(np.max(np.abs(res.displacement_m))) or 1e-12)
    columns = pixel_columns(ax)
    ax.plot(*column_extremes(res.speed_rpm, np.abs(res.displacement_m[:, 0]) / scale, columns), lw=0.4, label="|x|")
    ax.plot(*column_extremes(res.speed_rpm, np.abs(res.displacement_m[:, 1]) / scale, columns), lw=0.4, label="|y|")
    if peak_rpm is not None:
        ax.axvline(peak_rpm, color="tab:red", ls="--", lw=0.8, label=f"peak at {peak_rpm:.0f} rpm")
    ax.set_xlabel("speed [rpm]")
    ax.set_ylabel(f"displacement [{unit}]")
    ax.legend(fontsize=7)
    ax.grid(True, alpha=0.3)
    ax.set_title(title, fontsize=9)
    return fig
