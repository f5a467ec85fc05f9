"""Campbell diagrams (no physics beyond unit conversion); matplotlib is imported inside the functions
(through .figures), as in :mod:`.rotor_plots`."""

from __future__ import annotations

import numpy as np

from ..analysis.results import CampbellResult
from .figures import shade_above_speed_limit, fixed_layout, new_figure


def campbell_figure(r: CampbellResult, operating_rpm: float | None = None, teeth: int | None = None,
                    speed_limit_rpm: float | None = None):
    """Tracked modes (one colour per mode in both panels; marker = whirl), the 0.5x line and the
    excitation orders of the crossings (1x, 2x, a cutter's tooth passing), every crossing marked
    (a star where it is an API 684 critical speed, AF >= 2.5, labelled on the 1x line), speeds with an
    unstable mode shaded.

    Forward whirl is drawn with filled up-triangles at every other speed, backward whirl with open
    down-triangles at the speeds between, so the two halves of a split pair read apart where they
    coincide.  The frequency axis ends above the modes of interest (:func:`frequency_top`); the modes
    above it are named in the panel.  The log-decrement panel is symmetric-log with its linear part
    below the smallest log decrement drawn (:func:`log_dec_limits`)."""
    fig = new_figure(10, 7.5, layout=None)
    ax1, ax2 = fig.subplots(2, 1, sharex=True, height_ratios=[3, 2])
    s = r.speed_rpm
    marker = {"forward": "^", "backward": "v", "mixed": "o", "axial": "s"}
    stagger = {"forward": 0, "backward": 1}  # the speeds a whirl's markers sit on: even / odd indices
    orders = sorted({0.5, 1.0, 2.0} | set(r.crossings.orders if r.crossings is not None else ()))
    top, hidden = frequency_top(r.frequency_hz, max(orders) * float(np.max(s)) / 60.0)
    idx = np.arange(len(s))
    for k in range(r.frequency_hz.shape[1]):
        c = f"C{k % 10}"
        ax1.plot(s, r.frequency_hz[:, k], color=c, lw=1.0)
        for w, m in marker.items():
            sel = (r.whirl[:, k] == w) & ((idx % 2 == stagger[w]) if w in stagger else True)
            if sel.any():
                ax1.plot(s[sel], r.frequency_hz[sel, k], m, ms=5, color=c, mfc="white" if w == "backward" else c,
                         mew=1.0, ls="none", gid=f"whirl:{w}:{k + 1}")
        ax2.plot(s, r.log_dec[:, k], color=c, lw=1.2, label=f"mode {k + 1}")
    styles = {0.5: ":", 1.0: "--", 2.0: "-."}
    for mult in orders:
        tooth = teeth is not None and mult == float(teeth)
        ax1.plot(s, mult * s / 60.0, color="k", ls=styles.get(mult, (0, (5, 2, 1, 2, 1, 2))), lw=0.9,
                 label=f"{mult:g}x" + (" tooth passing" if tooth else ""))
    for w, m in marker.items():
        if np.any(r.whirl == w):
            ax1.plot([], [], m, color="0.3", mfc="white" if w == "backward" else "0.3", ls="none", label=w)
    c = r.crossings
    if c is not None and len(c):
        crit = c.critical
        if crit.any():
            ax1.plot(c.speed_rpm[crit], c.frequency_hz[crit], "*", ms=12, color="tab:green", mec="k", zorder=5,
                     ls="none", label="AF >= 2.5")
        if not crit.all():
            ax1.plot(c.speed_rpm[~crit], c.frequency_hz[~crit], "o", ms=7, mfc="none", mec="k", zorder=5,
                     ls="none", label="AF < 2.5")
    elif c is None:  # a result without the crossings: its 1x critical speeds
        ax1.plot(r.critical_speeds_rpm, r.critical_speeds_rpm / 60.0, "*", ms=12, color="tab:green", mec="k",
                 zorder=5, ls="none")
    for cs in r.critical_speeds_rpm:
        ax1.annotate(f"{cs:.0f} rpm", (cs, cs / 60.0), xytext=(6, -12), textcoords="offset points", fontsize=8)
    if hidden:
        lo, hi = np.nanmin(r.frequency_hz[:, hidden]), np.nanmax(r.frequency_hz[:, hidden])
        names = f"mode {hidden[0] + 1}" if len(hidden) == 1 else f"modes {hidden[0] + 1}-{hidden[-1] + 1}"
        ax1.text(0.99, 0.98, f"above the axis: {names} ({lo:.0f}-{hi:.0f} Hz; log dec below)", ha="right", va="top",
                 transform=ax1.transAxes, fontsize=7, color="0.3", gid="hidden-modes")
    unstable = np.any(r.log_dec < 0, axis=1)
    for a in (ax1, ax2):
        for i0, i1 in _runs(unstable):
            a.axvspan(s[i0], s[i1], color="tab:red", alpha=0.12, lw=0,
                      label="unstable" if (a is ax1 and i0 == _runs(unstable)[0][0]) else None)
    if operating_rpm:
        for a in (ax1, ax2):
            a.axvline(operating_rpm, color="0.3", lw=1.0, ls=(0, (1, 3)))
        ax1.annotate("operating speed", (operating_rpm, 0.98), xycoords=("data", "axes fraction"), rotation=90,
                     va="top", ha="right", fontsize=7, color="0.3")
    ax1.set_ylabel("damped natural frequency [Hz]")
    ax1.set_ylim(0, top)
    ax1.set_xlim(s[0], s[-1])
    if speed_limit_rpm is not None:
        shade_above_speed_limit([ax1, ax2], speed_limit_rpm, short=True)
    w = fig.get_size_inches()[0]
    fixed_layout(fig, right_in=1.4, gap_in=0.3)
    fig.legend(*ax1.get_legend_handles_labels(), loc="upper left", bbox_to_anchor=(1 - 1.35 / w, ax1.get_position().y1),
               fontsize=7, frameon=False)
    crit = ", ".join(f"{c:.0f}" for c in r.critical_speeds_rpm)
    ax1.set_title("Campbell diagram" + (f": critical speeds {crit} rpm (1x, AF >= 2.5)"
                                        if len(r.critical_speeds_rpm) else ": no critical speed in the range"),
                  fontsize=11)
    ax1.grid(True, alpha=0.3)
    ax2.axhline(0, color="k", lw=0.8)
    ax2.set_ylabel("log decrement [-]")
    ax2.set_xlabel("speed [rpm]")
    (bottom, top_ld), linthresh = log_dec_limits(r.log_dec)
    ax2.set_yscale("symlog", linthresh=linthresh, linscale=0.5)
    ax2.set_ylim(bottom, top_ld)
    fig.legend(*ax2.get_legend_handles_labels(), loc="lower left", bbox_to_anchor=(1 - 1.35 / w, ax2.get_position().y0),
               fontsize=7, frameon=False)
    ax2.grid(True, alpha=0.3)
    return fig


