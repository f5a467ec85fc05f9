"""Figures of the rotor analyses (no physics beyond unit conversion).

Each ``*_figure`` function returns a figure for :func:`spindlesim.output.drawing.draw`; the module
imports matplotlib only inside them (through .figures), so the main process of a command can name
them without importing matplotlib.
"""

from __future__ import annotations

import numpy as np

from ..analysis.results import CampbellResult, FrfResult, ModalResult, StaticResult, UnbalanceResult
from .figures import fixed_layout, new_figure


def static_figure(r: StaticResult):
    """Deflection and slope along the rotor, nodes in axial order (a tool ahead of the nose reads left to
    right), bearings and the tool tip marked."""
    fig = new_figure(8, 6)
    ax1, ax2 = fig.subplots(2, 1, sharex=True)
    order = np.argsort(r.node_z_m, kind="stable")
    z = r.node_z_m * 1e3
    zs = z[order]
    ax1.plot(zs, r.displacement_m[order, 0] * 1e6, "o-", ms=4, label="x (horizontal)")
    ax1.plot(zs, r.displacement_m[order, 1] * 1e6, "s-", ms=4, label="y (vertical)")
    for k, (name, node) in enumerate(zip(r.bearing_names, r.bearing_nodes)):
        ax1.axvline(z[node], color="0.6", ls="--", lw=0.8)
        same = sum(1 for n in r.bearing_nodes[:k] if z[n] == z[node])  # bearings at one node: stacked labels
        ax1.annotate(name, (z[node], 0), xycoords=("data", "axes fraction"), textcoords="offset points",
                     xytext=(3, 4 + 10 * same), fontsize=7, color="0.35")
    if r.tool_tip_node is not None:
        t = r.tool_tip_node
        ax1.annotate("tool tip", (z[t], r.displacement_m[t, 0] * 1e6), textcoords="offset points", xytext=(6, -4),
                     fontsize=8)
    ax1.set_ylabel("deflection [um]")
    F = r.applied_force_N
    ax1.set_title(f"Static deflection under Fx {F[0]:.4g} N, Fy {F[1]:.4g} N (applied, gravity included); "
                  f"stiffness at node {r.stiffness_node + 1} {r.stiffness_dof}: "
                  f"{r.static_stiffness_N_m / 1e6:.3g} N/um", fontsize=9)
    ax1.legend()
    ax1.grid(True, alpha=0.3)
    ax2.plot(zs, r.slope_rad[order, 0] * 1e6, "o-", ms=4, label="theta_x")
    ax2.plot(zs, r.slope_rad[order, 1] * 1e6, "s-", ms=4, label="theta_y")
    ax2.set_xlabel("axial position z [mm]")
    ax2.set_ylabel("slope [urad]")
    ax2.legend()
    ax2.grid(True, alpha=0.3)
    return fig


def modes_figure(r: ModalResult, max_modes: int = 8, bearings: tuple[tuple[str, float], ...] = ()):
    """Mode shapes along the rotor (nodes in axial order, so a tool ahead of the nose reads left to
    right); ``bearings`` = (name, z [m]) are marked on every panel; the legend sits above the panels."""
    n = min(max_modes, len(r.frequency_hz))
    fig = new_figure(10, 1.9 * max(n, 1) + 0.6, layout=None)
    axes = np.atleast_1d(fig.subplots(max(n, 1), 1, sharex=True))
    order = np.argsort(r.node_z_m, kind="stable")
    z = r.node_z_m[order] * 1e3
    for k in range(n):
        ax = axes[k]
        shape = r.mode_shape[k][order]
        ax.plot(z, shape[:, 0].real, "o-", ms=3, color="tab:blue", label="x (real part)")
        ax.plot(z, shape[:, 1].real, "s-", ms=3, color="tab:orange", label="y (real part)")
        X, Y = shape[:, 0], shape[:, 1]  # orbit semi-major axis: forward + backward circle radii
        ax.plot(z, 0.5 * (np.abs(X - 1j * Y) + np.abs(X + 1j * Y)), ":", color="0.45", label="orbit semi-major axis")
        if shape.shape[1] > 4:  # the axial DOF (z, last)
            ax.plot(z, shape[:, 4].real, "d-", ms=3, color="tab:green", label="z, axial (real part)")
        for name, zb in bearings:
            ax.axvline(zb * 1e3, color="0.55", lw=0.8, ls="--", label="bearing" if name == bearings[0][0] else None)
        ax.set_ylabel("amplitude [-]")
        ax.set_yticks([-1.0, 0.0, 1.0])  # normalised: the largest translation is 1 (three ticks keep 8 panels cheap)
        what = r.whirl[k]
        ax.set_title(f"mode {k + 1}: {r.frequency_hz[k]:.1f} Hz, damping ratio {r.damping_ratio[k]:.4f}, "
                     f"log dec {r.log_dec[k]:.3f}, {what}", fontsize=9, y=1.0)
        ax.grid(True, alpha=0.3)
    if bearings:
        for name, zb in bearings:
            axes[0].annotate(name, (zb * 1e3, 1.0), xycoords=("data", "axes fraction"), xytext=(2, -10),
                             textcoords="offset points", fontsize=7, color="0.35")
    h = fig.get_size_inches()[1]
    fixed_layout(fig, left_in=0.85, top_in=0.75, bottom_in=0.55, gap_in=0.5)
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="upper right", bbox_to_anchor=(0.99, 1 - 0.08 / h), ncols=len(labels),
               fontsize=8, frameon=False)
    axes[-1].set_xlabel("axial position z [mm]")
    fig.suptitle(f"Damped mode shapes at {r.speed_rpm:g} rpm", x=0.02, y=1 - 0.1 / h, ha="left", va="top")
    return fig


