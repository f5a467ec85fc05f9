"""Ball bearing figures (matplotlib object API, no pyplot): load distribution, stiffness against
preload and speed, contact angles against speed.  Plots only draw results; every title states the
operating point."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from .results import BallState, BallSweep

if TYPE_CHECKING:
    from matplotlib.figure import Figure

COLORS = ("tab:blue", "tab:red", "tab:green", "tab:purple")
STIFFNESS_TERMS = ((0, 0, "K_xx", 1e-6, "N/um"), (2, 2, "K_zz", 1e-6, "N/um"), (3, 3, "K_theta_x", 1.0, "N m/rad"))


def _figure(w: float, h: float) -> Figure:
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(w, h), layout="constrained")
    FigureCanvasAgg(fig)
    return fig


def row_style(k: int, n: int) -> dict:
    """Line style of row ``k`` against a sweep of ``n`` points: the first row wide and pale under the
    others, each later row thinner with its own marker, so rows that carry the same (a DB pair under a
    radial load) read as two lines on top of each other, not one."""
    marks = ("", "o", "s", "^")
    return dict(color=COLORS[k % 4], lw=3.2 if k == 0 else 1.3, alpha=0.45 if k == 0 else 1.0,
                marker=marks[k % 4] or None, ms=4, mfc="none", markevery=max(1, n // 8), zorder=2 + k)


def _row_label(state_or_sweep, k: int) -> str:
    z = getattr(state_or_sweep, "row_z_m", None)
    s = int(state_or_sweep.row_sign[k])
    where = "" if z is None else f" at z {z[k] * 1e3:+.3g} mm"
    return f"row {k + 1}{where} ({'+' if s > 0 else '-'}z thrust)"


def _deg(x: float) -> str:
    return f"{round(float(x), 1) + 0.0:.1f}"  # + 0.0: no "-0.0" for a round-off below zero


def state_label(state: BallState) -> str:
    """Operating point of a state: load on the bearing and speed."""
    from .sweeps import _load_label

    return f"{_load_label(state.applied_load())}, {state.speed_rpm:.6g} rpm"


def plot_load_distribution(state: BallState, title: str | None = None) -> Figure:
    """Inner and outer contact loads of every ball against its azimuth, one polar panel per row;
    ``title`` (default: load and speed of the state) heads the figure."""
    title = state_label(state) if title is None else title
    rows = state.row_sign.size
    fig = _figure(max(7.5, 4.3 * rows), 4.9)
    for k in range(rows):
        ax = fig.add_subplot(1, rows, k + 1, projection="polar")
        psi = np.append(state.psi_rad[k], state.psi_rad[k][0])
        for data, style, lab in ((state.element_load_outer_N, "-o", "outer Q_o"),
                                 (state.element_load_inner_N, "--s", "inner Q_i")):
            q = np.append(data[k], data[k][0])
            ax.plot(psi, q, style, color=COLORS[k % 4], ms=3, lw=1.1, label=lab)
        a_i, a_o = state.contact_angle_inner_deg[k], state.contact_angle_outer_deg[k]
        ax.set_title(f"{_row_label(state, k)}\nthrust {state.row_axial_load_N[k]:.4g} N; alpha_i "
                     f"{_deg(a_i.min())} to {_deg(a_i.max())} deg, alpha_o {_deg(a_o.min())} to {_deg(a_o.max())} deg",
                     fontsize=8)
        ax.tick_params(labelsize=7)
    # one legend under the panels, inside the figure (constrained layout makes room for it)
    fig.legend(*fig.axes[0].get_legend_handles_labels(), loc="outside lower center", ncols=2, fontsize=8,
               title="each row in its colour", title_fontsize=7)
    fig.suptitle("Ball contact loads [N] against azimuth (x at 0 deg)\n" + title.replace("; ", ";\n", 1), fontsize=9)
    return fig


def plot_contact_ellipses(state: BallState, title: str | None = None) -> Figure:
    """Contact angle of every ball against its azimuth with the span of its contact ellipse along the groove
    (a -/+ asin(a_H / (f D))) and the shoulder angle of each ring, one panel per row: a band above its
    ring's dashed line is a truncated contact."""
    title = state_label(state) if title is None else title
    rows = state.row_sign.size
    fig = _figure(max(9.0, 5.2 * rows), 4.6)
    for k in range(rows):
        ax = fig.add_subplot(1, rows, k + 1)
        psi = np.degrees(state.psi_rad[k]) % 360.0
        order = np.argsort(psi)
        for race, color, sh in (("inner", "tab:red", state.shoulder_angle_inner_deg),
                                ("outer", "tab:blue", state.shoulder_angle_outer_deg)):
            alpha = getattr(state, f"contact_angle_{race}_deg")[k][order]
            edge = getattr(state, f"edge_angle_{race}_deg")[k][order]
            loaded = getattr(state, f"element_load_{race}_N")[k][order] > 0.0
            cut = getattr(state, f"truncated_{race}")[k][order]
            x = psi[order]
            ax.plot(x, alpha, "-o", color=color, ms=3, lw=1.1, label=f"{race} contact angle")
            lo = np.where(loaded, 2.0 * alpha - edge, alpha)
            ax.fill_between(x, lo, np.where(loaded, edge, alpha), color=color, alpha=0.15, lw=0,
                            label=f"{race} ellipse span")
            ax.axhline(sh, color=color, ls="--", lw=1.0, label=f"{race} shoulder {sh:.3g} deg")
            if np.any(cut):
                ax.plot(x[cut], edge[cut], "x", color="k", ms=7, mew=1.5, label=f"{race}: truncated")
        ax.set_xlabel("ball azimuth psi [deg] (x at 0)")
        ax.set_ylabel("angle in the groove from the radial direction [deg]")
        ax.set_title(_row_label(state, k), fontsize=8)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=6, loc="best")
    fig.suptitle(f"Contact ellipses against the shoulders (truncation check), model {state.model}\n"
                 + title.replace("; ", ";\n", 1), fontsize=9)
    return fig