def frequency_top(freq_hz: np.ndarray, excitation_hz: float) -> tuple[float, list[int]]:
    """(top of the frequency axis, the tracked modes above it).  The modes of interest are those an
    excitation line of the diagram (up to ``excitation_hz`` at the top speed) comes within 30 % of
    (API 684's largest separation margin is 26 %), and the lowest mode above them; the axis ends 10 %
    above the highest of them (and of any other mode that enters the axis), and never below the
    excitation lines' end."""
    f = np.asarray(freq_hz, float)
    if not np.isfinite(f).any():
        return max(1.1 * excitation_hz, 1.0), []
    low = np.nanmin(f, axis=0)
    reach = 1.3 * excitation_hz
    near = [k for k in range(f.shape[1]) if low[k] <= reach]
    above = [k for k in range(f.shape[1]) if low[k] > reach]
    if above:
        near.append(min(above, key=lambda k: low[k]))
    top = 1.1 * max(float(np.nanmax(f[:, near])) if near else 0.0, excitation_hz)
    high = np.nanmax(f, axis=0)
    while True:  # a mode that enters the axis is drawn whole
        cut = (low < top) & (1.05 * high > top)
        if not cut.any():
            break
        top = 1.1 * float(np.max(high[cut]))
    return top, [k for k in range(f.shape[1]) if low[k] >= top]


def log_dec_limits(log_dec: np.ndarray) -> tuple[tuple[float, float], float]:
    """((bottom, top), linear threshold) of a symmetric-log log-decrement axis: the threshold a decade
    below the smallest nonzero magnitude (so every curve is in the logarithmic part, none collapsed onto
    0), the top half a decade above the largest value (no curve on the edge), and below 0 only a strip
    of the linear part when every mode is stable, else half a decade beyond the most negative."""
    d = np.asarray(log_dec, float)
    d = d[np.isfinite(d)]
    mag = np.abs(d[d != 0])
    if not mag.size:
        return (-0.01, 0.1), 0.01
    linthresh = 10.0 ** np.floor(np.log10(float(np.min(mag))))
    linthresh = float(np.clip(linthresh, 1e-6, 0.1))
    hi = float(np.max(d))
    top = 3.0 * hi if hi > linthresh else linthresh * 3.0
    lo = float(np.min(d))
    bottom = 3.0 * lo if lo < -linthresh else -linthresh
    return (bottom, top), linthresh


