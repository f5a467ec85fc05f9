"""``spindlesim transient``: the rotor in time with its bearings' full nonlinear reactions.

A rotor deck (``shaft:`` or ``journal:``, settings in ``rotor_transient:``), or the rig section
``transient:`` (seed 000's rigid journal in a roller bearing, ``model.rig``), through the one
engine (``analysis.transient.engine``).  Options: rollers, model (override every ``type: roller``
bearing, or the rig's), duration_s, plots.  Writes transient.h5 and PNGs; the linear modes at the
static state go into the file and onto the spectrum.  A DTRB's most loaded roller gets the
half-space contact pressure at the static state (seed 001 Fig. 13).  A run that stops early still
writes its files (complete = False) and then raises ``status.IncompleteRun`` (interrupted or not).
"""

from __future__ import annotations

import logging
import math
from pathlib import Path
from typing import Any

import numpy as np

from ..deck.loader import require_rotor
from ..deck.describe import bearing_entries, operating_text
from .common import first, operating_points, plots_wanted
from .status import IncompleteRun, Written, is_interrupt

log = logging.getLogger(__name__)
RPM = math.pi / 30.0
#: scipy method names of the rig section's integrator.method
_RIG_METHODS = {"RK4": "rk4"}
#: bound of the flexible race's default RK4 step [s]: its segment-on-housing and beam modes (about 200 kHz)
#: set the step through the stability limit (about 1.4 us with the default housing), not the accuracy of the
#: kHz response; the rigid race keeps the engine's 1 us (issue 4)
FLEXIBLE_RACE_STEP_BOUND = 2e-6


def _override_rollers(deck: Any, rollers: int | None, model: str | None) -> Any:
    """The deck with --rollers / --model applied to every bearing entry that has those keys."""
    if rollers is None and model is None:
        return deck
    new = []
    for b in deck.bearings:
        upd = {k: v for k, v in (("rollers", rollers), ("model", model)) if v is not None and k in type(b).model_fields}
        new.append(type(b).model_validate({**dict(b), **upd}) if upd else b)
    return deck.model_copy(update={"bearings": new})


def rig_setup(sec: Any, opts: dict):
    """(rotor, settings) of the rig section ``transient:``."""
    from ..analysis.transient.engine import RK4_STEP, TransientSettings
    from ..model.rig import rig_rotor

    model = opts.get("model") or sec.model
    rotor = rig_rotor(sec, opts.get("rollers"), model)
    T = first(opts.get("duration_s"), sec.duration_s)
    it = sec.integrator
    settings = TransientSettings(
        T, method=_RIG_METHODS.get(it.method, it.method),
        step_s=it.step_us * 1e-6 if it.step_us else None, sample_rate_hz=it.sample_rate_hz,
        settle_s=sec.settle_s if sec.settle_s is not None and sec.settle_s < T else 0.4 * T,
        record_node=0, rtol=it.rtol or (1e-5 if model == "flexible_race" else 1e-7), chunks=it.chunks,
        rk4_step_bound_s=FLEXIBLE_RACE_STEP_BOUND if model == "flexible_race" else RK4_STEP)
    return rotor, settings


def rotor_setup(deck: Any, opts: dict):
    """(rotor, settings) of a rotor deck and its ``rotor_transient:`` section."""
    from ..analysis.transient.engine import Perturbation, TransientSettings
    from ..analysis.transient.system import Excitation, TimeLoad, Unbalance
    from ..deck.transient import RotorTransientSection
    from ..model.build import build_rotor

    cfg = deck.rotor_transient or RotorTransientSection()
    rotor = build_rotor(_override_rollers(deck, opts.get("rollers"), opts.get("model")))
    dofs = rotor.dofs
    T = first(opts.get("duration_s"), cfg.duration_s)
    unb = ()
    if cfg.unbalance and deck.unbalance is not None:
        u = deck.unbalance
        unb = (Unbalance(dofs.index(u.node - 1, "x"), dofs.index(u.node - 1, "y"), u.amount_g_mm * 1e-6,
                         math.radians(u.phase_deg)),)
    loads = tuple(TimeLoad(dofs.index(ld.node - 1, ld.dof), ld.amplitude_N, ld.kind,
                           2 * math.pi * (ld.frequency_hz or 0.0), ld.order or 0.0, math.radians(ld.phase_deg),
                           ld.time_s) for ld in cfg.loads)
    pert = None
    if cfg.perturbation is not None:
        p = cfg.perturbation
        pert = Perturbation(dofs.index(p.node - 1, p.dof), p.force_N)
    ramp = None if cfg.speed_rpm is None else (cfg.speed_rpm.start, cfg.speed_rpm.stop)
    settings = TransientSettings(
        T, method=cfg.method, step_s=cfg.time_step_s, sample_rate_hz=cfg.sample_rate_hz,
        settle_s=cfg.settle_fraction * T, speed_rpm=ramp,
        record_node=None if cfg.record_node is None else cfg.record_node - 1,
        excitation=Excitation(unb, loads), perturbation=pert, rtol=cfg.rtol or 1e-8)
    return rotor, settings


