"""What ``spindlesim dtrb`` computes for one double-row tapered roller bearing, as one frozen result: its
equilibrium under the load at the speed, the stiffness over a preload and a radial-load sweep, and the roller
loads of the polar plots (the applied load, other preloads, other radial loads)."""

from __future__ import annotations

import logging
from dataclasses import dataclass, field
from typing import Callable, Sequence

import numpy as np

from .bearing import DtrbBearing
from .results import DtrbState, DtrbSweep

log = logging.getLogger(__name__)


@dataclass(frozen=True)
class DtrbStudy:
    """The equilibrium (``state``) at ``preload_m``, ``speed_rad_s`` and ``load`` (FX, FY, FZ, MX, MY), the sweeps
    by name ("preload_sweep", "radial_sweep"), the polar plots' states ((label, state), the applied load first)."""

    state: DtrbState
    preload_m: float
    speed_rad_s: float
    load: np.ndarray
    sweeps: dict[str, DtrbSweep] = field(default_factory=dict)
    polar: tuple[tuple[str, DtrbState], ...] = ()


def dtrb_study(bearing: DtrbBearing, load, speed_rad_s: float, preload_sweep_m: Sequence[float] = (),
               radial_sweep_N: Sequence[float] = (), polar_preloads_m: Sequence[float] = (),
               polar_radial_loads_N: Sequence[float] = (),
               progress: Callable[[int, int], None] | None = None) -> DtrbStudy:
    """The module note's study of ``bearing`` (at its preload) under ``load`` at ``speed_rad_s``."""
    load = np.asarray(load, float)
    total = 1 + len(preload_sweep_m) + len(radial_sweep_N)
    done = [0]

    def tick(n: int = 1) -> None:
        done[0] += n
        if progress is not None:
            progress(done[0], total)

    st = bearing.solve(load, speed_rad_s)
    tick()
    log.info("DTRB equilibrium: d = %s, loaded rollers %s", st.displacement, st.loaded_rollers())
    sweeps: dict[str, DtrbSweep] = {}
    if len(preload_sweep_m):
        sweeps["preload_sweep"] = bearing.preload_sweep(np.asarray(preload_sweep_m, float), load, speed_rad_s)
        tick(len(preload_sweep_m))
    if len(radial_sweep_N):
        sweeps["radial_sweep"] = bearing.load_sweep(0, np.asarray(radial_sweep_N, float), load, speed_rad_s)
        tick(len(radial_sweep_N))
    polar = [("applied load", st)]
    for p in polar_preloads_m:
        polar.append((f"delta0 = {p * 1e6:g} um", bearing.with_preload(p).solve(load, speed_rad_s)))
    for fx in polar_radial_loads_N:
        L = load.copy()
        L[0] = fx
        polar.append((f"FX = {fx / 1e3:g} kN", bearing.solve(L, speed_rad_s)))
    return DtrbStudy(st, bearing.preload_m, speed_rad_s, load, sweeps, tuple(polar))
