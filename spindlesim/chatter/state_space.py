"""First-order state-space model of the tool point: x' = A x + B u, y = C x.

``u`` = tool-tip force (x, y) [N], ``y`` = tool-tip displacement (x, y) [m], so that
H(w) = C (j w I - A)^-1 B is the receptance matrix of :class:`~spindlesim.chatter.frf.ToolPointFrf`.
Any real (A, B, C) is accepted (the lead builds one from the spindle's reduced FE model);
:meth:`ToolPointModel.from_modes` builds one from tap-test modal parameters and
:func:`spindlesim.chatter.modal_fit.fit_tool_point_model` from a measured FRF.

The FRF is evaluated through the eigendecomposition A = V diag(lambda) V^-1 (exact, one
decomposition for any number of frequencies); when V is ill-conditioned the resolvent is
solved at every frequency instead.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass
from functools import cached_property
from typing import Sequence

import numpy as np
import scipy.linalg as sla

from .frf import Mode, ToolPointFrf

__all__ = ["ToolPointModel", "ModeSummary"]

log = logging.getLogger(__name__)
_COND_LIMIT = 1e10
#: the resolvent of a pole is never evaluated closer to it than this share of its modulus: an undamped
#: mode's receptance at its own frequency is infinite, it is taken this far off the pole (the peak of a mode
#: with this damping ratio).  A mode damped more than this is never affected (|j w - lambda| >= |Re lambda|).
POLE_GAP = 1e-6


@dataclass(frozen=True)
class ModeSummary:
    """One oscillatory pole pair: natural frequency, damping ratio and its peak compliance."""

    frequency_hz: float
    damping_ratio: float
    peak_compliance_m_N: float


@dataclass(frozen=True, eq=False)
class ToolPointModel:
    """Real state-space tool-point model; ``A`` [n, n], ``B`` [n, 2], ``C`` [2, n] (SI).  A tool point of the
    protocol of :mod:`spindlesim.chatter.tool` (its ``state_space`` is itself)."""

    A: np.ndarray
    B: np.ndarray
    C: np.ndarray
    source: str = ""

    def __post_init__(self) -> None:
        A, B, C = (np.array(M, float) for M in (self.A, self.B, self.C))
        n = A.shape[0]
        if A.shape != (n, n) or n < 1:
            raise ValueError(f"A must be square, got {A.shape}")
        if B.shape != (n, 2):
            raise ValueError(f"B must have shape ({n}, 2), got {B.shape}")
        if C.shape != (2, n):
            raise ValueError(f"C must have shape (2, {n}), got {C.shape}")
        for name, M in (("A", A), ("B", B), ("C", C)):
            if not np.all(np.isfinite(M)):
                raise ValueError(f"{name} holds non-finite values")
            M.setflags(write=False)
        object.__setattr__(self, "A", A)
        object.__setattr__(self, "B", B)
        object.__setattr__(self, "C", C)

    # -- constructors -------------------------------------------------------------------------
    @classmethod
    def from_modes(cls, modes: Sequence[Mode], source: str = "modal parameters") -> "ToolPointModel":
        """Uncoupled modes, each a mass-spring-damper in its direction (q, q') per mode.

        Mode r in direction d: m_r q'' + c_r q' + k_r q = F_d, displacement_d += q, with
        m_r = k_r / w_r^2 and c_r = 2 zeta_r sqrt(k_r m_r); H_dd = sum_r 1 / (k_r (1 - r^2 + 2 j zeta_r r)).
        """
        modes = list(modes)
        if not modes:
            raise ValueError("at least one mode is needed")
        n = 2 * len(modes)
        A, B, C = np.zeros((n, n)), np.zeros((n, 2)), np.zeros((2, n))
        for r, md in enumerate(modes):
            w = 2 * np.pi * md.frequency_hz
            i = 2 * r
            A[i, i + 1] = 1.0
            A[i + 1, i] = -w * w
            A[i + 1, i + 1] = -2 * md.damping_ratio * w
            B[i + 1, md.index] = w * w / md.stiffness_N_m  # 1 / m_r
            C[md.index, i] = 1.0
        return cls(A, B, C, source)

    @classmethod
    def from_measured(cls, frf: ToolPointFrf, **fit_options) -> "ToolPointModel":
        """Modal fit of a measured FRF (:func:`spindlesim.chatter.modal_fit.fit_tool_point_model`)."""
        from .modal_fit import fit_tool_point_model

        return fit_tool_point_model(frf, **fit_options).model

    @property
    def state_space(self) -> "ToolPointModel":
        return self

    # -- frequency response -------------------------------------------------------------------
    @cached_property
    def eigen(self) -> tuple[np.ndarray, np.ndarray, tuple]:
        """(poles, eigenvectors V, LU factors of V): computed once for the FRF and the modal reductions (numpy's
        geev, which releases the interpreter lock: a lobe diagram's models are decomposed on the worker threads)."""
        lam, V = np.linalg.eig(self.A)
        return lam, V, sla.lu_factor(V, check_finite=False)

    @cached_property
    def _eig(self) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
        lam, V, lu = self.eigen
        gecon = sla.get_lapack_funcs("gecon", (V,))
        rcond, info = gecon(lu[0], np.linalg.norm(V, 1), norm="1")  # LAPACK's 1-norm estimate
        if info != 0 or rcond < 1.0 / _COND_LIMIT:
            log.info("tool-point model: ill-conditioned eigenvectors; FRF by direct solves")
            return None
        left = sla.lu_solve(lu, self.B.astype(complex), check_finite=False)  # V^-1 B [n, 2]
        CV = self.C @ V
        # residues: H(w) = sum_r R_r / (j w - lambda_r), R_r[i, j] = (C V)[i, r] (V^-1 B)[r, j]
        return lam, CV, left, (CV.T[:, :, None] * left[:, None, :]).reshape(len(lam), 4)

    def poles(self) -> np.ndarray:
        """Eigenvalues of A [1/s]."""
        e = self._eig
        return e[0] if e is not None else np.linalg.eigvals(self.A)

    def receptance(self, omega: np.ndarray) -> np.ndarray:
        """H(w) [len(w), 2, 2] for angular frequencies ``omega`` [rad/s]."""
        w = np.atleast_1d(np.asarray(omega, float))
        e = self._eig
        if e is not None:
            lam, _, _, residues = e
            R = _off_poles(1j * w[:, None] - lam[None, :], lam)  # [f, n], a new array
            np.divide(1.0, R, out=R)  # in place: half the time of 1 / R on a rotor model's grid (no second array)
            return (R @ residues).reshape(len(w), 2, 2)
        n = self.A.shape[0]
        out = np.empty((len(w), 2, 2), complex)
        for k, wk in enumerate(w):
            try:
                out[k] = self.C @ np.linalg.solve(1j * wk * np.eye(n) - self.A, self.B)
            except np.linalg.LinAlgError:  # exactly on an undamped pole: POLE_GAP off it
                out[k] = self.C @ np.linalg.solve(1j * wk * (1 + POLE_GAP) * np.eye(n) - self.A, self.B)
        return out

    def frf(self, frequency_hz: np.ndarray | None = None) -> ToolPointFrf:
        """Sampled FRF; without frequencies, on :meth:`frequency_grid`."""
        f = self.frequency_grid() if frequency_hz is None else np.asarray(frequency_hz, float)
        return ToolPointFrf(f, self.receptance(2 * np.pi * f), self.source)

    def modes(self) -> list[ModeSummary]:
        """Oscillatory pole pairs (Im > 0), sorted by frequency, with their peak compliance."""
        return list(self._modes)

    @cached_property
    def _modes(self) -> tuple[ModeSummary, ...]:
        lam = self.poles()
        osc = lam[lam.imag > 1e-9 * np.abs(lam).max()]
        osc = osc[np.argsort(np.abs(osc))]
        if not len(osc):
            return ()
        wn = np.abs(osc)
        peaks = np.linalg.svd(self.receptance(wn), compute_uv=False)[:, 0]
        return tuple(ModeSummary(float(w / (2 * np.pi)), float(-p.real / w), float(pk))
                     for p, w, pk in zip(osc, wn, peaks))

    def significant_modes(self, rel: float = 1e-3) -> list[ModeSummary]:
        """Modes whose peak compliance is at least ``rel`` times the largest one."""
        m = self.modes()
        if not m:
            return m
        top = max(s.peak_compliance_m_N for s in m)
        return [s for s in m if s.peak_compliance_m_N >= rel * top]

    def frequency_grid(self, f_min_hz: float | None = None, f_max_hz: float | None = None,
                       points_per_mode: int = 241, background: int = 600) -> np.ndarray:
        """Frequencies [Hz] clustered on the significant modes: equal phase steps of a
        single mode (w_n (1 + zeta tan(theta)), |theta| < 1.5) plus a geometric background over
        [f_min, f_max] (default 0.25 x lowest to 3 x highest significant mode).  Significant here:
        a hundredth of the largest peak compliance (a mode below that limits the depth of cut at a
        hundred times the minimum) and not above three times the highest mode with a tenth of it
        (a rotor model's stiff, lightly damped modes at tens of kHz, where no chatter arises)."""
        sig = self.significant_modes(rel=1e-2)
        if not sig:
            raise ValueError("the tool-point model has no oscillatory mode")
        top = max(s.frequency_hz for s in self.significant_modes(rel=0.1))
        sig = [s for s in sig if s.frequency_hz <= 3.0 * top]
        fl = f_min_hz if f_min_hz is not None else 0.25 * min(s.frequency_hz for s in sig)
        fh = f_max_hz if f_max_hz is not None else 3.0 * max(s.frequency_hz for s in sig)
        parts = [np.geomspace(fl, fh, background)]
        peak = max(s.peak_compliance_m_N for s in sig)
        for s in sig:  # a quarter of the points on the modes below a tenth of the largest peak
            th = np.linspace(-1.5, 1.5, points_per_mode if s.peak_compliance_m_N >= 0.1 * peak
                             else points_per_mode // 4 + 1)
            z = max(s.damping_ratio, 1e-4)
            parts.append(s.frequency_hz * (1.0 + min(z, 0.08) * np.tan(th)))
        f = np.unique(np.concatenate(parts))
        return f[(f >= fl) & (f <= fh)]

    def truncated(self, max_frequency_hz: float) -> "ToolPointModel":
        """Modal truncation: keep the poles with |lambda| <= 2 pi max_frequency_hz (real block form).

        The static compliance of the dropped modes is lost (no feed-through term); meant for
        large FE models before the semi-discretization or the time-domain simulation.
        """
        lam, V = sla.eig(self.A, check_finite=False)
        keep = np.abs(lam) <= 2 * np.pi * max_frequency_hz
        if not np.any(keep):
            raise ValueError("no pole below max_frequency_hz")
        W = sla.inv(V)
        cols, rows = [], []
        for r in np.flatnonzero(keep):
            if lam[r].imag < 0 and np.any(np.isclose(lam[keep], np.conj(lam[r]))):
                continue  # handled with its conjugate
            if abs(lam[r].imag) <= 1e-12 * max(abs(lam[r]), 1.0):
                cols.append(V[:, r].real)
                rows.append(W[r].real)
            else:  # pair: x = 2 Re(v q) -> basis (Re v, -Im v), coordinates (Re q, Im q)
                cols += [2 * V[:, r].real, -2 * V[:, r].imag]
                rows += [W[r].real, W[r].imag]
        T = np.array(cols).T
        S = np.array(rows)
        A = S @ self.A @ T
        return ToolPointModel(A, S @ self.B, self.C @ T,
                              f"{self.source} (modes below {max_frequency_hz:g} Hz)")


def _off_poles(d: np.ndarray, lam: np.ndarray) -> np.ndarray:
    """``d`` = j w - lambda [f, n] with every entry closer to its pole than POLE_GAP |lambda| moved out to that
    distance (same direction; on the pole itself, along +j): only undamped poles can be that close."""
    light = np.flatnonzero(np.abs(lam.real) < POLE_GAP * np.abs(lam))  # only these can come that close
    if not len(light):
        return d
    gap = POLE_GAP * np.abs(lam)[None, :]
    near = np.zeros(d.shape, bool)
    near[:, light] = np.abs(d[:, light]) < gap[:, light]
    if not near.any():
        return d
    d = d.copy()
    dn = d[near]
    mag = np.abs(dn)
    unit = np.where(mag > 0, dn / np.where(mag > 0, mag, 1.0), 1j)
    d[near] = unit * np.broadcast_to(gap, d.shape)[near]
    return d