def run(loaded: Any, outdir: Path, run_info: Any, opts: dict, progress: Any = None) -> Written:
    from ..analysis.modal import solve_modal
    from ..analysis.transient.engine import simulate
    from ..analysis.transient.result import TransientStudy
    from ..output.transient_writer import write_transient

    d = loaded.deck
    thermal_attrs: dict = {}
    if d.transient is not None and d.shaft is None and d.journal is None:
        rotor, settings = rig_setup(d.transient, opts)
    else:
        require_rotor(loaded, "transient")
        rotor, settings = rotor_setup(d, opts)
        rotor, thermal_attrs = _at_thermal_equilibrium(loaded, rotor, settings)

    def report(fraction: float, t: float) -> None:
        if progress is not None:
            progress(int(round(1000 * fraction)), 1000)

    res = simulate(rotor, settings, progress=report)
    start_rpm = res.speed_rpm[0] if res.speed_rpm.size else rotor.speed_rpm
    try:
        modal_hz = solve_modal(rotor, speed_rpm=start_rpm, n_modes=6).frequency_hz
    except (ValueError, ArithmeticError, np.linalg.LinAlgError) as exc:
        log.warning("no linear modes at the static state: %s", exc)
        modal_hz = None
    paths = [write_transient(outdir / "transient.h5", run_info, res, modal_hz, extra_attrs=thermal_attrs)]
    if plots_wanted(opts):
        paths += _figures(outdir, res, modal_hz, settings.speed_rpm is not None, operating_text(d))
    study = TransientStudy(res, modal_hz, thermal_attrs.get("thermal_equilibrium_rpm"))
    interrupted = not res.complete and is_interrupt(res)
    also: tuple = ()
    if not interrupted:  # the static roller pressure does not depend on the time history
        more, also = _dtrb_roller_pressure(loaded, rotor, outdir, run_info, opts)
        paths += more
    if res.complete:
        return Written(study, tuple(paths), also=also)
    log.info("transient run incomplete (%s); wrote what was computed", res.reason)
    raise IncompleteRun(f"transient run incomplete: {res.reason}", paths, interrupted=interrupted, result=study,
                        noted=res.reason, also=also)


def _figures(outdir: Path, res, modal_hz, run_up: bool, op: str) -> list[Path]:
    """The run's figures: time, orbit, spectrum, Poincare, the run-up, each bearing's outputs."""
    from ..output import transient_plots as tp
    from ..output.drawing import draw

    shown = tp.for_figures(res)  # what a figure process is sent: no rotor DOFs, no bearing forces
    figs = [("transient_time.png", tp.time_figure, (shown, op)),
            ("transient_orbit.png", tp.orbit_figure, (shown, op)),
            ("transient_spectrum.png", tp.spectrum_figure, (shown, modal_hz, op)),
            ("transient_poincare.png", tp.poincare_figure, (shown, op))]
    if run_up:
        figs.append(("transient_run_up.png", tp.run_up_figure, (shown, None, op)))
    for b, outs in enumerate(shown.bearing_outputs):
        for name in outs:
            figs.append((f"transient_{res.bearing_names[b]}_{name}.png", tp.bearing_output_figure,
                         (shown, b, name, op)))
    return [draw(outdir / name, figure, *args) for name, figure, args in figs]


def _at_thermal_equilibrium(loaded, rotor, settings):
    """With ``spindle_thermal: {analyses: steady}``: the rotor on its bearings at the spindle's thermal
    equilibrium of the run's (starting) speed, held through the run (temperatures change in minutes, a transient
    lasts seconds), and the attributes that say so; otherwise the rotor as it is."""
    points = operating_points(loaded)
    if points.thermal is None:
        return rotor, {}
    from ..analysis.spindle_thermal import SpindleThermal

    rpm = float(settings.speed_rpm[0]) if settings.speed_rpm is not None else float(rotor.speed_rpm)
    state = points.thermal_state(rpm)
    warm, _, _ = SpindleThermal(rotor, points.thermal.model, points.shaft).rotor_at(state.temperatures_C)
    log.info("transient: bearings at the thermal equilibrium of %g rpm", rpm)
    return warm, {"thermal_equilibrium_rpm": rpm}


def _dtrb_roller_pressure(loaded, rotor, outdir, run_info, opts) -> tuple[list[Path], tuple]:
    """Contact pressure of the most loaded roller of each DTRB at the static state (seed 001 eqs. 42-46): the paths
    written and, for the summary, (file name, "contact", the contact result) of each."""
    entries = [e for _, e in bearing_entries(loaded.deck, "dtrb")]
    if not entries:
        return [], ()
    from ..bearings.dtrb.roller_pressure import roller_pressure_under
    from ..contact.plots import pressure_map_figure, roller_profile_figure
    from ..output.figures import save_figure
    from ..output.contact_writer import write_contact

    st = operating_points(loaded).state(rotor.speed_rpm)  # the run's shared static state
    paths: list[Path] = []
    also = []
    for e in entries:
        b = next(b for b in st.bearings if b.name == e.name)
        rp = roller_pressure_under(b, st.load_of(b.name), st.speed_rad_s)
        stem = "contact" if len(entries) == 1 else f"contact_{e.name}"
        paths.append(write_contact(outdir / f"{stem}.h5", run_info, rp.contact, {
            "source": f"most loaded roller of DTRB {e.name!r} at the rotor's static equilibrium",
            "row": rp.row + 1, "roller": rp.roller + 1, "tilt_rad": rp.tilt_rad}))
        also.append((f"{stem}.h5", "contact", rp.contact))
        if plots_wanted(opts):
            paths.append(save_figure(pressure_map_figure(
                rp.contact, f"Most loaded roller of {e.name!r} (row {rp.row + 1}), Q = {rp.roller_load_N:.0f} N"),
                outdir / f"{stem}_pressure.png"))
            paths.append(save_figure(roller_profile_figure(rp.contact), outdir / f"{stem}_roller.png"))
    return paths, tuple(also)
