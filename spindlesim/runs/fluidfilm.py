"""The ``thermal`` (of the fluid-film bearings) and ``coefficients`` analyses: deck -> fluid-film bearings -> HDF5 + PNG.

Signatures follow ``spindlesim.runs`` (the RUNS table):
``(loaded_deck, outdir, run_info, options, progress) -> Written``: the bearings' thermal equilibria
(:class:`~spindlesim.bearings.fluidfilm.results.FilmBearings`, what the summaries read) and the files;
``options`` may set ``speed_rpm`` (None = the deck's ``operating.speed_rpm``).

The layouts of thermal.h5 and coefficients.h5: :mod:`spindlesim.output.fluidfilm_writer`.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np

from ..deck.describe import FLUID_FILM_TYPES, bearing_entries
from .status import Written


def _fluid_bearings(loaded: Any):
    from ..bearings.fluidfilm.section import build

    entries = [b for _, b in bearing_entries(loaded.deck, *FLUID_FILM_TYPES)]
    if not entries:
        raise ValueError("the deck has no fluid-film bearing (type three_lobe or plain)")
    return [build(e) for e in entries]


def _static_loads(loaded: Any, bearings: list, om: float) -> dict[str, np.ndarray | None]:
    """Each bearing's load: ``load_N`` where the deck gives it (None here), else what the shaft puts on
    it at the rotor's static equilibrium at this speed (a located deck error without a rotor)."""
    if all(b.load_N is not None for b in bearings):
        return {b.name: None for b in bearings}
    from ..deck import DeckError, require_rotor
    from .common import operating_points

    d = loaded.deck
    if d.shaft is None and d.journal is None:
        raise DeckError([loaded.issue(("bearings", i), f"bearing {e.name!r} has no load_N and the deck no rotor "
                                      "(shaft or journal) whose static equilibrium would load it: give load_N")
                         for i, e in bearing_entries(d, *FLUID_FILM_TYPES) if e.load_N is None])
    require_rotor(loaded, "thermal equilibrium from the rotor's static loads")
    state = operating_points(loaded).state(om * 30.0 / math.pi)
    return {b.name: None if b.load_N is not None else state.load_of(b.name) for b in bearings}


def _speed_rad_s(loaded: Any, options: dict) -> float:
    rpm = options.get("speed_rpm")
    if rpm is None:
        op = getattr(loaded.deck, "operating", None)
        if op is None:
            raise ValueError("no speed: give operating.speed_rpm in the deck or --speed")
        rpm = op.speed_rpm
    if not rpm > 0:
        from ..bearings.base import SpeedRequiredError

        raise SpeedRequiredError(f"a fluid-film bearing needs a positive speed (got {rpm:g} rpm): give "
                                 "operating.speed_rpm > 0 or --speed")
    return float(rpm) * math.pi / 30.0


def _analyze_all(loaded, options, progress):
    """The deck's fluid-film bearings and their :class:`~spindlesim.bearings.fluidfilm.results.FilmBearings`."""
    from ..bearings.fluidfilm.study import film_bearings

    bearings = _fluid_bearings(loaded)
    om = _speed_rad_s(loaded, options)
    return bearings, film_bearings(bearings, om, _static_loads(loaded, bearings, om), progress)


def run_thermal(loaded: Any, outdir: Path, run: Any, options: dict | None = None,
                progress: Any = None) -> Written:
    """Thermal equilibrium of every fluid-film bearing; thermal.h5 and pressure PNGs."""
    from ..bearings.fluidfilm.plots import pressure_figure
    from ..output.drawing import draw
    from ..output.fluidfilm_writer import write_film_thermal

    bearings, study = _analyze_all(loaded, options or {}, progress)
    results = list(zip(bearings, study.results))
    paths = [write_film_thermal(Path(outdir) / "thermal.h5", run, results, study.speed_rad_s)]
    for b, r in results:
        paths.append(draw(Path(outdir) / f"thermal_pressure_{b.name}.png", pressure_figure, r.film, f"{b.name}"))
    return Written(study, tuple(paths))


def run_coefficients(loaded: Any, outdir: Path, run: Any, options: dict | None = None,
                     progress: Any = None) -> Written:
    """Eight coefficients at the thermal equilibrium; coefficients.h5 and characteristic charts."""
    from ..bearings.fluidfilm.performance import characteristic_curves
    from ..bearings.fluidfilm.plots import characteristics_figure
    from ..output.drawing import draw
    from ..output.fluidfilm_writer import write_coefficients

    bearings, study = _analyze_all(loaded, options or {}, progress)
    results = list(zip(bearings, study.results))
    paths = [write_coefficients(Path(outdir) / "coefficients.h5", run, results, study.speed_rad_s)]
    for b, r in results:
        S0 = r.film.sommerfeld
        curves = characteristic_curves(b.geometry, S0 * np.logspace(-1.5, 1.5, 19),
                                       b.n_circ, b.n_axial)
        paths.append(draw(Path(outdir) / f"coefficients_{b.name}.png", characteristics_figure, curves,
                          f"{b.name}: L/D {b.geometry.l_over_d:.3g}, mp {b.geometry.preload:.3g}; operating S = {S0:.3g}",
                          mark_S=S0))
    return Written(study, tuple(paths))
