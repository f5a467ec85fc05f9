"""The ``dtrb`` analysis: deck section -> equilibrium, stiffness, sweeps -> dtrb.h5 and PNGs.

:func:`run_dtrb` follow ``spindlesim.runs`` (the RUNS table):
``(loaded_deck, outdir, run_info, options, progress) -> list[Path]``.  ``options`` may
override ``preload_um``, ``speed_rpm`` and ``sweeps`` (False skips the sweeps); None = deck.
"""

from __future__ import annotations

import logging
import math
from pathlib import Path
from typing import Any

import numpy as np

from ..bearings.dtrb.bearing import DtrbBearing
from ..bearings.dtrb.results import DtrbState, DtrbSweep
from ..output.hdf5 import DOF5_UNITS, LOAD5_UNITS, STIFFNESS5_UNITS, Data, five_dof, labels

log = logging.getLogger(__name__)

RPM = math.pi / 30.0
K_NOTE = "K[load, dof] = -dF/dd (N/m, N/rad, N m/m, N m/rad: see component_units)"


def _range(r) -> np.ndarray:
    return np.linspace(r.start, r.stop, r.count)


def run_dtrb(loaded: Any, outdir: Path, run: Any, options: dict | None = None, progress=None) -> list[Path]:
    from ..bearings.dtrb.plots import plot_load_distribution, plot_stiffness_sweep
    from ..bearings.dtrb.section import geometry_from
    from ..output.drawing import draw

    from ..deck import require_section

    sec = require_section(loaded, "dtrb", "dtrb", "bearing geometry, preload_um, speed_rpm, load, sweeps")
    opts = {k: v for k, v in (options or {}).items() if v is not None}
    preload = 1e-6 * float(opts.get("preload_um", sec.preload_um))
    speed = RPM * float(opts.get("speed_rpm", sec.speed_rpm))
    do_sweeps = bool(opts.get("sweeps", True))
    load = np.asarray(sec.load.vector(), float)
    bearing = DtrbBearing(geometry_from(sec.bearing), preload)
    g = bearing.geometry

    n_pre = sec.preload_sweep_um.count if (do_sweeps and sec.preload_sweep_um) else 0
    n_rad = sec.radial_sweep_N.count if (do_sweeps and sec.radial_sweep_N) else 0
    total = 1 + n_pre + n_rad
    done = 0

    def tick(n: int = 1) -> None:
        nonlocal done
        done += n
        if progress is not None:
            progress(done, total)

    st = bearing.equilibrium(load, speed)
    tick()
    log.info("DTRB equilibrium: d = %s, loaded rollers %s", st.displacement, st.loaded_rollers())
    datasets = _state_datasets("/dtrb", st)
    attrs = {"preload_m": preload, "speed_rpm": speed / RPM, "applied_load": load,
             "applied_load_units": "N, N, N, N m, N m", "rollers_per_row": g.rollers_per_row,
             "slices": g.n_slices, "cup_angle_deg": math.degrees(g.cup_angle_rad),
             "cone_angle_deg": math.degrees(g.cone_angle_rad),
             "roller_half_angle_deg": math.degrees(g.roller_half_angle_rad),
             "rib_angle_deg": math.degrees(g.rib_angle_rad), "converged": st.converged}
    group_attrs = {"/dtrb": attrs}
    figures = []
    sweeps: dict[str, DtrbSweep] = {}
    if n_pre:
        values = 1e-6 * _range(sec.preload_sweep_um)
        sweeps["preload_sweep"] = bearing.preload_sweep(values, load, speed)
        tick(n_pre)
    if n_rad:
        sweeps["radial_sweep"] = bearing.load_sweep(0, _range(sec.radial_sweep_N), load, speed)
        tick(n_rad)
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

    polar = [("applied load", st)]
    for p in sec.polar_preloads_um:
        polar.append((f"delta0 = {p:g} um", bearing.with_preload(1e-6 * p).equilibrium(load, speed)))
    for fx in sec.polar_radial_loads_N:
        L = load.copy()
        L[0] = fx
        polar.append((f"FX = {fx / 1e3:g} kN", bearing.equilibrium(L, speed)))
    for i, (label, s) in enumerate(polar[1:]):
        datasets.update(_state_datasets(f"/dtrb/polar/{i}", s, minimal=True))
        group_attrs[f"/dtrb/polar/{i}"] = {"label": label, "preload_m": s.preload_m}

    from ..output.hdf5 import write_h5

    paths = [write_h5(outdir / "dtrb.h5", run, datasets, group_attrs)]
    figures.append(draw(outdir / "dtrb_load_distribution.png", plot_load_distribution, polar))
    if "preload_sweep" in sweeps:
        figures.append(draw(outdir / "dtrb_stiffness_preload.png", plot_stiffness_sweep,
                            sweeps["preload_sweep"], [(0, 0, "KXX"), (2, 2, "KZZ")], 1e6, "preload delta0 [um]",
                            f"Direct stiffness against preload (load {_load_text(load)}; seed 001 Fig. 8)"))
    if "radial_sweep" in sweeps:
        figures.append(draw(outdir / "dtrb_stiffness_radial.png", plot_stiffness_sweep,
                            sweeps["radial_sweep"], [(0, 0, "KXX")], 1e-3, "radial load FX [kN]",
                            f"KXX against radial load (delta0 = {preload * 1e6:g} um; seed 001 Fig. 10)"))
    return paths + figures


def _load_text(load: np.ndarray) -> str:
    return f"FX {load[0] / 1e3:g} kN, FY {load[1] / 1e3:g} kN, FZ {load[2] / 1e3:g} kN"


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
