"""The tool-point model the semi-discretization works on: the dominant modes of a large model plus
the compliance of the others.

The semi-discretization costs, per (speed, depth), one matrix exponential of order n + 2 r per step
and a product of m matrices of order n: a rotor's tool-point model (100 to 200 states) makes it a
hundred times dearer than a tap-tested tool's.  The receptance at the tool point is dominated by a
few modes; the others act on it almost statically in the chatter band.  So (modal truncation with a
residual compliance):

    H(w) ~ sum over the kept modes R_r / (j w - lambda_r) + conj.  +  D,
    D = Re (H_full(w_d) - H_kept(w_d))   (real 2 x 2; y = C x + D F),

w_d the dominant mode's frequency: the modes above the band act statically there, the few below
(a rotor's heavily damped rigid-body-like modes at tens of Hz) mass-like, and matching the rest where
it matters serves both (a static D, matched at w = 0, left 1.6 % in the seed 003 spindle's depth
curve; matched at w_d, 0.08 %).  The kept modes are the pole pairs with the largest peak compliance
|R_r| / |Re lambda_r| among those up to three times the highest mode with a tenth of the largest
(the same number at every speed, the largest count any speed needs).  How many: the smallest set of
the modes with at least 10 %, 5 %, 2 % or 1 % of the largest peak compliance whose zero-order depth
per chatter frequency agrees with the full model's to ``REDUCTION_RTOL`` (:func:`models_for_sd`); if
none does, the full model is used.  Models of at most ``REDUCE_ABOVE_STATES`` states (a tap test's
few modes) are used as they are.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass
from functools import cached_property

import numpy as np
import scipy.linalg as sla

from .state_space import ToolPointModel

__all__ = ["SdModel", "dominant_modes", "models_for_sd", "REDUCTION_RTOL", "REDUCE_ABOVE_STATES"]

log = logging.getLogger(__name__)

REDUCTION_RTOL = 5e-3
REDUCE_ABOVE_STATES = 16
#: peak-compliance levels tried in turn (the modes at or above each share of the largest).  The finer ones keep
#: a tool library's short tools off the full model: em12_shrink_45 of decks/tool_library.yaml needs 30 of its
#: 125 pairs (depth curve within 2e-4; 23 pairs, the 0.01 level, leave 2 %), and the full 250-state model
#: with 350 steps a period costs minutes a speed
_LEVELS = (0.1, 0.05, 0.02, 0.01, 0.005, 0.002, 0.001)


@dataclass(frozen=True, eq=False)
class SdModel:
    """x' = A x + B F, y = C x + D F (SI); ``D`` the static compliance of the dropped modes."""

    A: np.ndarray
    B: np.ndarray
    C: np.ndarray
    D: np.ndarray
    source: str = ""

    @cached_property
    def dynamic(self) -> ToolPointModel:
        """The kept modes alone (no static rest)."""
        return ToolPointModel(self.A, self.B, self.C, self.source)

    def receptance(self, omega: np.ndarray) -> np.ndarray:
        return self.dynamic.receptance(omega) + self.D

    def significant_modes(self, rel: float = 1e-3):
        return self.dynamic.significant_modes(rel)


@dataclass(frozen=True, eq=False)
class _Modal:
    lam: np.ndarray  # poles with Im >= 0 (one of each conjugate pair)
    V: np.ndarray
    W: np.ndarray  # rows of V^-1
    peak: np.ndarray  # peak compliance estimate per pole [m/N]; 0 for real poles (never kept)


def _modal(model: ToolPointModel) -> _Modal:
    """Poles, eigenvectors and peak compliances; candidates are the oscillatory poles up to three
    times the highest mode with a tenth of the largest peak compliance (the band where chatter
    arises, as in the frequency grid; a rotor's stiff, nearly undamped modes far above it go to the
    rest)."""
    lam, V, lu = model.eigen
    W = sla.lu_solve(lu, np.eye(len(lam), dtype=complex), check_finite=False)
    up = lam.imag > 1e-9 * np.abs(lam).max()
    CV, WB = model.C @ V, W @ model.B
    R = np.einsum("ir,rj->rij", CV, WB)
    peak = np.where(up, np.linalg.norm(R, 2, axis=(1, 2)) / np.maximum(np.abs(lam.real), 1e-300), 0.0)
    top = max(s.frequency_hz for s in model.significant_modes(rel=0.1))
    peak[np.abs(lam) > 2 * np.pi * 3.0 * top] = 0.0
    keep = up | (np.abs(lam.imag) <= 1e-9 * np.abs(lam).max())
    return _Modal(lam[keep], V[:, keep], W[keep], peak[keep])


