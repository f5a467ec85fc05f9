"""``spindlesim transient`` on a rotor deck with nonlinear bearings (seed 001 section 2-2).

Static equilibrium with the full nonlinear bearing reactions, then Newmark time integration
(spindlesim.analysis.rotor_transient) with the deck's unbalance and/or an initial
perturbation; spectrum of the steady part, Poincare map once per revolution (the time step
divides the revolution exactly, so the samples are grid points), and the linearised natural
frequencies at the same static state for comparison (modal analysis).
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..deck.loader import require_rotor
from ..model.build import build_rotor
from .rotor_transient import RotorTransientResult, integrate, unbalance_force
from .spectrum import amplitude_spectrum

log = logging.getLogger(__name__)


@dataclass(frozen=True)
class RotorTransientStudy:
    transient: RotorTransientResult
    record_node: int  # 0-based
    speed_rpm: float
    steps_per_revolution: int
    spectrum_frequency_hz: np.ndarray
    spectrum_amplitude_m: np.ndarray  # [f, 2]
    poincare_xy_m: np.ndarray  # [k, 2]
    linearized_frequency_hz: np.ndarray  # modal at the static state
    linearized_whirl: tuple[str, ...]
    static_displacement_m: np.ndarray  # [2] at the record node
    roller_pressure: object = None  # most loaded DTRB roller at the static state (RollerPressure) or None


def nonlinear_bearings(rotor):
    return [b for b in rotor.bearings if hasattr(b, "force_and_tangent")]


def solve_rotor_transient(deck, progress=None) -> RotorTransientStudy:
    from ..fe.assembly import assemble_shaft, bearing_static_loads, load_vector, system_matrices
    from .modal import solve_modal

    cfg = deck.rotor_transient
    if cfg is None:
        from ..deck.schema import RotorTransientSection

        cfg = RotorTransientSection()
    rotor = build_rotor(deck)
    nl = nonlinear_bearings(rotor)
    if not nl:
        raise ValueError("the rotor transient needs a nonlinear bearing (e.g. type: dtrb) in 'bearings'")
    node = (cfg.record_node - 1) if cfg.record_node is not None else nl[0].node
    W = rotor.speed_rad_s
    if W <= 0:
        raise ValueError("the rotor transient needs operating.speed_rpm > 0")
    # a whole number of steps per revolution: Poincare samples fall on the grid
    t_rev = 2 * math.pi / W
    n_rev = max(8, math.ceil(t_rev / cfg.time_step_s))
    dt = t_rev / n_rev
    # static equilibrium with the nonlinear bearings (linear bearings enter K, C)
    linear = [b for b in rotor.bearings if b not in nl]
    lin_rotor = _with_bearings(rotor, linear)
    shaft = assemble_shaft(rotor)
    loads = bearing_static_loads(rotor, shaft)
    q_static = _static_state(lin_rotor, nl, loads)
    modal = solve_modal(rotor, n_modes=6, shaft=shaft)
    q0 = q_static.copy()
    if cfg.perturbation is not None:
        # released static force: the initial shape is the linearised deflection under it
        from ..fe.assembly import system_matrices as _sm

        p = cfg.perturbation
        e = np.zeros(rotor.dofs.size)
        e[rotor.dofs.index(p.node - 1, p.dof)] = p.force_N
        q0 += np.linalg.solve(_sm(rotor, shaft, W, loads).K, e)
    forces = []
    if cfg.unbalance and deck.unbalance is not None:
        forces.append(unbalance_force(rotor, deck.unbalance.node - 1, deck.unbalance.amount_g_mm * 1e-6,
                                      math.radians(deck.unbalance.phase_deg)))
    for b in nl:
        if hasattr(b, "speed_rad_s"):
            b.speed_rad_s = W
    res = integrate(lin_rotor, cfg.duration_s, dt, nonlinear=nl, forces=forces, q0=q0, record_nodes=[node],
                    progress=progress)
    xy = res.displacement_m[:, 0, :2]
    start = int(cfg.settle_fraction * (len(res.time_s) - 1))
    spec = amplitude_spectrum(xy[start:], 1.0 / dt)
    first = start + (-start) % n_rev
    poincare = xy[first::n_rev]
    static_xy = q_static[[rotor.dofs.index(node, "x"), rotor.dofs.index(node, "y")]]
    del system_matrices, load_vector
    pressure = None
    dtrb = next((b for b in nl if hasattr(b, "equilibrium") and hasattr(b, "geometry")), None)
    if dtrb is not None and loads is not None and dtrb.name in loads:
        from ..bearings.rolling.dtrb.roller_pressure import most_loaded_roller_pressure

        pressure = most_loaded_roller_pressure(dtrb.geometry, dtrb.equilibrium(loads[dtrb.name], W))
    return RotorTransientStudy(
        transient=res, record_node=node, speed_rpm=rotor.speed_rpm, steps_per_revolution=n_rev,
        spectrum_frequency_hz=spec.frequency_hz, spectrum_amplitude_m=spec.amplitude, poincare_xy_m=poincare,
        linearized_frequency_hz=modal.frequency_hz, linearized_whirl=modal.whirl, static_displacement_m=static_xy,
        roller_pressure=pressure)


def _with_bearings(rotor, bearings):
    from dataclasses import replace

    return replace(rotor, bearings=tuple(bearings))


def _static_state(lin_rotor, nl, loads):
    """Displacement at static equilibrium: linear bearings in K, the nonlinear ones by Newton."""
    from .rotor_transient import static_equilibrium

    return static_equilibrium(lin_rotor, nl)


def run_rotor_transient(loaded, outdir: Path, run, opts, progress) -> list[Path]:
    from ..output.figures import new_figure, save_figure
    from ..output.hdf5 import RunInfo, write_h5

    require_rotor(loaded, "transient")
    st = solve_rotor_transient(loaded.deck, progress=progress)
    tr = st.transient
    if not tr.complete:
        run = RunInfo(run.deck_text, run.deck_source, run.deck_sha256, run.command_line, False, tr.reason)
    xy = tr.displacement_m[:, 0, :2]
    nb = len([b for b in build_rotor(loaded.deck).bearings if hasattr(b, "force_and_tangent")])
    f_rev = st.speed_rpm / 60
    paths = [write_h5(outdir / "transient.h5", run, {
        "/transient/time_s": (tr.time_s, "s"),
        "/transient/displacement_m": (xy, "m"),
        "/transient/displacement_all_dofs": (tr.displacement_m[:, 0, :], "m, rad (" + ", ".join(tr.dof_names) + ")"),
        "/transient/bearing_force_N": (tr.bearing_force_N, "N, N m (force on the shaft)"),
        "/transient/spectrum/frequency_hz": (st.spectrum_frequency_hz, "Hz"),
        "/transient/spectrum/amplitude_m": (st.spectrum_amplitude_m, "m"),
        "/transient/poincare/x_m": (st.poincare_xy_m[:, 0], "m"),
        "/transient/poincare/y_m": (st.poincare_xy_m[:, 1], "m"),
        "/transient/linearized_frequency_hz": (st.linearized_frequency_hz, "Hz"),
        "/transient/static_displacement_m": (st.static_displacement_m, "m"),
        "/transient/newton_iterations": (tr.newton_iterations, "1"),
    }, {"/transient": {"model": "rotor", "record_node": st.record_node + 1, "speed_rpm": st.speed_rpm,
                       "revolution_frequency_hz": f_rev, "steps_per_revolution": st.steps_per_revolution,
                       "nonlinear_bearings": nb, "complete": tr.complete, "reason": tr.reason,
                       "poincare_sampling": "once per revolution"}})]
    fig = new_figure(9, 7)
    a1, a2 = fig.subplots(2, 1)
    a1.plot(tr.time_s, xy[:, 0] * 1e6, lw=0.8, label="x")
    a1.plot(tr.time_s, xy[:, 1] * 1e6, lw=0.8, label="y")
    a1.set_xlabel("time [s]")
    a1.set_ylabel("displacement [um]")
    a1.set_title(f"Node {st.record_node + 1} at {st.speed_rpm:g} rpm" + ("" if tr.complete else " (INCOMPLETE)"))
    a1.legend()
    a1.grid(True, alpha=0.3)
    a2.semilogy(st.spectrum_frequency_hz, np.maximum(st.spectrum_amplitude_m[:, 0], 1e-15) * 1e6, lw=0.8, label="x")
    for k, f in enumerate(st.linearized_frequency_hz[:4]):
        a2.axvline(f, color="tab:red", ls=":", lw=0.8, label="linearised modes" if k == 0 else None)
    a2.axvline(f_rev, color="k", ls="--", lw=0.8, label="1x")
    a2.set_xlim(0, max(3 * st.linearized_frequency_hz[:2].max(), 5 * f_rev))
    a2.set_xlabel("frequency [Hz]")
    a2.set_ylabel("amplitude [um]")
    a2.legend(fontsize=8)
    a2.grid(True, which="both", alpha=0.3)
    paths.append(save_figure(fig, outdir / "transient_time_spectrum.png"))
    fig = new_figure(6, 6)
    ax = fig.subplots()
    steady = xy[int(0.3 * len(xy)):]
    ax.plot(steady[:, 0] * 1e6, steady[:, 1] * 1e6, lw=0.5, color="0.6", label="orbit")
    ax.plot(st.poincare_xy_m[:, 0] * 1e6, st.poincare_xy_m[:, 1] * 1e6, "o", ms=3, color="tab:red",
            label="Poincare (once per rev)")
    ax.set_xlabel("x [um]")
    ax.set_ylabel("y [um]")
    ax.set_aspect("equal", adjustable="datalim")
    ax.legend(fontsize=8)
    ax.grid(True, alpha=0.3)
    paths.append(save_figure(fig, outdir / "transient_orbit.png"))
    if st.roller_pressure is not None:
        # most loaded roller at the static state, half-space solver (seed 001 eqs. 42-46)
        from ..contact.analysis import write_contact
        from ..contact.plots import pressure_map_figure, roller_profile_figure

        rp = st.roller_pressure
        paths.append(write_contact(outdir / "contact.h5", run, rp.contact, {
            "source": "most loaded roller of the DTRB at the rotor's static equilibrium",
            "row": rp.row + 1, "roller": rp.roller + 1, "tilt_rad": rp.tilt_rad}))
        paths.append(save_figure(pressure_map_figure(rp.contact, f"Most loaded DTRB roller (row {rp.row + 1}), "
                                                     f"Q = {rp.roller_load_N:.0f} N"), outdir / "contact_pressure.png"))
        paths.append(save_figure(roller_profile_figure(rp.contact), outdir / "contact_roller.png"))
    return paths
