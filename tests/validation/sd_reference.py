"""An independent semi-discretization of the milling delay equation, the reference of the chatter tests.

Written from Insperger and Stepan ("Updated semi-discretization method for periodic delay-differential
equations with discrete delay", IJNME 61 (2004) 117-141; "Semi-Discretization for Time-Delay Systems",
Springer 2011, ch. 3 and 4) with the first-order (linear) interpolation of the delayed term (Insperger,
Stepan and Turi, JSV 313 (2008) 334-341).  It shares no code with spindlesim's semi-discretization and
differs from it in how the period is cut:

* The milling model of the book (sec. 4.2), x feed, y normal, teeth at phi_j(t) = Omega t + 2 pi j / N:
      M q'' + C q' + K q = -a H(t) (q(t) - q(t - tau)),
      H(t) = sum_j g(phi_j) [[s (Kt c + Kn s), c (Kt c + Kn s)], [s (-Kt s + Kn c), c (-Kt s + Kn c)]],
  s, c = sin, cos phi_j; g = 1 within the cut (up milling from 0 to arccos(1 - 2 ae/D), down milling
  from arccos(2 ae/D - 1) to pi).  The 1-DOF model is the xx entry.
* Only the part of the tooth period during which a tooth cuts is discretised, in ``k`` equal steps
  starting at a tooth's entry; the rest (free vibration, H = 0) is one exact step.  The delayed
  samples are then the previous period's samples at the same instants, so the history holds the
  k + 1 outputs of the last cut and the resolution in the cut does not depend on the immersion.
* H is averaged over each step by Gauss-Legendre quadrature, split at every tooth entry and exit.
* Each step's ODE x' = A_i x + B_i (q_(i-m) + (t - t_i)/dt (q_(i-m+1) - q_(i-m))) is solved exactly
  (scipy.linalg.expm of the block matrix [[A_i dt, B_i dt, 0], [0, 0, I], [0, 0, 0]]).
* The limit is the first depth with spectral radius 1 going up from zero: a grid scan, then Brent.
  ``limit`` extrapolates k and 2 k steps (Richardson, second order) and returns the estimate and
  |a_2k - a_k| as its error bound.
"""

from __future__ import annotations

import numpy as np
from scipy.linalg import expm
from scipy.optimize import brentq

_GX, _GW = np.polynomial.legendre.leggauss(6)


