"""Classical RK4 with a fixed step and compiled forces (``explicit_kernel``).

For stiff-free systems that need many small steps, such as seed 000's rigid journal in a roller
bearing (1 us steps for a second of response).  Every bearing must have a compiled force (the
contract's ``compiled()``); the run is split into chunks so that an interrupt (Ctrl-C) between
chunks keeps what was computed.
"""

from __future__ import annotations

import logging

import numpy as np

from ...bearings import compiled
from . import explicit_kernel as k
from .result import Plan, Trajectory
from .system import RotorSystem

log = logging.getLogger(__name__)


def pack(system: RotorSystem) -> tuple[np.ndarray, np.ndarray, tuple]:
    """(floats, ints, bearing handles) of the compiled right-hand side, blocks as listed in
    ``explicit_kernel``; the handles are those of ``bearings.compiled``."""
    n, N = system.n_rotor, system.size
    sh = system.shaft
    a_h = (1 + sh.eta_h) / np.sqrt(1 + sh.eta_h ** 2)
    b_h = sh.eta_h / np.sqrt(1 + sh.eta_h ** 2)
    M = system.M
    p = system.profile
    ex = system.excitation
    comp = [b.compiled() for b in system.bearings]
    head = np.zeros(k.HEADER, np.int64)
    ints: list[np.ndarray] = [head]
    floats: list[np.ndarray] = []
    sizes = {"i": k.HEADER, "f": 0}

    def put(kind: str, arr) -> int:
        a = np.asarray(arr, np.int64 if kind == "i" else float).ravel()
        (ints if kind == "i" else floats).append(a)
        off = sizes[kind]
        sizes[kind] += a.size
        return off

    for A, (h_nnz, i_rc, f_v) in ((a_h * sh.K_B + sh.K_A + sh.K_J + b_h * sh.K_C, (k.H_K0_NNZ, k.I_K0, k.F_K0)),
                                   (sh.eta_v * sh.K_C, (k.H_KC_NNZ, k.I_KC, k.F_KC)),
                                   (sh.C_ground + sh.eta_v * sh.K_B, (k.H_C0_NNZ, k.I_C0, k.F_C0)),
                                   (sh.G, (k.H_G_NNZ, k.I_G, k.F_G)),
                                   (np.linalg.inv(M[:n, :n]), (k.H_M_NNZ, k.I_M, k.F_M))):
        r, c = np.nonzero(A)
        head[h_nnz] = r.size
        head[i_rc] = put("i", np.concatenate([r, c]))
        head[f_v] = put("f", A[r, c])
    head[k.H_N_ROTOR], head[k.H_N], head[k.H_NB] = n, N, len(comp)
    head[k.F_Q] = put("f", system.Q if ex.include_static else np.zeros(n))
    head[k.F_MINT] = put("f", 1.0 / np.diag(M)[n:])
    head[k.F_PROF] = put("f", [p.start_rad_s, p.acceleration])
    head[k.H_NUB] = len(ex.unbalances)
    head[k.I_UB] = put("i", [[u.ix, u.iy] for u in ex.unbalances])
    head[k.F_UB] = put("f", [[u.me_kg_m, u.phase_rad] for u in ex.unbalances])
    head[k.H_NLD] = len(ex.loads)
    head[k.I_LD] = put("i", [[ld.index, {"harmonic": 0, "step": 1, "ramp": 2}[ld.kind]] for ld in ex.loads])
    head[k.F_LD] = put("f", [[ld.amplitude_N, ld.omega_rad_s, ld.order, ld.phase_rad, ld.t_on_s] for ld in ex.loads])
    head[k.I_KIND] = put("i", [c.kind for c in comp])
    head[k.I_FLOFF] = put("i", np.cumsum([0] + [c.floats.size for c in comp]))
    head[k.I_ITOFF] = put("i", np.cumsum([0] + [c.ints.size for c in comp]))
    head[k.I_GOFF] = put("i", np.cumsum([0] + [g.size for g in system.index]))
    head[k.I_GIDX] = put("i", np.concatenate(list(system.index) + [np.zeros(0, int)]))
    head[k.F_BEAR] = put("f", np.concatenate([c.floats for c in comp] + [np.zeros(0)]))
    head[k.I_BEAR] = put("i", np.concatenate([c.ints for c in comp] + [np.zeros(0, np.int64)]))
    fo = head[k.F_BEAR] + np.cumsum([0] + [c.floats.size for c in comp])
    io = head[k.I_BEAR] + np.cumsum([0] + [c.ints.size for c in comp])
    handles = tuple(compiled.handle(c.kind, fo[j], fo[j + 1], io[j]) for j, c in enumerate(comp))
    return np.concatenate(floats), np.concatenate(ints), handles


def integrate(system: RotorSystem, x0: np.ndarray, v0: np.ndarray, plan: Plan, targets: np.ndarray,
              progress=None, chunks: int = 40, **_) -> Trajectory:
    """RK4 over ``plan`` (module note); states at the sorted instants ``targets`` by Hermite interpolation."""
    FL, IN, hs = pack(system)
    N = system.size
    h, s = plan.step_s, plan.steps_per_sample
    y = np.concatenate([x0, v0]).astype(float)
    samples = np.empty((plan.n_samples + 1, 2 * N))
    samples[0] = y
    targets = np.ascontiguousarray(targets, dtype=float)
    pstates = np.full((targets.size, 2 * N), np.nan)
    bounds = np.linspace(0, plan.n_samples, max(1, min(chunks, plan.n_samples)) + 1).round().astype(int)
    complete, reason, done, pdone = True, "", 0, 0
    for a, b in zip(bounds[:-1], bounds[1:]):
        if b <= a:
            continue
        try:
            rows, status, pdone = k.rk4(y, a * s * h, h, (b - a) * s, s, samples[a + 1:b + 1], targets, pstates,
                                        pdone, FL, IN, hs)
            if status == 0:
                done = b
                if progress is not None:  # a Ctrl-C while the progress is shown stops here too, not outside
                    progress(b / plan.n_samples, b * s * h)
        except KeyboardInterrupt:
            complete, reason = False, f"interrupted by the user at t = {done * s * h:.6g} s"
            break
        if status != 0:
            done = a + rows - 1
            complete, reason = False, (f"non-finite state between t = {done * s * h:.6g} and "
                                       f"{(done + 1) * s * h:.6g} s (RK4, h = {h:.4g} s; a smaller time step may help)")
            break
    n = done + 1
    Y = samples[:n]
    ok = np.all(np.isfinite(pstates), axis=1)
    return Trajectory(np.arange(n) * s * h, Y[:, :N], Y[:, N:], targets[ok], pstates[ok, :N], pstates[ok, N:],
                      complete, reason, np.zeros(n, int))
