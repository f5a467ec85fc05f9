"""Compiled right-hand side and fixed-step RK4 integrator of the rigid-race rotor.

The same equations as ``RigidRaceRotor.rhs`` (Sunnersjo 1978; Harsha and
Kankar 2004), written as loops for numba:

    m x'' + c x' = F_x(t) - sum_j K (x cos th_j + y sin th_j - gamma_0 + w_j)_+^n cos th_j
    m y'' + c y' = F_y(t) - sum_j K (...)_+^n sin th_j,   th_j = phase + 2 pi j/N + omega_c t

cos th_j and sin th_j come from the angle-addition formulas with the cage
angle, so a call costs two trigonometric evaluations whatever N is.
Parameters travel as one float vector (indices below) plus the roller base
angles and the waviness table, so one compiled kernel serves every deck and
is cached on disk.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
from numba import njit

from .rk4_parts import advance, stage, store

if TYPE_CHECKING:
    from .rigid_race import RigidRaceRotor

# indices into the parameter vector
K, EXPONENT, CLEARANCE, CAGE_SPEED, SHAFT_SPEED, SPIN_SPEED, MASS, DAMPING, LOAD_X, LOAD_Y, RAMP = range(11)
N_PARAMS = 11
# waviness table columns: surface (0 outer, 1 inner, 2 roller), waves, amplitude, phase
_SURFACE = {"outer": 0, "inner": 1, "roller": 2}


def pack(rotor: "RigidRaceRotor") -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(params, cos base angle, sin base angle, waviness table) of a ``RigidRaceRotor``."""
    b = rotor.bearing
    p = np.zeros(N_PARAMS)
    p[K], p[EXPONENT], p[CLEARANCE] = b.stiffness, b.exponent, b.radial_clearance_m
    p[CAGE_SPEED], p[SHAFT_SPEED] = b.cage_speed_rad_s, b.shaft_speed_rad_s
    p[SPIN_SPEED] = b.kinematics.spin_ratio * b.shaft_speed_rad_s
    p[MASS], p[DAMPING] = rotor.mass_kg, rotor.damping_Ns_m
    p[LOAD_X], p[LOAD_Y], p[RAMP] = rotor.load_N[0], rotor.load_N[1], rotor.load_ramp_s
    base = b.phase_rad + 2.0 * np.pi * np.arange(b.rollers) / b.rollers
    wav = np.array([[_SURFACE[w.surface], w.waves, w.amplitude_m, w.phase_rad] for w in b.waviness],
                   dtype=float).reshape(-1, 4)
    return p, np.cos(base), np.sin(base), wav


@njit(cache=True, fastmath=False)
def rhs(t, s, p, cb, sb, wav, out):
    """ds/dt for s = [x, y, vx, vy] into ``out``."""
    wc = p[CAGE_SPEED] * t
    cw, sw = np.cos(wc), np.sin(wc)
    x, y = s[0], s[1]
    k, n, gap = p[K], p[EXPONENT], p[CLEARANCE]
    fx, fy = 0.0, 0.0
    for j in range(cb.size):
        c = cb[j] * cw - sb[j] * sw
        sn = sb[j] * cw + cb[j] * sw
        d = x * c + y * sn - gap
        if wav.shape[0]:
            th = np.arctan2(sn, c)
            for h in range(wav.shape[0]):
                kind, waves, amp, ph = int(wav[h, 0]), wav[h, 1], wav[h, 2], wav[h, 3]
                if kind == 0:
                    d += amp * np.cos(waves * th + ph)
                elif kind == 1:
                    d += amp * np.cos(waves * (th - p[SHAFT_SPEED] * t) + ph)
                else:
                    spin = p[SPIN_SPEED] * t
                    d += amp * (np.cos(waves * spin + ph) + np.cos(waves * (spin + np.pi) + ph))
        if d > 0.0:
            q = k * d**n
            fx += q * c
            fy += q * sn
    scale = 1.0
    if p[RAMP] > 0.0:
        scale = min(t / p[RAMP], 1.0)
    m, cd = p[MASS], p[DAMPING]
    out[0] = s[2]
    out[1] = s[3]
    out[2] = (scale * p[LOAD_X] - cd * s[2] - fx) / m
    out[3] = (scale * p[LOAD_Y] - cd * s[3] - fy) / m


@njit(cache=True)
def rk4(y, t0, h, n_steps, every, p, cb, sb, wav, samples):
    """Advance ``y`` (in place) by ``n_steps`` classical RK4 steps of size h from t0.

    Writes the state after every ``every``-th step into the rows of ``samples``.
    Returns (rows written, status): status 0 done, 1 non-finite state.
    """
    k1 = np.empty_like(y)
    k2 = np.empty_like(y)
    k3 = np.empty_like(y)
    k4 = np.empty_like(y)
    tmp = np.empty_like(y)
    row = 0
    for i in range(n_steps):
        t = t0 + i * h
        rhs(t, y, p, cb, sb, wav, k1)
        stage(y, 0.5 * h, k1, tmp)
        rhs(t + 0.5 * h, tmp, p, cb, sb, wav, k2)
        stage(y, 0.5 * h, k2, tmp)
        rhs(t + 0.5 * h, tmp, p, cb, sb, wav, k3)
        stage(y, h, k3, tmp)
        rhs(t + h, tmp, p, cb, sb, wav, k4)
        advance(y, h, k1, k2, k3, k4)
        if (i + 1) % every == 0:
            finite = store(samples, row, y)
            row += 1
            if not finite:
                return row, 1
    return row, 0
