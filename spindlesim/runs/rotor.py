"""The linear rotor analyses: static, modal, Campbell, FRF, unbalance (deck -> physics -> files).

Each run hands back :class:`~.status.Written`: the analysis's frozen result (what the terminal summary and the
report read: output/rotor_summary.py) and the files written from it."""

from __future__ import annotations

import contextlib
import dataclasses
import logging

import numpy as np

from ..deck.document import NodeDof
from ..deck.loader import require_rotor, require_section
from ..output.drawing import draw
from .common import first, operating_points, plots_wanted, value_range
from .status import IncompleteRun, Written

log = logging.getLogger(__name__)


def run_static(loaded, outdir, run, opts, progress):
    from ..analysis.static import solve_static
    from ..output.rotor_plots import static_figure
    from ..output.rotor_writers import write_static

    require_rotor(loaded, "static")
    d = loaded.deck
    points = operating_points(loaded)
    at = d.static.stiffness_at
    res = solve_static(points, at.node - 1, at.dof, speed_rpm=first(opts.get("speed_rpm"), d.operating.speed_rpm))
    log.info("static stiffness at node %d %s: %.4g N/um", at.node, at.dof, res.static_stiffness_N_m / 1e6)
    paths = [write_static(outdir / "static.h5", run, res)]
    if plots_wanted(opts):
        paths.append(draw(outdir / "static_deflection.png", static_figure, res))
    return Written(res, tuple(paths))


def run_modal(loaded, outdir, run, opts, progress):
    from ..analysis.modal import solve_modal
    from ..output.rotor_plots import modes_figure
    from ..output.rotor_writers import write_modal

    require_rotor(loaded, "modal")
    d = loaded.deck
    speed = first(opts.get("speed_rpm"), d.modal.speed_rpm, d.operating.speed_rpm)
    points = operating_points(loaded)
    rotor = points.rotor
    res = solve_modal(points, speed, n_modes=first(opts.get("modes"), d.modal.modes))
    paths = [write_modal(outdir / "modal.h5", run, res)]
    if plots_wanted(opts):
        at: dict[float, str] = {}  # one mark per bearing position, named by the first bearing there
        for b in rotor.bearings:
            at.setdefault(float(rotor.node_z_m[b.node]), b.name)
        bearings = tuple((name, z) for z, name in at.items())
        paths.append(draw(outdir / "modal_shapes.png", modes_figure, res, bearings=bearings))
    return Written(res, tuple(paths))


def run_campbell(loaded, outdir, run, opts, progress):
    from ..analysis.campbell_study import campbell_study
    from ..output.campbell_plots import campbell_figure, campbell_frozen_figure, campbell_thermal_figure
    from ..output.rotor_writers import write_campbell

    require_rotor(loaded, "campbell")
    d = loaded.deck
    speeds = opts.get("speeds_rpm")
    speeds = value_range(d.campbell.speeds_rpm) if speeds is None else np.asarray(speeds, float)
    limit = _limit_aside(loaded, plots_wanted(opts))
    with _cancelled_on_error(limit):
        st = campbell_study(operating_points(loaded), speeds, first(opts.get("modes"), d.campbell.modes),
                            d.campbell.compare_frozen_rpm, excitation_orders(d), d.operating.speed_range_rpm,
                            bool(opts.get("exact")), progress, operating_rpm=d.operating.speed_rpm)
        res = st.hot
        if st.incomplete_reason:  # the speeds computed before a failure: written, marked incomplete
            run = dataclasses.replace(run, complete=False, incomplete_reason=st.incomplete_reason)
        paths = [write_campbell(outdir / "campbell.h5", run, res, st.frozen, st.frozen_rpm, st.cold, st.stiffness,
                                operating_rpm=st.operating_rpm)]
    if plots_wanted(opts):
        paths.append(draw(outdir / "campbell.png", campbell_figure, res, operating_rpm=d.operating.speed_rpm or None,
                          teeth=cutter_teeth(d), speed_limit_rpm=_limit(limit)))
        if st.frozen is not None:
            paths.append(draw(outdir / "campbell_frozen.png", campbell_frozen_figure, res, st.frozen, st.frozen_rpm))
        if st.cold is not None:
            paths.append(draw(outdir / "campbell_thermal.png", campbell_thermal_figure, res, st.cold, st.stiffness,
                              st.thermal_label))
    if st.incomplete_reason:  # the partial study, as its file notes it
        raise IncompleteRun(st.incomplete_reason, paths, interrupted=st.interrupted, result=st,
                            noted=run.incomplete_reason)
    return Written(st, tuple(paths))