def campbell_figure(r: CampbellResult, operating_rpm: float | None = None):
    """Tracked modes (one colour per mode in both panels; marker = whirl), the 0.5x line and the
    excitation orders of the crossings (1x, 2x, a cutter's tooth passing), every crossing marked
    (a star where it is an API 684 critical speed, AF >= 2.5, labelled on the 1x line), speeds with an
    unstable mode shaded."""
    fig = new_figure(10, 7.5, layout=None)
    ax1, ax2 = fig.subplots(2, 1, sharex=True, height_ratios=[3, 2])
    s = r.speed_rpm
    marker = {"forward": "^", "backward": "v", "mixed": "o", "axial": "s"}
    top = 1.08 * np.nanmax(r.frequency_hz)
    for k in range(r.frequency_hz.shape[1]):
        c = f"C{k % 10}"
        ax1.plot(s, r.frequency_hz[:, k], color=c, lw=1.0)
        for w, m in marker.items():
            sel = r.whirl[:, k] == w
            if sel.any():
                ax1.plot(s[sel], r.frequency_hz[sel, k], m, ms=3.5, color=c, mfc="none" if w == "backward" else c,
                         ls="none")
        ax2.plot(s, r.log_dec[:, k], color=c, lw=1.2, label=f"mode {k + 1}")
    orders = sorted({0.5, 1.0, 2.0} | set(r.crossings.orders if r.crossings is not None else ()))
    styles = {0.5: ":", 1.0: "--", 2.0: "-."}
    for mult in orders:
        ax1.plot(s, mult * s / 60.0, color="k", ls=styles.get(mult, (0, (5, 2, 1, 2, 1, 2))), lw=0.9,
                 label=f"{mult:g}x")
    for w, m in marker.items():
        if np.any(r.whirl == w):
            ax1.plot([], [], m, color="0.3", mfc="none" if w == "backward" else "0.3", ls="none", label=w)
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
    w = fig.get_size_inches()[0]
    fixed_layout(fig, right_in=1.2, gap_in=0.3)
    fig.legend(*ax1.get_legend_handles_labels(), loc="upper left", bbox_to_anchor=(1 - 1.15 / w, ax1.get_position().y1),
               fontsize=7, frameon=False)
    crit = ", ".join(f"{c:.0f}" for c in r.critical_speeds_rpm)
    ax1.set_title("Campbell diagram" + (f": critical speeds {crit} rpm (1x, AF >= 2.5)"
                                        if len(r.critical_speeds_rpm) else ": no critical speed in the range"),
                  fontsize=11)
    ax1.grid(True, alpha=0.3)
    ax2.axhline(0, color="k", lw=0.8)
    ax2.set_ylabel("log decrement [-]")
    ax2.set_xlabel("speed [rpm]")
    ax2.set_yscale("symlog", linthresh=0.01)
    fig.legend(*ax2.get_legend_handles_labels(), loc="lower left", bbox_to_anchor=(1 - 1.15 / w, ax2.get_position().y0),
               fontsize=7, frameon=False)
    ax2.grid(True, alpha=0.3)
    return fig


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


