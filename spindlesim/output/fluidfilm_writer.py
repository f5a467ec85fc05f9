"""thermal.h5 and coefficients.h5 of the fluid-film bearings (docs/output-format.md).

- thermal.h5: /thermal/<bearing>/ temperature_mean_C, temperature_out_C, viscosity_Pa_s,
  sommerfeld, eccentricity_ratio, attitude_angle_deg, min_film_m, friction_torque_Nm,
  oil_flow_m3_s, reynolds_number (+ heat flows, flows, inlet/ambient temperatures)
- coefficients.h5: /coefficients/<bearing>/ K_N_m, C_Ns_m (x horizontal, y vertical),
  k, c (on Cp, seed 003 eqs. 15-16), k_load, c_load (on Cb, load frame), sommerfeld,
  eccentricity_ratio, attitude_angle_deg

Each takes the bearings with their results, ``[(bearing, result), ...]``, and the speed [rad/s].
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np

from .hdf5 import Data, RunInfo, labels, write_h5

XY, FXY = ("x", "y"), ("Fx", "Fy")
LOAD_FRAME = ("along_load", "ahead_of_load")
SOMMERFELD = "mu N D L / (psi^2 W), psi = 2 Cp / D"


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


def write_film_thermal(path: Path, run: RunInfo, results: list, om: float) -> Path:
    """thermal.h5: the thermal equilibrium of every fluid-film bearing at ``om`` [rad/s]."""
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
    return write_h5(path, run, ds, attrs)


def write_coefficients(path: Path, run: RunInfo, results: list, om: float) -> Path:
    """coefficients.h5: the eight coefficients of every fluid-film bearing at its thermal equilibrium."""
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
    return write_h5(path, run, ds, attrs)
