"""A reduced rotor model for analyses that solve many speeds (Campbell, chatter at every speed).

The basis T holds the undamped modes of the rotor on its nominal supports (the shaft with the
symmetric part of every bearing's stiffness at a reference speed) up to a cut-off, and the static
correction modes: the deflections K_0^-1 e_b under a unit load at each interface DOF b (every
bearing DOF, both sides of every joint, and the DOFs whose response is asked for, a tool tip),
M-orthonormalised:

    T = orth_M [ Phi_1..p,  K_0^-1 E_b ].

Any bearing stiffness acts on interface DOFs only, so for any coefficients at any speed the
static response to interface loads lies in the span of T (K_0 u = f - dK u, and dK u is an
interface load): the reduced model is exact in statics, and the modes carry the dynamics (MacNeal's
residual-flexibility argument; Craig and Kurdila, Fundamentals of Structural Dynamics, 2006, ch.
17).  A Craig-Bampton basis (modes with the interface held) was tried first: with 30 interface
DOFs (a spindle with a tool on joints) it needed 80 of 130 coordinates for 1.6e-3 in frequency,
where this basis gives 1e-5 with 72.  The reduced equations at a speed,

    T^T M T q_r'' + T^T C(Omega) T q_r' + T^T K(Omega) T q_r = T^T f,   q = T q_r,

take the bearings' coefficients at that speed's static state (``operating``), so a Campbell
diagram is one small dense eigenproblem per speed.

How many modes are enough depends on the rotor, so ``checked_basis`` does not trust a fixed
cut-off: it solves the full model at the first and the last speed, and raises the cut-off
(``factor`` times the frequency of the highest mode asked for, at least ``min_modes`` modes)
until the reduced model's frequencies agree within ``FREQ_RTOL`` and its damping ratios within
``ZETA_ATOL`` there; if no cut-off does, the caller solves the full model.
tests/validation/test_reduced_model.py holds the whole sweep to 1e-4 in frequency and 1e-3 in
damping ratio against the full state-space solution.
"""

from __future__ import annotations

from dataclasses import dataclass

import logging

import numpy as np
import scipy.linalg as sla

from ..fe.assembly import ShaftMatrices
from ..model.rotor import Rotor
from .operating import OperatingState, SystemMatrices, system_matrices

log = logging.getLogger(__name__)

FREQ_RTOL = 2e-5  # agreement demanded at the checked speeds (five times tighter than promised)
ZETA_ATOL = 2e-4
FACTORS = (4.0, 8.0, 16.0, 32.0)
MAX_SHARE = 0.7  # a larger reduced model is not worth its set-up


@dataclass(frozen=True)
class ReducedBasis:
    """T (n x m), M-orthonormal, and the shaft's matrices projected on it."""

    T: np.ndarray
    M: np.ndarray
    G: np.ndarray
    K_B: np.ndarray
    K_A: np.ndarray
    K_C: np.ndarray
    K_J: np.ndarray
    C_ground: np.ndarray
    eta_v: float
    eta_h: float

    @property
    def size(self) -> int:
        return self.T.shape[1]

    def system(self, st: OperatingState) -> SystemMatrices:
        """Reduced M, C, K at the static state ``st`` (bearings linearised there)."""
        W = st.speed_rad_s
        a_h = (1 + self.eta_h) / np.sqrt(1 + self.eta_h ** 2)
        b_h = self.eta_h / np.sqrt(1 + self.eta_h ** 2)
        K = a_h * self.K_B + self.K_A + self.K_J + (self.eta_v * W + b_h) * self.K_C
        C = self.C_ground + W * self.G + self.eta_v * self.K_B
        for (kb, cb), i in zip(st.coefficients, st.bearing_index):
            Tb = self.T[i]
            K = K + Tb.T @ kb @ Tb
            C = C + Tb.T @ cb @ Tb
        return SystemMatrices(M=self.M, C=C, K=K, speed_rad_s=W)