def _limit_aside(loaded, wanted: bool):
    """The spindle's thermal speed limit a figure shades above, solved meanwhile in a forked process
    (``common.thermal_speed_limit_aside``) when figures are wanted; nothing otherwise."""
    from ..analysis.aside import Known
    from .common import thermal_speed_limit_aside

    return thermal_speed_limit_aside(loaded) if wanted else Known(None)


@contextlib.contextmanager
def _cancelled_on_error(pending):
    """The computation set aside stopped when what runs meanwhile fails or is interrupted."""
    try:
        yield
    except BaseException:
        pending.cancel()
        raise


def _limit(pending) -> float | None:
    """The highest speed the spindle runs at its thermal equilibrium (its thermal speed limit), or None, from
    :func:`_limit_aside`'s pending result."""
    with _cancelled_on_error(pending):
        lim = pending.result()
    return None if lim is None else lim[0]


def excitation_orders(d) -> tuple[float, ...]:
    """The excitation orders a Campbell diagram checks: 1x (unbalance), 2x (misalignment, a shaft's
    asymmetry) and, for a deck with a milling cutter, the tooth-passing order."""
    teeth = cutter_teeth(d)
    return tuple(sorted({1.0, 2.0} | ({float(teeth)} if teeth else set())))


def cutter_teeth(d) -> int | None:
    """The milling cutter's number of teeth (its tooth-passing order), None without a cutter."""
    return getattr(d.chatter, "teeth", None) if d.chatter is not None else None


def run_frf(loaded, outdir, run, opts, progress):
    from ..analysis.frf import solve_frf
    from ..output.rotor_plots import frf_magnitude_phase_figure, frf_real_imag_figure
    from ..output.rotor_writers import write_frf

    require_rotor(loaded, "frf")
    d = loaded.deck
    fr = d.frf
    points = operating_points(loaded)
    rotor = points.rotor
    speed = first(opts.get("speed_rpm"), fr.speed_rpm, d.operating.speed_rpm)
    tip = rotor.tool_tip + 1 if rotor.tool_tip is not None else 1
    inp, out = fr.input or NodeDof(node=tip, dof="x"), fr.output or NodeDof(node=tip, dof="x")
    f = value_range(fr.frequencies_hz)
    # with the tool point's 2 x 2 receptance (xx, xy; yx, yy) on the refined grid, where the rotor has a tool
    res = solve_frf(points, f, inp.node, inp.dof, out.node, out.dof, speed_rpm=speed, refine=True, tool_point=True)
    tool = res.tool_point
    paths = [write_frf(outdir / "frf.h5", run, res, tool)]
    if plots_wanted(opts):
        paths.append(draw(outdir / "frf_magnitude_phase.png", frf_magnitude_phase_figure, res))
        paths.append(draw(outdir / "frf_real_imag.png", frf_real_imag_figure, res))
        if tool is not None:
            from ..chatter.plots import frf_figure

            paths.append(draw(outdir / "frf_tool_point.png", frf_figure, tool, terms=("xx", "yy", "xy"),
                              title=f"Tool point (node {tip}) at {speed:g} rpm"))
    return Written(res, tuple(paths))


def run_unbalance(loaded, outdir, run, opts, progress):
    from ..analysis.unbalance import solve_unbalance
    from ..output.rotor_plots import unbalance_figure
    from ..output.rotor_writers import write_unbalance

    require_rotor(loaded, "unbalance")
    d = loaded.deck
    u = require_section(loaded, "unbalance", "unbalance", "node, amount_g_mm, output, speeds_rpm")
    limit = _limit_aside(loaded, plots_wanted(opts))
    with _cancelled_on_error(limit):
        res = solve_unbalance(operating_points(loaded), value_range(u.speeds_rpm), u.node, u.amount_g_mm * 1e-6,
                              u.phase_deg, u.output.node, u.output.dof, refine=True,
                              operating=d.operating.speed_range_rpm)
        paths = [write_unbalance(outdir / "unbalance.h5", run, res)]
    if plots_wanted(opts):
        paths.append(draw(outdir / "unbalance.png", unbalance_figure, res, speed_limit_rpm=_limit(limit)))
    return Written(res, tuple(paths))
