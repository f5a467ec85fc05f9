"""The figures of ``spindlesim fitmodes``: the stabilisation diagram and the measured-vs-fitted overlay.

matplotlib is imported inside the functions (output/drawing.py: they may be drawn in the figure process)."""

from __future__ import annotations

import numpy as np

from .figures import new_figure

#: status -> (marker, colour, label) of the stabilisation diagram
_STATUS = {0: ("o", "0.75", "new"), 1: ("x", "C1", "frequency stable"), 2: ("^", "C2", "frequency, damping stable"),
           3: ("s", "C0", "stable: frequency, damping, residue")}


def stabilisation_figure(ident):
    """Per direction: each model order's candidate poles by their stability (markers), the chosen modes
    (vertical lines; the computational ones left out dashed red), over |H| measured."""
    n = len(ident.directions)
    fig = new_figure(10.0, 1.0 + 4.2 * n)
    axes = np.atleast_1d(fig.subplots(n, 1, squeeze=False)[:, 0])
    for ax, d in zip(axes, ident.directions):
        diag = d.diagram
        for s, (marker, color, label) in _STATUS.items():
            o, p = np.nonzero(diag.status == s)
            ax.plot(diag.frequency_hz[o, p], diag.orders[o], marker, ms=3.5 if s == 3 else 3, color=color,
                    mfc="none" if s != 3 else color, ls="none", label=label)
        for m in d.modes:
            ax.axvline(m.frequency_hz, color="C0", lw=0.8, alpha=0.6)
        for k, m in enumerate(d.discarded):
            ax.axvline(m.frequency_hz, color="C3", lw=0.8, ls="--",
                       label="left out (computational)" if k == 0 else None)
        ax.set_xlim(d.band_hz)
        ax.set_ylabel("model order")
        ax.set_title(f"{d.direction}: {len(d.modes)} mode(s) in {d.band_hz[0]:g}-{d.band_hz[1]:g} Hz "
                     f"(a mode: {ident.criteria.min_stable} or more stable orders)", fontsize="small", loc="left")
        twin = ax.twinx()
        twin.semilogy(d.frequency_hz, np.abs(d.measured_m_N), color="0.45", lw=0.8)
        twin.set_ylabel(f"|H_{d.direction}{d.direction}| measured [m/N]", color="0.45")
        ax.set_zorder(twin.get_zorder() + 1)
        ax.patch.set_visible(False)
        ax.legend(fontsize="x-small", loc="upper left", ncol=2)
        ax.grid(True, alpha=0.3)
    axes[-1].set_xlabel("frequency [Hz]")
    fig.suptitle(f"stabilisation diagram: {ident.source} ({ident.library}, LSCF)", fontsize="medium")
    return fig


def overlay_figure(ident):
    """Per direction (columns): magnitude, phase, real and imaginary parts of the measured receptance (points),
    the LSFD fit (modes and residuals) and the modes alone (what the chatter section gets)."""
    n = len(ident.directions)
    fig = new_figure(7.5 * n + 1.0, 10.0)
    axes = fig.subplots(4, n, sharex="col", squeeze=False)
    for c, d in enumerate(ident.directions):
        f = d.frequency_hz
        curves = ((d.measured_m_N, dict(ls="none", marker=".", ms=2.5, color="0.35"), "measured"),
                  (d.fitted_m_N, dict(color="C0", lw=1.3), f"LSFD fit ({100 * d.fit_error:.1f} % rms)"),
                  (d.modal_m_N, dict(color="C3", lw=1.0, ls="--"),
                   f"modes alone, modal form ({100 * d.modal_fit_error:.1f} % rms)"))
        a_mag, a_ph, a_re, a_im = axes[:, c]
        for h, style, label in curves:
            a_mag.semilogy(f, 1e6 * np.abs(h), label=label, **style)
            a_ph.plot(f, np.rad2deg(np.angle(h)), **style)
            a_re.plot(f, 1e6 * h.real, **style)
            a_im.plot(f, 1e6 * h.imag, **style)
        for m in d.modes:
            a_mag.axvline(m.frequency_hz, color="C0", lw=0.6, alpha=0.4)
        a_mag.set_ylabel(f"|H_{d.direction}{d.direction}| [um/N]")
        a_ph.set_ylabel("phase [deg]")
        a_ph.set_ylim(-180, 180)
        a_ph.set_yticks([-180, -90, 0, 90, 180])
        a_re.set_ylabel("real [um/N]")
        a_im.set_ylabel("imaginary [um/N]")
        a_im.set_xlabel("frequency [Hz]")
        title = f"{d.direction}: {len(d.modes)} mode(s), band {d.band_hz[0]:g}-{d.band_hz[1]:g} Hz"
        if d.window_decay_1_s:
            title += f"; exponential window {d.window_decay_1_s:.3g} 1/s (curves with it, damping without)"
        a_mag.set_title(title, fontsize="small", loc="left")
        a_mag.legend(fontsize="x-small", loc="lower left")
        for a in axes[:, c]:
            a.grid(True, alpha=0.3)
    fig.suptitle(f"measured and fitted receptance: {ident.source}", fontsize="medium")
    return fig