def reduced_basis(rotor: Rotor, shaft: ShaftMatrices, reference: OperatingState, n_modes: int,
                  extra_dofs: tuple[int, ...] = (), min_modes: int = 16, factor: float = 4.0) -> ReducedBasis:
    """The basis of the module note: the modes of the rotor on its bearings at ``reference`` up to
    ``factor`` times the frequency of its ``n_modes``-th mode (at least ``min_modes`` of them) and
    the static correction modes of the interface DOFs (bearings, joints, ``extra_dofs``)."""
    n = shaft.M.shape[0]
    M = 0.5 * (shaft.M + shaft.M.T)
    K0 = shaft.stiffness(0.0)
    K0 = 0.5 * (K0 + K0.T)
    for (kb, _), i in zip(reference.coefficients, reference.bearing_index):
        K0[np.ix_(i, i)] += 0.5 * (kb + kb.T)
    # keeps K0 positive where the supports leave a motion free (an axially floating rotor)
    shift = 1e-8 * max(float(np.max(np.abs(np.diag(K0)))), 1.0)
    Ks = K0 + shift * M
    w2, phi = sla.eigh(Ks, M, check_finite=False)
    w_cut = factor * np.sqrt(max(w2[min(n_modes, n) - 1], 0.0))
    keep = max(min(min_modes, n), int(np.count_nonzero(w2 <= w_cut ** 2)))
    joints = [rotor.dofs.index(node, d) for j in rotor.joints for node in (j.node_a, j.node_b)
              for d in ("x", "y", "z", "theta_x", "theta_y") if rotor.dofs.has(d)]
    b = np.array(sorted(set(np.concatenate([*reference.bearing_index, np.asarray(extra_dofs, int),
                                            np.asarray(joints, int)]).tolist())), int)
    E = np.zeros((n, b.size))
    E[b, np.arange(b.size)] = 1.0
    S = sla.solve(Ks, E, assume_a="sym", check_finite=False)
    S /= np.sqrt(np.einsum("ij,ij->j", S, M @ S))  # unit M-norm, as the modes
    T = _m_orthonormal(np.hstack([phi[:, :keep], S]), M)
    p = lambda A: T.T @ A @ T  # noqa: E731
    return ReducedBasis(T=T, M=p(shaft.M), G=p(shaft.G), K_B=p(shaft.K_B), K_A=p(shaft.K_A), K_C=p(shaft.K_C),
                        K_J=p(shaft.K_J), C_ground=p(shaft.C_ground), eta_v=shaft.eta_v, eta_h=shaft.eta_h)


def _m_orthonormal(V: np.ndarray, M: np.ndarray, rtol: float = 1e-10) -> np.ndarray:
    """An M-orthonormal basis of the columns of V (dependent columns dropped)."""
    G = V.T @ M @ V
    G = 0.5 * (G + G.T)
    s, U = np.linalg.eigh(G)
    keep = s > rtol * s.max()
    return V @ (U[:, keep] / np.sqrt(s[keep]))


def first_basis(rotor: Rotor, shaft: ShaftMatrices, reference: OperatingState, n_modes: int) -> ReducedBasis | None:
    """The basis :func:`checked_basis` tries first (the first cut-off, at ``reference``, the first
    state), or None when it is already too large to be worth it; not yet checked."""
    basis = reduced_basis(rotor, shaft, reference, n_modes, factor=FACTORS[0])
    return None if basis.size > MAX_SHARE * shaft.M.shape[0] else basis


class RootsMatch:
    """Criterion of a Campbell diagram: the first ``n_check`` roots of the reduced model match the full
    model's within ``FREQ_RTOL`` in frequency and ``ZETA_ATOL`` in damping ratio."""

    def __init__(self, n_check: int):
        self.n_check = n_check

    def reference(self, rotor: Rotor, states: list[OperatingState]) -> list[np.ndarray]:
        from .modal import state_matrix

        if len(states) < 2 or usable_cores() < 2:
            return [_roots(system_matrices(rotor, state=st), self.n_check) for st in states]
        # the full model's eigenvalue problems side by side (``on_cores``; alone, eigvals is a quarter cheaper)
        systems = [system_matrices(rotor, state=st) for st in states]
        lams = on_cores(lambda sysm: np.linalg.eig(state_matrix(sysm))[0], systems)
        return [_roots(sysm, self.n_check, lam) for sysm, lam in zip(systems, lams)]

    def accepts(self, basis: "ReducedBasis", states, reference) -> tuple[bool, str]:
        errors = [_mismatch(exact, _roots(basis.system(st), self.n_check)) for exact, st in zip(reference, states)]
        df, dz = (max(e[k] for e in errors) for k in (0, 1))
        return df <= FREQ_RTOL and dz <= ZETA_ATOL, f"frequency within {df:.1e}, damping ratio within {dz:.1e}"


