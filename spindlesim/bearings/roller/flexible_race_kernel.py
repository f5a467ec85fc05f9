"""Compiled force of seed 000's flexible-race bearing (``FlexibleRaceBearing``).

Loop form of ``FlexibleRaceBearing.generalized_force`` for numba: the same equations (seed 000
eqs. 1-31; module notes of ``flexible_race``, ``outer_race``, ``contact_search`` and
``contact_force``), in the contract coordinates [x, y, dr_1..dr_N, q_race (3n)] (dr_j = r_j -
(R_i + R_r)), checked against the numpy form to round-off in tests.  Rewrites that do not
change the equations:

- cos and sin of the roller angles come from the angle-addition formulas with the cage angle
  (two trigonometric calls per evaluation); the roller's beam from its angle reduced once per call;
- an angle difference wrap(atan2(b) - atan2(a)) is computed as atan2(a x b, a . b) (beam chord
  rotation, segment slip in the housing), with a x b and a . b taken from the displacements, and
  below 1e-3 rad by the series of atan (its remainder under the rounding of the angle);
- every penetration and stretch is a difference of nearly equal lengths, taken without the
  cancellation: A - |c| = (A^2 - |c|^2) / (A + |c|) with A^2 - |c|^2 from the displacements (inner
  contact, segment on the housing, beam length), so they keep their digits at any size (the numpy
  form loses those below ~1e-16 of the radius) and need a square root instead of ``hypot``.

Parameters travel as one float vector (layout below) and two integers (N rollers, n segments),
so one compiled kernel serves every deck and is cached on disk.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
from numba import njit

if TYPE_CHECKING:
    from .bearing import FlexibleRaceBearing

(CAGE_RATIO, SPIN_RATIO, R_INNER, R_ROLLER, R_RACE, R_MEAN, CHORD, ROLLER_MASS, CENTRIFUGAL, R_REF,
 C_K, C_M1, C_C, C_M2, C_M3, C_MU, C_VREG,
 H_K, H_M1, H_C, H_M2, H_M3, H_MU, H_VREG, H_INTERFERENCE, H_KT, H_BILATERAL, H_KR,
 TAN_HALF, COS_HALF, SIN_HALF) = range(31)
HEAD = 31
# then: base angles in [0, 2 pi) (N), roller cos/sin (2N), segment cos/sin (2n), reference chord cos/sin (2n),
# frame stiffness (36)


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
    half = np.pi / ring.segments
    p[TAN_HALF], p[COS_HALF], p[SIN_HALF] = np.tan(half), np.cos(half), np.sin(half)
    base = b.cage_phase_rad + 2.0 * np.pi * np.arange(b.rollers) / b.rollers
    roll = np.column_stack([np.cos(base), np.sin(base)])
    seg = np.column_stack([np.cos(ring.phi), np.sin(ring.phi)])
    chord = np.column_stack([np.cos(ring.ref_chord_angle), np.sin(ring.ref_chord_angle)])
    fl = np.concatenate([p, np.mod(base, 2.0 * np.pi), roll.ravel(), seg.ravel(), chord.ravel(),
                         np.ravel(ring.local_stiffness)])
    return fl, np.array([b.rollers, ring.segments], np.int64)


@njit(cache=True, inline="always")
def _power(x, e):
    """x^e; the exponents 1 and 0 of the default contacts without a call to pow."""
    if e == 1.0:
        return x
    if e == 0.0:
        return 1.0
    return x**e


@njit(cache=True, inline="always")
def _angle(y, x):
    """atan2(y, x); for |y| < 1e-3 x > 0 (the small rotations of a beam chord and a segment) its series
    z - z^3/3 + z^5/5, z = y/x, whose remainder z^7/7 lies below the rounding of z."""
    if x > 0.0 and abs(y) < 1e-3 * x:
        z = y / x
        z2 = z * z
        return z * (1.0 - z2 * (1.0 / 3.0 - 0.2 * z2))
    return np.arctan2(y, x)


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
def _generalized_force(fl, f0, N, n, pos, vel, speed, angle, F, q_outer, want_outer):
    """All bearing forces on the contract coordinates into F (parameters at fl[f0:], layout above);
    with ``want_outer`` the roller to outer race loads into q_outer."""
    base = f0 + HEAD  # fl[base + j]: roller base angle
    roll = base + N  # fl[roll + 2 j], fl[roll + 2 j + 1]: its cos, sin
    seg = roll + 2 * N  # segment cos, sin
    chord = seg + 2 * n  # reference chord cos, sin
    kl = chord + 2 * n  # 6 x 6 frame stiffness, row-major
    o = 2 + N  # first race DOF
    for a in range(F.size):
        F[a] = 0.0
    cage_ratio = fl[f0 + CAGE_RATIO]
    wc, Rr, Ri, Ro, L = cage_ratio * speed, fl[f0 + R_ROLLER], fl[f0 + R_INNER], fl[f0 + R_RACE], fl[f0 + CHORD]
    w_abs = (cage_ratio - fl[f0 + SPIN_RATIO]) * speed  # absolute roller spin (eq. 4)
    ck, cm1, cc, cm2, cm3 = fl[f0 + C_K], fl[f0 + C_M1], fl[f0 + C_C], fl[f0 + C_M2], fl[f0 + C_M3]
    cmu, cvreg = fl[f0 + C_MU], fl[f0 + C_VREG]
    sx, sy, sdx, sdy = pos[0], pos[1], vel[0], vel[1]
    cage = cage_ratio * angle
    ca, sa = np.cos(cage), np.sin(cage)
    two_pi = 2.0 * np.pi
    cage_mod = cage % two_pi
    pitch = two_pi / n
    tan_half, c_half, s_half = fl[f0 + TAN_HALF], fl[f0 + COS_HALF], fl[f0 + SIN_HALF]
    A = fl[f0 + R_REF]  # R_i + R_r: r_j of a roller touching the centred inner race
    c_out = Rr + A - Ro  # outer penetration of a roller at dr = 0 on the undeformed race
    s2 = sx * sx + sy * sy
    fsx, fsy = 0.0, 0.0
    for j in range(N):
        rc, rs = fl[roll + 2 * j], fl[roll + 2 * j + 1]
        fc = rc * ca - rs * sa  # f = (cos psi, sin psi)
        fs = rs * ca + rc * sa
        dr, rd = pos[2 + j], vel[2 + j]
        r = A + dr
        cx, cy = r * fc, r * fs
        cdx, cdy = rd * fc - r * wc * fs, rd * fs + r * wc * fc
        # inner contact: circle against circle, penetration A - |c - s| = (A^2 - |c - s|^2) / (A + |c - s|)
        num = 2.0 * r * (fc * sx + fs * sy) - s2 - dr * (2.0 * A + dr)
        dist = np.sqrt(A * A - num)
        nx, ny = (cx - sx) / dist, (cy - sy) / dist
        d_in = num / (A + dist)
        dd_in = -(nx * (cdx - sdx) + ny * (cdy - sdy))
        q_in = _normal_force(d_in, dd_in, ck, cm1, cc, cm2, cm3)
        # where the ray psi meets the reference polygon: beam i, chord fraction x
        psi = fl[base + j] + cage_mod  # both in [0, 2 pi)
        if psi >= two_pi:
            psi -= two_pi
        i = min(int(psi / pitch), n - 1)
        jj = (i + 1) % n
        si0, si1 = fl[seg + 2 * i], fl[seg + 2 * i + 1]
        sj0, sj1 = fl[seg + 2 * jj], fl[seg + 2 * jj + 1]
        # tan(alpha - h) with alpha - h = psi - (phi_i + pi/n)
        cm = si0 * c_half - si1 * s_half
        sm = si1 * c_half + si0 * s_half
        x = 0.5 * (1.0 + (fs * cm - fc * sm) / (fc * cm + fs * sm) / tan_half)
        # surface operator G (outer_race.SegmentedRing.surface_operator)
        ex, ey = -fl[chord + 2 * i + 1], fl[chord + 2 * i]  # eta
        proj = ex * fc + ey * fs
        N1 = x - 2.0 * x * x + x * x * x
        N2 = x * x * x - x * x
        b = (N1 + N2) * proj
        g0, g1 = (1.0 - x) * si0 + b * ex, (1.0 - x) * si1 + b * ey
        g3, g4 = x * sj0 - b * ex, x * sj1 - b * ey
        g2, g5 = L * N1 * proj, L * N2 * proj
        qi, qj = o + 3 * i, o + 3 * jj
        u = g0 * pos[qi] + g1 * pos[qi + 1] + g2 * pos[qi + 2] + g3 * pos[qj] + g4 * pos[qj + 1] + g5 * pos[qj + 2]
        ud = g0 * vel[qi] + g1 * vel[qi + 1] + g2 * vel[qi + 2] + g3 * vel[qj] + g4 * vel[qj + 1] + g5 * vel[qj + 2]
        # outer contact, eqs. 18-29 (fixed housing: l = r)
        d_out = c_out + dr - u
        q_out = _normal_force(d_out, rd - ud, ck, cm1, cc, cm2, cm3)
        if want_outer:
            q_outer[j] = q_out
        # friction, eq. 31
        tix, tiy = -ny, nx
        v_si = (cdx - sdx) * tix + (cdy - sdy) * tiy - w_abs * Rr - speed * Ri
        v_so = r * wc + w_abs * Rr
        ff_in = _friction(q_in, v_si, cmu, cvreg)
        ff_out = _friction(q_out, v_so, cmu, cvreg)
        frx, fry = q_in * nx + ff_in * tix, q_in * ny + ff_in * tiy
        F[2 + j] = frx * fc + fry * fs - q_out
        if fl[f0 + CENTRIFUGAL] != 0.0:
            F[2 + j] += fl[f0 + ROLLER_MASS] * r * wc * wc
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
    Rm = fl[f0 + R_MEAN]
    # beams, eqs. 10-13 (co-rotational)
    for i in range(n):
        jj = (i + 1) % n
        qi, qj = o + 3 * i, o + 3 * jj
        si0, si1 = fl[seg + 2 * i], fl[seg + 2 * i + 1]
        sj0, sj1 = fl[seg + 2 * jj], fl[seg + 2 * jj + 1]
        ch0, ch1 = fl[chord + 2 * i], fl[chord + 2 * i + 1]
        # chord = reference chord D0 (length L, direction ch) + du; stretch and rotation from du
        D0x, D0y = Rm * (sj0 - si0), Rm * (sj1 - si1)
        dux, duy = pos[qj] - pos[qi], pos[qj + 1] - pos[qi + 1]
        dx, dy = D0x + dux, D0y + duy
        l = np.sqrt(dx * dx + dy * dy)
        ex, ey = dx / l, dy / l
        nx, ny = -ey, ex
        dgamma = _angle(ch0 * duy - ch1 * dux, L + ch0 * dux + ch1 * duy)
        e2 = _wrap(pos[qi + 2] - dgamma)
        e3 = (2.0 * (D0x * dux + D0y * duy) + dux * dux + duy * duy) / (l + L)
        e5 = _wrap(pos[qj + 2] - dgamma)
        # rows 0, 2, 3, 5 of the frame stiffness times (e2, e3, e5) (its columns 2, 3, 5)
        S0 = fl[kl + 2] * e2 + fl[kl + 3] * e3 + fl[kl + 5] * e5
        S2 = fl[kl + 14] * e2 + fl[kl + 15] * e3 + fl[kl + 17] * e5
        S3 = fl[kl + 20] * e2 + fl[kl + 21] * e3 + fl[kl + 23] * e5
        S5 = fl[kl + 32] * e2 + fl[kl + 33] * e3 + fl[kl + 35] * e5
        S1 = (S2 + S5) / l
        S4 = -S1
        F[qi] -= S0 * ex + S1 * nx
        F[qi + 1] -= S0 * ey + S1 * ny
        F[qi + 2] -= S2
        F[qj] -= S3 * ex + S4 * nx
        F[qj + 1] -= S3 * ey + S4 * ny
        F[qj + 2] -= S5
    # housing support per segment
    hk, hm1, hc, hm2, hm3 = fl[f0 + H_K], fl[f0 + H_M1], fl[f0 + H_C], fl[f0 + H_M2], fl[f0 + H_M3]
    bilateral = fl[f0 + H_BILATERAL] != 0.0
    for i in range(n):
        qi = o + 3 * i
        si0, si1 = fl[seg + 2 * i], fl[seg + 2 * i + 1]
        ux, uy = pos[qi], pos[qi + 1]
        px, py = Rm * si0 + ux, Rm * si1 + uy
        rho = np.sqrt(px * px + py * py)
        ex, ey = px / rho, py / rho
        tx, ty = -ey, ex
        # rho - Rm = (rho^2 - Rm^2) / (rho + Rm); slip angle from the displacement
        delta = (2.0 * Rm * (si0 * ux + si1 * uy) + ux * ux + uy * uy) / (rho + Rm) + fl[f0 + H_INTERFERENCE]
        ddelta = ex * vel[qi] + ey * vel[qi + 1]
        slip = Rm * _angle(si0 * uy - si1 * ux, Rm + si0 * ux + si1 * uy)
        vt = tx * vel[qi] + ty * vel[qi + 1]
        if bilateral:
            sgn = 1.0 if delta > 0.0 else (-1.0 if delta < 0.0 else 0.0)
            fn = hk * sgn * _power(abs(delta), hm1) + hc * ddelta
        else:
            fn = _normal_force(delta, ddelta, hk, hm1, hc, hm2, hm3)
        ft = -fl[f0 + H_KT] * slip + _friction(fn, vt, fl[f0 + H_MU], fl[f0 + H_VREG])
        mr = fl[f0 + H_KR] * (pos[qi + 2] - slip / Rm)  # rocking on the bore
        ft += mr / rho
        F[qi] += -fn * ex + ft * tx
        F[qi + 1] += -fn * ey + ft * ty
        F[qi + 2] -= mr


@njit(cache=True)
def force(fl, it, q, v, speed, angle, out):
    """Contract force on [x, y, dr_j, q_race] into ``out`` (length 2 + N + 3n)."""
    _generalized_force(fl, 0, it[0], it[1], q, v, speed, angle, out, out, False)


@njit(cache=True, inline="always")
def force_at(fl, f0, it, i0, q, v, speed, angle, out):
    """:func:`force` for parameters at fl[f0:] and it[i0:i0 + 2] (the engine's concatenated vectors)."""
    _generalized_force(fl, f0, it[i0], it[i0 + 1], q, v, speed, angle, out, out, False)


@njit(cache=True)
def outer_loads(fl, it, q, v, speed, angle, out):
    """Roller to outer race contact load of each roller into ``out`` (length N)."""
    F = np.empty(2 + it[0] + 3 * it[1])
    _generalized_force(fl, 0, it[0], it[1], q, v, speed, angle, F, out, True)
