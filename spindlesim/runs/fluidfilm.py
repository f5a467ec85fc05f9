"""The ``thermal`` and ``coefficients`` analyses: deck -> fluid-film bearings -> HDF5 + PNG.

Signatures follow ``spindlesim.runs`` (the RUNS table):
``(loaded_deck, outdir, run_info, options, progress) -> list[Path]``; ``options`` may set
``speed_rpm`` (None = the deck's ``operating.speed_rpm``).

Output (DESIGN.md section 5):

- thermal.h5: /thermal/<bearing>/ temperature_mean_C, temperature_out_C, viscosity_Pa_s,
  sommerfeld, eccentricity_ratio, attitude_angle_deg, min_film_m, friction_torque_Nm,
  oil_flow_m3_s, reynolds_number (+ heat flows, flows, inlet/ambient temperatures)
- coefficients.h5: /coefficients/<bearing>/ K_N_m, C_Ns_m (x horizontal, y vertical),
  k, c (on Cp, seed 003 eqs. 15-16), k_load, c_load (on Cb, load frame), sommerfeld,
  eccentricity_ratio, attitude_angle_deg
"""

from __future__ import annotations

import logging
import math
from pathlib import Path
from typing import Any

import numpy as np

from ..deck.describe import FLUID_FILM_TYPES, bearing_entries

log = logging.getLogger(__name__)

XY, FXY = ("x", "y"), ("Fx", "Fy")
LOAD_FRAME = ("along_load", "ahead_of_load")
SOMMERFELD = "mu N D L / (psi^2 W), psi = 2 Cp / D"


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
    bearings = _fluid_bearings(loaded)
    om = _speed_rad_s(loaded, options)
    loads = _static_loads(loaded, bearings, om)
    out = []
    for i, b in enumerate(bearings):
        res = b.analyze(om, loads[b.name])
        f = res.film
        log.info("%s: mean film %.2f degC, mu %.4g Pa s, S %.4g, e/Cb %.4f, attitude %.1f deg",
                 b.name, res.temperature_mean_C, f.viscosity_Pa_s, f.sommerfeld,
                 f.eccentricity_ratio, f.attitude_angle_deg)
        from ..bearings.fluidfilm.viscosity import OIL_MAX_C

        if res.temperature_mean_C > OIL_MAX_C:
            log.warning("bearing %r: mean film temperature %.0f C at %.0f rpm is above %.0f C, beyond a mineral "
                        "oil's usable range: more oil flow, a lighter grade or more cooling",
                        b.name, res.temperature_mean_C, om * 30 / math.pi, OIL_MAX_C)
        out.append((b, res))
        if progress is not None:
            progress(i + 1, len(bearings))
    return out, om


def _present(entries: dict, r: Any, group_attrs: dict) -> dict:
    """The datasets of one bearing without the quantities its model does not give: an isoviscous film
    whose oil has no density and specific heat has no heat balance, so its temperatures, heat flows
    and Reynolds number are absent (named in the group attribute ``not_computed``), not NaN."""
    if not r.isoviscous:
        return entries
    absent = [k for k, v in entries.items()
              if np.ndim(v[0] if isinstance(v, tuple) else v.value) == 0
              and not np.isfinite(float(v[0] if isinstance(v, tuple) else v.value))]
    if absent:
        group_attrs["not_computed"] = (", ".join(k.rsplit("/", 1)[1] for k in absent)
                                       + ": isoviscous film without the oil's density and specific heat (no heat balance)")
    return {k: v for k, v in entries.items() if k not in absent}


