"""Frequency-domain regenerative stability boundary shared by the oriented-FRF and zero-order methods.

Both reduce the characteristic equation at the stability limit to, for every branch lambda(w)
(the oriented FRF in turning, an eigenvalue in milling; per unit depth, [m/N] x [N/m^2] = 1/m):

    1 + a (1 - exp(-j w tau)) lambda(w) = 0.

Taking real and imaginary parts (Tlusty; Altintas and Budak 1995) gives, wherever Re lambda < 0,

    a_lim = -1 / (2 Re lambda(w)),
    w tau = eps + 2 pi k,  eps = (2 psi - pi) mod 2 pi,  psi = atan2(Im lambda, Re lambda),

k = 0, 1, 2 ... the lobe number (whole waves per tooth period).  For the usual Im lambda < 0,
eps = 2 pi - 2 arctan(Re / Im) (Schmitz and Smith, Machining Dynamics, ch. 4) = 3 pi + 2 psi
(Altintas).  At a given delay tau the chatter frequencies are the roots of
Phi(w) = w tau - eps(w) = 2 pi k; they are located on the frequency grid (eps is continuous
where Re lambda < 0) and interpolated linearly, together with Re lambda.
"""

from __future__ import annotations

from typing import Callable

import numpy as np

from .results import LobeDiagram, lobe_diagram_from_lobes
from .tool import ToolPoint, ToolSource, tool_series

__all__ = ["phase_eps", "limits_at_delays", "parametric_lobes", "eigen_branches", "sample_tool",
           "frequency_domain_diagram"]

_TWO_PI = 2 * np.pi


def phase_eps(lam: np.ndarray) -> np.ndarray:
    """eps in [0, 2 pi): phase shift between inner and outer modulation at the limit."""
    return np.mod(2.0 * np.angle(lam) - np.pi, _TWO_PI)


def eigen_branches(M: np.ndarray) -> np.ndarray:
    """Eigenvalues of 2x2 matrices ``M[f]`` as two branches ``[2, f]`` continuous in f.

    Closed-form roots; the pairing between neighbouring samples is the one of smaller jump,
    accumulated as a parity so the whole sort is vectorised.
    """
    tr = M[:, 0, 0] + M[:, 1, 1]
    det = M[:, 0, 0] * M[:, 1, 1] - M[:, 0, 1] * M[:, 1, 0]
    disc = np.sqrt(tr * tr / 4 - det)
    l1, l2 = tr / 2 + disc, tr / 2 - disc
    if len(tr) > 1:
        same = np.abs(l1[1:] - l1[:-1]) + np.abs(l2[1:] - l2[:-1])
        swap = np.abs(l1[1:] - l2[:-1]) + np.abs(l2[1:] - l1[:-1])
        parity = np.concatenate([[0], np.cumsum(swap < same) % 2]).astype(bool)
        l1, l2 = np.where(parity, l2, l1), np.where(parity, l1, l2)
    return np.stack([l1, l2])


