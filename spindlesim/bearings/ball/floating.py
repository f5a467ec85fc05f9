"""The floating outer rings of a spring-preloaded ball set: their axial shift w carrying the spring force.

The floating rows' thrust h(v) (v the approach of their outer rings in their thrust direction, w = -s v)
equals the spring force F_s at every inner-ring displacement q: safeguarded Newton on h^(2/3) = F_s^(2/3)
(linear in v for Hertz contacts) with the exact dh/dv of the rows' tangent, bisection when a step leaves the
bracket.  Starts: within one call (a ``Work``), the last solution moved to first order with q,
u = u_0 + du/dq (q - q_0), where u = v + s z does not depend on the inner ring's z and du/dq = -s K_z,q / K_zz
of the floating rows (zero along z); a call's first solve starts where one ball carries its share of F_s
at the speed (:func:`_one_ball`).  Converged at |h - F_s| <= 1e-11 F_s, or at the noise of the balls' own
equilibria (each solved to about 1e-13 of its forces: some 1e-9 N at speed) once a step no longer halves a
residual below 3e-11 F_s; the set equilibrium's tolerance is 1e-10 F_s or more.
"""

from __future__ import annotations

import math

import numpy as np

from . import kernel as kn
from .equilibrium import BallEquilibriumError


def shift(bearing, q, om: float, phi: float, fl: np.ndarray, work):
    """(w, evaluation of the floating rows ``fl`` at w): the axial shift of their outer rings along z
    (module note); ``work``: the call's :class:`~.equilibrium.Work`, its start in and its solution out."""
    g = bearing.geometry
    Fs, sg = bearing.preload.axial_N, bearing._s_float
    w = np.zeros(g.rows)

    def thrust(v):
        w[fl] = -sg * v
        ev = bearing._rows(q, om, phi, w, fl, work)
        return -sg * ev.f_rows[:, 2].sum(), ev.K_rows[:, 2, 2].sum(), ev

    if work.shift is None:
        v = _one_ball(bearing, q, om, fl, work)
    else:
        u0, q0, slope = work.shift
        v = u0 + float(slope @ (q - q0)) - sg * q[2]
    lo = hi = None
    r_before = math.inf
    for _ in range(200):
        h, k, ev = thrust(v)
        r = h - Fs
        if abs(r) <= 1e-11 * Fs or (abs(r) <= 3e-11 * Fs and abs(r) > 0.5 * abs(r_before)):
            return _solved(v, q, sg, ev, work)
        r_before = r
        if r < 0.0:
            lo = v
        else:
            hi = v
        vn = _newton_step(v, h, k, Fs)
        if lo is not None and hi is not None and not lo < vn < hi:
            vn = 0.5 * (lo + hi)
        if lo is not None and hi is not None and hi - lo <= 1e-16 * max(abs(v), 1e-3):
            return _solved(v, q, sg, ev, work)
        v = vn
    raise BallEquilibriumError(
        f"bearing {bearing.name!r}: floating outer ring(s) found no axial position carrying the spring "
        f"force {Fs:g} N (Newton with bisection, 200 iterations; residual {r:.3g} N) at "
        f"{om * 30 / math.pi:.6g} rpm, q = {np.round(np.asarray(q) * 1e6, 4).tolist()} (um, urad)")


def _newton_step(v, h, k, target):
    """Newton's step on h^(2/3) = target^(2/3) (linear in v for Hertz contacts: ``target`` reached from afar);
    out of contact (h <= 0) a step out of the clearance."""
    if k > 0.0 and h > 0.0:
        return v - (h ** (2.0 / 3.0) - target ** (2.0 / 3.0)) / ((2.0 / 3.0) * k / np.cbrt(h))
    return v - (h - target) / k if k > 0.0 else v + max(1e-6, abs(v))


def _one_ball(bearing, q, om: float, fl, work) -> float:
    """The start without one: the approach v at which one ball of the first floating row, the inner ring moved
    along z alone (q's z), carries its share of F_s at the speed (speed effects included; the radial load and
    tilts left to the full solve).  Each step solves one ball instead of the rows'; from the spring force shared
    over the balls at the mounted contact angle (at rest exact for a set under thrust alone)."""
    g = bearing.geometry
    Fs, sg = bearing.preload.axial_N, bearing._s_float
    sin_a = max(math.sin(g.mounted_angle_rad), 0.05)
    share = Fs / (fl.size * g.balls)
    v = (share / sin_a / g.K_series) ** (2.0 / 3.0) / sin_a - sg * q[2]
    if om == 0.0:
        return v
    k0 = fl[:1]
    qa = np.zeros(5)
    qa[2] = q[2]
    X = np.full((1, 1, 2), np.nan)
    f, K = np.empty((1, 5)), np.empty((1, 5, 5))
    out = [np.empty((1, 1)) for _ in range(7)]
    race = np.ascontiguousarray(bearing.race[k0][:, :1], dtype=np.float64)
    params = work.params(bearing, om)
    for _ in range(30):
        try:
            status = kn.evaluate_rows(qa, float(om), 0.0, params, bearing._row_sign[k0], bearing._row_zc[k0],
                                      bearing._row_offset[k0], np.array([-sg * v]), race, 1, X, f, K, *out)
        except ZeroDivisionError:
            status = 0
        if status >= 0:
            break  # the full solve starts from the last good estimate
        h = -sg * f[0, 2]
        if abs(h - share) <= 1e-6 * share:
            break
        v = _newton_step(v, h, K[0, 2, 2], share)
    return v


def _solved(v, q, sg, ev, work):
    """-s v, the evaluation, and the start of the next solve of the call kept in ``work``."""
    K = ev.K_rows.sum(axis=0)
    slope = -sg * K[2] / K[2, 2] if K[2, 2] > 0.0 else np.zeros(5)
    slope[2] = 0.0
    work.shift = (v + sg * q[2], np.array(q, float), slope)
    return -sg * v, ev
