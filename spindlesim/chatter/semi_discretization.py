"""Semi-discretization of the regenerative delay equation (Insperger and Stepan).

Model, with the tool-point state-space model x' = A x + B F, y = C x and the linearised cutting
force F = K(t) (y(t) - y(t - tau)) of :mod:`spindlesim.chatter.process` (depth included):

    x'(t) = (A + B K(t) C) x(t) - B K(t) y(t - tau),     K(t + tau) = K(t).

The period tau is cut into m steps dt = tau / m.  On [t_i, t_i+1] K(t) is replaced by its
exact average K_i over the step and the delayed output by

* zeroth order (Insperger and Stepan, IJNME 55 (2002) 503-518; updated form IJNME 61 (2004)
  117-141, tau = m dt): y(t - tau) ~ (y_{i-m} + y_{i-m+1}) / 2;
* first order (Insperger, Stepan and Turi, JSV 313 (2008) 334-341): the linear interpolation
  y(t - tau) ~ (1 - s/dt) y_{i-m} + (s/dt) y_{i-m+1}, s = t - t_i;

and the resulting ODE with constant coefficients is solved exactly:

    x_{i+1} = P_i x_i + R0_i y_{i-m} + R1_i y_{i-m+1},
    P_i = exp(A_i dt),  Phi0 = int_0^dt exp(A_i (dt - s)) ds,  Phi1 = int_0^dt exp(A_i (dt - s)) s/dt ds,
    first order: R0 = (Phi0 - Phi1) D_i, R1 = Phi1 D_i;  zeroth order: R0 = R1 = Phi0 D_i / 2,
    D_i = -B K_i,

(P, Phi0, Phi1 from one exponential of a block matrix, Van Loan).  The state
z_i = (x_i, y_{i-1}, ..., y_{i-m}) is mapped over one period by the monodromy (transition)
matrix Phi = G_{m-1} ... G_0; the cut is asymptotically stable when its spectral radius is
below one.  Output rows of C that are identically zero are dropped from the history (a tool
flexible in one direction only keeps n + m states instead of n + 2 m).

The critical multiplier mu gives the kind of the boundary (complex: secondary Hopf; -1: flip,
period doubling) and the chatter frequencies (arg mu + 2 pi q) / tau; the dominant one is read
from the eigenvector: the stored outputs over one period, demodulated by mu^(t/tau), are
Fourier-analysed and the largest harmonic q is taken (Dombovari, Zatarain and Insperger).
"""

from __future__ import annotations

import copy
import logging
import multiprocessing
import os
import signal
import threading
from concurrent.futures import ProcessPoolExecutor, ThreadPoolExecutor
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass

import numpy as np
import scipy.linalg as sla
from scipy.sparse.linalg import ArpackNoConvergence, eigs

from ._expm import expm_batch, van_loan_blocks
from .period_map import StepMaps, monodromy_matrix, period_history
from .state_space import ToolPointModel

__all__ = ["SdProblem", "CriticalMultiplier", "spectral_radius"]

log = logging.getLogger(__name__)


_POOLS: dict[int, ThreadPoolExecutor] = {}
#: work of one call of :meth:`SdProblem.batches` (evaluations x steps x states x monodromy order, about 1 ms
#: of one core per 1e5) above which its pieces go to worker processes: an evaluation holds the interpreter
#: lock for most of its time (a loop over the steps of small products), so threads share one core
PROCESS_WORK = 2e6
_SERIAL = False  # in a worker process: everything on its one thread
_PROCESSES: list[ProcessPoolExecutor | None] = []
_PROCESS_LOCK = threading.Lock()


def _worker_start() -> None:
    global _SERIAL
    _SERIAL = True
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # the parent decides (it cancels and stops the pool)


def _process_pool() -> ProcessPoolExecutor | None:
    """The worker processes of the semi-discretization (one per core, forked once, as the sweep's local pool:
    a fork server or a spawned worker would import the main module again, which a user's script may not
    allow); None with one core, inside another process pool's worker (a sweep's case: the cores are taken)
    or with SPINDLESIM_SD_PROCESSES=0."""
    if (_SERIAL or workers() < 2 or os.environ.get("SPINDLESIM_SD_PROCESSES", "1") == "0"
            or multiprocessing.parent_process() is not None):
        return None
    with _PROCESS_LOCK:
        if not _PROCESSES:
            try:
                ctx = multiprocessing.get_context("fork")
                _PROCESSES.append(ProcessPoolExecutor(workers(), mp_context=ctx, initializer=_worker_start))
            except (OSError, ValueError) as exc:  # no fork on this platform
                log.info("semi-discretization on threads only: %s", exc)
                _PROCESSES.append(None)
        return _PROCESSES[0]


