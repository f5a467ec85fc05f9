"""Tensor-product cubic B-splines for the land-force tables, and the compiled land evaluation.

Fitting: interpolating cubic splines along each table axis in turn (the tensor-product
interpolant is separable), ``scipy.interpolate.make_interp_spline`` with not-a-knot ends on
open axes and ``bc_type="periodic"`` on periodic ones (de Boor, A Practical Guide to Splines,
2001, ch. XIII and XVII).

Evaluation (:func:`eval_land_group`, numba): the value and the three partial derivatives of
the same piecewise polynomial (Cox-de Boor recursion; Piegl & Tiller, The NURBS Book, 1997,
algorithms A2.1-A2.3), so the tangent is the exact derivative of the interpolated force.

Land force (film_table module docstring): in the lobe frame a land at journal position
``(xi', eta) = r (cos phi, sin phi)`` about its centre of curvature and with right-hand side
``(alpha, beta) = rho (cos psi, sin psi)`` carries ``G = rho g`` with
``g = R(phi) T(u(r), phi, psi - phi) [+ g0(psi)]``: T tabulated in the journal's radial frame,
``u = ln((a - r_lo)/(a - r)) / L_u``, and g0 the force at the centre of curvature (r = 0) for
tables that contain it (T = 0 there, so g is single-valued and smooth at the pole).  With
``alpha = omega xi' - 2 kappa eta_r`` and ``beta = omega eta + 2 kappa xi_r`` the chain rule::

    dG/dxi   = dG/dxi'|_rhs + omega dG/dalpha          dG/dxi_r  =  2 kappa dG/dbeta
    dG/deta  = dG/deta|_rhs + omega dG/dbeta           dG/deta_r = -2 kappa dG/dalpha
    dG/dalpha = g cos psi - g_psi sin psi,             dG/dbeta  = g sin psi + g_psi cos psi

At ``rho = 0`` (no rotation, no motion) G = 0 and its derivative in (alpha, beta) does not
exist (G is homogeneous of degree 1); the describing-function average
``(1/pi) int g (cos psi, sin psi) dpsi`` (the Jacobian averaged over all directions) is used.
"""

from __future__ import annotations

import math

import numba
import numpy as np
from scipy.interpolate import make_interp_spline

K = 3  # cubic


def fit_tensor_spline(axes: tuple, periodic: tuple, values: np.ndarray):
    """Knots per axis and coefficients of the tensor-product interpolating cubic spline.

    ``values`` has one axis per entry of ``axes`` plus trailing component axes; a periodic
    axis lists its nodes including the repeated end point (``values`` equal there).
    """
    c = np.asarray(values, dtype=float)
    knots = []
    for ax, (x, per) in enumerate(zip(axes, periodic)):
        spl = make_interp_spline(np.asarray(x, float), c, k=K, axis=ax,
                                 bc_type="periodic" if per else "not-a-knot")
        knots.append(np.ascontiguousarray(spl.t))
        c = np.moveaxis(spl.c, 0, ax)
    return tuple(knots), np.ascontiguousarray(c)


@numba.njit(cache=True)
def _basis(t, x, periodic, b, d):
    """Cubic B-spline basis values ``b`` and derivatives ``d`` at x; returns the first index."""
    lo = t[K]
    hi = t[t.size - K - 1]
    if periodic:
        span = hi - lo
        x = lo + (x - lo) % span
    elif x < lo:
        x = lo
    elif x > hi:
        x = hi
    # span index m: t[m] <= x < t[m + 1], K <= m <= n_coef - 1
    m_lo = K
    m_hi = t.size - K - 2
    while m_lo < m_hi:
        mid = (m_lo + m_hi + 1) // 2
        if t[mid] <= x:
            m_lo = mid
        else:
            m_hi = mid - 1
    m = m_lo
    # degree-0..2 values (Piegl & Tiller A2.2), N[j] = N_{m-p+j, p}
    n = np.zeros(K + 1)
    left = np.zeros(K + 1)
    right = np.zeros(K + 1)
    n[0] = 1.0
    for p in range(1, K):
        left[p] = x - t[m + 1 - p]
        right[p] = t[m + p] - x
        saved = 0.0
        for r in range(p):
            tmp = n[r] / (right[r + 1] + left[p - r])
            n[r] = saved + right[r + 1] * tmp
            saved = left[p - r] * tmp
        n[p] = saved
    # n[0..2] = N_{m-2..m, 2}; derivatives of the cubic basis N_{i,3}, i = m-3..m
    for j in range(K + 1):
        i = m - K + j
        dv = 0.0
        bv = 0.0
        if j >= 1:  # N_{i,2} = n[j-1]
            den = t[i + K] - t[i]
            if den > 0.0:
                dv += K * n[j - 1] / den
                bv += (x - t[i]) / den * n[j - 1]
        if j <= K - 1:  # N_{i+1,2} = n[j]
            den = t[i + K + 1] - t[i + 1]
            if den > 0.0:
                dv -= K * n[j] / den
                bv += (t[i + K + 1] - x) / den * n[j]
        b[j] = bv
        d[j] = dv
    return m - K


