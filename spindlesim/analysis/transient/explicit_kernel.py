"""Compiled fixed-step RK4 loop of the rotor system and its right-hand side (numba, cached on disk).

y = [x (N), v (N)], x = [rotor DOFs (n), internal DOFs of the bearings]:

    x' = v
    a_rotor = M_r^-1 (F_r(t) - (K0 + Omega Kc) x_r - (C0 + Omega G) v_r + f_b,r)
    a_internal = f_b,internal / m_internal

with Omega = w0 + alpha t, phi = w0 t + alpha t^2 / 2 (``system.SpeedProfile``), the excitation of
``system.Excitation`` and every bearing's compiled force (``spindlesim.bearings.compiled.force``).
RK4 (Kutta 1901): y_{n+1} = y_n + h/6 (k1 + 2 k2 + 2 k3 + k4).  States at instants between
steps (Poincare) come from the cubic Hermite interpolant of (y, y') at the step ends.

Everything travels in one float vector and one int vector (``explicit.pack``), with the block
offsets in the int vector's header (indices below): numba reference-counts every array it takes
out of a tuple at every call, which cost more than the physics of a small rotor.  A bearing whose
DOFs are consecutive in y (a journal with its internal DOFs) reads its state in place; the others
are gathered.  The state is checked for non-finite values at every sample (a NaN stays NaN), and
the end of a step is kept for interpolation only when a Poincare instant falls in the next one.  The rotor
matrices are coordinate triplets without their zeros: a rigid journal costs a few products, a
Timoshenko shaft its band.
"""

from __future__ import annotations

import numpy as np
from numba import literal_unroll, njit

from ...bearings.compiled import KERNEL_FILES
from ...bearings.compiled import force as bearing_force
from .kernel_cache import track

# rk4 inlines every bearing family's force: its cached machine code is stale when one of them changes
track(__file__, "rk4", KERNEL_FILES)

# int header: sizes, then (offset) of each block in the int (I_) or float (F_) vector
(H_N_ROTOR, H_N, H_NB, H_NUB, H_NLD,
 H_K0_NNZ, I_K0, F_K0, H_KC_NNZ, I_KC, F_KC, H_C0_NNZ, I_C0, F_C0, H_G_NNZ, I_G, F_G, H_M_NNZ, I_M, F_M,
 F_Q, F_MINT, F_PROF, I_UB, F_UB, I_LD, F_LD, I_KIND, I_FLOFF, I_ITOFF, I_GOFF, I_GIDX, F_BEAR, I_BEAR,
 HEADER) = range(35)


@njit(cache=True, inline="always")
def _matvec_add(IN, FL, nnz, ir, fv, scale, x, x0, out, o0):
    """out[o0 + rows] += scale * vals * x[x0 + cols]; rows at IN[ir:], cols at IN[ir + nnz:], vals at FL[fv:]."""
    for k in range(nnz):
        out[o0 + IN[ir + k]] += scale * FL[fv + k] * x[x0 + IN[ir + nnz + k]]


@njit(cache=True, inline="always")
def _applied(t, y, F, FL, IN, W, phi, acc):
    """F = static loads + unbalance + time loads - shaft stiffness and damping terms (rotor DOFs)."""
    n, N = IN[H_N_ROTOR], IN[H_N]
    fq = IN[F_Q]
    for i in range(n):
        F[i] = FL[fq + i]
    for i in range(n, N):
        F[i] = 0.0
    iu, fu = IN[I_UB], IN[F_UB]
    for u in range(IN[H_NUB]):  # rotating unbalance: (ix, iy), (m e, phase)
        me, ph = FL[fu + 2 * u], FL[fu + 2 * u + 1]
        c, s = np.cos(phi + ph), np.sin(phi + ph)
        F[IN[iu + 2 * u]] += me * (W * W * c - acc * s)
        F[IN[iu + 2 * u + 1]] += me * (W * W * s + acc * c)
    il, fl = IN[I_LD], IN[F_LD]
    for k in range(IN[H_NLD]):  # (index, 0 harmonic / 1 step / 2 ramp), (amplitude, omega, order, phase, t_on)
        amp, om, order, ph, ton = FL[fl + 5 * k], FL[fl + 5 * k + 1], FL[fl + 5 * k + 2], FL[fl + 5 * k + 3], \
            FL[fl + 5 * k + 4]
        kind = IN[il + 2 * k + 1]
        if kind == 1:
            if t >= ton:
                F[IN[il + 2 * k]] += amp
        elif kind == 2:
            F[IN[il + 2 * k]] += amp * (min(t / ton, 1.0) if ton > 0.0 else 1.0)
        else:
            arg = order * phi if order > 0.0 else om * t
            F[IN[il + 2 * k]] += amp * np.sin(arg + ph)
    # shaft: -(K0 + W Kc) x - (C0 + W G) v
    _matvec_add(IN, FL, IN[H_K0_NNZ], IN[I_K0], IN[F_K0], -1.0, y, 0, F, 0)
    _matvec_add(IN, FL, IN[H_KC_NNZ], IN[I_KC], IN[F_KC], -W, y, 0, F, 0)
    _matvec_add(IN, FL, IN[H_C0_NNZ], IN[I_C0], IN[F_C0], -1.0, y, N, F, 0)
    _matvec_add(IN, FL, IN[H_G_NNZ], IN[I_G], IN[F_G], -W, y, N, F, 0)


