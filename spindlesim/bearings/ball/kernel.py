"""Compiled (numba) ball equilibria, and the row reactions on the shaft with their exact tangent.

One ball in its meridional plane (a, r) (:mod:`.geometry`; Harris and Kotzalas 2007, *Advanced Concepts*,
ch. 3); unknown: the ball centre X from the outer groove centre O_o.  With u = X, w = A - X (A = O_i - O_o,
set by the inner ring): n_o = u/|u| = (sin a_o, cos a_o), n_i = w/|w|, delta_o = |u| - (f_o - 1/2) D,
delta_i = |w| - (f_i - 1/2) D, Q = K <delta>^1.5 (Hertz), and

    R = Q_i n_i - Q_o n_o + F_c e_r + c_i t_i + c_o t_o = 0,      t = (cos a, -sin a)

with F_c = m (d_m / 2) w_c^2 and friction forces c_i = lambda_i M_g / D, c_o = -lambda_o M_g / D carrying
the gyroscopic couple M_g = J w_R w_c sin(beta) (Jones 1960; M_g a size), (D/2)(c_i - c_o) = M_g.  Race
control (``p[RACE]``, set per ball by ``evaluate_rows`` from its ``race`` code: 1 outer, -1 inner, 0 full;
g = D / d_m, per-ball angles, outer ring fixed, w the shaft speed):

- outer: lambda = (0, 2), no spin at the outer contact; w_c / w = (1 - g cos a_i)/(1 + cos(a_i - a_o)),
  M_g = (J / g) w_c^2 sin a_o;
- full (shared): lambda = (1, 1), beta = (a_i + a_o)/2; w_c / w = (1 - g cos a_i)/(2 + g (cos a_o - cos a_i));
- inner: lambda = (2, 0), no spin at the inner contact, tan(beta) = sin a_i / (cos a_i - g);
  w_c / w = (cos(a_i - a_o) - g cos a_o)/(1 + cos(a_i - a_o)),
  M_g = (J / g) w^2 (1 + g cos a_o)(cos(a_i - a_o) - g cos a_o) sin a_i / (1 + cos(a_i - a_o))^2.

Derivations, the sense of the couple and Harris and Kotzalas' sign conventions: docs/theory.md, "Ball
bearings".  The ball's force on the inner ring, G = -Q_i n_i - c_i t_i at O_i plus the couple -r_i c_i, is
summed over the rows with its exact tangent through every ball equilibrium (implicit-function theorem); at
rest the ball is two springs in series along A (closed form).  One module on purpose: numba's cache does not
see changes in functions compiled from another file.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

# parameter vector
G_I, G_O, K_I, K_O, GAMMA, M_HALF_DM, J_BALL, D_BALL, R_I_GROOVE, LAM_I, LAM_O, RACE, \
    A_AX0, A_RAD0, R_I_CENTRE, K_N, A_0, SPLIT_O, FC_FLOOR, COUPLE = range(20)
N_PARAMS = 20  # COUPLE: factor on the couple's friction forces (1; the validation's other readings: -1, 0)
#: race control codes of p[RACE]
RACE_OUTER, RACE_FULL, RACE_INNER = 0.0, 1.0, 2.0

# work buffer of _terms
B_R, B_J, B_RW, B_G, B_GU, B_GW, B_M, B_MU, B_MW, B_QI, B_QO, B_AI, B_AO, B_FC, B_MG, B_DQ, B_REST = \
    0, 2, 6, 10, 12, 16, 20, 21, 23, 25, 26, 27, 28, 29, 30, 31, 32
N_BUF = 33
EPS = 2.220446049250313e-16

MAX_NEWTON = 80


@njit(cache=True)
def _speed_terms(si, ci, so, co, ai, ao, om, p):
    """(F_c, dF_c/da_i, dF_c/da_o, M_g, dM_g/da_i, dM_g/da_o) of one ball at the contact angles, for the
    race control p[RACE] (module docstring)."""
    if om == 0.0:
        return 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
    gam = p[GAMMA]
    Jg = p[J_BALL] / gam
    race = p[RACE]
    if race == RACE_OUTER or race == RACE_INNER:
        cd = ci * co + si * so
        sd = si * co - ci * so
        Dn = 1.0 + cd
        if race == RACE_OUTER:
            N = 1.0 - gam * ci
            wc = om * N / Dn
            dwi = om * (gam * si * Dn + N * sd) / (Dn * Dn)
            dwo = -om * N * sd / (Dn * Dn)
            Mg = Jg * wc * wc * so
            dMi = Jg * 2.0 * wc * dwi * so
            dMo = Jg * (2.0 * wc * dwo * so + wc * wc * co)
        else:
            N = cd - gam * co
            P = 1.0 + gam * co
            wc = om * N / Dn
            dwi = -om * sd * P / (Dn * Dn)
            dwo = om * ((sd + gam * so) * Dn - N * sd) / (Dn * Dn)
            C0 = Jg * om * om
            D2, D3 = Dn * Dn, Dn * Dn * Dn
            Mg = C0 * P * N * si / D2
            dMi = C0 * (P * (N * ci - sd * si) / D2 + 2.0 * P * N * si * sd / D3)
            dMo = C0 * ((P * (sd + gam * so) - gam * so * N) * si / D2 - 2.0 * P * N * si * sd / D3)
    else:
        P = 1.0 + gam * co
        N = 1.0 - gam * ci
        S = P + N
        wc = om * N / S
        dwi = om * gam * si * P / (S * S)
        dwo = om * gam * so * N / (S * S)
        h = 0.5 * (ai - ao)
        ch, sh = math.cos(h), math.sin(h)
        bs = 0.5 * (ai + ao)
        sb, cb = math.sin(bs), math.cos(bs)
        C0 = p[J_BALL] * om * om / gam
        den = ch * S * S
        Mg = C0 * P * N * N * sb / den
        dMi = C0 * (2.0 * P * N * gam * si * sb / den + P * N * N * 0.5 * cb / den
                    + P * N * N * sb * 0.5 * sh / (ch * den) - 2.0 * P * N * N * sb * gam * si / (den * S))
        dMo = C0 * (-gam * so * N * N * sb / den + P * N * N * 0.5 * cb / den
                    - P * N * N * sb * 0.5 * sh / (ch * den) + 2.0 * P * N * N * sb * gam * so / (den * S))
    mh = p[M_HALF_DM]
    return mh * wc * wc, 2.0 * mh * wc * dwi, 2.0 * mh * wc * dwo, Mg, dMi, dMo


@njit(cache=True)
def _terms(ua, ur, wa, wr, om, p, b):
    """Residual R, its Jacobian R_u - R_w, R_w, the ring force G with G_u, G_w, the ring couple
    m with m_u, m_w, and the contact quantities, at u = X, w = A - X (see module docstring)."""
    Lo = math.sqrt(ua * ua + ur * ur)
    Li = math.sqrt(wa * wa + wr * wr)
    so, co = ua / Lo, ur / Lo
    si, ci = wa / Li, wr / Li
    ao = math.atan2(ua, ur)
    ai = math.atan2(wa, wr)
    do = Lo - p[G_O]
    di = Li - p[G_I]
    Qo = dQo = Qi = dQi = 0.0
    if do > 0.0:
        sq = math.sqrt(do)
        Qo = p[K_O] * do * sq
        dQo = 1.5 * p[K_O] * sq
    if di > 0.0:
        sq = math.sqrt(di)
        Qi = p[K_I] * di * sq
        dQi = 1.5 * p[K_I] * sq
    Fc, dFci, dFco, Mg, dMi, dMo = _speed_terms(si, ci, so, co, ai, ao, om, p)
    D = p[D_BALL]
    li, lo = p[LAM_I], p[LAM_O]
    cfi = li * Mg / D
    cfo = -lo * Mg / D
    # residual
    b[B_R] = Qi * si - Qo * so + cfi * ci + cfo * co
    b[B_R + 1] = Qi * ci - Qo * co + Fc - cfi * si - cfo * so
    # partials w.r.t. the angles and lengths
    mi_i, mi_o = dMi / D, dMo / D
    dRao_a = -Qo * co + li * mi_o * ci - lo * mi_o * co - cfo * so
    dRao_r = Qo * so + dFco - li * mi_o * si + lo * mi_o * so - cfo * co
    dRai_a = Qi * ci + li * mi_i * ci - lo * mi_i * co - cfi * si
    dRai_r = -Qi * si + dFci - li * mi_i * si + lo * mi_i * so - cfi * ci
    # R_u = dR/da_o (t_o / L_o)^T + dR/dL_o n_o^T,   dR/dL_o = -dQo n_o
    tu0, tu1 = co / Lo, -so / Lo
    Ru00 = dRao_a * tu0 - dQo * so * so
    Ru01 = dRao_a * tu1 - dQo * so * co
    Ru10 = dRao_r * tu0 - dQo * co * so
    Ru11 = dRao_r * tu1 - dQo * co * co
    tw0, tw1 = ci / Li, -si / Li
    Rw00 = dRai_a * tw0 + dQi * si * si
    Rw01 = dRai_a * tw1 + dQi * si * ci
    Rw10 = dRai_r * tw0 + dQi * ci * si
    Rw11 = dRai_r * tw1 + dQi * ci * ci
    b[B_J], b[B_J + 1], b[B_J + 2], b[B_J + 3] = Ru00 - Rw00, Ru01 - Rw01, Ru10 - Rw10, Ru11 - Rw11
    b[B_RW], b[B_RW + 1], b[B_RW + 2], b[B_RW + 3] = Rw00, Rw01, Rw10, Rw11
    # force of the ball on the inner ring, G = -Q_i n_i - c_i t_i
    b[B_G] = -Qi * si - cfi * ci
    b[B_G + 1] = -Qi * ci + cfi * si
    dGai_a = -Qi * ci - li * mi_i * ci + cfi * si
    dGai_r = Qi * si + li * mi_i * si + cfi * ci
    dGao_a = -li * mi_o * ci
    dGao_r = li * mi_o * si
    b[B_GU], b[B_GU + 1], b[B_GU + 2], b[B_GU + 3] = dGao_a * tu0, dGao_a * tu1, dGao_r * tu0, dGao_r * tu1
    b[B_GW] = dGai_a * tw0 - dQi * si * si
    b[B_GW + 1] = dGai_a * tw1 - dQi * si * ci
    b[B_GW + 2] = dGai_r * tw0 - dQi * ci * si
    b[B_GW + 3] = dGai_r * tw1 - dQi * ci * ci
    # couple of the inner friction force about O_i: m = -r_i c_i
    ri = p[R_I_GROOVE]
    b[B_M] = -ri * cfi
    b[B_MU], b[B_MU + 1] = -ri * li * mi_o * tu0, -ri * li * mi_o * tu1
    b[B_MW], b[B_MW + 1] = -ri * li * mi_i * tw0, -ri * li * mi_i * tw1
    b[B_QI], b[B_QO], b[B_AI], b[B_AO], b[B_FC], b[B_MG] = Qi, Qo, ai, ao, Fc, Mg
    b[B_DQ] = (dQo + dQi) * (Lo + Li)  # force change per unit relative position change (round-off floor)
    b[B_REST] = 0.0


@njit(cache=True)
def _rest(Aa, Ar, p, b):
    """Zero speed: the ball sits on the line O_o -> O_i; two springs in series (closed form).
    Fills b like _terms (R = 0); returns the ball centre (X_a, X_r)."""
    for k in range(N_BUF):
        b[k] = 0.0
    L = math.sqrt(Aa * Aa + Ar * Ar)
    na, nr = Aa / L, Ar / L
    a = math.atan2(Aa, Ar)
    b[B_AI] = a
    b[B_AO] = a
    d = L - p[A_0]
    b[B_REST] = 1.0
    if d <= 0.0:
        r = p[G_O] / p[A_0] * L
        return r * na, r * nr
    sq = math.sqrt(d)
    Q = p[K_N] * d * sq
    dQ = 1.5 * p[K_N] * sq
    b[B_QI] = Q
    b[B_QO] = Q
    b[B_G] = -Q * na
    b[B_G + 1] = -Q * nr
    # dG/dA = -(dQ n n^T + Q/L t t^T), stored in B_GW with G_u = 0 and dX/dA irrelevant
    ta, tr = nr, -na
    b[B_GW] = -(dQ * na * na + Q / L * ta * ta)
    b[B_GW + 1] = -(dQ * na * nr + Q / L * ta * tr)
    b[B_GW + 2] = b[B_GW + 1]
    b[B_GW + 3] = -(dQ * nr * nr + Q / L * tr * tr)
    r = p[G_O] + p[SPLIT_O] * d
    b[B_REST] = 1.0
    return r * na, r * nr


@njit(cache=True)
def _tolerance(b):
    """|R| that counts as balanced: 1e-13 of the largest force, or the round-off floor of the
    contact approaches (delta = L - (f - 1/2) D loses digits when delta is tiny)."""
    return 1e-13 * max(b[B_QO], b[B_QI], b[B_FC]) + 64.0 * EPS * b[B_DQ]


@njit(cache=True)
def _norm2(b):
    return math.sqrt(b[B_R] * b[B_R] + b[B_R + 1] * b[B_R + 1])


@njit(cache=True)
def _sane(ua, ur, wa, wr):
    """Trial ball centres must keep both groove centres on the same side (n_i . n_o > 0)."""
    return ua * wa + ur * wr > 0.0


@njit(cache=True)
def _newton(Aa, Ar, om, p, rad, ang, b):
    """Damped Newton on the ball centre in polar coordinates about O_o, X = rad (sin ang, cos ang):
    a move along the outer groove keeps the approach delta_o = rad - (f_o - 1/2) D, which stays well
    conditioned when delta_o is tiny (a lightly loaded ball); steps capped at 0.1 rad and half the
    groove-centre distance, then halved until |R| falls."""
    xa, xr = rad * math.sin(ang), rad * math.cos(ang)
    _terms(xa, xr, Aa - xa, Ar - xr, om, p, b)
    rn = _norm2(b)
    cap = 0.5 * p[A_0]
    for it in range(1, MAX_NEWTON + 1):
        if rn <= _tolerance(b):
            return xa, xr, it - 1, True
        sa, ca = math.sin(ang), math.cos(ang)
        j00, j01, j10, j11 = b[B_J], b[B_J + 1], b[B_J + 2], b[B_J + 3]
        # columns: dR/drad = J n, dR/dang = J (rad t), n = (sin, cos), t = (cos, -sin)
        p00, p10 = j00 * sa + j01 * ca, j10 * sa + j11 * ca
        p01, p11 = rad * (j00 * ca - j01 * sa), rad * (j10 * ca - j11 * sa)
        det = p00 * p11 - p01 * p10
        if det == 0.0 or not det == det:
            return xa, xr, it, False
        r0, r1 = b[B_R], b[B_R + 1]
        drad = -(p11 * r0 - p01 * r1) / det
        dang = -(-p10 * r0 + p00 * r1) / det
        big = max(abs(dang) / 0.1, abs(drad) / cap)
        if big > 1.0:
            drad /= big
            dang /= big
        step_small = abs(drad) <= 4e-16 * rad and abs(dang) <= 4e-16
        t = 1.0
        accepted = False
        for _ in range(60):
            tr_, ta_ = rad + t * drad, ang + t * dang
            ya, yr = tr_ * math.sin(ta_), tr_ * math.cos(ta_)
            if tr_ > 0.0 and _sane(ya, yr, Aa - ya, Ar - yr):
                _terms(ya, yr, Aa - ya, Ar - yr, om, p, b)
                rt = _norm2(b)
                if rt < rn or (step_small and rt <= rn):
                    rad, ang, xa, xr, rn = tr_, ta_, ya, yr, rt
                    accepted = True
                    break
            t *= 0.5
        if not accepted:
            _terms(xa, xr, Aa - xa, Ar - xr, om, p, b)
            return xa, xr, it, step_small or rn <= 100.0 * _tolerance(b)  # stalled: at round-off or failed
        if step_small:
            return xa, xr, it, True
    return xa, xr, MAX_NEWTON, False


@njit(cache=True)
def _normal_balance(Aa, Ar, om, p, ang, b):
    """For an outer contact angle ang, the approach along n_o = (sin ang, cos ang) that balances the
    ball along n_o: h(rad) = R . n_o = 0, h decreasing in rad (Q_o grows, Q_i falls).  Safeguarded
    Newton in a bracket.  Returns (rad, ok); b holds the terms there."""
    sa, ca = math.sin(ang), math.cos(ang)
    lo = p[G_O]
    _terms(lo * sa, lo * ca, Aa - lo * sa, Ar - lo * ca, om, p, b)
    if b[B_R] * sa + b[B_R + 1] * ca <= 0.0:
        return lo, True
    step = 1e-9 * p[A_0]
    hi = lo + step
    for _ in range(200):
        _terms(hi * sa, hi * ca, Aa - hi * sa, Ar - hi * ca, om, p, b)
        if b[B_R] * sa + b[B_R + 1] * ca < 0.0:
            break
        lo = hi
        step *= 4.0
        hi = lo + step
    rad = hi
    for _ in range(200):
        _terms(rad * sa, rad * ca, Aa - rad * sa, Ar - rad * ca, om, p, b)
        h = b[B_R] * sa + b[B_R + 1] * ca
        if abs(h) <= _tolerance(b):
            return rad, True
        if h > 0.0:
            lo = rad
        else:
            hi = rad
        dh = (b[B_J] * sa + b[B_J + 1] * ca) * sa + (b[B_J + 2] * sa + b[B_J + 3] * ca) * ca
        nxt = rad - h / dh if dh < 0.0 else 0.5 * (lo + hi)
        if not lo < nxt < hi:
            nxt = 0.5 * (lo + hi)
        if hi - lo <= 4.0 * EPS * hi:
            return rad, True
        rad = nxt
    return rad, False


@njit(cache=True)
def _tangential(Aa, Ar, om, p, ang, b):
    """g(ang) = R . t_o after the normal balance (the force rolling the ball along the outer groove)."""
    rad, ok = _normal_balance(Aa, Ar, om, p, ang, b)
    return b[B_R] * math.cos(ang) - b[B_R + 1] * math.sin(ang), rad, ok


@njit(cache=True)
def _solve_nested(Aa, Ar, om, p, b):
    """Fallback for hard balls (a ball pressed into a wedge by a tiny centrifugal force, where the
    both-contacts region is a sliver of the outer contact angle): bracket the outer contact angle
    on g(ang) = 0 (bisection with Illinois secant steps, each g after a 1-D normal balance), then
    polish with _newton.  Returns (X_a, X_r, iterations, ok)."""
    a0 = math.atan2(Aa, Ar)
    lo, hi = a0 - 0.02, a0 + 0.02
    glo, _, ok1 = _tangential(Aa, Ar, om, p, lo, b)
    ghi, _, ok2 = _tangential(Aa, Ar, om, p, hi, b)
    width = 0.02
    for _ in range(40):
        if glo > 0.0 and ghi < 0.0:
            break
        width *= 2.0
        if glo <= 0.0:
            lo = max(lo - width, -1.5)
            glo, _, ok1 = _tangential(Aa, Ar, om, p, lo, b)
        if ghi >= 0.0:
            hi = min(hi + width, 1.5)
            ghi, _, ok2 = _tangential(Aa, Ar, om, p, hi, b)
    if not (glo > 0.0 and ghi < 0.0):
        return math.nan, math.nan, 0, False
    side = 0
    ang = 0.5 * (lo + hi)
    rad = p[G_O]
    for it in range(200):
        ang = (lo * ghi - hi * glo) / (ghi - glo)  # regula falsi (Illinois)
        if not lo < ang < hi:
            ang = 0.5 * (lo + hi)
        g, rad, ok = _tangential(Aa, Ar, om, p, ang, b)
        if not ok:
            return math.nan, math.nan, it, False
        if abs(g) <= _tolerance(b) or hi - lo <= 1e-15:
            break
        if g > 0.0:
            lo, glo = ang, g
            if side == 1:
                ghi *= 0.5
            side = 1
        else:
            hi, ghi = ang, g
            if side == -1:
                glo *= 0.5
            side = -1
    return _newton(Aa, Ar, om, p, rad, ang, b)


@njit(cache=True)
def solve_ball(Aa, Ar, om, p, xa, xr, b):
    """Ball equilibrium for the groove-centre vector (Aa, Ar) at shaft speed om; (xa, xr): a warm start (NaN:
    none).  Returns (X_a, X_r, iterations, ok); b holds the terms at the solution.  The closed form at rest
    and below p[FC_FLOOR] of centrifugal force (1e-8 of the series Hertz load at 1 um: 0.04 rad/s for a
    12.7 mm ball on a 90 mm pitch circle).  Starts: the warm start if its residual beats the built-in guess
    (the ball on the line O_o -> O_i, pressed outwards by its rest load plus F_c), else the guess; the other
    if Newton fails from the first; then the bracketing fallback _solve_nested."""
    L = math.sqrt(Aa * Aa + Ar * Ar)
    wc = 0.5 * om * (1.0 - p[GAMMA] * Ar / L)
    fc = p[M_HALF_DM] * wc * wc
    if fc <= p[FC_FLOOR]:  # at rest, or so slow that the ball inertia is below any force of interest
        ya, yr = _rest(Aa, Ar, p, b)
        return ya, yr, 0, True
    d = L - p[A_0]
    q_rest = p[K_N] * d * math.sqrt(d) if d > 0.0 else 0.0
    g_rad = p[G_O] + ((q_rest + fc) / p[K_O]) ** (2.0 / 3.0)
    g_ang = math.atan2(Aa, Ar)
    have_warm = xa == xa and xr == xr and _sane(xa, xr, Aa - xa, Ar - xr)
    w_rad = math.sqrt(xa * xa + xr * xr) if have_warm else 0.0
    w_ang = math.atan2(xa, xr) if have_warm else 0.0
    warm_first = False
    if have_warm:
        ga, gr = g_rad * math.sin(g_ang), g_rad * math.cos(g_ang)
        _terms(ga, gr, Aa - ga, Ar - gr, om, p, b)
        r_guess = _norm2(b)
        _terms(xa, xr, Aa - xa, Ar - xr, om, p, b)
        warm_first = _norm2(b) < r_guess
    if warm_first:
        ya, yr, its, ok = _newton(Aa, Ar, om, p, w_rad, w_ang, b)
        if ok:
            return ya, yr, its, ok
    ya, yr, its, ok = _newton(Aa, Ar, om, p, g_rad, g_ang, b)
    if ok:
        return ya, yr, its, ok
    if have_warm and not warm_first:
        ya, yr, its, ok = _newton(Aa, Ar, om, p, w_rad, w_ang, b)
        if ok:
            return ya, yr, its, ok
    return _solve_nested(Aa, Ar, om, p, b)


@njit(cache=True)
def _ball_tangent(b, out):
    """dG/dA (2x2) and dm/dA (2) at the solution in b: out[0:4], out[4:6]."""
    if b[B_REST] != 0.0:
        out[0], out[1], out[2], out[3] = b[B_GW], b[B_GW + 1], b[B_GW + 2], b[B_GW + 3]
        out[4] = 0.0
        out[5] = 0.0
        return
    j00, j01, j10, j11 = b[B_J], b[B_J + 1], b[B_J + 2], b[B_J + 3]
    det = j00 * j11 - j01 * j10
    i00, i01, i10, i11 = j11 / det, -j01 / det, -j10 / det, j00 / det
    w00, w01, w10, w11 = b[B_RW], b[B_RW + 1], b[B_RW + 2], b[B_RW + 3]
    # dX/dA = -J^-1 R_w
    x00 = -(i00 * w00 + i01 * w10)
    x01 = -(i00 * w01 + i01 * w11)
    x10 = -(i10 * w00 + i11 * w10)
    x11 = -(i10 * w01 + i11 * w11)
    # I - dX/dA
    y00, y01, y10, y11 = 1.0 - x00, -x01, -x10, 1.0 - x11
    gu00, gu01, gu10, gu11 = b[B_GU], b[B_GU + 1], b[B_GU + 2], b[B_GU + 3]
    gw00, gw01, gw10, gw11 = b[B_GW], b[B_GW + 1], b[B_GW + 2], b[B_GW + 3]
    out[0] = gu00 * x00 + gu01 * x10 + gw00 * y00 + gw01 * y10
    out[1] = gu00 * x01 + gu01 * x11 + gw00 * y01 + gw01 * y11
    out[2] = gu10 * x00 + gu11 * x10 + gw10 * y00 + gw11 * y10
    out[3] = gu10 * x01 + gu11 * x11 + gw10 * y01 + gw11 * y11
    mu0, mu1, mw0, mw1 = b[B_MU], b[B_MU + 1], b[B_MW], b[B_MW + 1]
    out[4] = mu0 * x00 + mu1 * x10 + mw0 * y00 + mw1 * y10
    out[5] = mu0 * x01 + mu1 * x11 + mw0 * y01 + mw1 * y11


@njit(cache=True)
def evaluate_rows(q, om, cage_angle, p, row_sign, row_zc, row_offset, row_w, race, Z, X, f_rows, K_rows,
                  Qi, Qo, ai, ao, Fc, Mg, psi):
    """Reaction and tangent of every row at the inner-ring displacement q (5).

    Per row k: thrust direction row_sign[k], axial position of its inner groove-centre locus
    row_zc[k], preload offset row_offset[k] (added to the axial groove-centre distance) and
    axial displacement row_w[k] of its outer ring; race[k, j]: race control of each ball (1 outer,
    -1 inner, 0 full).  X (rows, Z, 2): ball centres, start values
    in (NaN for the built-in guess), solutions out.  f_rows (rows, 5): force on the shaft;
    K_rows (rows, 5, 5) = -df/dq.  Returns -1, or the flat index row * Z + ball of the first
    ball whose equilibrium failed."""
    n_rows = row_sign.size
    b = np.empty(N_BUF)
    tg = np.empty(6)
    Ri = p[R_I_CENTRE]
    ta = np.empty(5)
    tr = np.empty(5)
    em = np.empty(5)
    pb = p.copy()
    for k in range(n_rows):
        s = float(row_sign[k])
        zc = row_zc[k]
        for r in range(5):
            f_rows[k, r] = 0.0
            for c in range(5):
                K_rows[k, r, c] = 0.0
        for j in range(Z):
            ps = cage_angle + 2.0 * math.pi * j / Z
            cp, sp = math.cos(ps), math.sin(ps)
            psi[k, j] = ps
            ta[0], ta[1], ta[2], ta[3], ta[4] = 0.0, 0.0, s, s * Ri * sp, -s * Ri * cp
            tr[0], tr[1], tr[2], tr[3], tr[4] = cp, sp, 0.0, -zc * sp, zc * cp
            em[0], em[1], em[2], em[3], em[4] = 0.0, 0.0, 0.0, -s * sp, s * cp
            Aa = p[A_AX0] + row_offset[k] - s * row_w[k]
            Ar = p[A_RAD0]
            for r in range(5):
                Aa += ta[r] * q[r]
                Ar += tr[r] * q[r]
            code, c = race[k, j], p[COUPLE]
            if code > 0:
                pb[RACE], pb[LAM_I], pb[LAM_O] = RACE_OUTER, 0.0, 2.0 * c
            elif code < 0:
                pb[RACE], pb[LAM_I], pb[LAM_O] = RACE_INNER, 2.0 * c, 0.0
            else:
                pb[RACE], pb[LAM_I], pb[LAM_O] = RACE_FULL, c, c
            xa, xr, its, ok = solve_ball(Aa, Ar, om, pb, X[k, j, 0], X[k, j, 1], b)
            if not ok:
                return k * Z + j
            X[k, j, 0] = xa
            X[k, j, 1] = xr
            _ball_tangent(b, tg)
            Ga, Gr, m = b[B_G], b[B_G + 1], b[B_M]
            for r in range(5):
                f_rows[k, r] += ta[r] * Ga + tr[r] * Gr + em[r] * m
            # K = -(T^T dG/dA T + em (dm/dA T))
            for r in range(5):
                ua = ta[r] * tg[0] + tr[r] * tg[2]
                ur = ta[r] * tg[1] + tr[r] * tg[3]
                for c in range(5):
                    K_rows[k, r, c] -= ua * ta[c] + ur * tr[c] + em[r] * (tg[4] * ta[c] + tg[5] * tr[c])
            Qi[k, j] = b[B_QI]
            Qo[k, j] = b[B_QO]
            ai[k, j] = b[B_AI]
            ao[k, j] = b[B_AO]
            Fc[k, j] = b[B_FC]
            Mg[k, j] = b[B_MG]
    return -1