@numba.njit(cache=True)
def _eval3(tu, tp, tc, C, has_phi, phi_periodic, u, phi, chi, out):
    """g and its partials (u, phi, chi) -> out[4, 2]."""
    bu = np.zeros(4)
    du = np.zeros(4)
    bp = np.zeros(4)
    dp = np.zeros(4)
    bc = np.zeros(4)
    dc = np.zeros(4)
    iu = _basis(tu, u, False, bu, du)
    ic = _basis(tc, chi, True, bc, dc)
    npl = 1
    ip = 0
    if has_phi:
        ip = _basis(tp, phi, phi_periodic, bp, dp)
        npl = 4
    else:
        bp[0] = 1.0
    out[:, :] = 0.0
    for a in range(4):
        for p in range(npl):
            wa = bu[a] * bp[p]
            wu = du[a] * bp[p]
            wp = bu[a] * dp[p]
            for c in range(4):
                for k in range(2):
                    v = C[iu + a, ip + p, ic + c, k]
                    out[0, k] += wa * bc[c] * v
                    out[1, k] += wu * bc[c] * v
                    out[2, k] += wp * bc[c] * v
                    out[3, k] += wa * dc[c] * v


@numba.njit(cache=True)
def _land_g(tu, tp, tc, C, has_phi, phi_periodic, tg0, G0, has_centre, u, dudr, phi, psi,
            s, out):
    """Land function g(r, phi, psi) (lobe frame) and d/dr, d/dphi, d/dpsi -> out[4, 2].

    ``g = R(phi) T(u, phi, psi - phi) [+ g0(psi)]``: T the table (journal's radial frame),
    g0 the centre term of tables that contain the centre of curvature.
    """
    _eval3(tu, tp, tc, C, has_phi, phi_periodic, u, phi, psi - phi, s)
    cp = math.cos(phi)
    sp = math.sin(phi)
    hx = s[2, 0] - s[3, 0] - s[0, 1]  # T_phi - T_chi + S T  (d/dphi at fixed psi)
    hy = s[2, 1] - s[3, 1] + s[0, 0]
    out[0, 0] = cp * s[0, 0] - sp * s[0, 1]
    out[0, 1] = sp * s[0, 0] + cp * s[0, 1]
    out[1, 0] = (cp * s[1, 0] - sp * s[1, 1]) * dudr
    out[1, 1] = (sp * s[1, 0] + cp * s[1, 1]) * dudr
    out[2, 0] = cp * hx - sp * hy
    out[2, 1] = sp * hx + cp * hy
    out[3, 0] = cp * s[3, 0] - sp * s[3, 1]
    out[3, 1] = sp * s[3, 0] + cp * s[3, 1]
    if has_centre:
        b = np.zeros(4)
        d = np.zeros(4)
        i0 = _basis(tg0, psi, True, b, d)
        for c in range(4):
            for k in range(2):
                out[0, k] += b[c] * G0[i0 + c, k]
                out[3, k] += d[c] * G0[i0 + c, k]