@njit(cache=True, inline="always")
def _accelerations(y, F, out, FL, IN):
    """out = [v, M^-1 F]."""
    n, N = IN[H_N_ROTOR], IN[H_N]
    for i in range(N):
        out[i] = y[N + i]
        out[N + i] = 0.0
    _matvec_add(IN, FL, IN[H_M_NNZ], IN[I_M], IN[F_M], 1.0, F, 0, out, N)
    fm = IN[F_MINT]
    for i in range(n, N):
        out[N + i] = F[i] * FL[fm + i - n]


@njit(cache=True)
def _hermite_into(y0, d0, y1, d1, h, s, dest):
    s2, s3 = s * s, s * s * s
    a0, b0, a1, b1 = 2 * s3 - 3 * s2 + 1, (s3 - 2 * s2 + s) * h, -2 * s3 + 3 * s2, (s3 - s2) * h
    for i in range(y0.size):
        dest[i] = a0 * y0[i] + b0 * d0[i] + a1 * y1[i] + b1 * d1[i]


@njit(cache=True)
def rk4(y, t0, h, n_steps, every, samples, targets, pstates, p_done, FL, IN, hs):
    """Advance y (in place) n_steps RK4 steps from t0; every ``every``-th state into ``samples``.

    ``targets`` (sorted times) from index ``p_done`` on are filled into ``pstates`` as the run
    passes them; ``hs`` are the bearings' handles (``bearings.compiled``).  ``n_steps = 0``
    evaluates the right-hand side once into ``samples[0]`` (a check of the equations).
    Returns (rows written, status 0 ok / 1 non-finite, targets done).
    """
    N2 = y.size
    N = N2 // 2
    gmax = 1
    igo, igi = IN[I_GOFF], IN[I_GIDX]
    for b in range(IN[H_NB]):
        gmax = max(gmax, IN[igo + b + 1] - IN[igo + b])
    F, bq, bv, bf = np.empty(N), np.empty(gmax), np.empty(gmax), np.empty(gmax)
    # a bearing whose DOFs are consecutive in x reads its state in place (no gather)
    first = np.full(IN[H_NB], -1, np.int64)
    for b in range(IN[H_NB]):
        g0, g1 = IN[igo + b], IN[igo + b + 1]
        consecutive = True
        for a in range(1, g1 - g0):
            consecutive = consecutive and IN[igi + g0 + a] == IN[igi + g0] + a
        if consecutive and g1 > g0:
            first[b] = IN[igi + g0]
    K = np.empty((4, N2))
    arg = np.empty(N2)
    yp = y.copy()
    dp = np.empty(N2)
    w0, acc = FL[IN[F_PROF]], FL[IN[F_PROF] + 1]
    row = 0
    pi = p_done
    count = every
    for i in range(n_steps + 1):
        t = t0 + i * h
        for stage in range(4):  # the right-hand side at the four RK4 stages
            if stage == 0:
                ts = t
                for a in range(N2):
                    arg[a] = y[a]
            else:
                c = h if stage == 3 else 0.5 * h
                ts = t + c
                for a in range(N2):
                    arg[a] = y[a] + c * K[stage - 1, a]
            W = w0 + acc * ts
            phi = w0 * ts + 0.5 * acc * ts * ts
            _applied(ts, arg, F, FL, IN, W, phi, acc)
            b = 0
            for hb in literal_unroll(hs):  # one compiled body per bearing family present
                g0, g1 = IN[igo + b], IN[igo + b + 1]
                j0 = first[b]
                if j0 >= 0:  # in place
                    q_b, v_b = arg[j0:j0 + g1 - g0], arg[N + j0:N + j0 + g1 - g0]
                else:
                    for a in range(g1 - g0):
                        j = IN[igi + g0 + a]
                        bq[a] = arg[j]
                        bv[a] = arg[N + j]
                    q_b, v_b = bq, bv
                bearing_force(hb, FL, IN, q_b, v_b, ts, W, phi, bf)
                if j0 >= 0:
                    for a in range(g1 - g0):
                        F[j0 + a] += bf[a]
                else:
                    for a in range(g1 - g0):
                        F[IN[igi + g0 + a]] += bf[a]
                b += 1
            _accelerations(arg, F, K[stage], FL, IN)
            if stage == 0:
                if n_steps == 0:  # the right-hand side alone
                    for a in range(N2):
                        samples[0, a] = K[0, a]
                    return 1, 0, pi
                if i > 0:  # Poincare instants in (t - h, t]
                    while pi < targets.size and targets[pi] <= t + 1e-9 * h:
                        s = (targets[pi] - (t - h)) / h
                        _hermite_into(yp, dp, y, K[0], h, min(max(s, 0.0), 1.0), pstates[pi])
                        pi += 1
                if i == n_steps:
                    return row, 0, pi
                if pi < targets.size and targets[pi] <= t0 + (i + 1) * h + 1e-9 * h:  # one in the next step
                    for a in range(N2):
                        yp[a] = y[a]
                        dp[a] = K[0, a]
        for a in range(N2):
            y[a] += h / 6.0 * (K[0, a] + 2.0 * K[1, a] + 2.0 * K[2, a] + K[3, a])
        count -= 1
        if count == 0:
            count = every
            finite = True
            for a in range(N2):
                samples[row, a] = y[a]
                finite = finite and np.isfinite(y[a])
            row += 1
            if not finite:
                return row, 1, pi
    return row, 0, pi


def rhs(t, y, FL, IN, hs) -> np.ndarray:
    """dy/dt of the compiled equations at (t, y), through :func:`rk4` with no step (for checks)."""
    out = np.empty((1, y.size))
    rk4(np.array(y, float), t, 1.0, 0, 1, out, np.zeros(0), np.zeros((0, y.size)), 0, FL, IN, hs)
    return out[0]
