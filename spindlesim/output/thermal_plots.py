"""Figures of the spindle's thermal model (no physics beyond unit conversion), from the arrays of
:class:`~spindlesim.output.thermal_writer.ThermalTable`: equilibria against speed, and a warm-up in time
(temperatures, operating preload, the tool tip's axial drift in the style of ISO 230-3, natural frequencies)."""

from __future__ import annotations

import numpy as np

from .figures import fixed_layout, new_figure

_COLORS = ("tab:red", "tab:blue", "tab:green", "tab:purple")


def _temperatures(ax, x, t, marker) -> None:
    for k, b in enumerate(t.bearings):
        c = _COLORS[k % len(_COLORS)]
        # inner solid with filled markers, outer dashed, thinner, with open markers: apart in the legend too
        ax.plot(x, t.inner_C[:, k], "-", color=c, lw=1.8, marker=marker, ms=4, label=f"{b}: inner ring")
        ax.plot(x, t.outer_C[:, k], ls=(0, (4, 2)), color=c, lw=1.1, marker="s" if marker else None, ms=4,
                mfc="white", label=f"{b}: outer ring")
    if t.motor_rotor_C is not None:
        ax.plot(x, t.motor_rotor_C, ":", color="0.2", label="motor rotor")
        ax.plot(x, t.motor_stator_C, "-.", color="0.5", label="motor stator")
    ax.set_ylabel("temperature [degC]")
    ax.legend(fontsize=7, ncols=3, loc="upper left", handlelength=3.0)


def _has_drift(t) -> bool:
    """A drift panel only where there is a drift: a tool tip."""
    return bool(np.isfinite(t.drift_m).any() or (t.radial_m is not None and np.isfinite(t.radial_m).any()))


def _preload_and_drift(axes, x, t, marker) -> None:
    """The preload panel (bearings with rows' thrust: not a cylindrical roller bearing) and, with a drift, the
    drift panel: ``axes`` holds one or two axes."""
    ax_p = axes[0]
    for k, b in enumerate(t.bearings):
        if np.isfinite(t.preload_N[:, k]).any():
            ax_p.plot(x, t.preload_N[:, k], "-", color=_COLORS[k % len(_COLORS)], marker=marker, ms=3, label=b)
    ax_p.set_ylabel("operating preload [N]\n(largest row thrust)")
    ax_p.legend(fontsize=8, loc="upper left")
    if len(axes) > 1:
        ax = axes[1]  # axial on the left scale, radial (often 10-100 x smaller) on its own right scale
        lines = []
        if np.isfinite(t.drift_m).any():
            lines += ax.plot(x, 1e6 * t.drift_m, "-", color="tab:brown", marker=marker, ms=3, label="axial z (left)")
        ax.set_ylabel("tool tip axial drift [um]\n(from the cold, unloaded spindle)")
        if t.radial_m is not None and np.isfinite(t.radial_m).any():
            ar = ax.twinx()
            lines += ar.plot(x, 1e6 * t.radial_m[:, 0], "--", color="tab:olive", marker=marker, ms=3,
                             label="radial x (right)")
            lines += ar.plot(x, 1e6 * t.radial_m[:, 1], ":", color="tab:cyan", marker=marker, ms=3,
                             label="radial y (right)")
            ar.set_ylabel("radial [um]")
        ax.legend(handles=lines, fontsize=8, ncols=3, loc="best")


