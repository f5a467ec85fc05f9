"""Figures of a transient result (matplotlib Figure API, no pyplot state).  No physics here."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from ...analysis.transient import TransientResult
from ...output.figures import new_figure


def _title(res: TransientResult) -> str:
    s = f"{res.model}, {res.rollers} rollers, f_rp = {res.roller_pass_frequency_hz:.1f} Hz"
    return s if res.complete else s + f"  [INCOMPLETE: {res.reason}]"


def time_history_figure(res: TransientResult) -> Figure:
    fig = new_figure(8, 5)
    ax = fig.subplots(2, 1, sharex=True)
    for k, lab in enumerate(("x (horizontal)", "y (vertical)")):
        ax[k].plot(res.time_s, res.displacement_m[:, k] * 1e6, lw=0.6)
        ax[k].axvline(res.settle_s, color="0.6", ls="--", lw=0.8)
        ax[k].set_ylabel(f"{lab} [um]")
    ax[1].set_xlabel("time [s]")
    fig.suptitle("Shaft centre: " + _title(res), fontsize=9)
    return fig


def orbit_figure(res: TransientResult) -> Figure:
    fig = new_figure(5.5, 5)
    ax = fig.subplots()
    steady = res.time_s >= res.settle_s
    ax.plot(res.displacement_m[steady, 0] * 1e6, res.displacement_m[steady, 1] * 1e6, lw=0.5)
    ax.set_xlabel("x [um]")
    ax.set_ylabel("y [um]")
    ax.set_title("Orbit (steady part): " + _title(res), fontsize=8)
    return fig


def spectrum_figure(res: TransientResult) -> Figure:
    fig = new_figure(8, 5)
    ax = fig.subplots(2, 1, sharex=True)
    f = res.spectrum.frequency_hz
    for k, lab in enumerate(("x", "y")):
        if f.size:
            ax[k].semilogy(f, np.maximum(res.spectrum.amplitude[:, k], 1e-30) * 1e6, lw=0.7)
        for h in range(1, 4):
            ax[k].axvline(h * res.roller_pass_frequency_hz, color="r", ls=":", lw=0.8)
        ax[k].set_ylabel(f"{lab} amplitude [um]")
    ax[1].set_xlabel("frequency [Hz] (dotted: multiples of N f_cage)")
    if f.size:
        ax[1].set_xlim(0, min(f[-1], 6 * res.roller_pass_frequency_hz))
    fig.suptitle("Hann-windowed spectrum: " + _title(res), fontsize=9)
    return fig


def poincare_figure(res: TransientResult) -> Figure:
    fig = new_figure(9, 4.5)
    ax = fig.subplots(1, 2)
    for k, lab in enumerate(("x", "y")):
        ax[k].plot(res.poincare_xy_m[:, k] * 1e6, res.poincare_v_m_s[:, k] * 1e3, ".", ms=3)
        ax[k].set_xlabel(f"{lab} [um]")
        ax[k].set_ylabel(f"d{lab}/dt [mm/s]")
    fig.suptitle("Poincare map, sampled every 1/(N f_cage): " + _title(res), fontsize=9)
    return fig


def roller_force_figure(res: TransientResult) -> Figure:
    fig = new_figure(8, 4.5)
    ax = fig.subplots()
    for j in range(res.roller_force_N.shape[1]):
        ax.plot(res.time_s, res.roller_force_N[:, j], lw=0.5, label=f"roller {j + 1}")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("contact load [N]")
    if res.roller_force_N.shape[1] <= 12:
        ax.legend(fontsize=6, ncol=4)
    ax.set_title("Roller contact loads: " + _title(res), fontsize=9)
    return fig


def race_deflection_figure(res: TransientResult) -> Figure:
    fig = new_figure(8, 4.5)
    ax = fig.subplots()
    d = res.race_deflection_m
    if d is not None and d.size:
        im = ax.imshow(d.T * 1e9, aspect="auto", origin="lower", cmap="RdBu_r",
                       extent=(res.time_s[0], res.time_s[-1], 0.5, d.shape[1] + 0.5))
        fig.colorbar(im, ax=ax, label="radial displacement [nm]")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("outer race segment")
    ax.set_title("Outer race segment deflection: " + _title(res), fontsize=9)
    return fig
