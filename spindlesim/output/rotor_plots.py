"""PNG plots of rotor analyses (plots never compute physics beyond unit conversion)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..analysis.results import CampbellResult, FrfResult, ModalResult, StaticResult, UnbalanceResult
from .figures import new_figure, save_figure


def plot_static(r: StaticResult, path: Path) -> Path:
    fig = new_figure(8, 6)
    ax1, ax2 = fig.subplots(2, 1, sharex=True)
    z = r.node_z_m * 1e3
    ax1.plot(z, r.displacement_m[:, 0] * 1e6, "o-", label="x (horizontal)")
    ax1.plot(z, r.displacement_m[:, 1] * 1e6, "s-", label="y (vertical)")
    for name, node in zip(r.bearing_names, r.bearing_nodes):
        ax1.axvline(z[node], color="0.6", ls="--")
        ax1.annotate(name, (z[node], 0), textcoords="offset points", xytext=(3, 5), fontsize=8)
    ax1.set_ylabel("deflection [um]")
    ax1.set_title(f"Static deflection; stiffness at node {r.stiffness_node + 1} {r.stiffness_dof}: "
                  f"{r.static_stiffness_N_m / 1e6:.3g} N/um")
    ax1.legend()
    ax1.grid(True, alpha=0.3)
    ax2.plot(z, r.slope_rad[:, 0] * 1e6, "o-", label="theta_x")
    ax2.plot(z, r.slope_rad[:, 1] * 1e6, "s-", label="theta_y")
    ax2.set_xlabel("axial position z [mm]")
    ax2.set_ylabel("slope [urad]")
    ax2.legend()
    ax2.grid(True, alpha=0.3)
    return save_figure(fig, path)


def plot_modes(r: ModalResult, path: Path, max_modes: int = 8) -> Path:
    n = min(max_modes, len(r.frequency_hz))
    fig = new_figure(10, 2.0 * max(n, 1))
    axes = np.atleast_1d(fig.subplots(max(n, 1), 1, sharex=True))
    z = r.node_z_m * 1e3
    for k in range(n):
        ax = axes[k]
        shape = r.mode_shape[k]
        ax.plot(z, shape[:, 0].real, "o-", ms=3, label="x (real)")
        ax.plot(z, shape[:, 1].real, "s-", ms=3, label="y (real)")
        ax.plot(z, np.abs(shape[:, 0]), ":", color="0.5", label="|x|")
        ax.set_ylabel("amplitude [-]")
        ax.set_title(f"mode {k + 1}: {r.frequency_hz[k]:.1f} Hz, zeta {r.damping_ratio[k]:.4f}, "
                     f"log dec {r.log_dec[k]:.3f}, {r.whirl[k]}", fontsize=9)
        ax.grid(True, alpha=0.3)
    axes[0].legend(fontsize=7, loc="upper right")
    axes[-1].set_xlabel("axial position z [mm]")
    fig.suptitle(f"Damped mode shapes at {r.speed_rpm:g} rpm")
    return save_figure(fig, path)


def plot_campbell(r: CampbellResult, path: Path) -> Path:
    fig = new_figure(9, 7)
    ax1, ax2 = fig.subplots(2, 1, sharex=True, height_ratios=[3, 2])
    s = r.speed_rpm
    colors = {"forward": "tab:blue", "backward": "tab:red", "mixed": "tab:gray", "": "k"}
    for k in range(r.frequency_hz.shape[1]):
        ax1.plot(s, r.frequency_hz[:, k], color="0.8", lw=0.8)
        for w, c in colors.items():
            sel = r.whirl[:, k] == w
            if sel.any():
                ax1.scatter(s[sel], r.frequency_hz[sel, k], s=6, color=c)
        ax2.plot(s, r.log_dec[:, k], lw=1)
    ax1.plot(s, s / 60.0, "k--", lw=1, label="1x")
    for cs in r.critical_speeds_rpm:
        ax1.axvline(cs, color="tab:green", ls=":", lw=1)
    for w, c in list(colors.items())[:3]:
        ax1.scatter([], [], color=c, s=10, label=w)
    ax1.set_ylabel("damped natural frequency [Hz]")
    ax1.set_ylim(0, np.nanmax(r.frequency_hz) * 1.05)
    ax1.legend(fontsize=8)
    ax1.set_title("Campbell diagram (critical speeds dotted green)")
    ax1.grid(True, alpha=0.3)
    ax2.axhline(0, color="k", lw=0.8)
    ax2.set_ylabel("log decrement [-]")
    ax2.set_xlabel("speed [rpm]")
    ax2.set_yscale("symlog", linthresh=0.01)
    ax2.grid(True, alpha=0.3)
    return save_figure(fig, path)


def plot_frf(r: FrfResult, path_magphase: Path, path_reim: Path) -> tuple[Path, Path]:
    f, h = r.frequency_hz, r.receptance_m_N
    label = f"node {r.output_node} {r.output_dof} / node {r.input_node} {r.input_dof} at {r.speed_rpm:g} rpm"
    fig = new_figure(8, 6)
    a1, a2 = fig.subplots(2, 1, sharex=True)
    a1.semilogy(f, np.abs(h) * 1e6)
    a1.set_ylabel("|receptance| [um/N]")
    a1.set_title("Receptance " + label)
    a1.grid(True, which="both", alpha=0.3)
    a2.plot(f, np.degrees(np.angle(h)))
    a2.set_ylabel("phase [deg]")
    a2.set_xlabel("frequency [Hz]")
    a2.set_yticks([-180, -90, 0, 90, 180])
    a2.grid(True, alpha=0.3)
    p1 = save_figure(fig, path_magphase)
    fig = new_figure(8, 6)
    b1, b2 = fig.subplots(2, 1, sharex=True)
    b1.plot(f, h.real * 1e6)
    b1.set_ylabel("real part [um/N]")
    b1.set_title("Receptance " + label)
    b1.grid(True, alpha=0.3)
    b2.plot(f, h.imag * 1e6)
    b2.set_ylabel("imaginary part [um/N]")
    b2.set_xlabel("frequency [Hz]")
    b2.grid(True, alpha=0.3)
    return p1, save_figure(fig, path_reim)


def plot_unbalance(r: UnbalanceResult, path: Path) -> Path:
    fig = new_figure(8, 6)
    a1, a2 = fig.subplots(2, 1, sharex=True)
    node = r.output_node - 1
    comp = 0 if r.output_dof == "x" else 1
    q = r.response_m[:, node, comp]
    a1.semilogy(r.speed_rpm, np.abs(q) * 1e6)
    a1.set_ylabel("amplitude [um]")
    a1.set_title(f"Unbalance {r.unbalance_kg_m * 1e6:g} g mm at node {r.unbalance_node}: "
                 f"response at node {r.output_node} {r.output_dof}")
    a1.grid(True, which="both", alpha=0.3)
    a2.plot(r.speed_rpm, np.degrees(np.angle(q)))
    a2.set_ylabel("phase [deg]")
    a2.set_xlabel("speed [rpm]")
    a2.grid(True, alpha=0.3)
    return save_figure(fig, path)