def run_thermal(loaded: Any, outdir: Path, run: Any, options: dict | None = None,
                progress: Any = None) -> list[Path]:
    """Thermal equilibrium of every fluid-film bearing; thermal.h5 and pressure PNGs."""
    from ..bearings.fluidfilm.plots import pressure_figure
    from ..output.drawing import draw
    from ..output.hdf5 import Data, labels, write_h5

    results, om = _analyze_all(loaded, options or {}, progress)
    ds: dict[str, tuple[Any, str]] = {}
    attrs: dict[str, dict] = {"/thermal": {"speed_rpm": om * 30.0 / math.pi}}
    for b, r in results:
        f = r.film
        g = f"/thermal/{b.name}"
        entries = {
            f"{g}/temperature_mean_C": (r.temperature_mean_C, "degC", ()),
            f"{g}/temperature_out_C": (r.temperature_out_C, "degC", ()),
            f"{g}/temperature_in_C": (r.temperature_in_C, "degC", ()),
            f"{g}/ambient_C": (r.ambient_C, "degC", ()),
            f"{g}/viscosity_Pa_s": (f.viscosity_Pa_s, "Pa s", ()),
            f"{g}/sommerfeld": Data(f.sommerfeld, "1", (), SOMMERFELD),
            f"{g}/sommerfeld_b": Data(f.sommerfeld_b, "1", (), "Sommerfeld number on Cb"),
            f"{g}/eccentricity_ratio": Data(f.eccentricity_ratio, "1", (), "e / Cb"),
            f"{g}/attitude_angle_deg": (f.attitude_angle_deg, "degree", ()),
            f"{g}/min_film_m": (f.min_film_m, "m", ()),
            f"{g}/friction_torque_Nm": (f.friction_torque_Nm, "N m", ()),
            f"{g}/power_loss_W": (f.power_loss_W, "W", ()),
            f"{g}/friction_coefficient": (f.friction_coefficient, "1", ()),
            f"{g}/oil_flow_m3_s": (r.oil_flow_m3_s, "m^3/s", ()),
            f"{g}/inlet_flow_m3_s": (f.inlet_flow_m3_s, "m^3/s", ()),
            f"{g}/side_flow_m3_s": (f.side_flow_m3_s, "m^3/s", ()),
            f"{g}/reynolds_number": Data(f.reynolds_number, "1", (), "rho omega R Cb / mu"),
            f"{g}/heat_generated_W": (r.heat_generated_W, "W", ()),
            f"{g}/heat_to_oil_W": (r.heat_to_oil_W, "W", ()),
            f"{g}/heat_to_housing_W": (r.heat_to_housing_W, "W", ()),
            f"{g}/load_N": Data(f.load_N, "N", ("load",), "load on the bearing (x horizontal, y vertical)"),
            f"{g}/journal_position_m": Data(f.position_m, "m", ("dof",), "journal centre (x horizontal, y vertical)"),
            **labels(g, "dof", XY), **labels(g, "load", FXY),
        }
        ds.update(_present(entries, r, attrs.setdefault(g, {})))
        attrs[g].update({"type": "isoviscous" if r.isoviscous else "thermal equilibrium", "node": b.node + 1})
        if math.isfinite(r.housing_conductance_W_K):
            attrs[g]["housing_conductance_W_K"] = r.housing_conductance_W_K
    paths = [write_h5(Path(outdir) / "thermal.h5", run, ds, attrs)]
    for b, r in results:
        paths.append(draw(Path(outdir) / f"thermal_pressure_{b.name}.png", pressure_figure, r.film, f"{b.name}"))
    return paths


def run_coefficients(loaded: Any, outdir: Path, run: Any, options: dict | None = None,
                     progress: Any = None) -> list[Path]:
    """Eight coefficients at the thermal equilibrium; coefficients.h5 and characteristic charts."""
    from ..bearings.fluidfilm.performance import characteristic_curves
    from ..bearings.fluidfilm.plots import characteristics_figure
    from ..output.drawing import draw
    from ..output.hdf5 import Data, labels, write_h5

    results, om = _analyze_all(loaded, options or {}, progress)
    ds: dict[str, tuple[Any, str]] = {}
    attrs: dict[str, dict] = {"/coefficients": {"speed_rpm": om * 30.0 / math.pi,
                                                "frame": "x horizontal, y vertical (up)"}}
    for b, r in results:
        f = r.film
        g = f"/coefficients/{b.name}"
        ld, lf = ("load", "dof"), ("load_frame_load", "load_frame_dof")
        entries = {
            f"{g}/K_N_m": Data(f.K_N_m, "N/m", ld, "K[load, dof] = -dF/dq, x-y frame"),
            f"{g}/C_Ns_m": Data(f.C_Ns_m, "N s/m", ld, "C[load, dof] = -dF/dv, x-y frame"),
            f"{g}/k": Data(f.k, "1", ld, "K Cp / W, x-y frame"),
            f"{g}/c": Data(f.c, "1", ld, "B Cp omega / W, x-y frame"),
            f"{g}/k_load": Data(f.k_load, "1", lf, "K Cb / W, load frame"),
            f"{g}/c_load": Data(f.c_load, "1", lf, "B Cb omega / W, load frame"),
            f"{g}/sommerfeld": Data(f.sommerfeld, "1", (), SOMMERFELD),
            f"{g}/eccentricity_ratio": Data(f.eccentricity_ratio, "1", (), "e / Cb"),
            f"{g}/attitude_angle_deg": (f.attitude_angle_deg, "degree", ()),
            f"{g}/viscosity_Pa_s": (f.viscosity_Pa_s, "Pa s", ()),
            f"{g}/temperature_mean_C": (r.temperature_mean_C, "degC", ()),
            **labels(g, "dof", XY), **labels(g, "load", FXY),
            **labels(g, "load_frame_dof", LOAD_FRAME, "along the load, 90 deg ahead in the direction of rotation"),
            **labels(g, "load_frame_load", LOAD_FRAME, "along the load, 90 deg ahead in the direction of rotation"),
        }
        attrs[g] = {"node": b.node + 1}
        ds.update(_present(entries, r, attrs[g]))
    paths = [write_h5(Path(outdir) / "coefficients.h5", run, ds, attrs)]
    for b, r in results:
        S0 = r.film.sommerfeld
        curves = characteristic_curves(b.geometry, S0 * np.logspace(-1.5, 1.5, 19),
                                       b.n_circ, b.n_axial)
        paths.append(draw(Path(outdir) / f"coefficients_{b.name}.png", characteristics_figure, curves,
                          f"{b.name}: L/D {b.geometry.l_over_d:.3g}, mp {b.geometry.preload:.3g}; operating S = {S0:.3g}",
                          mark_S=S0))
    return paths
