"""Figures of the rotor analyses (no physics beyond unit conversion).

Each ``*_figure`` function returns a figure for :func:`spindlesim.output.drawing.draw`; the module
imports matplotlib only inside them (through .figures), so the main process of a command can name
them without importing matplotlib.
"""

from __future__ import annotations

import numpy as np

from ..analysis.results import FrfResult, ModalResult, StaticResult, UnbalanceResult
from .figures import shade_above_speed_limit, fixed_layout, new_figure
from .numbers import g


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
    fz = f", Fz {g(r.applied_axial_force_N)} N" if r.axial_displacement_m is not None else ""
    grav = ", gravity included" if r.gravity_m_s2 else ", no gravity"
    ax1.set_title(f"Static deflection under Fx {g(F[0])} N, Fy {g(F[1])} N{fz} (applied{grav}); "
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
        ax.set_title(f"mode {k + 1}: {r.frequency_hz[k]:.1f} Hz, damping ratio {r.damping_ratio[k]:.3g}, "
                     f"log dec {r.log_dec[k]:.3g}, {what}", fontsize=9, y=1.0)  # 3 significant digits
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
    if r.static_compliance_m_N is not None and r.static_compliance_m_N != 0:  # K^-1 at 0 Hz, below the grid
        a1.plot([0.0], [abs(r.static_compliance_m_N) * 1e6], "o", color="k", ms=5, gid="static",
                label=f"static compliance K^-1 (0 Hz) {abs(r.static_compliance_m_N) * 1e6:.4g} um/N")
        a1.legend(fontsize=8, loc="upper right")
        a1.set_xlim(left=0.0)
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


def unbalance_figure(r: UnbalanceResult, speed_limit_rpm: float | None = None):
    """0-peak amplitude (log) and phase at the output DOF over speed; the 1x crossings marked; the speeds above the
    spindle's thermal speed limit shaded."""
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
    if speed_limit_rpm is not None:
        a1.set_xlim(r.speed_rpm[0], r.speed_rpm[-1])
        shade_above_speed_limit([a1, a2], speed_limit_rpm)
        a1.legend(fontsize=8, loc="upper left")
    return fig
