"""The ``transient`` analysis: deck section -> run -> transient.h5 + PNGs.

Registered with ``spindlesim.analysis.runner.register_analysis("transient", run_transient_analysis)``.
An incomplete run (interrupt, non-finite state, step collapse) is still written,
with root attributes complete = False and incomplete_reason.
"""

from __future__ import annotations

import dataclasses
import logging
from pathlib import Path
from typing import Any

from ...analysis.transient import TransientResult, run_transient

log = logging.getLogger(__name__)


def write_transient(path: Path, run: Any, res: TransientResult) -> Path:
    from ...output.hdf5 import write_h5

    run = dataclasses.replace(run, complete=res.complete, incomplete_reason=res.reason)
    data = {
        "/transient/time_s": (res.time_s, "s"),
        "/transient/displacement_m": (res.displacement_m, "m"),
        "/transient/roller_force_N": (res.roller_force_N, "N"),
        "/transient/spectrum/frequency_hz": (res.spectrum.frequency_hz, "Hz"),
        "/transient/spectrum/amplitude_m": (res.spectrum.amplitude, "m"),
        "/transient/poincare/time_s": (res.poincare_time_s, "s"),
        "/transient/poincare/x_m": (res.poincare_xy_m[:, 0], "m"),
        "/transient/poincare/y_m": (res.poincare_xy_m[:, 1], "m"),
        "/transient/poincare/vx_m_s": (res.poincare_v_m_s[:, 0], "m/s"),
        "/transient/poincare/vy_m_s": (res.poincare_v_m_s[:, 1], "m/s"),
    }
    if res.race_deflection_m is not None:
        data["/transient/race_deflection_m"] = (res.race_deflection_m, "m")
    attrs = {"/transient": {"rollers": res.rollers, "cage_frequency_hz": res.cage_frequency_hz,
                            "roller_pass_frequency_hz": res.roller_pass_frequency_hz, "model": res.model,
                            "settle_s": res.settle_s, "sample_rate_hz": res.sample_rate_hz,
                            "complete": res.complete, "incomplete_reason": res.reason,
                            "t_reached_s": res.t_reached_s, "wall_time_s": res.wall_time_s,
                            "integrator": res.method, "step_s": res.step_s}}
    return write_h5(path, run, data, attrs)


def run_transient_analysis(loaded: Any, outdir: Path, run: Any, options: dict | None = None,
                           progress: Any = None) -> list[Path]:
    """Run the deck's ``transient:`` section (defaults if absent); options: rollers, duration_s, model, plots."""
    from ...deck.sections.transient import TransientSection
    from ...output.figures import save_figure
    from . import plots
    from .build import system_from_section

    opts = options or {}
    sec = getattr(loaded.deck, "transient", None) or TransientSection()
    system, settings = system_from_section(sec, opts.get("rollers"), opts.get("model"), opts.get("duration_s"))

    def report(fraction: float, t: float) -> None:
        if progress is not None:
            progress(int(round(100 * fraction)), 100)

    res = run_transient(system, settings, progress=report)
    outdir = Path(outdir)
    paths = [write_transient(outdir / "transient.h5", run, res)]
    if opts.get("plots", True) and res.time_s.size:
        figs = {"transient_time.png": plots.time_history_figure, "transient_orbit.png": plots.orbit_figure,
                "transient_spectrum.png": plots.spectrum_figure, "transient_poincare.png": plots.poincare_figure,
                "transient_roller_forces.png": plots.roller_force_figure}
        if res.race_deflection_m is not None:
            figs["transient_race.png"] = plots.race_deflection_figure
        for name, make in figs.items():
            paths.append(save_figure(make(res), outdir / name))
    if not res.complete:
        log.warning("transient run incomplete (%s); wrote what was computed", res.reason)
    return paths
