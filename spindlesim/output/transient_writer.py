"""transient.h5: one layout for every rotor transient (docs/output-format.md).

    /transient/time_s [t], /transient/speed_rpm [t]
    /transient/displacement_m [t, 2], /transient/velocity_m_s [t, 2]   x, y at the record node
    /transient/rotor_displacement [t, n]                                 every rotor DOF (m, rad)
    /transient/static_displacement [n]                                   the static state the run starts from
    /transient/spectrum/frequency_hz [f], /transient/spectrum/amplitude_m [f, 2]
    /transient/poincare/x_m, y_m, vx_m_s, vy_m_s, time_s                  the primary Poincare set
    /transient/poincare/<set>/...                                        every Poincare set
    /transient/bearings/<name>/force [t, dofs] and the bearing's other outputs
    /transient/linearized_frequency_hz                                   the linear modes at the static state

Attributes of /transient also say whether the steady part has settled and what its spectrum resolves
(``steadiness.Settling``); each Poincare group says whether its set is periodic (``Periodicity``).
Numbers that are not finite are left out (no ringing mode: no ``ringing_mode_hz``).

Dimensions: ``time_s`` (a copy in every bearing group), ``dof`` (x, y), ``rotor_dof`` ("<dof>.<node>",
node 1-based), ``frequency_hz`` in /transient/spectrum, each Poincare group's own ``time_s``.
An incomplete run is still written, with complete = False and the reason (root and group).
"""

from __future__ import annotations

import dataclasses
from pathlib import Path
from typing import Any

import numpy as np

from ..analysis.transient.result import TransientResult
from .hdf5 import Data, RunInfo, labels, write_h5

#: the second dimension of a bearing output [t, k] by output name (others: "<name>_index")
_OUTPUT_DIMS = {"force": "dof", "roller_load_N": "roller", "race_deflection_m": "race_node"}


def _units(units: str, n: int) -> tuple[str, list[str] | None]:
    """A bearing output's units string "N, N, N m, N m" as (units, component units or None)."""
    parts = [u.strip() for u in units.split(",")]
    if len(parts) == 1:
        return units, None
    if len(set(parts)) == 1:
        return parts[0], None
    if len(parts) != n:
        raise ValueError(f"units {units!r} do not name the {n} components")
    return "", parts


