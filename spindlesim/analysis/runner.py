"""Run a named analysis on a loaded deck and write its HDF5 and PNG files.

This is the scriptable API the CLI wraps::

    from spindlesim.deck import load_deck
    from spindlesim.analysis.runner import run_analysis
    paths = run_analysis("modal", load_deck("spindle.yaml"), "out/spindle")

Other packages add analyses with ``register_analysis(name, function)``; the
function takes (loaded_deck, outdir, run_info, options, progress) and returns
the written paths.
"""

from __future__ import annotations

import logging
from pathlib import Path
from typing import Any, Callable

import numpy as np

from ..deck.loader import LoadedDeck, require_rotor
from ..model.build import build_rotor
from ..output.hdf5 import RunInfo

log = logging.getLogger(__name__)
Progress = Callable[[int, int], None] | None
_ANALYSES: dict[str, Callable[..., list[Path]]] = {}


def register_analysis(name: str, fn: Callable[..., list[Path]]) -> None:
    _ANALYSES[name] = fn


def analyses() -> tuple[str, ...]:
    return tuple(_ANALYSES)


def run_info_for(loaded: LoadedDeck, command_line: str | None = None) -> RunInfo:
    kw = {} if command_line is None else {"command_line": command_line}
    return RunInfo(deck_text=loaded.text, deck_source=loaded.source, deck_sha256=loaded.sha256, **kw)


def run_analysis(name: str, loaded: LoadedDeck, outdir: str | Path, options: dict[str, Any] | None = None,
                 progress: Progress = None, run: RunInfo | None = None) -> list[Path]:
    """Run analysis ``name`` and write its outputs into ``outdir``; returns the written paths."""
    if name not in _ANALYSES:
        raise KeyError(f"unknown analysis {name!r}; known: {', '.join(_ANALYSES)}")
    run = run or run_info_for(loaded)
    return _ANALYSES[name](loaded, Path(outdir), run, options or {}, progress)


def _plots(opts: dict, make) -> list[Path]:
    """PNG paths unless options say ``plots: False`` (sweeps skip per-case plots by default)."""
    if not opts.get("plots", True):
        return []
    out = make()
    return list(out) if isinstance(out, tuple) else [out]


def _first(*values):
    """The first value that is not None (0 is a valid speed)."""
    return next((v for v in values if v is not None), None)


def _range(r) -> np.ndarray:
    if isinstance(r, list):
        return np.asarray(r, float)
    return np.linspace(r.start, r.stop, r.count)


def _static(loaded, outdir, run, opts, progress):
    require_rotor(loaded, "static")
    from ..output.rotor_plots import plot_static
    from ..output.rotor_writers import write_static
    from .static import solve_static

    d = loaded.deck
    rotor = build_rotor(d, speed_rpm=opts.get("speed_rpm"))
    at = d.static.stiffness_at
    res = solve_static(rotor, at.node - 1, at.dof)
    log.info("static stiffness at node %d %s: %.4g N/um", at.node, at.dof, res.static_stiffness_N_m / 1e6)
    return [write_static(outdir / "static.h5", run, res),
            *_plots(opts, lambda: plot_static(res, outdir / "static_deflection.png"))]


def _modal(loaded, outdir, run, opts, progress):
    require_rotor(loaded, "modal")
    from ..output.rotor_plots import plot_modes
    from ..output.rotor_writers import write_modal
    from .modal import solve_modal

    d = loaded.deck
    speed = _first(opts.get("speed_rpm"), d.modal.speed_rpm)
    rotor = build_rotor(d, speed_rpm=speed)
    res = solve_modal(rotor, n_modes=_first(opts.get("modes"), d.modal.modes))
    return [write_modal(outdir / "modal.h5", run, res), *_plots(opts, lambda: plot_modes(res, outdir / "modal_shapes.png"))]


def _campbell(loaded, outdir, run, opts, progress):
    require_rotor(loaded, "campbell")
    from ..output.rotor_plots import plot_campbell
    from ..output.rotor_writers import write_campbell
    from .campbell import solve_campbell

    d = loaded.deck
    speeds = opts.get("speeds_rpm")
    speeds = _range(d.campbell.speeds_rpm) if speeds is None else np.asarray(speeds, float)
    rotor = build_rotor(d)
    res = solve_campbell(rotor, speeds, n_modes=_first(opts.get("modes"), d.campbell.modes), progress=progress)
    return [write_campbell(outdir / "campbell.h5", run, res),
            *_plots(opts, lambda: plot_campbell(res, outdir / "campbell.png"))]


