"""The figures of ``spindlesim impact``: the impact records and the FRF with its coherence.

matplotlib is imported inside the functions (output/drawing.py: they may be drawn in the figure process)."""

from __future__ import annotations

import numpy as np

from .figures import new_figure

_RESPONSE_LABEL = {"acceleration": "acceleration [m/s^2]", "velocity": "velocity [m/s]",
                   "displacement": "displacement [m]"}


def records_figure(res):
    """Force (top, its first milliseconds) and response of every impact; the ones left out dashed red, with why."""
    fig = new_figure(10.0, 7.0)
    a_f, a_r = fig.subplots(2, 1)
    t_ms = 1e3 * res.dt_s * np.arange(res.samples)
    zoom = t_ms <= max(4 * 1e3 * res.force_window_s, 5.0)
    for k, (rec, v) in enumerate(zip(res.records, res.verdicts)):
        style = dict(lw=0.9) if v.used else dict(lw=0.9, ls="--", color="C3")
        label = f"{k + 1}" + ("" if v.used else f": left out ({', '.join(v.reasons)})")
        a_f.plot(t_ms[zoom], rec.force_N[zoom], label=label, **style)
        a_r.plot(t_ms, rec.response, **style)
    a_f.axvline(1e3 * res.force_window_s, color="0.4", lw=0.8, ls=":", label="force window fades from here")
    a_f.set_ylabel("force [N]")
    a_f.set_xlabel("time [ms]")
    a_f.legend(fontsize="x-small", loc="upper right")
    a_r.set_ylabel(_RESPONSE_LABEL[res.kind])
    a_r.set_xlabel("time [ms]")
    if res.window_decay_1_s:
        a_r.set_title(f"an exponential window e^(-{res.window_decay_1_s:.3g} t) is applied to both channels",
                      fontsize="small", loc="left")
    for a in (a_f, a_r):
        a.grid(True, alpha=0.3)
    fig.suptitle(f"impact records: {res.used} of {len(res.verdicts)} averaged", fontsize="medium")
    return fig


def impact_frf_figure(res):
    """|H1| (the coherent band set the scale), its phase and the coherence; the resonances marked."""
    from ..measured.bands import coherent_band

    fig = new_figure(10.0, 8.0)
    a_m, a_p, a_c = fig.subplots(3, 1, sharex=True, height_ratios=[2.2, 1, 1])
    f, h = res.frequency_hz, res.receptance_m_N
    a_m.semilogy(f, 1e6 * np.abs(h), color="C0", lw=1.0)
    a_p.plot(f, np.rad2deg(np.angle(h)), color="C0", lw=0.8)
    a_c.plot(f, res.coherence, color="C2", lw=0.9)
    band = coherent_band(f, res.coherence)
    if band is not None:
        inside = (f >= band[0]) & (f <= band[1])
        mag = 1e6 * np.abs(h[inside])
        a_m.set_ylim(0.5 * mag.min(), 2.0 * mag.max())
        for a in (a_m, a_p, a_c):
            a.axvspan(f[0], band[0], color="0.85", lw=0, zorder=0)
        a_m.text(0.01, 0.03, f"grey: coherence under 0.9 (below {band[0]:.0f} Hz)", transform=a_m.transAxes,
                 fontsize="x-small")
    for p in res.peaks_hz():
        a_m.axvline(p, color="0.5", lw=0.6, ls=":")
        a_c.axvline(p, color="0.5", lw=0.6, ls=":")
    a_m.set_ylabel(f"|H_{res.direction}{res.direction}| [um/N]")
    a_p.set_ylabel("phase [deg]")
    a_p.set_ylim(-180, 180)
    a_p.set_yticks([-180, -90, 0, 90, 180])
    a_c.set_ylabel("coherence")
    a_c.set_ylim(0, 1.05)
    a_c.set_xlabel("frequency [Hz]")
    for a in (a_m, a_p, a_c):
        a.grid(True, alpha=0.3)
    fig.suptitle(f"tap test FRF (H1 of {res.used} impacts)", fontsize="medium")
    return fig