@numba.njit(cache=True)
def eval_land_group(X, V, omega, thetas, c0, a, r_lo, L_u, kappa, has_phi, phi_periodic,
                    tu, tp, tc, C, has_centre, tg0, G0, f, Jp, Jr):
    """Add the force of the lands sharing one table to f (2), Jp = df/dX, Jr = df/dX_r.

    ``thetas``: frame angles of the lands (lobe preload direction); ``X``, ``V`` journal
    position and velocity over Cb (velocity in 1/s); ``omega`` in rad/s.
    """
    s = np.zeros((4, 2))
    o = np.zeros((4, 2))
    G = np.zeros(2)
    dGx = np.zeros((2, 2))  # columns d/dxi', d/deta (rhs fixed)
    dGa = np.zeros((2, 2))  # columns d/dalpha, d/dbeta
    Pp = np.zeros((2, 2))
    Pr = np.zeros((2, 2))
    for th in thetas:
        ct = math.cos(th)
        st = math.sin(th)
        xi = ct * X[0] + st * X[1]
        eta = -st * X[0] + ct * X[1]
        xir = ct * V[0] + st * V[1]
        etar = -st * V[0] + ct * V[1]
        xp = xi + c0
        al = omega * xp - 2.0 * kappa * etar
        be = omega * eta + 2.0 * kappa * xir
        r = math.hypot(xp, eta)
        phi = math.atan2(eta, xp) if r > 0.0 else 0.0
        cp = math.cos(phi)
        sp = math.sin(phi)
        u = math.log((a - r_lo) / (a - r)) / L_u
        dudr = 1.0 / ((a - r) * L_u)
        rho = math.hypot(al, be)
        G[:] = 0.0
        dGx[:, :] = 0.0
        dGa[:, :] = 0.0
        if rho > 0.0:
            psi = math.atan2(be, al)
            cs = math.cos(psi)
            sn = math.sin(psi)
            _land_g(tu, tp, tc, C, has_phi, phi_periodic, tg0, G0, has_centre, u, dudr, phi,
                    psi, s, o)
            for k in range(2):
                G[k] = rho * o[0, k]
                if r > 0.0:
                    dGx[k, 0] = rho * (o[1, k] * cp - o[2, k] * sp / r)
                    dGx[k, 1] = rho * (o[1, k] * sp + o[2, k] * cp / r)
                else:
                    dGx[k, 0] = rho * o[1, k]
                dGa[k, 0] = o[0, k] * cs - o[3, k] * sn
                dGa[k, 1] = o[0, k] * sn + o[3, k] * cs
            if r == 0.0:  # radial derivative towards +eta at the centre of curvature
                _land_g(tu, tp, tc, C, has_phi, phi_periodic, tg0, G0, has_centre, u, dudr,
                        0.5 * math.pi, psi, s, o)
                for k in range(2):
                    dGx[k, 1] = rho * o[1, k]
        else:
            # describing-function average of the Jacobian in (alpha, beta) at rho = 0
            nq = 4 * (tc.size - 2 * K - 1)
            w = 2.0 / nq  # (1/pi) * (2 pi / nq)
            for q in range(nq):
                psi = 2.0 * math.pi * q / nq
                _land_g(tu, tp, tc, C, has_phi, phi_periodic, tg0, G0, has_centre, u, dudr,
                        phi, psi, s, o)
                for k in range(2):
                    dGa[k, 0] += w * o[0, k] * math.cos(psi)
                    dGa[k, 1] += w * o[0, k] * math.sin(psi)
        # lobe-frame derivatives w.r.t. (xi, eta) and (xi_r, eta_r)
        for k in range(2):
            Pp[k, 0] = dGx[k, 0] + omega * dGa[k, 0]
            Pp[k, 1] = dGx[k, 1] + omega * dGa[k, 1]
            Pr[k, 0] = 2.0 * kappa * dGa[k, 1]
            Pr[k, 1] = -2.0 * kappa * dGa[k, 0]
        # to the x, y frame: F = R G, J = R P R^T
        f[0] += ct * G[0] - st * G[1]
        f[1] += st * G[0] + ct * G[1]
        _add_rotated(Pp, ct, st, Jp)
        _add_rotated(Pr, ct, st, Jr)


@numba.njit(cache=True)
def _add_rotated(M, ct, st, J):
    """J += R M R^T with R the rotation by the angle of (ct, st)."""
    A00 = ct * M[0, 0] - st * M[1, 0]
    A01 = ct * M[0, 1] - st * M[1, 1]
    A10 = st * M[0, 0] + ct * M[1, 0]
    A11 = st * M[0, 1] + ct * M[1, 1]
    J[0, 0] += A00 * ct - A01 * st
    J[0, 1] += A00 * st + A01 * ct
    J[1, 0] += A10 * ct - A11 * st
    J[1, 1] += A10 * st + A11 * ct