def _piece(prob: "SdProblem", depth: np.ndarray, what: str = "multipliers"):
    return getattr(prob, what)(np.arange(len(prob.speeds)), depth)


def _broken() -> None:
    with _PROCESS_LOCK:
        if _PROCESSES and _PROCESSES[0] is not None:
            _PROCESSES[0].shutdown(wait=False, cancel_futures=True)
        _PROCESSES[:] = [None]


def workers() -> int:
    """Threads for the monodromy batches: the cores this process may use (numpy and LAPACK release the
    interpreter lock in the products, solves and eigenvalue problems, where the time goes)."""
    try:
        n = len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        n = os.cpu_count() or 1
    return max(1, min(n, 8))


_PREFIX = "semi-discretization"


def parallel_map(fn, items) -> list:
    """``[fn(x) for x in items]``, on the worker threads when there are several items and this is not
    already a worker (a worker waiting on its own pool could wait forever)."""
    items = list(items)
    n = workers()
    if n == 1 or len(items) < 2 or _SERIAL or threading.current_thread().name.startswith(_PREFIX):
        return [fn(x) for x in items]
    if n not in _POOLS:
        _POOLS[n] = ThreadPoolExecutor(n, thread_name_prefix=_PREFIX)
    return list(_POOLS[n].map(fn, items))


#: how many of the largest multipliers an evaluation returns (those Arnoldi resolves; the root search
#: follows the chatter multiplier among them)
N_MULTIPLIERS = 6
#: Arnoldi's basis: the multipliers outside the cluster near zero are about as many as the structure's states
#: n, and ARPACK's default 2k + 1 = 13 vectors restart often when they crowd the unit circle (a rotor's
#: dominant modes near a stability boundary).  n + 12, at least 13 (and below the matrix's order): the milling
#: deck's 18-state monodromy matrices at 0.99 of the limit (178-718 states) take 0.82 ms each against 1.64 ms
#: with 13 (the same rho to 1e-14), while a one- or four-mode model keeps ARPACK's speed (30 vectors there:
#: 10-15 % slower).  No upper bound below that: a tool library's short tools (42- and 54-state models, 154-754
#: states, captured from a run) took 7.5 and 11.1 ms a matrix with at most 30 vectors, 3.8 and 4.9 ms with n + 12
#: (rho equal to the dense eigenvalues' within 1e-14 either way); the whole `tools` of the 54-state tool 0.97 of
#: its wall time on threads, unchanged with the worker processes
ARNOLDI_MIN_BASIS = 13


#: Arnoldi restarts before the dense eigenvalues take over: a converging case needs a few, while a monodromy whose
#: leading multipliers crowd together (a short tool's high-frequency mode: 400 steps, 800 states) ran ARPACK's
#: budget of 50 N restarts for minutes on one evaluation; the dense QR of that matrix takes about a second
ARNOLDI_RESTARTS = 60


def _arnoldi_basis(n_states: int, order: int) -> int:
    """ARPACK's basis for a monodromy matrix of ``order`` from a structure of ``n_states`` (ARNOLDI_MIN_BASIS)."""
    return int(min(max(n_states + 12, ARNOLDI_MIN_BASIS), order - 1))


