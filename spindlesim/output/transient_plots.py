"""Figures of a rotor transient (matplotlib Figure API, no pyplot state).  No physics here."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from ..analysis.transient.result import TransientResult
from ..analysis.transient.spectrum import distinct_points
from .figures import new_figure

UM = 1e6


def _title(res: TransientResult, what: str) -> str:
    sp = res.speed_rpm
    speed = (f"{sp[0]:.0f} rpm" if sp.size and np.ptp(sp) < 1e-9 * max(abs(sp[0]), 1.0)
             else f"{sp[0]:.0f}-{sp[-1]:.0f} rpm" if sp.size else "")
    s = f"{what}, node {res.record_node + 1}, {speed}, {res.method}"
    return s if res.complete else s + f"\nINCOMPLETE: {res.reason}"


def _no_data(ax, text: str) -> None:
    ax.text(0.5, 0.5, text, ha="center", va="center", transform=ax.transAxes, color="0.4")
    ax.set_xticks([])
    ax.set_yticks([])


def _window(res: TransientResult, periods: int = 5) -> np.ndarray:
    """The last few periods of the slowest characteristic frequency (at least 2 % of the run)."""
    t = res.time_s
    f = min((v for v in res.frequencies_hz.values() if v > 0), default=0.0)
    span = periods / f if f > 0 else 0.1 * (t[-1] - t[0] if t.size else 0.0)
    return t >= (t[-1] - max(span, 0.02 * (t[-1] - t[0]))) if t.size else t > 0


def time_figure(res: TransientResult) -> Figure:
    """Whole run (thin) and the last few revolutions (readable) of x and y at the record node."""
    fig = new_figure(9, 6)
    ax = fig.subplots(2, 1)
    t, d = res.time_s, res.displacement_m * UM
    if not t.size:
        _no_data(ax[0], "no samples")
        return fig
    for k, lab in enumerate(("x", "y")):
        ax[0].plot(t, d[:, k], lw=0.4, label=lab)
    ax[0].axvline(res.settle_s, color="0.5", ls="--", lw=0.8, label="steady part from")
    ax[0].set_xlabel("time [s]")
    ax[0].set_ylabel("displacement [um]")
    ax[0].set_title("whole run", fontsize=9)
    ax[0].legend(fontsize=7, loc="upper right")
    w = _window(res)
    for k, lab in enumerate(("x", "y")):
        ax[1].plot(t[w] * 1e3, d[w, k], lw=0.9, label=lab)
    ax[1].set_xlabel("time [ms]")
    ax[1].set_ylabel("displacement [um]")
    ax[1].set_title("last periods", fontsize=9)
    for a in ax:
        a.grid(True, alpha=0.3)
    fig.suptitle(_title(res, "Response"), fontsize=9)
    return fig


def orbit_figure(res: TransientResult) -> Figure:
    fig = new_figure(6, 6)
    ax = fig.subplots()
    steady = res.time_s >= res.settle_s
    if steady.sum() < 2:
        _no_data(ax, "not enough steady data")
        return fig
    d = res.displacement_m[steady] * UM
    ax.plot(d[:, 0], d[:, 1], lw=0.5, color="0.4", label="orbit")
    p = res.poincare[0] if res.poincare else None
    if p is not None and p.time_s.size:
        ax.plot(p.xy_m[:, 0] * UM, p.xy_m[:, 1] * UM, "o", ms=3, color="tab:red", label=f"once per {p.name}")
    ax.set_aspect("equal", adjustable="datalim")
    ax.ticklabel_format(useOffset=False)
    ax.set_xlabel("x [um]")
    ax.set_ylabel("y [um]")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)
    ax.set_title(_title(res, "Orbit, steady part"), fontsize=9)
    return fig


def spectrum_figure(res: TransientResult, modal_hz: np.ndarray | None = None) -> Figure:
    """x and y amplitude spectra of the steady part, with the excitation harmonics and the linear modes."""
    fig = new_figure(9, 6)
    ax = fig.subplots(2, 1, sharex=True)
    f, A = res.spectrum.frequency_hz, res.spectrum.amplitude
    if not f.size:
        _no_data(ax[0], "not enough steady data for a spectrum")
        return fig
    marks = {k: v for k, v in res.frequencies_hz.items() if v > 0 and (k == "revolution" or k.endswith("roller_pass"))}
    fmax = max([3.0 * v for v in marks.values()] + [1.5 * float(np.max(modal_hz[:2])) if modal_hz is not None and
                                                     modal_hz.size else 0.0])
    fmax = min(f[-1], fmax) if fmax > 0 else f[-1]
    colors = ("k", "tab:red", "tab:green", "tab:purple")
    for k, lab in enumerate(("x", "y")):
        ax[k].semilogy(f, np.maximum(A[:, k], 1e-30) * UM, lw=0.7, color="tab:blue")
        for c, (name, fr) in zip(colors, marks.items()):
            for h in range(1, int(fmax / fr) + 1 if fr > 0 else 1):
                ax[k].axvline(h * fr, color=c, ls=":", lw=0.8, label=(f"{name} x1..{int(fmax / fr)}" if h == 1 and k == 0
                                                                       else None))
        if modal_hz is not None:
            for j, fm in enumerate(modal_hz[modal_hz <= fmax]):
                ax[k].axvline(fm, color="tab:orange", ls="--", lw=0.8, label="linear modes" if j == 0 and k == 0 else None)
        ax[k].set_ylabel(f"{lab} amplitude [um]")
        ax[k].grid(True, which="both", alpha=0.3)
    ax[0].legend(fontsize=7, loc="upper right")
    ax[1].set_xlim(0, fmax)
    ax[1].set_xlabel(f"frequency [Hz] (bin {res.spectrum.resolution_hz:.3g} Hz)")
    fig.suptitle(_title(res, "Spectrum of the steady part"), fontsize=9)
    return fig


def poincare_figure(res: TransientResult) -> Figure:
    """Every Poincare set: displacement vs velocity in x, with the period found."""
    sets = [p for p in res.poincare if p.time_s.size]
    fig = new_figure(4.5 * max(len(sets), 1), 4.5)
    axes = np.atleast_1d(fig.subplots(1, max(len(sets), 1)))
    if not sets:
        _no_data(axes[0], "not enough steady data for a Poincare map")
        return fig
    for ax, p in zip(axes, sets):
        x, v = p.xy_m[:, 0] * UM, p.v_m_s[:, 0] * 1e3
        scale = max(float(np.ptp(res.displacement_m[:, 0])) if res.displacement_m.size else 0.0, 1e-15)
        k = distinct_points(p.xy_m, 1e-4 * scale)
        label = f"period-{k}" if k <= 8 else f"{k} distinct points (not periodic)"
        ax.plot(x, v, ".", ms=3)
        if k == 1:
            ax.plot(x[:1], v[:1], "o", ms=8, mfc="none", color="tab:red")
        ax.ticklabel_format(useOffset=False)
        ax.set_xlabel("x [um]")
        ax.set_ylabel("dx/dt [mm/s]")
        ax.set_title(f"once per {p.name} ({p.frequency_hz:.4g} Hz): {label}", fontsize=8)
        ax.grid(True, alpha=0.3)
    fig.suptitle(_title(res, "Poincare maps"), fontsize=9)
    return fig


def bearing_output_figure(res: TransientResult, b: int, name: str) -> Figure:
    """A per-element bearing output over time (e.g. roller loads) as a map, with the last periods drawn."""
    values, units = res.bearing_outputs[b][name]
    fig = new_figure(9, 6)
    ax = fig.subplots(2, 1)
    t = res.time_s
    if not t.size:
        _no_data(ax[0], "no samples")
        return fig
    V = values.reshape(len(t), -1)
    im = ax[0].imshow(V.T, aspect="auto", origin="lower", cmap="viridis",
                      extent=(t[0], t[-1], 0.5, V.shape[1] + 0.5), interpolation="nearest")
    fig.colorbar(im, ax=ax[0], label=f"{name} [{units}]")
    ax[0].set_xlabel("time [s]")
    ax[0].set_ylabel("element")
    w = _window(res, 2)
    for j in range(min(V.shape[1], 4)):
        ax[1].plot(t[w] * 1e3, V[w, j], lw=0.9, label=f"element {j + 1}")
    ax[1].set_xlabel("time [ms]")
    ax[1].set_ylabel(f"{name} [{units}]")
    ax[1].legend(fontsize=7)
    ax[1].grid(True, alpha=0.3)
    fig.suptitle(_title(res, f"Bearing {res.bearing_names[b]!r}: {name}"), fontsize=9)
    return fig


def run_up_figure(res: TransientResult, peak_rpm: float | None = None) -> Figure:
    """Response amplitude against the speed of a run-up (envelope of |x|, |y|)."""
    fig = new_figure(9, 5)
    ax = fig.subplots()
    if not res.time_s.size:
        _no_data(ax, "no samples")
        return fig
    ax.plot(res.speed_rpm, np.abs(res.displacement_m[:, 0]) * UM, lw=0.4, label="|x|")
    ax.plot(res.speed_rpm, np.abs(res.displacement_m[:, 1]) * UM, lw=0.4, label="|y|")
    if peak_rpm is not None:
        ax.axvline(peak_rpm, color="tab:red", ls="--", lw=0.8, label=f"peak at {peak_rpm:.0f} rpm")
    ax.set_xlabel("speed [rpm]")
    ax.set_ylabel("displacement [um]")
    ax.legend(fontsize=7)
    ax.grid(True, alpha=0.3)
    ax.set_title(_title(res, "Run-up"), fontsize=9)
    return fig