def _runs(mask: np.ndarray) -> list[tuple[int, int]]:
    """(first, last) index of every run of True in ``mask``."""
    out, start = [], None
    for i, v in enumerate(mask):
        if v and start is None:
            start = i
        if not v and start is not None:
            out.append((start, i - 1))
            start = None
    if start is not None:
        out.append((start, len(mask) - 1))
    return out


def campbell_frozen_figure(r: CampbellResult, frozen: CampbellResult, frozen_rpm: float):
    """The speed-dependent diagram (solid) over the one with bearing coefficients frozen at one speed (dashed)."""
    fig = new_figure(9, 6)
    ax = fig.subplots()
    s = r.speed_rpm
    for k in range(r.frequency_hz.shape[1]):
        ax.plot(s, r.frequency_hz[:, k], color="tab:blue", lw=1.2, label="bearings at every speed" if k == 0 else None)
        ax.plot(s, frozen.frequency_hz[:, k], color="tab:orange", lw=1.0, ls="--",
                label=f"bearings frozen at {frozen_rpm:g} rpm" if k == 0 else None)
    ax.plot(s, s / 60.0, "k:", lw=1, label="1x")
    top = np.nanmax(np.concatenate([r.frequency_hz.ravel(), frozen.frequency_hz.ravel()]))
    ax.set_ylim(0, top * 1.05)
    ax.set_xlabel("speed [rpm]")
    ax.set_ylabel("damped natural frequency [Hz]")
    ax.set_title("Campbell diagram: effect of the bearings' speed dependence")
    ax.legend(fontsize=8)
    ax.grid(True, alpha=0.3)
    return fig


def campbell_thermal_figure(r: CampbellResult, cold: CampbellResult, stiffness: dict,
                            label: str = "at thermal equilibrium"):
    """Natural frequencies (top) and the bearings' radial stiffness (bottom) against speed, at the spindle's
    thermal equilibrium of every speed (or the temperatures ``label`` names; solid) and with the bearings as
    assembled (dashed)."""
    fig = new_figure(9, 8, layout=None)
    ax1, ax2 = fig.subplots(2, 1, sharex=True, height_ratios=[3, 2])
    s = r.speed_rpm
    for k in range(r.frequency_hz.shape[1]):
        ax1.plot(s, r.frequency_hz[:, k], color="tab:red", lw=1.2, label=label if k == 0 else None)
        ax1.plot(s, cold.frequency_hz[:, k], color="tab:blue", lw=1.0, ls="--", label="bearings cold" if k == 0 else None)
    ax1.plot(s, s / 60.0, "k:", lw=1, label="1x")
    top = np.nanmax(np.concatenate([r.frequency_hz.ravel(), cold.frequency_hz.ravel()]))
    ax1.set_ylim(0, top * 1.05)
    ax1.set_ylabel("damped natural frequency [Hz]")
    ax1.legend(fontsize=8, loc="upper left")
    for j, name in enumerate(stiffness["bearing"]):
        if not np.any(stiffness["thermal"][:, j]) and not np.any(stiffness["cold"][:, j]):
            continue  # a damper without stiffness
        color = f"C{j}"
        ax2.plot(stiffness["speed_rpm"], stiffness["thermal"][:, j] / 1e6, "-", color=color, label=f"{name}")
        ax2.plot(stiffness["speed_rpm"], stiffness["cold"][:, j] / 1e6, "--", color=color)
    ax2.set_ylabel("radial stiffness K_xx [N/um]\n(solid: thermal, dashed: cold)")
    ax2.set_xlabel("speed [rpm]")
    ax2.legend(fontsize=7, ncols=4, loc="upper left")
    for ax in (ax1, ax2):
        ax.grid(True, alpha=0.3)
    fixed_layout(fig, left_in=1.0, top_in=0.5, gap_in=0.25)
    fig.suptitle("Campbell diagram and bearing stiffness with and without the spindle's temperatures", x=0.02,
                 ha="left", fontsize=10)
    return fig