def _stiffness_panels(fig: Figure, x: np.ndarray, sweep: BallSweep, x_label: str) -> None:
    for i, (a, b, name, scale, unit) in enumerate(STIFFNESS_TERMS):
        ax = fig.add_subplot(1, len(STIFFNESS_TERMS), i + 1)
        ax.plot(x, sweep.stiffness[:, a, b] * scale, "k-o", ms=3, lw=1.4)
        ax.set_xlabel(x_label)
        ax.set_ylabel(f"{name} [{unit}]")
        ax.grid(True, alpha=0.3)
        if i == 1:
            tw = ax.twinx()
            for k in range(sweep.row_sign.size):
                tw.plot(x, sweep.row_axial_load_N[:, k], ls=":", label=f"thrust row {k + 1} [N]",
                        **row_style(k, len(x)))
            tw.set_ylabel("row thrust [N]")
            thrust = sweep.row_axial_load_N
            if np.ptp(thrust) <= 1e-6 * max(1.0, float(np.max(np.abs(thrust)))):  # constant: no round-off scale
                mid = float(np.mean(thrust))
                tw.set_ylim(mid - 0.1 * abs(mid) - 1.0, mid + 0.1 * abs(mid) + 1.0)
            tw.legend(fontsize=7, loc="best")


def plot_stiffness_vs_preload(sweep: BallSweep, title: str = "") -> Figure:
    """Radial, axial and tilt stiffness of the set against the preload (row thrust on the axial panel)."""
    fig = _figure(14.0, 4.2)
    unit = "um" if sweep.name.endswith("um") else "N"
    _stiffness_panels(fig, sweep.values, sweep, f"preload axial [{unit}]")
    fig.suptitle(f"Stiffness against preload; {sweep.preload_label}\n{title}".strip(), fontsize=9)
    return fig