def speeds_figure(t, title: str = ""):
    """Temperatures, operating preload and (with a tool tip) its drift at the thermal equilibrium of each speed;
    where a runaway ended the list, a red line."""
    n = 2 + _has_drift(t)
    fig = new_figure(9, 3.0 * n, layout=None)
    axes = fig.subplots(n, 1, sharex=True)
    _temperatures(axes[0], t.x, t, "o")
    _preload_and_drift(axes[1:], t.x, t, "o")
    axes[-1].set_xlabel("spindle speed [rpm]")
    if t.runaway_rpm is not None and np.isfinite(t.runaway_rpm):
        # the limit the summary states (bisected), else the first speed of the list that ran away
        at = t.limit_rpm[1] if t.limit_rpm is not None else t.runaway_rpm
        text = (f"thermal speed limit: stable up to {t.limit_rpm[0]:.0f} rpm, runs away from {t.limit_rpm[1]:.0f} rpm"
                if t.limit_rpm is not None else f"thermal runaway at {t.runaway_rpm:g} rpm")
        for ax in axes:
            if t.limit_rpm is not None:
                ax.axvspan(t.limit_rpm[1], max(t.runaway_rpm, t.limit_rpm[1]) * 1.03, color="tab:red", alpha=0.08)
            ax.axvline(at, color="tab:red", lw=1.5, ls="--")
        axes[1].annotate(text, (at, 0.95), xycoords=("data", "axes fraction"), xytext=(-4, -10),
                         textcoords="offset points", ha="right", fontsize=8, color="tab:red")
        for ax in axes:
            ax.set_xlim(right=max(max(t.runaway_rpm, at) * 1.03, ax.get_xlim()[1]))
    for ax in axes:
        ax.grid(True, alpha=0.3)
    fixed_layout(fig, left_in=1.0, right_in=0.8 if _has_drift(t) else 0.25, top_in=0.5, bottom_in=0.55,
                 gap_in=0.25)
    fig.suptitle(f"Thermal equilibrium against speed{': ' + title if title else ''}", x=0.02, ha="left",
                 fontsize=10)
    return fig


def warm_up_figure(t, title: str = ""):
    """A warm-up: temperatures, operating preload, the tool tip's axial drift (ISO 230-3 style), the first
    natural frequencies and (with a chatter section) the stable depth of cut at the running speed against time, every other speed step shaded and labelled with its speed."""
    minutes = t.x / 60.0
    drift = _has_drift(t)
    n = 2 + drift + (t.frequency_hz is not None) + (t.depth_m is not None)
    fig = new_figure(9, 2.6 * n + 0.8, layout=None)
    axes = fig.subplots(n, 1, sharex=True)
    _temperatures(axes[0], minutes, t, None)
    _preload_and_drift(axes[1:3 if drift else 2], minutes, t, None)
    if t.frequency_hz is not None:
        ax = axes[2 + drift]
        # modes of one pair (backward and forward whirl) lie on top of each other: each its own line style and
        # marker, the lower one drawn wider under the higher, so both show
        styles = (("-", "o", 2.6), ("--", "s", 1.4), ("-", "^", 2.6), ("--", "v", 1.4))
        for k in range(t.frequency_hz.shape[1]):
            ls, mk, lw = styles[k % len(styles)]
            ax.plot(minutes, t.frequency_hz[:, k], ls=ls, marker=mk, ms=3, markevery=max(1, len(minutes) // 12),
                    lw=lw, label=f"mode {k + 1}", zorder=3 + k)
        ax.set_ylabel("natural frequency [Hz]")
        ax.legend(fontsize=7, ncols=4, loc="upper left")
    if t.depth_m is not None:
        ax = axes[-1]
        ax.plot(minutes, 1e3 * t.depth_m, "-o", ms=3, color="C3",
                label="at the running speed (the chatter section's method, the FRF of each instant)")
        ax.set_ylabel("stable depth [mm]")
        ax.set_ylim(bottom=0.0, top=1.15 * max(float(np.nanmax(1e3 * t.depth_m)), 1e-6)
                    if np.isfinite(t.depth_m).any() else None)
        ax.legend(fontsize=7, loc="lower left")
    axes[-1].set_xlabel("time [min]")
    starts = np.concatenate([[0], np.flatnonzero(np.diff(t.speed_rpm)) + 1])
    ends = np.concatenate([starts[1:], [len(minutes) - 1]])
    for ax in axes:
        ax.grid(True, alpha=0.3)
        for k, (i, j) in enumerate(zip(starts, ends)):
            if k % 2:
                ax.axvspan(minutes[i], minutes[j], color="0.93", zorder=0)
    for i in starts:
        axes[0].annotate(f"{t.speed_rpm[i]:g} rpm", (minutes[i], 0.0), xycoords=("data", "axes fraction"),
                         xytext=(2, 3), textcoords="offset points", fontsize=7, color="0.3")
    fixed_layout(fig, left_in=1.0, right_in=0.8 if _has_drift(t) else 0.25, top_in=0.5, bottom_in=0.55,
                 gap_in=0.25)
    fig.suptitle(f"Warm-up{': ' + title if title else ''}", x=0.02, ha="left", fontsize=10)
    return fig
