"""The compiled kernels of the time-domain chatter simulation (:mod:`.simulation`): the regenerative force on the
tool from the stored surface and the step-by-step integration of the discretised tool-point model.  A module of
their own so that importing the chatter package (every lobe diagram) does not import numba; the simulation imports
it when it runs."""

from __future__ import annotations

import numba
import numpy as np

__all__ = ["integrate"]


@numba.njit(cache=True)
def _force(y, kk, E, Fv, H0, W, BIN, surf, depth, update, counts, h_count):  # pragma: no cover
    F0 = 0.0
    F1 = 0.0
    for s in range(W.shape[1]):
        w = W[kk, s]
        if w <= 0.0:
            continue
        b = BIN[kk, s]
        ey = E[kk, s, 0] * y[0] + E[kk, s, 1] * y[1]
        h = H0[kk, s] + ey - surf[b]
        if h > 0.0:
            F0 += depth * w * h * Fv[kk, s, 0]
            F1 += depth * w * h * Fv[kk, s, 1]
            if update:
                surf[b] = ey
                if H0[kk, s] >= h_count:
                    counts[0] += 1
        elif update:
            surf[b] -= H0[kk, s]
            if H0[kk, s] >= h_count:
                counts[1] += 1
    return F0, F1


@numba.njit(cache=True)
def integrate(P, G0, G1, C, E, Fv, H0, W, BIN, nbins, depth, m, periods, h_count):  # pragma: no cover
    n = P.shape[0]
    total = m * periods
    Y = np.zeros((total + 1, 2))
    Fh = np.zeros((total + 1, 2))
    surf = np.zeros(nbins)
    x = np.zeros(n)
    xp = np.zeros(n)
    y = np.zeros(2)
    counts = np.zeros(2, np.int64)
    late = np.zeros(2, np.int64)
    F0, F1 = _force(y, 0, E, Fv, H0, W, BIN, surf, depth, True, counts, h_count)
    Fh[0, 0], Fh[0, 1] = F0, F1
    for k in range(total):
        for a in range(n):
            acc = G0[a, 0] * F0 + G0[a, 1] * F1
            for b in range(n):
                acc += P[a, b] * x[b]
            xp[a] = acc
        for p in range(2):
            acc = 0.0
            for a in range(n):
                acc += C[p, a] * xp[a]
            y[p] = acc
        kk = (k + 1) % m
        Q0, Q1 = _force(y, kk, E, Fv, H0, W, BIN, surf, depth, False, counts, h_count)
        for a in range(n):
            x[a] = xp[a] + G1[a, 0] * (Q0 - F0) + G1[a, 1] * (Q1 - F1)
        for p in range(2):
            acc = 0.0
            for a in range(n):
                acc += C[p, a] * x[a]
            y[p] = acc
        if k + 1 >= total // 2:
            before0, before1 = counts[0], counts[1]
            F0, F1 = _force(y, kk, E, Fv, H0, W, BIN, surf, depth, True, counts, h_count)
            late[0] += counts[0] - before0
            late[1] += counts[1] - before1
        else:
            F0, F1 = _force(y, kk, E, Fv, H0, W, BIN, surf, depth, True, counts, h_count)
        Y[k + 1, 0], Y[k + 1, 1] = y[0], y[1]
        Fh[k + 1, 0], Fh[k + 1, 1] = F0, F1
    return Y, Fh, late