def _rotor_dofs(dof_names: tuple[str, ...], n: int) -> tuple[list[str], str, list[str] | None]:
    """Labels "<dof>.<node>" of the n rotor DOFs (node-major), their units and component units."""
    if not dof_names or n % len(dof_names):
        return [str(i + 1) for i in range(n)], "m", None
    names = [(d, k + 1) for k in range(n // len(dof_names)) for d in dof_names]
    units = ["rad" if d.startswith("theta") else "m" for d, _ in names]
    if len(set(units)) == 1:
        return [f"{d}.{k}" for d, k in names], units[0] if units else "m", None
    return [f"{d}.{k}" for d, k in names], "", units


def _bearing_datasets(g: str, time_s: np.ndarray, dofs: tuple[str, ...], outs: dict) -> dict[str, Any]:
    data: dict[str, Any] = {f"{g}/time_s": (time_s, "s", ("time_s",))}
    for key, (value, units) in outs.items():
        v = np.asarray(value)
        dims = ("time_s",) + tuple(_OUTPUT_DIMS.get(key, f"{key}_index") if i == 1 else f"{key}_axis{i}"
                                   for i in range(1, v.ndim))
        u, comp = _units(units, v.shape[-1] if v.ndim > 1 else 1)
        data[f"{g}/{key}"] = Data(v, u, dims, component_units=comp)
    if any(key == "force" for key in outs):
        data.update(labels(g, "dof", dofs))
    return data


def _finite(attrs: dict) -> dict:
    """The attributes without the numbers that are not finite (an attribute absent means "none")."""
    return {k: v for k, v in attrs.items() if isinstance(v, (str, bool)) or np.isfinite(v)}


def _periodicity_attrs(p) -> dict:
    q = p.periodicity
    if q is None:
        return {}
    return _finite({"periodicity": q.label, "period": q.period, "distinct_points": q.distinct,
                    "classified_points": q.points, "tolerance_m": q.tolerance_m,
                    "relative_tolerance": q.relative_tolerance, "spread_m": q.spread_m, "orbit_extent_m": q.extent_m})


def _settling_attrs(s) -> dict:
    if s is None:
        return {}
    return _finite({"settled": bool(s.settled), "settling_note": s.note, "resolution_note": s.resolution_note,
                    "steady_duration_s": s.duration_s,
                    "frequency_resolution_hz": s.resolution_hz, "envelope_change": s.envelope_change,
                    "centre_drift": s.centre_drift, "dominant_periods": s.dominant_periods,
                    "ringing_mode_hz": s.ringing_mode_hz, "ringing_mode_decay": s.ringing_mode_decay,
                    "unresolved_frequencies": ", ".join(k for k, _ in s.unresolved)})


def _poincare(g: str, p) -> dict[str, Any]:
    t = ("time_s",)
    return {f"{g}/time_s": (p.time_s, "s", t), f"{g}/x_m": (p.xy_m[:, 0], "m", t), f"{g}/y_m": (p.xy_m[:, 1], "m", t),
            f"{g}/vx_m_s": (p.v_m_s[:, 0], "m/s", t), f"{g}/vy_m_s": (p.v_m_s[:, 1], "m/s", t)}


def write_transient(path: Path, run: RunInfo, res: TransientResult, linearized_hz: np.ndarray | None = None,
                    extra_attrs: dict | None = None) -> Path:
    run = dataclasses.replace(run, complete=res.complete, incomplete_reason=res.reason)
    rd = res.rotor_displacement
    n = int(np.shape(rd)[1]) if np.ndim(rd) == 2 else len(res.static_displacement)
    rotor_dofs, rotor_unit, rotor_units = _rotor_dofs(tuple(res.dof_names), n)
    t, td = ("time_s",), ("time_s", "dof")
    note = "every rotor DOF, node-major (" + ", ".join(res.dof_names) + " of node 1, then node 2, ...)"
    data: dict[str, Any] = {
        "/transient/time_s": (res.time_s, "s", t),
        "/transient/speed_rpm": (res.speed_rpm, "rpm", t),
        "/transient/displacement_m": (res.displacement_m, "m", td),
        "/transient/velocity_m_s": (res.velocity_m_s, "m/s", td),
        "/transient/rotor_displacement": Data(res.rotor_displacement, rotor_unit,
                                              ("time_s", "rotor_dof"), note, component_units=rotor_units),
        "/transient/static_displacement": Data(res.static_displacement, rotor_unit, ("rotor_dof",),
                                               "the static state the run starts from; " + note,
                                               component_units=rotor_units),
        "/transient/spectrum/frequency_hz": (res.spectrum.frequency_hz, "Hz", ("frequency_hz",)),
        "/transient/spectrum/amplitude_m": (res.spectrum.amplitude, "m", ("frequency_hz", "dof")),
        "/transient/newton_iterations": (res.newton_iterations, "1", t),
        **labels("/transient", "dof", ("x", "y")), **labels("/transient/spectrum", "dof", ("x", "y")),
        **labels("/transient", "rotor_dof", rotor_dofs),
    }
    group_attrs: dict[str, dict] = {}
    for i, p in enumerate(res.poincare):
        g = f"/transient/poincare/{p.name}"
        data.update(_poincare(g, p))
        group_attrs[g] = {"frequency_hz": p.frequency_hz, **_periodicity_attrs(p)}
        if i == 0:  # the primary set also at the top of the group (DESIGN.md section 5)
            data.update(_poincare("/transient/poincare", p))
            group_attrs["/transient/poincare"] = {"sampling": f"once per {p.name}", "frequency_hz": p.frequency_hz,
                                                  **_periodicity_attrs(p)}
    for name, dofs, outs in zip(res.bearing_names, res.bearing_dofs, res.bearing_outputs):
        g = f"/transient/bearings/{name}"
        data.update(_bearing_datasets(g, res.time_s, tuple(dofs), outs))
        group_attrs[g] = {"dof_names": ", ".join(dofs)}
    if linearized_hz is not None:
        data["/transient/linearized_frequency_hz"] = Data(np.asarray(linearized_hz, float), "Hz", ("mode",),
                                                          "linear modes at the static state")
    attrs = {"method": res.method, "step_s": res.step_s, "sample_rate_hz": res.sample_rate_hz,
             "record_node": res.record_node + 1, "settle_s": res.settle_s, "complete": res.complete,
             "incomplete_reason": res.reason, "wall_time_s": res.wall_time_s,
             "dof_names": ", ".join(res.dof_names), **_settling_attrs(res.settling)}
    for key, f in res.frequencies_hz.items():
        attrs[f"frequency_hz.{key}"] = f
    rp = [k for k in res.frequencies_hz if k.endswith(".roller_pass")]
    if rp:  # the rolling bearing's numbers of DESIGN.md section 5
        attrs["roller_pass_frequency_hz"] = res.frequencies_hz[rp[0]]
        cage = res.frequencies_hz.get(rp[0].replace("roller_pass", "cage"))
        if cage is not None:
            attrs["cage_frequency_hz"] = cage
            if cage > 0:
                attrs["rollers"] = int(round(attrs["roller_pass_frequency_hz"] / cage))
    attrs.update(extra_attrs or {})
    group_attrs["/transient"] = attrs
    return write_h5(path, run, data, group_attrs)
