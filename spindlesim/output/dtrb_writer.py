"""dtrb.h5 of a double-row tapered roller bearing (docs/output-format.md).

    /dtrb/displacement [dof], reaction [load], stiffness [load, dof]       at the applied load
    /dtrb/roller_load_N, inner_load_N, rib_load_N, psi_rad [row, roller]    per roller
    /dtrb/inner_slice_load_N_m, outer_slice_load_N_m [row, roller, slice]   along each roller
    /dtrb/preload_sweep/..., /dtrb/radial_sweep/...                         stiffness over the sweeps
    /dtrb/polar/<i>/...                                                     the load distributions drawn

Dimensions: string coordinates ``dof`` (x .. theta_y), ``load`` (Fx .. My) and ``roller_dof`` (u_x, u_z,
phi_y); ``row``, ``roller``, ``slice`` 1-based; a sweep's own variable.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ..bearings.dtrb.results import DtrbState, DtrbSweep
from .hdf5 import DOF5_UNITS, LOAD5_UNITS, STIFFNESS5_UNITS, Data, RunInfo, five_dof, labels, write_h5

RPM = math.pi / 30.0
K_NOTE = "K[load, dof] = -dF/dd (N/m, N/rad, N m/m, N m/rad: see component_units)"


def write_dtrb(path: Path, run: RunInfo, geometry, preload_m: float, speed_rad_s: float, load: np.ndarray,
               st: DtrbState, sweeps: dict[str, DtrbSweep], polar: list[tuple[str, DtrbState]]) -> Path:
    """dtrb.h5: the state ``st`` of the bearing of ``geometry`` at ``preload_m``, ``speed_rad_s`` and the applied
    ``load`` (Fx, Fy, Fz, Mx, My), the ``sweeps`` by name and the ``polar`` states after the first (the
    applied load's, ``st``) with their labels."""
    g = geometry
    datasets = _state_datasets("/dtrb", st)
    attrs = {"preload_m": preload_m, "speed_rpm": speed_rad_s / RPM, "applied_load": load,
             "applied_load_units": "N, N, N, N m, N m", "rollers_per_row": g.rollers_per_row,
             "slices": g.n_slices, "cup_angle_deg": math.degrees(g.cup_angle_rad),
             "cone_angle_deg": math.degrees(g.cone_angle_rad),
             "roller_half_angle_deg": math.degrees(g.roller_half_angle_rad),
             "rib_angle_deg": math.degrees(g.rib_angle_rad), "converged": st.converged}
    group_attrs = {"/dtrb": attrs}
    for name, sw in sweeps.items():
        base = f"/dtrb/{name}"
        sd, sdr = (sw.name,), (sw.name, "row")
        datasets.update(five_dof(base))
        datasets[f"{base}/{sw.name}"] = (sw.values, "m" if sw.name.endswith("_m") else "N", sd)
        datasets[f"{base}/stiffness"] = Data(sw.stiffness, "", (sw.name, "load", "dof"), K_NOTE,
                                             component_units=STIFFNESS5_UNITS)
        datasets[f"{base}/KXX_N_m"] = (sw.stiffness[:, 0, 0], "N/m", sd)
        datasets[f"{base}/KZZ_N_m"] = (sw.stiffness[:, 2, 2], "N/m", sd)
        datasets[f"{base}/loaded_rollers"] = (sw.loaded_rollers, "1", sdr)
        datasets[f"{base}/max_roller_load_N"] = (sw.max_roller_load_N, "N", sdr)
    for i, (label, s) in enumerate(polar[1:]):
        datasets.update(_state_datasets(f"/dtrb/polar/{i}", s, minimal=True))
        group_attrs[f"/dtrb/polar/{i}"] = {"label": label, "preload_m": s.preload_m}
    return write_h5(path, run, datasets, group_attrs)


def _state_datasets(base: str, st: DtrbState, minimal: bool = False) -> dict:
    rr = ("row", "roller")
    out = {
        f"{base}/stiffness": Data(st.stiffness, "", ("load", "dof"), K_NOTE, component_units=STIFFNESS5_UNITS),
        f"{base}/reaction": Data(st.reaction, "", ("load",), "reaction on the shaft", component_units=LOAD5_UNITS),
        f"{base}/roller_load_N": Data(st.outer_load_N, "N", rr, "cup load Q_o"),
        f"{base}/psi_rad": Data(st.psi_rad, "rad", rr, "roller azimuth"),
        f"{base}/displacement": Data(st.displacement, "", ("dof",), "inner-ring displacement",
                                     component_units=DOF5_UNITS),
        **five_dof(base),
    }
    if not minimal:
        out.update({
            f"{base}/inner_load_N": Data(st.inner_load_N, "N", rr, "cone raceway load Q_i"),
            f"{base}/rib_load_N": Data(st.rib_load_N, "N", rr, "rib load Q_f"),
            f"{base}/inner_slice_load_N_m": Data(st.inner_slice_N_m, "N/m", rr + ("slice",), "q_i per unit length"),
            f"{base}/outer_slice_load_N_m": Data(st.outer_slice_N_m, "N/m", rr + ("slice",), "q_o per unit length"),
            f"{base}/roller_displacement": Data(st.roller_u, "", rr + ("roller_dof",),
                                                component_units=("m", "m", "rad")),
            **labels(base, "roller_dof", ("u_x", "u_z", "phi_y")),
        })
    return out
