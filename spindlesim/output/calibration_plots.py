"""The calibration's figure: per measurement, magnitude and phase of the measured FRF (points), the deck's model
(dashed) and the calibrated model (solid)."""

from __future__ import annotations

import numpy as np

from .figures import new_figure


def calibration_figure(res, title: str = ""):
    n = len(res.measurements)
    fig = new_figure(10.0, 3.2 + 2.6 * n)
    axes = fig.subplots(2 * n, 1, sharex=True, gridspec_kw={"height_ratios": [2, 1] * n})
    for k, m in enumerate(res.measurements):
        a_mag, a_ph = axes[2 * k], axes[2 * k + 1]
        f = m.frequency_hz
        a_mag.semilogy(f, 1e6 * np.abs(m.H), ".", ms=3, color="0.35", label="measured")
        a_mag.semilogy(f, 1e6 * np.abs(res.initial_H[k]), "--", color="C1", lw=1.2,
                       label=f"deck ({100 * res.initial_error[k]:.1f} % rms)" if np.isfinite(res.initial_error[k])
                       else "deck")
        a_mag.semilogy(f, 1e6 * np.abs(res.calibrated_H[k]), "-", color="C0", lw=1.4,
                       label=f"calibrated ({100 * res.final_error[k]:.1f} % rms)" if np.isfinite(res.final_error[k])
                       else "best evaluated (interrupted)")
        a_ph.plot(f, np.rad2deg(np.angle(m.H)), ".", ms=3, color="0.35")
        a_ph.plot(f, np.rad2deg(np.angle(res.initial_H[k])), "--", color="C1", lw=1.0)
        a_ph.plot(f, np.rad2deg(np.angle(res.calibrated_H[k])), "-", color="C0", lw=1.2)
        a_mag.set_ylabel(f"|H_{m.direction}{m.direction}| [um/N]")
        a_mag.set_title(f"{m.label}: node {m.node}, {m.direction}, {m.speed_rpm:g} rpm", fontsize="small", loc="left")
        a_ph.set_ylabel("phase [deg]")
        a_ph.set_ylim(-180, 180)
        a_ph.set_yticks([-180, -90, 0, 90, 180])
        a_mag.legend(fontsize="small", loc="upper left")
        for a in (a_mag, a_ph):
            a.grid(True, alpha=0.3)
    axes[-1].set_xlabel("frequency [Hz]")
    fit = "; ".join(f"{p.path.split('.')[-2] + '.' + p.path.split('.')[-1]} {p.value:.3g}" for p in res.parameters)
    fig.suptitle((f"{title}\n" if title else "") + f"calibration: {fit}", fontsize="medium")
    return fig