def _largest_multipliers(Phi: np.ndarray, n_states: int) -> np.ndarray:
    """The N_MULTIPLIERS eigenvalues of largest modulus of each matrix [E, k], largest first: dense QR for
    small ones, Arnoldi (ARPACK, fixed start vector) above 64 states, dense on no convergence.  The
    dominant multipliers of the milling monodromy are well separated from the cluster near zero, which
    Arnoldi resolves in a few tens of products; ``n_states`` the structure's states (the basis size)."""
    E, N, _ = Phi.shape
    k = min(N_MULTIPLIERS, N)
    out = np.empty((E, k), complex)
    if N <= 64:
        ev = np.linalg.eigvals(Phi)
        order = np.argsort(-np.abs(ev), axis=1, kind="stable")[:, :k]
        return np.take_along_axis(ev, order, axis=1)
    v0 = np.ones(N)
    for e in range(E):
        try:
            ev = eigs(Phi[e], k=k, which="LM", return_eigenvectors=False, tol=1e-12, v0=v0, maxiter=ARNOLDI_RESTARTS,
                      ncv=_arnoldi_basis(n_states, N))
        except ArpackNoConvergence:
            ev = np.linalg.eigvals(Phi[e])
        out[e] = ev[np.argsort(-np.abs(ev), kind="stable")[:k]]
    return out


def _dominant_eigenpair(Phi: np.ndarray, n_states: int) -> tuple[complex, np.ndarray]:
    """Eigenvalue of largest modulus and its eigenvector (Arnoldi above 64 states, as for rho)."""
    if len(Phi) > 64:
        try:
            ev, V = eigs(Phi, k=N_MULTIPLIERS, which="LM", tol=1e-12, v0=np.ones(len(Phi)), maxiter=ARNOLDI_RESTARTS,
                         ncv=_arnoldi_basis(n_states, len(Phi)))
            j = int(np.argmax(np.abs(ev)))
            return complex(ev[j]), V[:, j]
        except ArpackNoConvergence:
            pass
    mu_all, V = np.linalg.eig(Phi)
    j = int(np.argmax(np.abs(mu_all)))
    return complex(mu_all[j]), V[:, j]


@dataclass(frozen=True)
class CriticalMultiplier:
    """Largest characteristic multiplier at one (speed, depth) and what it means."""

    spectral_radius: float
    multiplier: complex
    kind: str  # "hopf", "flip" or "fold"
    chatter_frequency_hz: float
    lobe: int  # whole chatter waves per tooth period


def _balanced(A: np.ndarray, B: np.ndarray, C: np.ndarray):
    """The models [E] in balanced states x = S x~, S diagonal of powers of two (LAPACK's gebal, so exact): the
    same outputs, multipliers and monodromy spectra, but a step's 1-norm that follows its dynamics.  A tap test's
    modes in (q, q') coordinates have |A| ~ w^2 against w for the balanced form: at 5 % immersion an 8-mode model's
    steps had 1-norms in the thousands, and each exponential took ten squarings instead of a low Pade degree."""
    A, B, C = A.copy(), B.copy(), C.copy()
    for e in range(len(A)):
        _, (s, _perm) = sla.matrix_balance(A[e], permute=False, separate=True)
        A[e] *= s[None, :] / s[:, None]
        B[e] /= s[:, None]
        C[e] *= s[None, :]
    return A, B, C


