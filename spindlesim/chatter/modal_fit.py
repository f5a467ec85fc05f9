"""Modal fit of a measured direct FRF: peak picking, then variable-projection least squares.

For each direction d with a non-zero direct term H_dd(w) the model is

    H(w) = sum_r a_r / (w_r^2 - w^2 + 2 j zeta_r w_r w)  +  R_u  -  R_l / w^2,

a_r = 1 / m_r = w_r^2 / k_r the modal residues, R_u and R_l the upper (compliance) and lower
(mass-line) residuals of the modes outside the band.  The fit is separable:

1. Initial modes by peak picking on |H| (scipy.signal.find_peaks, prominence above
   ``prominence`` x max|H|, the ``n_modes`` most prominent if given); zeta from the half-power
   bandwidth, a_r from the peak height.
2. Variable projection (Golub and Pereyra): for given (w_r, zeta_r) the residues and residuals
   are the linear least-squares solution of the stacked real and imaginary parts; only
   log w_r and log zeta_r are iterated (scipy.optimize.least_squares, trust region, soft-L1 loss
   against outliers), equal weights on all samples (the resonance peaks, which set the chatter
   limit, dominate).

Cross terms H_xy are not fitted (tap-test modes are per direction); the state-space model is
:meth:`ToolPointModel.from_modes` of the fitted modes (residual terms are reported, not
modelled).  The fit quality is the RMS of the complex error over the RMS of |H|.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass

import numpy as np
from scipy.optimize import least_squares
from scipy.signal import find_peaks

from .frf import DIRECTIONS, Mode, ToolPointFrf
from .state_space import ToolPointModel

__all__ = ["DirectionFit", "ModalFit", "fit_direction", "fit_tool_point_model"]

log = logging.getLogger(__name__)


@dataclass(frozen=True)
class DirectionFit:
    direction: str
    modes: tuple[Mode, ...]
    upper_residual_m_N: float
    lower_residual_N_m_s2: float  # R_l [m/N * (rad/s)^2]
    relative_rms_error: float


@dataclass(frozen=True, eq=False)
class ModalFit:
    directions: tuple[DirectionFit, ...]
    model: ToolPointModel

    @property
    def modes(self) -> tuple[Mode, ...]:
        return tuple(m for d in self.directions for m in d.modes)


def noise_level(h: np.ndarray) -> float:
    """RMS sample noise [m/N] from the second differences d2 = h[k-1] - 2 h[k] + h[k+1] (tiny for a
    smooth FRF): E|d2|^2 = 6 sigma^2 and, for complex Gaussian noise, median |d2| = sqrt(6 ln 2) sigma."""
    d2 = h[:-2] - 2 * h[1:-1] + h[2:]
    return float(np.median(np.abs(d2)) / np.sqrt(6 * np.log(2)))


def _initial(f: np.ndarray, h: np.ndarray, n_modes: int | None, prominence: float):
    sigma = noise_level(h)
    width = max(1, int(np.ceil(len(h) / 400)))
    mag = np.abs(np.convolve(h, np.ones(2 * width + 1) / (2 * width + 1), mode="same")) if sigma else np.abs(h)
    peaks, props = find_peaks(mag, prominence=max(prominence * mag.max(), 6 * sigma), distance=width + 1)
    if len(peaks) == 0:
        peaks = np.array([int(np.argmax(mag))])
        props = {"prominences": np.array([mag.max()])}
    order = np.argsort(props["prominences"])[::-1]
    if n_modes is not None:
        if len(peaks) < n_modes:
            log.warning("only %d peak(s) found for %d mode(s)", len(peaks), n_modes)
        order = order[:n_modes]
    peaks = np.sort(peaks[order])
    fr, zeta = [], []
    for p in peaks:
        half = mag[p] / np.sqrt(2)
        lo = p
        while lo > 0 and mag[lo] > half:
            lo -= 1
        hi = p
        while hi < len(f) - 1 and mag[hi] > half:
            hi += 1
        z = (f[hi] - f[lo]) / (2 * f[p]) if hi > lo else 0.01
        fr.append(f[p])
        zeta.append(float(np.clip(z, 2e-4, 0.3)))
    return np.array(fr), np.array(zeta)


def _basis(w: np.ndarray, wr: np.ndarray, zeta: np.ndarray, residuals: bool) -> np.ndarray:
    cols = [1.0 / (r * r - w * w + 2j * z * r * w) for r, z in zip(wr, zeta)]
    if residuals:
        cols += [np.ones_like(w, dtype=complex), -1.0 / (w * w) + 0j]
    return np.array(cols).T  # [F, P]


def _linear(w, h, wr, zeta, residuals):
    Phi = _basis(w, wr, zeta, residuals)
    scale = np.abs(Phi).max(axis=0)
    M = np.concatenate([Phi.real, Phi.imag]) / scale
    c, *_ = np.linalg.lstsq(M, np.concatenate([h.real, h.imag]), rcond=None)
    c = c / scale
    return c, Phi @ c


def fit_direction(frequency_hz: np.ndarray, h: np.ndarray, direction: str, *, n_modes: int | None = None,
                  band_hz: tuple[float, float] | None = None, prominence: float = 0.05,
                  residuals: bool = True) -> DirectionFit:
    """Fit the direct receptance ``h`` [m/N] of one direction."""
    f = np.asarray(frequency_hz, float)
    h = np.asarray(h, complex)
    keep = f > 0
    if band_hz is not None:
        keep &= (f >= band_hz[0]) & (f <= band_hz[1])
    f, h = f[keep], h[keep]
    if len(f) < 8:
        raise ValueError(f"direction {direction}: too few samples in the band to fit modes")
    w = 2 * np.pi * f
    fr0, z0 = _initial(f, h, n_modes, prominence)
    R = len(fr0)
    scale = np.abs(h).max()

    def resid(theta):
        wr, z = np.exp(theta[:R]), np.exp(theta[R:])
        _, model = _linear(w, h, wr, z, residuals)
        d = (model - h) / scale
        return np.concatenate([d.real, d.imag])

    theta0 = np.concatenate([np.log(2 * np.pi * fr0), np.log(z0)])
    lo = np.concatenate([np.log(2 * np.pi * np.full(R, f[0])), np.full(R, np.log(1e-5))])
    hi = np.concatenate([np.log(2 * np.pi * np.full(R, f[-1])), np.full(R, np.log(0.9))])
    sol = least_squares(resid, np.clip(theta0, lo + 1e-9, hi - 1e-9), bounds=(lo, hi), loss="soft_l1",
                        f_scale=0.02, x_scale="jac")
    wr, z = np.exp(sol.x[:R]), np.exp(sol.x[R:])
    c, model = _linear(w, h, wr, z, residuals)
    modes = []
    for r in np.argsort(wr):
        k = wr[r] ** 2 / c[r] if c[r] != 0 else np.inf
        if not np.isfinite(k):
            continue
        if k < 0:
            log.warning("direction %s: mode at %.1f Hz has a negative modal stiffness", direction, wr[r] / 2 / np.pi)
        modes.append(Mode(direction, float(wr[r] / (2 * np.pi)), float(z[r]), float(k)))
    err = float(np.sqrt(np.mean(np.abs(model - h) ** 2)) / np.sqrt(np.mean(np.abs(h) ** 2)))
    ru, rl = (float(c[R]), float(c[R + 1])) if residuals else (0.0, 0.0)
    return DirectionFit(direction, tuple(modes), ru, rl, err)


def fit_tool_point_model(frf: ToolPointFrf, *, n_modes: int | dict[str, int] | None = None,
                         band_hz: tuple[float, float] | None = None, prominence: float = 0.05,
                         residuals: bool = True) -> ModalFit:
    """Fit every direction with a non-zero direct FRF and build the state-space model."""
    fits = []
    for i, d in enumerate(DIRECTIONS):
        h = frf.H[:, i, i]
        if not np.any(h != 0):
            continue
        n = n_modes.get(d) if isinstance(n_modes, dict) else n_modes
        fits.append(fit_direction(frf.frequency_hz, h, d, n_modes=n, band_hz=band_hz,
                                  prominence=prominence, residuals=residuals))
    if not fits:
        raise ValueError("the FRF has no non-zero direct term to fit")
    modes = [m for fit in fits for m in fit.modes]
    model = ToolPointModel.from_modes(modes, f"modal fit of {frf.source or 'measured FRF'}")
    return ModalFit(tuple(fits), model)
