"""The linear rotor analyses: static, modal, Campbell, FRF, unbalance (deck -> physics -> files)."""

from __future__ import annotations

import logging

import numpy as np

from ..deck.loader import require_rotor
from ..model.build import build_rotor
from .common import first, plots_wanted, value_range

log = logging.getLogger(__name__)


def run_static(loaded, outdir, run, opts, progress):
    from ..analysis.static import solve_static
    from ..output.rotor_plots import plot_static
    from ..output.rotor_writers import write_static

    require_rotor(loaded, "static")
    d = loaded.deck
    rotor = build_rotor(d, speed_rpm=opts.get("speed_rpm"))
    at = d.static.stiffness_at
    res = solve_static(rotor, at.node - 1, at.dof)
    log.info("static stiffness at node %d %s: %.4g N/um", at.node, at.dof, res.static_stiffness_N_m / 1e6)
    paths = [write_static(outdir / "static.h5", run, res)]
    if plots_wanted(opts):
        paths.append(plot_static(res, outdir / "static_deflection.png"))
    return paths


def run_modal(loaded, outdir, run, opts, progress):
    from ..analysis.modal import solve_modal
    from ..output.rotor_plots import plot_modes
    from ..output.rotor_writers import write_modal

    require_rotor(loaded, "modal")
    d = loaded.deck
    speed = first(opts.get("speed_rpm"), d.modal.speed_rpm)
    rotor = build_rotor(d, speed_rpm=speed)
    res = solve_modal(rotor, n_modes=first(opts.get("modes"), d.modal.modes))
    paths = [write_modal(outdir / "modal.h5", run, res)]
    if plots_wanted(opts):
        paths.append(plot_modes(res, outdir / "modal_shapes.png"))
    return paths


def run_campbell(loaded, outdir, run, opts, progress):
    from ..analysis.campbell import solve_campbell
    from ..output.rotor_plots import plot_campbell
    from ..output.rotor_writers import write_campbell

    require_rotor(loaded, "campbell")
    d = loaded.deck
    speeds = opts.get("speeds_rpm")
    speeds = value_range(d.campbell.speeds_rpm) if speeds is None else np.asarray(speeds, float)
    rotor = build_rotor(d)
    res = solve_campbell(rotor, speeds, n_modes=first(opts.get("modes"), d.campbell.modes), progress=progress)
    paths = [write_campbell(outdir / "campbell.h5", run, res)]
    if plots_wanted(opts):
        paths.append(plot_campbell(res, outdir / "campbell.png"))
    return paths


def run_frf(loaded, outdir, run, opts, progress):
    from ..analysis.frf import solve_frf
    from ..output.rotor_plots import plot_frf
    from ..output.rotor_writers import write_frf

    require_rotor(loaded, "frf")
    d = loaded.deck
    fr = d.frf
    rotor = build_rotor(d, speed_rpm=first(opts.get("speed_rpm"), fr.speed_rpm))
    res = solve_frf(rotor, value_range(fr.frequencies_hz), fr.input.node, fr.input.dof, fr.output.node,
                    fr.output.dof)
    paths = [write_frf(outdir / "frf.h5", run, res)]
    if plots_wanted(opts):
        paths += list(plot_frf(res, outdir / "frf_magnitude_phase.png", outdir / "frf_real_imag.png"))
    return paths


def run_unbalance(loaded, outdir, run, opts, progress):
    from ..analysis.frf import solve_unbalance
    from ..output.rotor_plots import plot_unbalance
    from ..output.rotor_writers import write_unbalance

    require_rotor(loaded, "unbalance")
    d = loaded.deck
    u = d.unbalance
    if u is None:
        raise ValueError("the deck has no 'unbalance' section (node, amount_g_mm, speeds_rpm)")
    rotor = build_rotor(d)
    res = solve_unbalance(rotor, value_range(u.speeds_rpm), u.node, u.amount_g_mm * 1e-6, u.phase_deg,
                          u.output.node, u.output.dof)
    paths = [write_unbalance(outdir / "unbalance.h5", run, res)]
    if plots_wanted(opts):
        paths.append(plot_unbalance(res, outdir / "unbalance.png"))
    return paths
