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

An incomplete run is still written, with complete = False and the reason (root and group).
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np

from ..analysis.transient.result import TransientResult
from .hdf5 import RunInfo, write_h5


def _unit(units: str) -> str:
    return units


def write_transient(path: Path, run: RunInfo, res: TransientResult, linearized_hz: np.ndarray | None = None,
                    extra_attrs: dict | None = None) -> Path:
    run = dataclasses.replace(run, complete=res.complete, incomplete_reason=res.reason)
    per_dof = ", ".join(f"{d}: {'rad' if d.startswith('theta') else 'm'}" for d in res.dof_names)
    data = {
        "/transient/time_s": (res.time_s, "s"),
        "/transient/speed_rpm": (res.speed_rpm, "rpm"),
        "/transient/displacement_m": (res.displacement_m, "m"),
        "/transient/velocity_m_s": (res.velocity_m_s, "m/s"),
        "/transient/rotor_displacement": (res.rotor_displacement, "m, rad per DOF (" + per_dof + ", node-major)"),
        "/transient/static_displacement": (res.static_displacement, "m, rad per DOF"),
        "/transient/spectrum/frequency_hz": (res.spectrum.frequency_hz, "Hz"),
        "/transient/spectrum/amplitude_m": (res.spectrum.amplitude, "m"),
        "/transient/newton_iterations": (res.newton_iterations, "1"),
    }
    group_attrs: dict[str, dict] = {}
    for i, p in enumerate(res.poincare):
        g = f"/transient/poincare/{p.name}"
        data.update({f"{g}/time_s": (p.time_s, "s"), f"{g}/x_m": (p.xy_m[:, 0], "m"), f"{g}/y_m": (p.xy_m[:, 1], "m"),
                     f"{g}/vx_m_s": (p.v_m_s[:, 0], "m/s"), f"{g}/vy_m_s": (p.v_m_s[:, 1], "m/s")})
        group_attrs[g] = {"frequency_hz": p.frequency_hz}
        if i == 0:  # the primary set also at the top of the group (DESIGN.md section 5)
            data.update({"/transient/poincare/time_s": (p.time_s, "s"), "/transient/poincare/x_m": (p.xy_m[:, 0], "m"),
                         "/transient/poincare/y_m": (p.xy_m[:, 1], "m"),
                         "/transient/poincare/vx_m_s": (p.v_m_s[:, 0], "m/s"),
                         "/transient/poincare/vy_m_s": (p.v_m_s[:, 1], "m/s")})
            group_attrs["/transient/poincare"] = {"sampling": f"once per {p.name}", "frequency_hz": p.frequency_hz}
    for name, dofs, outs in zip(res.bearing_names, res.bearing_dofs, res.bearing_outputs):
        g = f"/transient/bearings/{name}"
        for key, (value, units) in outs.items():
            data[f"{g}/{key}"] = (value, units)
        group_attrs[g] = {"dof_names": ", ".join(dofs)}
    if linearized_hz is not None:
        data["/transient/linearized_frequency_hz"] = (np.asarray(linearized_hz, float), "Hz")
    attrs = {"method": res.method, "step_s": res.step_s, "sample_rate_hz": res.sample_rate_hz,
             "record_node": res.record_node + 1, "settle_s": res.settle_s, "complete": res.complete,
             "incomplete_reason": res.reason, "wall_time_s": res.wall_time_s,
             "dof_names": ", ".join(res.dof_names)}
    for key, f in res.frequencies_hz.items():
        attrs[f"frequency_hz.{key}"] = f
    rp = [k for k in res.frequencies_hz if k.endswith(".roller_pass")]
    if rp:  # the rolling bearing's numbers of DESIGN.md section 5
        attrs["roller_pass_frequency_hz"] = res.frequencies_hz[rp[0]]
        cage = res.frequencies_hz.get(rp[0].replace("roller_pass", "cage"), float("nan"))
        attrs["cage_frequency_hz"] = cage
        if cage > 0:
            attrs["rollers"] = int(round(attrs["roller_pass_frequency_hz"] / cage))
    attrs.update(extra_attrs or {})
    group_attrs["/transient"] = attrs
    return write_h5(path, run, data, group_attrs)