class SdProblem:
    """Semi-discretized stability problem of one process over a set of speeds.

    ``models[s]`` is the tool-point model at speed ``speeds_rpm[s]`` (all of the same order).  A
    model with a feed-through ``D`` (y = C x + D F, :class:`~spindlesim.chatter.sd_model.SdModel`)
    has the force F = K (y - y_tau) solved for first: F = K~ (C x - y_tau), K~ = (I - K D)^-1 K, and
    records y = C x + D F in the history.
    """

    def __init__(self, process, models: list[ToolPointModel], speeds_rpm: np.ndarray,
                 steps: int = 40, order: int = 1):
        if order not in (0, 1):
            raise ValueError("semi-discretization order must be 0 or 1")
        if steps < 2:
            raise ValueError("at least two steps per period")
        self.process, self.steps, self.order = process, int(steps), int(order)
        self.speeds = np.asarray(speeds_rpm, float)
        self.tau = process.tooth_period_s(self.speeds)
        n = models[0].A.shape[0]
        if any(mdl.A.shape[0] != n for mdl in models):
            raise ValueError("all tool models must have the same number of states")
        feed = [np.asarray(getattr(mdl, "D", np.zeros((2, 2))), float) for mdl in models]
        rows = np.zeros(2, bool)
        for mdl, d in zip(models, feed):
            rows |= np.any(mdl.C != 0.0, axis=1) | np.any(d != 0.0, axis=1)
        self.U = np.eye(2)[:, rows]  # [2, r] outputs kept in the history
        self.A, self.B, self.Cr = _balanced(np.stack([mdl.A for mdl in models]), np.stack([mdl.B for mdl in models]),
                                            np.stack([mdl.C[rows] for mdl in models]))
        self.D = np.stack(feed) if any(np.any(d) for d in feed) else None
        self.shared = len(models) == 1
        self._K: dict[float, np.ndarray] = {}

    def __getstate__(self) -> dict:
        state = dict(self.__dict__)
        state["_K"] = {}  # rebuilt where needed
        return state

    def subset(self, sel: np.ndarray) -> "SdProblem":
        """The same problem at the speeds ``speeds[sel]`` only (what a worker process is sent)."""
        new = copy.copy(self)
        new.speeds, new.tau, new._K = self.speeds[sel], self.tau[sel], {}
        if not self.shared:
            new.A, new.B, new.Cr = self.A[sel], self.B[sel], self.Cr[sel]
            new.D = None if self.D is None else self.D[sel]
        return new

    def work(self, evaluations: int) -> float:
        """Size of ``evaluations`` evaluations (steps x states x monodromy order each), for PROCESS_WORK."""
        n = self.A.shape[1]
        return float(evaluations) * self.steps * n * (n + self.U.shape[1] * self.steps)

    @staticmethod
    def batches(pieces, what: str = "multipliers") -> list:
        """``[prob.multipliers(s_idx, depth) for prob, s_idx, depth in pieces]`` (or ``prob.criticals``, with
        ``what``): on the worker processes when there are several pieces and their work is above PROCESS_WORK,
        else on the worker threads.  The numbers are the same either way (each piece is evaluated whole, in one
        place)."""
        pieces = list(pieces)
        pool = None
        if len(pieces) > 1 and sum(p.work(len(s)) for p, s, _ in pieces) > PROCESS_WORK:
            pool = _process_pool()
        if pool is not None:
            futures = []
            try:
                futures = [pool.submit(_piece, p.subset(np.asarray(s)), np.asarray(d, float), what)
                           for p, s, d in pieces]
                return [f.result() for f in futures]
            except BrokenProcessPool as exc:  # a worker died (killed, out of memory): on threads from now on
                log.warning("semi-discretization worker processes stopped (%s); going on with threads", exc)
                _broken()
            except BaseException:
                for f in futures:
                    f.cancel()
                raise
        return parallel_map(lambda t: getattr(t[0], what)(t[1], t[2]), pieces)

    def _model(self, s: np.ndarray):
        idx = np.zeros_like(s) if self.shared else s
        return self.A[idx], self.B[idx], self.Cr[idx]

    def _directional(self, depth: float) -> np.ndarray:
        key = float(depth)
        K = self._K.get(key)
        if K is None:  # (a local reference: another thread may clear the cache meanwhile)
            if len(self._K) > 4096:
                self._K.clear()
            K = self._K[key] = self.process.directional_steps(self.steps, key)
        return K

    def monodromy(self, s_idx: np.ndarray, depth: np.ndarray, full: bool = True) -> np.ndarray:
        """Monodromy matrices [E, N, N] at speeds ``speeds[s_idx]`` and depths ``depth`` [m]; with ``full=False``
        the history only of the slots the cut reads (:mod:`.period_map`: the same nonzero multipliers)."""
        return monodromy_matrix(self.step_maps(s_idx, depth), full)

    def step_maps(self, s_idx: np.ndarray, depth: np.ndarray) -> StepMaps:
        """The maps of each step of the period (module note) at speeds ``speeds[s_idx]`` and depths ``depth``."""
        s_idx = np.atleast_1d(np.asarray(s_idx, np.int64))
        depth = np.broadcast_to(np.asarray(depth, float), s_idx.shape)
        m, n, r = self.steps, self.A.shape[1], self.U.shape[1]
        A, B, Cr = self._model(s_idx)
        K = np.stack([self._directional(d) for d in depth])  # [E, m, 2, 2]
        Yx = Yh = None
        if self.D is not None:  # feed-through: F = K~ (C x - y_tau), y = C x + D F
            Dm = self.D[np.zeros_like(s_idx) if self.shared else s_idx][:, None]  # [E, 1, 2, 2]
            M = np.eye(2) - K @ Dm  # K~ = M^-1 K, the 2 x 2 inverse written out
            det = M[..., 0, 0] * M[..., 1, 1] - M[..., 0, 1] * M[..., 1, 0]
            inv = np.stack([np.stack([M[..., 1, 1], -M[..., 0, 1]], -1),
                            np.stack([-M[..., 1, 0], M[..., 0, 0]], -1)], -2) / det[..., None, None]
            K = inv @ K
            DK = self.U.T @ (Dm @ K) @ self.U  # [E, m, r, r]
            Yx = (np.eye(r) + DK) @ Cr[:, None]
            Yh = -DK
        dt = self.tau[s_idx] / m  # [E]
        BK = np.einsum("eak,eikl->eial", B, K)  # [E, m, n, 2]
        D = -BK @ self.U  # [E, m, n, r]
        # exp of [[A_i dt, D_i dt, 0], [0, 0, I_r], [0, 0, 0]] = [[P, Phi0 D, Phi1 D], ...] (Van Loan),
        # A_i = A + B K_i C (C = U Cr) on the steps in the cut; the steps out of it (K_i = 0: A_i = A, D_i = 0)
        # share one exponential per evaluation
        E = len(s_idx)
        free = ~np.any(K != 0.0, axis=(2, 3))  # [E, m]
        cut = ~free
        e_cut = np.nonzero(cut)[0]  # the evaluation of each step in the cut
        # the blocks D dt / g and c I are scaled so that the 1-norm follows A_i dt (a low Pade degree, no
        # squaring); the exponential's (1, 2) block is linear in the (1, 2) block of Z, the (1, 3) block in
        # the product of the (1, 2) and (2, 3) blocks, so Phi0 D = g X12 and Phi1 D = g X13 / c
        dt_c = dt[e_cut, None, None]
        F_c = (A[e_cut] - D[cut] @ Cr[e_cut]) * dt_c
        Dd = D[cut] * dt_c
        g = np.maximum(np.abs(Dd).sum(axis=-2).max(axis=-1) / np.maximum(np.abs(F_c).sum(axis=-2).max(
            axis=-1), 1e-300), 1.0)[..., None, None]
        c = 2.0 ** -5 if self.order == 1 else 0.0
        P = np.empty((E, m, n, n))
        Phi0D, Phi1D = np.empty((E, m, n, r)), np.empty((E, m, n, r))
        if len(F_c):
            P[cut], X1, X2 = self._exponentials(F_c, Dd / g, c)
            Phi0D[cut], Phi1D[cut] = X1 * g, X2 * g
        e_free = np.flatnonzero(free.any(axis=1))
        if len(e_free):  # one exponential per evaluation for its steps out of the cut
            X = self._exponentials(A[e_free] * dt[e_free, None, None], np.zeros((len(e_free), n, r)), c)
            counts = free[e_free].sum(axis=1)
            P[free], Phi0D[free], Phi1D[free] = (np.repeat(x, counts, axis=0) for x in X)
        if self.order == 1:
            R0, R1 = Phi0D - Phi1D, Phi1D
        else:
            R0 = R1 = 0.5 * Phi0D
        return StepMaps(P, R0, R1, Cr, Yx, Yh, cut.any(axis=0))

    @staticmethod
    def _exponentials(F, G, c):
        """(exp F, phi1(F) G, phi2(F) G) of the steps (Van Loan's block exponential, :mod:`._expm`); the
        1-norm of [[F, G, 0], [0, 0, c I], [0, 0, 0]] picks the Pade degree."""
        cols = np.maximum(np.abs(F).sum(axis=-2).max(axis=-1), np.abs(G).sum(axis=-2).max(axis=-1))
        got = van_loan_blocks(F, G, max(float(cols.max()), c))
        if got is not None:
            return got
        n, r = G.shape[-2:]
        Z = np.zeros(F.shape[:-2] + (n + 2 * r,) * 2)
        Z[..., :n, :n], Z[..., :n, n:n + r] = F, G
        Z[..., n:n + r, n + r:] = c * np.eye(r)
        X = expm_batch(Z)
        return X[..., :n, :n], X[..., :n, n:n + r], X[..., :n, n + r:] / c if c else X[..., :n, n + r:]

    def spectral_radius(self, s_idx, depth) -> np.ndarray:
        """Spectral radius at (speed index, depth) pairs."""
        return np.abs(self.multipliers(s_idx, depth)[:, 0])

    def multipliers(self, s_idx, depth) -> np.ndarray:
        """The largest characteristic multipliers [E, k] (largest first) at (speed index, depth) pairs,
        built in batches of bounded memory."""
        s_idx = np.atleast_1d(np.asarray(s_idx, np.int64))
        depth = np.broadcast_to(np.asarray(depth, float), s_idx.shape)
        chunk = min(self._chunk(), max(1, -(-len(s_idx) // workers())))  # every worker gets a share
        starts = range(0, len(s_idx), chunk)

        def part(a):
            return _largest_multipliers(self.monodromy(s_idx[a:a + chunk], depth[a:a + chunk], full=False),
                                        self.A.shape[1])

        return np.concatenate(parallel_map(part, starts))

    def _chunk(self) -> int:
        """Evaluations built together: about 20 million numbers of the largest temporary at most."""
        N = self.A.shape[1] + self.U.shape[1] * self.steps
        m, size = self.steps, self.A.shape[1] + 2 * self.U.shape[1]
        return int(np.clip(2e7 // max(N * N, 6 * m * size * size, m * self.U.shape[1] * N), 1, 128))

    def critical(self, s: int, depth: float) -> CriticalMultiplier:
        """Critical multiplier, boundary kind and dominant chatter frequency at one point."""
        return self.criticals(np.array([s]), np.array([depth]))[0]

    def criticals(self, s_idx, depth) -> list[CriticalMultiplier]:
        """:meth:`critical` at (speed index, depth) pairs, the monodromy matrices built in batches as for
        :meth:`multipliers` (each matrix is the same as alone: the batch runs the same products per matrix)."""
        s_idx = np.atleast_1d(np.asarray(s_idx, np.int64))
        depth = np.broadcast_to(np.asarray(depth, float), s_idx.shape)
        chunk = self._chunk()
        out = []
        for a in range(0, len(s_idx), chunk):
            maps = self.step_maps(s_idx[a:a + chunk], depth[a:a + chunk])
            Phi = monodromy_matrix(maps, full=False)  # the history the cut reads; the rest from the eigenvector
            for e, (s, P) in enumerate(zip(s_idx[a:a + chunk], Phi)):
                mu, v = _dominant_eigenpair(P, self.A.shape[1])
                if mu.imag < 0:  # the conjugate pair member with arg in [0, pi]
                    mu, v = mu.conjugate(), v.conj()
                out.append(self._critical(int(s), mu, period_history(maps, e, mu, v)))
        return out

    def _critical(self, s: int, mu: complex, hist: np.ndarray) -> CriticalMultiplier:
        """Kind and dominant chatter frequency of the critical multiplier ``mu`` from its eigenvector's outputs over
        the period before, ``hist`` [m, r] = y_{-m} ... y_{-1}."""
        rho = abs(mu)
        tol = 1e-9 * max(rho, 1e-300)
        kind = "fold" if (abs(mu.imag) <= tol and mu.real > 0) else ("flip" if abs(mu.imag) <= tol else "hopf")
        m, tau = self.steps, self.tau[s]
        t = (np.arange(m) - m) * (tau / m)  # the samples' instants
        p = hist * np.exp(-np.log(mu) * t / tau)[:, None]
        c = np.fft.fft(p, axis=0)  # harmonic q at (arg mu + 2 pi q) / tau
        q = np.fft.fftfreq(m, 1.0 / m)
        q_best = q[int(np.argmax(np.linalg.norm(c, axis=1)))]
        f = abs(np.angle(mu) + 2 * np.pi * q_best) / (2 * np.pi * tau)
        return CriticalMultiplier(rho, mu, kind, float(f), int(np.floor(f * tau + 1e-9)))


def spectral_radius(process, model: ToolPointModel, speed_rpm: float, depth_m: float,
                    steps: int = 40, order: int = 1) -> float:
    """Spectral radius of the monodromy matrix at one speed [rpm] and depth [m]."""
    prob = SdProblem(process, [model], np.array([speed_rpm]), steps, order)
    return float(prob.spectral_radius(np.array([0]), np.array([depth_m]))[0])
