"""Compiled force of the rigid-race bearing (``RigidRaceBearing``), for the explicit integrator.

The same equations as ``RigidRaceBearing.force_and_tangent`` (Sunnersjo 1978; Harsha and
Kankar 2004), written as a loop for numba:

    f_x = -sum_j K (x cos th_j + y sin th_j - gamma_0 + w_j)_+^n cos th_j,   f_y likewise with sin,
    th_j = phase + 2 pi j/N + c phi   (c the cage ratio, phi the shaft angle)

minus the damping force: beta K_t v, K_t = sum_j n K delta_j^(n-1) (cos, sin)(cos, sin)^T the contacts'
tangent (``bearings.damping``; skipped when beta = 0), or C v with the matrix held at the operating point.

cos th_j and sin th_j come from the angle-addition formulas with the cage angle, so a call
costs two trigonometric evaluations whatever N is.  The parameters are the float vector of
``RigidRaceBearing.compiled()`` (layout below), so one compiled kernel serves every deck and is
cached on disk.
"""

from __future__ import annotations

import numpy as np
from numba import njit

# float layout: K, n, gamma0, cage ratio, spin ratio, beta, held C (4, row-major), cos base (N), sin base (N),
# waviness rows (4 each: surface 0 outer / 1 inner / 2 roller, waves, amplitude, phase); ints: N, waviness rows
K, EXPONENT, CLEARANCE, CAGE_RATIO, SPIN_RATIO, DAMPING, HELD = range(7)
HEAD = HELD + 4


@njit(cache=True, inline="always")
def _power(d, n):
    """d^n for d > 0; the line-contact exponent 10/9 as d * d^(1/9) (one cube root of a cube root)."""
    if n == 1.5:
        return d * np.sqrt(d)
    return d ** n


@njit(cache=True, inline="always")
def force(fl, f0, it, i0, q, v, t, speed, angle, out):
    """Force on the shaft (x, y) at displacement q and velocity v into out[0:2]; this bearing's parameters start
    at fl[f0], it[i0]."""
    N, nw = it[i0], it[i0 + 1]
    cb0 = f0 + HEAD
    sb0 = cb0 + N
    w0 = sb0 + N
    cage = fl[f0 + CAGE_RATIO] * angle
    cw, sw = np.cos(cage), np.sin(cage)
    x, y = q[0], q[1]
    k, n, gap, beta = fl[f0 + K], fl[f0 + EXPONENT], fl[f0 + CLEARANCE], fl[f0 + DAMPING]
    fx, fy = 0.0, 0.0
    kxx, kxy, kyy = 0.0, 0.0, 0.0
    for j in range(N):
        c = fl[cb0 + j] * cw - fl[sb0 + j] * sw
        sn = fl[sb0 + j] * cw + fl[cb0 + j] * sw
        d = x * c + y * sn - gap
        if nw > 0:
            th = np.arctan2(sn, c)
            for h in range(nw):
                r = w0 + 4 * h
                kind, waves, amp, ph = int(fl[r]), fl[r + 1], fl[r + 2], fl[r + 3]
                if kind == 0:
                    d += amp * np.cos(waves * th + ph)
                elif kind == 1:
                    d += amp * np.cos(waves * (th - angle) + ph)
                else:
                    spin = fl[f0 + SPIN_RATIO] * angle
                    d += amp * (np.cos(waves * spin + ph) + np.cos(waves * (spin + np.pi) + ph))
        if d > 0.0:
            qj = k * _power(d, n)
            fx += qj * c
            fy += qj * sn
            if beta != 0.0:
                kj = n * qj / d
                kxx += kj * c * c
                kxy += kj * c * sn
                kyy += kj * sn * sn
    h = f0 + HELD
    out[0] = -fx - beta * (kxx * v[0] + kxy * v[1]) - fl[h] * v[0] - fl[h + 1] * v[1]
    out[1] = -fy - beta * (kxy * v[0] + kyy * v[1]) - fl[h + 2] * v[0] - fl[h + 3] * v[1]
