"""Compiled force of seed 000's flexible-race bearing (``FlexibleRaceBearing``).

Loop form of ``FlexibleRaceBearing.generalized_force`` for numba: the same equations (seed 000
eqs. 1-31; module notes of ``flexible_race``, ``outer_race``, ``contact_search`` and
``contact_force``), in the contract coordinates [x, y, dr_1..dr_N, q_race (3n)] (dr_j = r_j -
(R_i + R_r)), checked against the numpy form to round-off in tests.  Two rewrites that do not
change the equations:

- cos and sin of the roller angles come from the angle-addition formulas with the cage angle
  (two trigonometric calls per evaluation);
- an angle difference wrap(atan2(b) - atan2(a)) is computed as atan2(a x b, a . b) (beam chord
  rotation, segment slip in the housing).

Parameters travel as one float vector (layout below) and two integers (N rollers, n segments),
so one compiled kernel serves every deck and is cached on disk.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
from numba import njit

if TYPE_CHECKING:
    from .flexible_race import FlexibleRaceBearing

(CAGE_RATIO, SPIN_RATIO, R_INNER, R_ROLLER, R_RACE, R_MEAN, CHORD, ROLLER_MASS, CENTRIFUGAL, R_REF,
 C_K, C_M1, C_C, C_M2, C_M3, C_MU, C_VREG,
 H_K, H_M1, H_C, H_M2, H_M3, H_MU, H_VREG, H_INTERFERENCE, H_KT, H_BILATERAL, H_KR) = range(28)
HEAD = 28
# then: base angles (N), roller cos/sin (2N), segment cos/sin (2n), reference chord cos/sin (2n), frame stiffness (36)


def pack(b: "FlexibleRaceBearing") -> tuple[np.ndarray, np.ndarray]:
    """(floats, ints) of a bearing, in the layout above."""
    ring, rc, hs = b.ring, b.roller_contact, b.housing
    hc = hs.contact
    p = np.zeros(HEAD)
    p[CAGE_RATIO], p[SPIN_RATIO] = b.kinematics.cage_ratio, b.kinematics.spin_ratio
    p[R_INNER], p[R_ROLLER], p[R_RACE] = b.inner_radius_m, b.roller_radius_m, ring.inner_radius_m
    p[R_MEAN], p[CHORD], p[ROLLER_MASS] = ring.mean_radius_m, ring.chord_m, b.roller_mass_kg
    p[CENTRIFUGAL] = 1.0 if b.centrifugal else 0.0
    p[R_REF] = b.roller_reference_radius_m
    p[C_K:C_VREG + 1] = [rc.stiffness, rc.exponent, rc.damping, rc.velocity_exponent, rc.indentation_exponent,
                         rc.friction, rc.slip_regularisation_m_s]
    p[H_K:H_VREG + 1] = [hc.stiffness, hc.exponent, hc.damping, hc.velocity_exponent, hc.indentation_exponent,
                         hc.friction, hc.slip_regularisation_m_s]
    p[H_INTERFERENCE], p[H_KT] = hs.interference_m, hs.tangential_stiffness_N_m
    p[H_BILATERAL] = 1.0 if hs.bilateral else 0.0
    p[H_KR] = hs.rocking_stiffness_Nm_rad
    base = b.cage_phase_rad + 2.0 * np.pi * np.arange(b.rollers) / b.rollers
    roll = np.column_stack([np.cos(base), np.sin(base)])
    seg = np.column_stack([np.cos(ring.phi), np.sin(ring.phi)])
    chord = np.column_stack([np.cos(ring.ref_chord_angle), np.sin(ring.ref_chord_angle)])
    fl = np.concatenate([p, base, roll.ravel(), seg.ravel(), chord.ravel(), np.ravel(ring.local_stiffness)])
    return fl, np.array([b.rollers, ring.segments], np.int64)


@njit(cache=True)
def _views(fl, it):
    N, n = it[0], it[1]
    o = HEAD
    base = fl[o:o + N]
    o += N
    roll = fl[o:o + 2 * N].reshape((N, 2))
    o += 2 * N
    seg = fl[o:o + 2 * n].reshape((n, 2))
    o += 2 * n
    chord = fl[o:o + 2 * n].reshape((n, 2))
    o += 2 * n
    kloc = fl[o:o + 36].reshape((6, 6))
    return base, roll, seg, chord, kloc


@njit(cache=True, inline="always")
def _power(x, e):
    return x if e == 1.0 else x**e


@njit(cache=True, inline="always")
def _normal_force(d, dd, k, m1, c, m2, m3):
    """Eq. 30, clipped at zero; 0 for d <= 0."""
    if d <= 0.0:
        return 0.0
    f = k * _power(d, m1)
    if c != 0.0:
        sgn = 1.0 if dd > 0.0 else (-1.0 if dd < 0.0 else 0.0)
        f += c * sgn * _power(abs(dd), m2) * _power(d, m3)
    return f if f > 0.0 else 0.0


@njit(cache=True, inline="always")
def _friction(fn, v, mu, vreg):
    """Eq. 31 with the regularised sign v / sqrt(v^2 + v_reg^2)."""
    if mu == 0.0:
        return 0.0
    return -mu * abs(fn) * v / np.sqrt(v * v + vreg * vreg)


@njit(cache=True, inline="always")
def _wrap(a):
    """Angle in [-pi, pi) (``outer_race._wrap``); the modulo only when needed."""
    if -np.pi <= a < np.pi:
        return a
    return (a + np.pi) % (2.0 * np.pi) - np.pi


@njit(cache=True)
def _generalized_force(p, base, roll, seg, chord, kloc, pos, vel, speed, angle, F, q_outer):
    """All bearing forces on the contract coordinates into F; roller to outer race loads into q_outer."""
    N = roll.shape[0]
    n = seg.shape[0]
    o = 2 + N  # first race DOF
    F[:] = 0.0
    wc, Rr, Ri, Ro, L = p[CAGE_RATIO] * speed, p[R_ROLLER], p[R_INNER], p[R_RACE], p[CHORD]
    w_abs = (p[CAGE_RATIO] - p[SPIN_RATIO]) * speed  # absolute roller spin (eq. 4)
    sx, sy, sdx, sdy = pos[0], pos[1], vel[0], vel[1]
    cage = p[CAGE_RATIO] * angle
    ca, sa = np.cos(cage), np.sin(cage)
    pitch = 2.0 * np.pi / n
    half = np.pi / n
    tan_half, c_half, s_half = np.tan(half), np.cos(half), np.sin(half)
    fsx, fsy = 0.0, 0.0
    for j in range(N):
        fc = roll[j, 0] * ca - roll[j, 1] * sa  # f = (cos psi, sin psi)
        fs = roll[j, 1] * ca + roll[j, 0] * sa
        r, rd = p[R_REF] + pos[2 + j], vel[2 + j]
        cx, cy = r * fc, r * fs
        cdx, cdy = rd * fc - r * wc * fs, rd * fs + r * wc * fc
        # inner contact: circle against circle
        dx, dy = cx - sx, cy - sy
        dist = np.hypot(dx, dy)
        nx, ny = dx / dist, dy / dist
        d_in = Ri + Rr - dist
        dd_in = -(nx * (cdx - sdx) + ny * (cdy - sdy))
        q_in = _normal_force(d_in, dd_in, p[C_K], p[C_M1], p[C_C], p[C_M2], p[C_M3])
        # where the ray psi meets the reference polygon: beam i, chord fraction x
        a = ((base[j] + cage) % (2.0 * np.pi)) / pitch
        i = min(int(a), n - 1)
        jj = (i + 1) % n
        # tan(alpha - h) with alpha - h = psi - (phi_i + pi/n)
        cm = seg[i, 0] * c_half - seg[i, 1] * s_half
        sm = seg[i, 1] * c_half + seg[i, 0] * s_half
        x = 0.5 * (1.0 + (fs * cm - fc * sm) / (fc * cm + fs * sm) / tan_half)
        # surface operator G (outer_race.SegmentedRing.surface_operator)
        ex, ey = -chord[i, 1], chord[i, 0]  # eta
        proj = ex * fc + ey * fs
        N1 = x - 2.0 * x * x + x * x * x
        N2 = x * x * x - x * x
        b = (N1 + N2) * proj
        g0, g1 = (1.0 - x) * seg[i, 0] + b * ex, (1.0 - x) * seg[i, 1] + b * ey
        g3, g4 = x * seg[jj, 0] - b * ex, x * seg[jj, 1] - b * ey
        g2, g5 = L * N1 * proj, L * N2 * proj
        qi, qj = o + 3 * i, o + 3 * jj
        u = g0 * pos[qi] + g1 * pos[qi + 1] + g2 * pos[qi + 2] + g3 * pos[qj] + g4 * pos[qj + 1] + g5 * pos[qj + 2]
        ud = g0 * vel[qi] + g1 * vel[qi + 1] + g2 * vel[qi + 2] + g3 * vel[qj] + g4 * vel[qj + 1] + g5 * vel[qj + 2]
        # outer contact, eqs. 18-29 (fixed housing: l = r)
        d_out = Rr + r - Ro - u
        q_out = _normal_force(d_out, rd - ud, p[C_K], p[C_M1], p[C_C], p[C_M2], p[C_M3])
        q_outer[j] = q_out
        # friction, eq. 31
        tix, tiy = -ny, nx
        v_si = (cdx - sdx) * tix + (cdy - sdy) * tiy - w_abs * Rr - speed * Ri
        v_so = r * wc + w_abs * Rr
        ff_in = _friction(q_in, v_si, p[C_MU], p[C_VREG])
        ff_out = _friction(q_out, v_so, p[C_MU], p[C_VREG])
        frx, fry = q_in * nx + ff_in * tix, q_in * ny + ff_in * tiy
        F[2 + j] = frx * fc + fry * fs - q_out
        if p[CENTRIFUGAL] != 0.0:
            F[2 + j] += p[ROLLER_MASS] * r * wc * wc
        fsx += frx
        fsy += fry
        # roller load on the race through G^T, friction split on the two segments
        F[qi] += q_out * g0
        F[qi + 1] += q_out * g1
        F[qi + 2] += q_out * g2
        F[qj] += q_out * g3
        F[qj + 1] += q_out * g4
        F[qj + 2] += q_out * g5
        F[qi] += (1.0 - x) * ff_out * fs
        F[qi + 1] -= (1.0 - x) * ff_out * fc
        F[qj] += x * ff_out * fs
        F[qj + 1] -= x * ff_out * fc
    F[0] = -fsx
    F[1] = -fsy
    Rm = p[R_MEAN]
    # beams, eqs. 10-13 (co-rotational)
    for i in range(n):
        jj = (i + 1) % n
        qi, qj = o + 3 * i, o + 3 * jj
        pix, piy = Rm * seg[i, 0] + pos[qi], Rm * seg[i, 1] + pos[qi + 1]
        pjx, pjy = Rm * seg[jj, 0] + pos[qj], Rm * seg[jj, 1] + pos[qj + 1]
        dx, dy = pjx - pix, pjy - piy
        l = np.hypot(dx, dy)
        ex, ey = dx / l, dy / l
        nx, ny = -ey, ex
        dgamma = np.arctan2(chord[i, 0] * dy - chord[i, 1] * dx, chord[i, 0] * dx + chord[i, 1] * dy)
        e2 = _wrap(pos[qi + 2] - dgamma)
        e3 = l - L
        e5 = _wrap(pos[qj + 2] - dgamma)
        S0 = kloc[0, 2] * e2 + kloc[0, 3] * e3 + kloc[0, 5] * e5
        S2 = kloc[2, 2] * e2 + kloc[2, 3] * e3 + kloc[2, 5] * e5
        S3 = kloc[3, 2] * e2 + kloc[3, 3] * e3 + kloc[3, 5] * e5
        S5 = kloc[5, 2] * e2 + kloc[5, 3] * e3 + kloc[5, 5] * e5
        S1 = (S2 + S5) / l
        S4 = -S1
        F[qi] -= S0 * ex + S1 * nx
        F[qi + 1] -= S0 * ey + S1 * ny
        F[qi + 2] -= S2
        F[qj] -= S3 * ex + S4 * nx
        F[qj + 1] -= S3 * ey + S4 * ny
        F[qj + 2] -= S5
    # housing support per segment
    for i in range(n):
        qi = o + 3 * i
        px, py = Rm * seg[i, 0] + pos[qi], Rm * seg[i, 1] + pos[qi + 1]
        rho = np.hypot(px, py)
        ex, ey = px / rho, py / rho
        tx, ty = -ey, ex
        delta = rho - Rm + p[H_INTERFERENCE]
        ddelta = ex * vel[qi] + ey * vel[qi + 1]
        slip = Rm * np.arctan2(seg[i, 0] * py - seg[i, 1] * px, seg[i, 0] * px + seg[i, 1] * py)
        vt = tx * vel[qi] + ty * vel[qi + 1]
        if p[H_BILATERAL] != 0.0:
            sgn = 1.0 if delta > 0.0 else (-1.0 if delta < 0.0 else 0.0)
            fn = p[H_K] * sgn * _power(abs(delta), p[H_M1]) + p[H_C] * ddelta
        else:
            fn = _normal_force(delta, ddelta, p[H_K], p[H_M1], p[H_C], p[H_M2], p[H_M3])
        ft = -p[H_KT] * slip + _friction(fn, vt, p[H_MU], p[H_VREG])
        mr = p[H_KR] * (pos[qi + 2] - slip / Rm)  # rocking on the bore
        ft += mr / rho
        F[qi] += -fn * ex + ft * tx
        F[qi + 1] += -fn * ey + ft * ty
        F[qi + 2] -= mr


@njit(cache=True)
def force(fl, it, q, v, speed, angle, out):
    """Contract force on [x, y, dr_j, q_race] into ``out`` (length 2 + N + 3n)."""
    base, roll, seg, chord, kloc = _views(fl, it)
    q_outer = np.empty(it[0])
    _generalized_force(fl, base, roll, seg, chord, kloc, q, v, speed, angle, out, q_outer)


@njit(cache=True)
def force_at(fl, f0, f1, it, i0, q, v, speed, angle, out):
    """:func:`force` for parameters at fl[f0:f1], it[i0:i0 + 2] (the engine's concatenated vectors)."""
    force(fl[f0:f1], it[i0:i0 + 2], q, v, speed, angle, out)


@njit(cache=True)
def outer_loads(fl, it, q, v, speed, angle, out):
    """Roller to outer race contact load of each roller into ``out`` (length N)."""
    base, roll, seg, chord, kloc = _views(fl, it)
    F = np.empty(2 + it[0] + 3 * it[1])
    _generalized_force(fl, base, roll, seg, chord, kloc, q, v, speed, angle, F, out)