def _frf(loaded, outdir, run, opts, progress):
    require_rotor(loaded, "frf")
    from ..output.rotor_plots import plot_frf
    from ..output.rotor_writers import write_frf
    from .frf import solve_frf

    d = loaded.deck
    fr = d.frf
    rotor = build_rotor(d, speed_rpm=_first(opts.get("speed_rpm"), fr.speed_rpm))
    res = solve_frf(rotor, _range(fr.frequencies_hz), fr.input.node, fr.input.dof, fr.output.node, fr.output.dof)
    return [write_frf(outdir / "frf.h5", run, res),
            *_plots(opts, lambda: plot_frf(res, outdir / "frf_magnitude_phase.png", outdir / "frf_real_imag.png"))]


def _unbalance(loaded, outdir, run, opts, progress):
    require_rotor(loaded, "unbalance")
    from ..output.rotor_plots import plot_unbalance
    from ..output.rotor_writers import write_unbalance
    from .frf import solve_unbalance

    d = loaded.deck
    u = d.unbalance
    if u is None:
        raise ValueError("the deck has no 'unbalance' section (node, amount_g_mm, speeds_rpm)")
    rotor = build_rotor(d)
    res = solve_unbalance(rotor, _range(u.speeds_rpm), u.node, u.amount_g_mm * 1e-6, u.phase_deg,
                          u.output.node, u.output.dof)
    return [write_unbalance(outdir / "unbalance.h5", run, res),
            *_plots(opts, lambda: plot_unbalance(res, outdir / "unbalance.png"))]


def _contact(loaded, outdir, run, opts, progress):
    from ..contact.analysis import run_contact

    return run_contact(loaded, outdir, run, opts, progress)


def _thermal(loaded, outdir, run, opts, progress):
    from ..bearings.fluidfilm.runner import run_thermal

    return run_thermal(loaded, outdir, run, opts, progress)


def _coefficients(loaded, outdir, run, opts, progress):
    from ..bearings.fluidfilm.runner import run_coefficients

    return run_coefficients(loaded, outdir, run, opts, progress)


def _dtrb(loaded, outdir, run, opts, progress):
    from ..bearings.rolling.dtrb.run import run_dtrb

    return run_dtrb(loaded, outdir, run, opts, progress)


def _rotor_transient(loaded, outdir, run, opts, progress):
    from .rotor_transient_run import run_rotor_transient

    return run_rotor_transient(loaded, outdir, run, opts, progress)


def _transient(loaded, outdir, run, opts, progress):
    """Roller-bearing transient (deck section ``transient:``, seed 000), or the time response of a
    rotor with nonlinear bearings (a shaft with e.g. a ``dtrb`` bearing, seed 001)."""
    d = loaded.deck
    if getattr(d, "transient", None) is None and d.shaft is not None:
        return _rotor_transient(loaded, outdir, run, opts, progress)
    from ..bearings.rolling.report import run_transient_analysis

    return run_transient_analysis(loaded, outdir, run, opts, progress)


for _n, _f in (("transient", _transient), ("rotor_transient", _rotor_transient), ("dtrb", _dtrb), ("thermal", _thermal), ("coefficients", _coefficients), ("contact", _contact), ("static", _static), ("modal", _modal), ("campbell", _campbell), ("frf", _frf),
               ("unbalance", _unbalance)):
    register_analysis(_n, _f)


def default_analyses(loaded: LoadedDeck) -> list[str]:
    """What ``spindlesim run`` does when the deck has no ``analyses`` list."""
    d = loaded.deck
    names = []
    if d.shaft is not None and d.operating is not None:
        names = ["static", "modal", "campbell", "frf"]
        if d.unbalance is not None:
            names.append("unbalance")
    if any(getattr(b, "type", "") in ("three_lobe", "plain", "multilobe") for b in d.bearings):
        names[:0] = ["thermal", "coefficients"]
    # sections contributed by other packages (contact, transient, ...) run when present
    names += [n for n in _ANALYSES if n not in names and n not in ("static", "modal", "campbell", "frf", "unbalance")
              and getattr(d, n, None) is not None]
    return names