def checked_basis(rotor: Rotor, shaft: ShaftMatrices, states: list[OperatingState], n_modes: int,
                  n_check: int | None = None, extra_dofs: tuple[int, ...] = (),
                  first: ReducedBasis | None = None, criterion=None,
                  candidate: ReducedBasis | None = None) -> ReducedBasis | None:
    """The smallest basis of ``reduced_basis`` (cut-off from ``FACTORS``, built for ``n_modes``) that
    ``criterion`` accepts at the first and the last of ``states`` (default :class:`RootsMatch` of the
    first ``n_check`` roots); None when none does with fewer than ``MAX_SHARE`` of the full model's
    coordinates (then the reduction would not pay).  A criterion has ``reference(rotor, states)`` (the
    full model's answer, computed once) and ``accepts(basis, states, reference) -> (ok, text)``.
    ``first``: the basis of the first cut-off already built (:func:`first_basis`); it is returned itself
    when it passes.  ``candidate``: a basis built for another diagram of the rotor (a frozen comparison's
    Campbell basis), tried before any is built and returned when it passes."""
    criterion = criterion if criterion is not None else RootsMatch(n_modes if n_check is None else n_check)
    check = [states[0]] if len(states) == 1 else [states[0], states[-1]]
    reference = criterion.reference(rotor, check)
    size = shaft.M.shape[0]
    if candidate is not None and candidate.size <= MAX_SHARE * size:
        ok, text = criterion.accepts(candidate, check, reference)
        if ok:
            log.info("reduced model: the %d coordinates of the diagram before (%s)", candidate.size, text)
            return candidate
    for factor in FACTORS:
        if first is not None and factor == FACTORS[0] and not extra_dofs:
            basis = first
        else:
            basis = reduced_basis(rotor, shaft, states[0], n_modes, extra_dofs, factor=factor)
        if basis.size > MAX_SHARE * size:
            break
        ok, text = criterion.accepts(basis, check, reference)
        log.debug("reduced basis of %d (cut-off %g x): %s", basis.size, factor, text)
        if ok:
            log.info("reduced model: %d of %d coordinates (%s of the full model at %g and %g rpm)", basis.size,
                     size, text, check[0].speed_rad_s * 30 / np.pi, check[-1].speed_rad_s * 30 / np.pi)
            return basis
    log.info("the reduced model needs more than %d of %d coordinates for the demanded accuracy: full model used",
             int(MAX_SHARE * size), size)
    return None


def usable_cores() -> int:
    """The cores this process may run on (its CPU affinity where the platform says, e.g. under taskset)."""
    import os

    if hasattr(os, "sched_getaffinity"):
        return max(len(os.sched_getaffinity(0)), 1)
    return os.cpu_count() or 1


def on_cores(fn, items) -> list:
    """``[fn(x) for x in items]``, an item a thread where two or more cores are free: for work done in LAPACK
    calls that release the interpreter lock (numpy's ``eig`` does; its ``eigvals`` and scipy's eigenvalue
    routines do not: two 208 x 208 eigenvalue problems on two threads take 1.03-1.08 times as long as one after
    the other, with eigenvectors by ``np.linalg.eig`` 0.56 times)."""
    items = list(items)
    cores = usable_cores()
    if len(items) < 2 or cores < 2:
        return [fn(x) for x in items]
    from concurrent.futures import ThreadPoolExecutor

    with ThreadPoolExecutor(max_workers=min(len(items), cores)) as ex:
        return list(ex.map(fn, items))


def _roots(sysm: SystemMatrices, n_modes: int, lam: np.ndarray | None = None) -> np.ndarray:
    """The first ``n_modes`` oscillatory roots (positive imaginary part, not rigid-body, not
    overdamped: the roots ``modal`` reports as modes) by frequency; ``lam``: all the eigenvalues of the
    state matrix, when known."""
    from .modal import OVERDAMPED_ZETA, RIGID_BODY_RAD_S, state_matrix

    lam = np.linalg.eigvals(state_matrix(sysm)) if lam is None else lam
    mag = np.abs(lam)
    lam = lam[(lam.imag > 0) & (mag > RIGID_BODY_RAD_S) & (-lam.real < OVERDAMPED_ZETA * mag)]
    return lam[np.argsort(lam.imag)][:n_modes]


def _mismatch(exact: np.ndarray, reduced: np.ndarray) -> tuple[float, float]:
    """Largest relative frequency and absolute damping-ratio difference, each exact root paired with
    the nearest reduced root."""
    if reduced.size < exact.size:
        return np.inf, np.inf
    df = dz = 0.0
    for lam in exact:
        k = int(np.argmin(np.abs(reduced - lam)))
        df = max(df, abs(reduced[k].imag / lam.imag - 1.0))
        dz = max(dz, abs(-reduced[k].real / abs(reduced[k]) + lam.real / abs(lam)))
    return df, dz