def dominant_modes(model: ToolPointModel, count: int, modal: _Modal | None = None) -> SdModel:
    """The ``count`` pole pairs of largest peak compliance (real block form) and the rest, as the
    real part of its receptance at the dominant mode (static for the modes above, mass-like for
    the few below)."""
    md = modal or _modal(model)
    order = np.argsort(-md.peak)[:count]
    cols, rows = [], []
    for r in order:  # pair: x = 2 Re(v q) -> basis (Re v, -Im v), coordinates (Re q, Im q)
        v, w = md.V[:, r], md.W[r]
        cols += [2 * v.real, -2 * v.imag]
        rows += [w.real, w.imag]
    T, S = np.array(cols).T, np.array(rows)
    A, B, C = S @ model.A @ T, S @ model.B, model.C @ T
    kept = ToolPointModel(A, B, C)
    w0 = np.array([abs(md.lam[order[0]])])
    D = (model.receptance(w0)[0] - kept.receptance(w0)[0]).real
    return SdModel(A, B, C, D, f"{model.source}: {count} dominant modes + the rest's compliance")


def _depth_curve(K0: np.ndarray, H: np.ndarray) -> np.ndarray:
    """Smallest zero-order depth per frequency, -1 / (2 min Re lambda), lambda the eigenvalues of
    -K0 H (inf where no branch has Re lambda < 0): the parametric lobes' depth, free of the speed."""
    M = -np.einsum("ij,fjk->fik", K0, H)
    half = 0.5 * (M[:, 0, 0] + M[:, 1, 1])  # the 2 x 2 eigenvalues in closed form: half -+ disc
    disc = np.sqrt(half * half - (M[:, 0, 0] * M[:, 1, 1] - M[:, 0, 1] * M[:, 1, 0]))
    re = np.minimum((half + disc).real, (half - disc).real)
    return np.where(re < 0, -0.5 / np.where(re < 0, re, -1.0), np.inf)


def models_for_sd(models: list[ToolPointModel], K0: np.ndarray, span: float = 3.0,
                  frfs: list | None = None) -> tuple[list, str]:
    """The models the semi-discretization runs on (one, or one per speed) and a note saying which; ``frfs``
    the models' FRFs on their own grids (``model.frf()``) where the caller has them already.

    The check: at every frequency of each model's mode-clustered grid where the depth curve
    -1 / (2 min Re lambda(w)) of the full model (lambda the eigenvalues of -K0 H(w); the zero-order
    lobes are this curve mapped onto the speeds) is within ``span`` times its minimum, the reduced
    model's must agree to REDUCTION_RTOL.  Checked per frequency, not per speed, so that a steep
    lobe flank does not magnify a tiny shift in speed into a large change of depth.  Where the
    curve is higher the dropped modes weigh more (milling spindle: 9 modes agree to 0.16 % up to
    3 x the minimum, 2.4 % up to 8 x; the zero-order limits at 200 speeds to 0.02 % median, 1.4 %
    at the tip of the highest pocket, 7 x the minimum)."""
    if not models or any(m.A.shape[0] <= REDUCE_ABOVE_STATES for m in models):
        return models, ""
    from .semi_discretization import parallel_map  # the speeds' models on the worker threads

    def full(i):
        m = models[i]
        frf = m.frf() if frfs is None else frfs[i]
        return _modal(m), frf.omega, _depth_curve(K0, frf.H)

    try:
        modal, grids, curves = (list(x) for x in zip(*parallel_map(full, range(len(models)))))
    except (np.linalg.LinAlgError, ValueError):
        return models, ""
    masks = [np.isfinite(c) & (c <= span * c.min()) for c in curves]
    n_full = models[0].A.shape[0]
    for level in _LEVELS:
        count = max(int(np.count_nonzero(md.peak >= level * md.peak.max())) for md in modal)
        if 2 * count >= n_full:
            break
        def reduced(i, count=count):
            r = dominant_modes(models[i], count, modal[i])
            cr = _depth_curve(K0, r.receptance(grids[i][masks[i]]))
            c = curves[i][masks[i]]
            return r, float(np.max(np.abs(cr / c - 1), initial=0.0)) if np.all(np.isfinite(cr)) else np.inf

        got = parallel_map(reduced, range(len(models)))
        red = [g[0] for g in got]
        err = max(g[1] for g in got)
        log.info("semi-discretization model: %d modes (peak compliance >= %g of the largest): depth curve "
                 "within %.2g", count, level, err)
        if err <= REDUCTION_RTOL:
            return red, (f"semi-discretization on the {count} dominant modes of the {n_full}-state tool-point "
                         f"model plus the others' compliance at the dominant mode (zero-order depth per chatter "
                         f"frequency within {100 * err:.2g} % up to {span:g} x its minimum)")
    return models, ""