def plot_stiffness_vs_speed(sweep: BallSweep, title: str = "") -> Figure:
    """Radial, axial and tilt stiffness against shaft speed (row thrust on the axial panel)."""
    fig = _figure(14.0, 4.2)
    _stiffness_panels(fig, sweep.values, sweep, "speed [rpm]")
    fig.suptitle(f"Stiffness against speed; {sweep.preload_label}\n{title}".strip(), fontsize=9)
    return fig


def plot_contact_angles_vs_speed(sweep: BallSweep, title: str = "") -> Figure:
    """Inner and outer contact angles (range over the balls of each row) and contact loads against speed;
    the speeds with a truncated contact are marked."""
    fig = _figure(11.0, 4.2)
    ax = fig.add_subplot(1, 2, 1)
    ax2 = fig.add_subplot(1, 2, 2)
    x = sweep.values
    for k in range(sweep.row_sign.size):
        c = COLORS[k % 4]
        for data, style, lab in ((sweep.contact_angle_inner_deg, "-", "inner"),
                                 (sweep.contact_angle_outer_deg, "--", "outer")):
            d = data[:, k, :]
            ax.plot(x, d.mean(axis=1), ls=style, label=f"{lab}, row {k + 1}", **row_style(k, len(x)))
            if np.ptp(d, axis=1).max() > 1e-6:
                ax.fill_between(x, d.min(axis=1), d.max(axis=1), color=c, alpha=0.12, lw=0)
        for data, style, lab in ((sweep.element_load_inner_N, "-", "Q_i max"),
                                 (sweep.element_load_outer_N, "--", "Q_o max")):
            ax2.plot(x, data[:, k, :].max(axis=1), ls=style, label=f"{lab}, row {k + 1}", **row_style(k, len(x)))
    cut = np.any(sweep.truncated_inner | sweep.truncated_outer, axis=(1, 2))
    if np.any(cut):
        ax.plot(x[cut], np.max(sweep.contact_angle_inner_deg[cut], axis=(1, 2)), "kx", ms=7,
                label="contact ellipse truncated")
    ax.set_xlabel("speed [rpm]")
    ax.set_ylabel("contact angle [deg]")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7, title="lines: mean over the balls\nbands: range over the balls", title_fontsize=7)
    ax2.set_xlabel("speed [rpm]")
    ax2.set_ylabel("largest contact load [N]")
    ax2.grid(True, alpha=0.3)
    ax2.legend(fontsize=7)
    fig.suptitle(f"Contact angles and loads against speed; {sweep.preload_label}\n{title}".strip(), fontsize=9)
    return fig


def figures(run) -> dict[str, Figure]:
    """All figures of a :class:`~.sweeps.BallRun`, keyed by a file stem."""
    title = run.title()
    out = {"ball_load_distribution": plot_load_distribution(run.state, title),
           "ball_contact_ellipses": plot_contact_ellipses(run.state, title)}
    if "preload" in run.sweeps:
        out["ball_stiffness_vs_preload"] = plot_stiffness_vs_preload(run.sweeps["preload"], _bearing_line(run))
    if "speed" in run.sweeps:
        out["ball_stiffness_vs_speed"] = plot_stiffness_vs_speed(run.sweeps["speed"], _bearing_line(run))
        out["ball_contact_angles_vs_speed"] = plot_contact_angles_vs_speed(run.sweeps["speed"], _bearing_line(run))
    return out


def _bearing_line(run) -> str:
    g = run.bearing.geometry
    kind = g.arrangement if g.arrangement != "single" else "single row"
    return (f"{run.bearing.name}: {kind}, {g.balls} x {g.ball_diameter_m * 1e3:.4g} mm balls, d_m "
            f"{g.pitch_diameter_m * 1e3:.4g} mm, {math.degrees(g.contact_angle_rad):.3g} deg, "
            f"model {run.model_setting}")