def campbell_thermal_figure(r: CampbellResult, cold: CampbellResult, stiffness: dict):
    """Natural frequencies (top) and the bearings' radial stiffness (bottom) against speed, at the spindle's
    thermal equilibrium of every speed (solid) and with the bearings as assembled (dashed)."""
    fig = new_figure(9, 8, layout=None)
    ax1, ax2 = fig.subplots(2, 1, sharex=True, height_ratios=[3, 2])
    s = r.speed_rpm
    for k in range(r.frequency_hz.shape[1]):
        ax1.plot(s, r.frequency_hz[:, k], color="tab:red", lw=1.2, label="at thermal equilibrium" if k == 0 else None)
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


def _frf_label(r: FrfResult) -> str:
    return (f"response at node {r.output_node} {r.output_dof} / force at node {r.input_node} {r.input_dof}, "
            f"{r.speed_rpm:g} rpm")


def frf_magnitude_phase_figure(r: FrfResult):
    """|H| (log) over the unwrapped phase."""
    from matplotlib.ticker import MultipleLocator

    f, h = r.frequency_hz, r.receptance_m_N
    fig = new_figure(8, 6, layout=None)
    a1, a2 = fig.subplots(2, 1, sharex=True)
    a1.semilogy(f, np.abs(h) * 1e6)
    a1.set_ylabel("|receptance| [um/N]")
    a1.set_title("Receptance: " + _frf_label(r))
    a1.grid(True, which="both", alpha=0.3)
    a2.plot(f, np.degrees(np.unwrap(np.angle(h))))  # unwrapped: no false vertical jumps at +-180
    a2.set_ylabel("phase (unwrapped) [deg]")
    a2.set_xlabel("frequency [Hz]")
    a2.yaxis.set_major_locator(MultipleLocator(90))
    a2.grid(True, alpha=0.3)
    return fixed_layout(fig)


def frf_real_imag_figure(r: FrfResult):
    """Real over imaginary part of H."""
    f, h = r.frequency_hz, r.receptance_m_N
    fig = new_figure(8, 6, layout=None)
    b1, b2 = fig.subplots(2, 1, sharex=True)
    b1.plot(f, h.real * 1e6)
    b1.set_ylabel("real part [um/N]")
    b1.set_title("Receptance: " + _frf_label(r))
    b1.grid(True, alpha=0.3)
    b2.plot(f, h.imag * 1e6)
    b2.set_ylabel("imaginary part [um/N]")
    b2.set_xlabel("frequency [Hz]")
    b2.grid(True, alpha=0.3)
    return fixed_layout(fig)


def unbalance_figure(r: UnbalanceResult):
    """0-peak amplitude (log) and phase at the output DOF over speed; the 1x crossings marked."""
    fig = new_figure(8, 6)
    a1, a2 = fig.subplots(2, 1, sharex=True)
    node = r.output_node - 1
    comp = 0 if r.output_dof == "x" else 1
    q = r.response_m[:, node, comp]
    a1.semilogy(r.speed_rpm, np.abs(q) * 1e6, label="response")
    if r.resonances is not None and len(r.resonances.crossings):
        c = r.resonances.crossings
        for k, (sc, w) in enumerate(zip(c.speed_rpm, c.whirl)):
            for a in (a1, a2):
                a.axvline(sc, color="0.55", lw=0.8, ls="--", label=None if (k or a is a2) else "1x crossing of a mode")
            a1.annotate(f"{sc:.0f} rpm ({w})", (sc, 0.02), xycoords=("data", "axes fraction"), rotation=90,
                        xytext=(-3, 0), textcoords="offset points", ha="right", va="bottom", fontsize=7, color="0.35")
        a1.legend(fontsize=8, loc="upper left")
    a1.set_ylabel("amplitude, 0-peak [um]\n(peak-to-peak = 2x)")
    a1.set_title(f"Unbalance {r.unbalance_kg_m * 1e6:g} g mm at node {r.unbalance_node}: "
                 f"response at node {r.output_node} {r.output_dof}")
    a1.grid(True, which="both", alpha=0.3)
    a2.plot(r.speed_rpm, np.degrees(np.angle(q)))
    a2.set_ylabel("phase [deg]")
    a2.set_xlabel("speed [rpm]")
    a2.grid(True, alpha=0.3)
    return fig