class MillingReference:
    def __init__(self, teeth: int, immersion: float, mode: str, Kt: float, Kn: float, fn_hz, zeta, k_N_m):
        self.N, self.Kt, self.Kn = teeth, Kt, Kn
        self.st, self.ex = ((0.0, np.arccos(1 - 2 * immersion)) if mode == "up"
                            else (np.arccos(2 * immersion - 1), np.pi))
        fn, zeta, k = (np.atleast_1d(np.asarray(v, float)) for v in (fn_hz, zeta, k_N_m))
        self.n = len(fn)
        w = 2 * np.pi * fn
        m = k / w**2
        n = self.n
        self.Minv = np.diag(1 / m)
        self.A0 = np.zeros((2 * n, 2 * n))
        self.A0[:n, n:] = np.eye(n)
        self.A0[n:, :n] = -np.diag(k / m)
        self.A0[n:, n:] = -np.diag(2 * zeta * w)

    def _H(self, phi: np.ndarray) -> np.ndarray:
        p = np.mod(phi, 2 * np.pi)
        g = (p >= self.st) & (p <= self.ex)
        s, c = np.sin(p), np.cos(p)
        a, b = self.Kt * c + self.Kn * s, -self.Kt * s + self.Kn * c
        h = np.stack([np.stack([s * a, c * a], -1), np.stack([s * b, c * b], -1)], -2)
        return np.where(g[..., None, None], h, 0.0).sum(axis=-3)[..., :self.n, :self.n]

    def _step_means(self, Om: float, T: float, k: int) -> np.ndarray:
        N = self.N
        breaks = []
        for j in range(N):
            for edge in (self.st, self.ex):
                t = np.mod(edge - self.st - 2 * np.pi * j / N, 2 * np.pi) / Om + np.arange(-2, 3) * 2 * np.pi / Om
                breaks.extend(t[(t > 0) & (t < T)])
        edges = np.linspace(0.0, T, k + 1)
        out = np.zeros((k, self.n, self.n))
        for i in range(k):
            pts = np.unique(np.r_[edges[i], [b for b in breaks if edges[i] < b < edges[i + 1]], edges[i + 1]])
            for lo, hi in zip(pts[:-1], pts[1:]):
                t = 0.5 * (lo + hi) + 0.5 * (hi - lo) * _GX
                phi = self.st + Om * t[:, None] + 2 * np.pi * np.arange(N)[None, :] / N
                out[i] += 0.5 * (hi - lo) * np.einsum("q,qij->ij", _GW, self._H(phi))
            out[i] /= edges[i + 1] - edges[i]
        return out

    def spectral_radius(self, rpm: float, depths, k: int) -> np.ndarray:
        n, N = self.n, self.N
        Om = 2 * np.pi * rpm / 60.0
        tau = 2 * np.pi / (N * Om)
        T = tau if N * (self.ex - self.st) >= 2 * np.pi else (self.ex - self.st) / Om
        dt = T / k
        Hs = self._step_means(Om, T, k)
        a = np.atleast_1d(np.asarray(depths, float))
        E, Nz = len(a), 2 * n + (k + 1) * n
        X = np.zeros((E, 2 * n, Nz))
        X[:, :, :2 * n] = np.eye(2 * n)
        Q = np.zeros((E, k + 1, n, Nz))
        for i in range(k):
            Q[:, i] = X[:, :n]
            aMH = self.Minv @ (a[:, None, None] * Hs[i])
            Z = np.zeros((E, 4 * n, 4 * n))
            Z[:, :2 * n, :2 * n] = self.A0 * dt
            Z[:, n:2 * n, :n] -= aMH * dt
            Z[:, n:2 * n, 2 * n:3 * n] = aMH * dt
            Z[:, 2 * n:3 * n, 3 * n:] = np.eye(n)
            F = expm(Z)
            P, G0, G1 = F[:, :2 * n, :2 * n], F[:, :2 * n, 2 * n:3 * n], F[:, :2 * n, 3 * n:]
            Xn = P @ X
            c = 2 * n + i * n
            Xn[:, :, c:c + n] += G0 - G1
            Xn[:, :, c + n:c + 2 * n] += G1
            X = Xn
        Q[:, k] = X[:, :n]
        if tau - T > 0:
            X = expm(self.A0 * (tau - T)) @ X
        Phi = np.concatenate([X, Q.reshape(E, (k + 1) * n, Nz)], axis=1)
        return np.abs(np.linalg.eigvals(Phi)).max(axis=-1)

    def _first_crossing(self, rpm: float, a_max: float, k: int, grid: int) -> float:
        a = np.linspace(a_max / grid, a_max, grid)
        r = self.spectral_radius(rpm, a, k)
        bad = np.flatnonzero(r >= 1.0)
        if not len(bad):
            return np.inf
        j = bad[0]
        lo = a[j - 1] if j else 1e-3 * a[0]
        return brentq(lambda x: self.spectral_radius(rpm, [x], k)[0] - 1.0, lo, a[j], xtol=1e-10 * a_max, rtol=1e-9)

    def limit(self, rpm: float, a_max: float, k: int = 40, grid: int = 80) -> tuple[float, float]:
        """(limit depth [m], error bound): Richardson from k and 2 k steps in the cut; inf above a_max."""
        a1 = self._first_crossing(rpm, a_max, k, grid)
        a2 = self._first_crossing(rpm, a_max, 2 * k, grid)
        if not (np.isfinite(a1) and np.isfinite(a2)):
            return np.inf, np.inf
        return (4 * a2 - a1) / 3, abs(a2 - a1)