def limits_at_delays(omega: np.ndarray, lam: np.ndarray, tau: np.ndarray,
                     max_lobes: int | None = None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Limit depth per lobe at each delay.

    omega [F] rad/s increasing; lam [B, F] branches; tau [S] delays.  Returns (lobe numbers [K],
    depth [K, S] (inf where none), chatter frequency [K, S] Hz) with, for each (k, s), the
    smallest limit over the branches and crossings of that lobe.
    """
    omega = np.asarray(omega, float)
    tau = np.atleast_1d(np.asarray(tau, float))
    lam = np.atleast_2d(lam)
    scale = np.abs(lam).max()
    valid = (lam.real < 0) & (np.abs(lam) > 1e-9 * scale)  # [B, F]
    eps = phase_eps(lam)
    ok = valid[:, :-1] & valid[:, 1:]  # [B, F-1]
    b_idx, f_idx = np.nonzero(ok)
    w0, w1 = omega[f_idx], omega[f_idx + 1]
    e0, e1 = eps[b_idx, f_idx], eps[b_idx, f_idx + 1]
    r0, r1 = lam.real[b_idx, f_idx], lam.real[b_idx, f_idx + 1]
    # phase in turns, Q = (w tau - eps) / 2 pi; level k is crossed where floor(Q) changes.
    # Speeds in blocks, so the [speed, interval] work arrays stay in cache.
    a0, a1 = w0 / _TWO_PI, w1 / _TWO_PI
    c0, c1 = e0 / _TWO_PI, e1 / _TWO_PI
    block = max(1, int(2e5 // max(len(w0), 1)))
    parts = []
    for b in range(0, len(tau), block):
        tb = tau[b:b + block]
        Q0 = np.multiply.outer(tb, a0)
        Q0 -= c0  # [S, I]
        Q1 = np.multiply.outer(tb, a1)
        Q1 -= c1
        F0, F1 = np.floor(Q0), np.floor(Q1)
        s_b, i_b = np.nonzero(F0 != F1)
        parts.append((s_b + b, i_b, F0[s_b, i_b], F1[s_b, i_b], Q0[s_b, i_b], Q1[s_b, i_b]))
    s_i, i_i, f0, f1, q0, q1 = (np.concatenate(v) for v in zip(*parts))
    reps = np.abs(f1 - f0).astype(np.int64)
    kmin = (np.minimum(f0, f1) + 1).astype(np.int64)
    s_i, i_i, kmin = np.repeat(s_i, reps), np.repeat(i_i, reps), np.repeat(kmin, reps)
    q0, q1 = np.repeat(q0, reps), np.repeat(q1, reps)
    offs = np.arange(reps.sum()) - np.repeat(np.cumsum(reps) - reps, reps)
    k = kmin + offs
    keep = k >= 0
    if max_lobes is not None:
        keep &= k < max_lobes
    s_i, i_i, k, p0, p1 = s_i[keep], i_i[keep], k[keep], q0[keep], q1[keep]
    t = (k - p0) / (p1 - p0)
    w_c = w0[i_i] + t * (w1[i_i] - w0[i_i])
    re_c = r0[i_i] + t * (r1[i_i] - r0[i_i])
    a = -0.5 / re_c
    if len(k) == 0:
        return np.zeros(0, int), np.zeros((0, len(tau))), np.zeros((0, len(tau)))
    lobes = np.arange(k.max() + 1)
    depth = np.full((len(lobes), len(tau)), np.inf)
    freq = np.full((len(lobes), len(tau)), np.nan)
    order = np.lexsort((a, s_i, k))  # by lobe, then delay, then depth
    k_o, s_o = k[order], s_i[order]
    first = np.ones(len(order), bool)
    first[1:] = (k_o[1:] != k_o[:-1]) | (s_o[1:] != s_o[:-1])
    sel = order[first]
    depth[k[sel], s_i[sel]] = a[sel]
    freq[k[sel], s_i[sel]] = w_c[sel] / _TWO_PI
    return lobes, depth, freq


def parametric_lobes(omega: np.ndarray, lam: np.ndarray, lobes, periods_per_rev: int
                     ) -> list[tuple[int, np.ndarray, np.ndarray, np.ndarray]]:
    """Classical parametric lobes for a speed-independent FRF.

    For each lobe k and branch: (k, speed [rpm], limit depth [m], chatter frequency [Hz]) over the
    frequencies where Re lambda < 0, speed = 60 w / (N (eps + 2 pi k)).
    """
    lam = np.atleast_2d(lam)
    out = []
    for b in range(lam.shape[0]):
        v = lam[b].real < 0
        eps = phase_eps(lam[b, v])
        a = -0.5 / lam[b, v].real
        for k in lobes:
            tau = (eps + _TWO_PI * k) / omega[v]
            out.append((int(k), 60.0 / (periods_per_rev * tau), a, omega[v] / _TWO_PI))
    return out


def sample_tool(tool: ToolPoint, frequency_hz: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """(omega [F] rad/s, H [F, 2, 2]): the tool's FRF on its own grid (a model's mode-clustered grid, a sampled
    FRF's samples) or on the given frequencies, zero frequency dropped."""
    frf = tool.frf(frequency_hz)
    keep = frf.frequency_hz > 0
    return frf.omega[keep], frf.H[keep]


def frequency_domain_diagram(process, tool: ToolSource, speeds_rpm: np.ndarray,
                             branches: Callable[[np.ndarray], np.ndarray], method: str,
                             max_lobes: int | None = None, frequency_hz: np.ndarray | None = None,
                             notes: tuple[str, ...] = ()) -> LobeDiagram:
    """Lobe diagram from ``branches(H) -> lambda [B, F]`` per unit depth.

    A speed-independent tool is sampled once and all speeds are solved together; with one
    tool per speed each speed is solved on its own FRF.
    """
    speeds = np.asarray(speeds_rpm, float)
    tau = process.tooth_period_s(speeds)
    series = tool_series(tool, speeds)
    per_speed = series.speed_dependent
    if not per_speed:
        omega, H = sample_tool(series.first, frequency_hz)
        lobes, depth, freq = limits_at_delays(omega, branches(H), tau, max_lobes)
    else:
        from .semi_discretization import parallel_map  # the speeds on the worker threads

        tools = series.along(speeds)

        def one(s):
            omega, H = sample_tool(tools[s], frequency_hz)
            return limits_at_delays(omega, branches(H), tau[s:s + 1], max_lobes)

        parts = parallel_map(one, range(len(tools)))
        K = max((len(p[0]) for p in parts), default=0)
        lobes = np.arange(K)
        depth = np.full((K, len(speeds)), np.inf)
        freq = np.full((K, len(speeds)), np.nan)
        for s, (lk, d, fr) in enumerate(parts):
            depth[: len(lk), s] = d[:, 0]
            freq[: len(lk), s] = fr[:, 0]
    return lobe_diagram_from_lobes(speeds, depth, freq, lobes, method, process.describe(), per_speed, notes)
