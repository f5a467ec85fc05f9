"""One tooth period of the semi-discretization: the step maps, the monodromy matrix, the outputs of a period.

Step i of m (:mod:`.semi_discretization`) maps

    x_{i+1} = P_i x_i + R0_i y_{i-m} + R1_i y_{i-m+1},      y_i = C x_i   (or Yx_i x_i + Yh_i y_{i-m}
                                                                          with a feed-through),

and the state z = (x_0, y_{-1}, ..., y_{-m}) (history slot s holds y_{-s-1}) goes to the next period's by the
monodromy matrix.  Out of the cut a step's delayed terms vanish (R0_i = R1_i = 0, Yh_i = 0: no cutting force), so
the history slots that no step in the cut reads are zero columns of that matrix, and contribute only zero
multipliers: the matrix of the slots read (:func:`used_slots`) has the same nonzero multipliers at a fraction of
the order (5 % radial immersion, two teeth: 50 instead of 306 at 150 steps).  An eigenvector of that matrix gives
the outputs of a whole period by running the steps from it (:func:`period_history`), where the chatter frequency
is read.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["StepMaps", "used_slots", "monodromy_matrix", "period_history"]


@dataclass(frozen=True, eq=False)
class StepMaps:
    """The maps of the m steps of E evaluations: P [E, m, n, n], R0 and R1 [E, m, n, r], Cr [E, r, n]; with a
    feed-through Yx [E, m, r, n] and Yh [E, m, r, r] (else None); ``cut`` [m]: the steps in the cut of any of
    the E evaluations."""

    P: np.ndarray
    R0: np.ndarray
    R1: np.ndarray
    Cr: np.ndarray
    Yx: np.ndarray | None
    Yh: np.ndarray | None
    cut: np.ndarray


def used_slots(cut: np.ndarray) -> np.ndarray:
    """Which history slots a period reads [m] (slot s holds y_{-s-1}), from the steps in the cut ``cut`` [m]: step i
    reads y_{i-m} (slot m - i - 1) and y_{i-m+1} (slot m - i - 2) only when it cuts."""
    m = len(cut)
    used = np.zeros(m, bool)
    i = np.flatnonzero(cut)
    used[m - 1 - i] = True
    used[m - 2 - i[i < m - 1]] = True
    return used


def _kept(maps: StepMaps, full: bool) -> tuple[np.ndarray, np.ndarray]:
    """(slots kept [m] bool, first column of each kept slot in z (-1: dropped))."""
    m, n, r = maps.P.shape[1], maps.P.shape[2], maps.Cr.shape[1]
    used = np.ones(m, bool) if full or maps.cut.all() else used_slots(maps.cut)
    col = np.full(m, -1)
    col[used] = n + r * np.arange(int(used.sum()))
    return used, col


def monodromy_matrix(maps: StepMaps, full: bool = True) -> np.ndarray:
    """Phi [E, N, N]: every history slot (``full``), else those the cut reads (the module note; N = n + r x the
    slots kept).

    The rows of x_i as linear functions of z_0 are carried through the m steps (batched over E); only the
    history columns reached so far are multiplied.  Slot s of the new state holds the output recorded at step
    m - 1 - s."""
    P, R0, R1, Cr, Yx, Yh = maps.P, maps.R0, maps.R1, maps.Cr, maps.Yx, maps.Yh
    E, m, n, _ = P.shape
    r = Cr.shape[1]
    cut = np.ones(m, bool) if full else maps.cut
    used, col = _kept(maps, full)
    kept = np.flatnonzero(used)
    N = n + r * len(kept)
    out = np.zeros((E, N, N))
    Ys = out[:, n:].reshape(E, len(kept), r, N)  # the outputs recorded, by the slot they fill (kept order)
    # x_i's rows in two buffers, each step writing the other (no temporaries): columns [n, c) stay zero in both,
    # as c never grows
    X, X_next = np.zeros((E, n, N)), np.zeros((E, n, N))
    X[:, :, :n] = np.eye(n)
    y0 = None  # y_0 as a function of z_0, for the last step's y_{i-m+1}
    c = N  # history columns at or above c may be nonzero in X (slots reached so far): multiply those only
    for i in range(m):
        s_new = m - 1 - i  # the slot this step's output fills for the next period
        if used[s_new] or (i == 0 and cut[m - 1]):
            Yi = Cr if Yx is None else Yx[:, i]
            Y = Ys[:, np.searchsorted(kept, s_new)] if used[s_new] else np.zeros((E, r, N))
            np.matmul(Yi, X[:, :, :n], out=Y[:, :, :n])
            np.matmul(Yi, X[:, :, c:], out=Y[:, :, c:])
            if Yx is not None and col[m - i - 1] >= 0:  # y_{i-m} (Yh is zero out of the cut)
                h = col[m - i - 1]
                Y[:, :, h:h + r] += Yh[:, i]
            if i == 0:
                y0 = Y
        np.matmul(P[:, i], X[:, :, :n], out=X_next[:, :, :n])
        np.matmul(P[:, i], X[:, :, c:], out=X_next[:, :, c:])
        X, X_next = X_next, X
        if not cut[i]:
            continue  # R0 = R1 = 0 out of the cut
        h0 = col[m - i - 1]  # y_{i-m}
        X[:, :, h0:h0 + r] += R0[:, i]
        c = min(c, h0)
        if i < m - 1:  # y_{i-m+1} still in the history
            h1 = col[m - i - 2]
            X[:, :, h1:h1 + r] += R1[:, i]
            c = min(c, h1)
        else:  # y_{i-m+1} = y_0
            X += R1[:, i] @ y0
    out[:, :n] = X
    return out


def period_history(maps: StepMaps, e: int, mu: complex, v: np.ndarray) -> np.ndarray:
    """The outputs y_{-m} ... y_{-1} [m, r] of eigenvector ``v`` (multiplier ``mu``) of evaluation ``e``'s matrix
    with the slots the cut reads (``monodromy_matrix(maps, full=False)``).  Where every slot is kept they are read
    from ``v``; else the steps are run from it over one period, y_j = mu y_{j-m}."""
    m, n, r = maps.P.shape[1], maps.P.shape[2], maps.Cr.shape[1]
    used, col = _kept(maps, False)
    if used.all():
        return v[n:].reshape(m, r)[::-1]
    P, R0, R1 = maps.P[e], maps.R0[e], maps.R1[e]

    def slot(s):
        return v[col[s]:col[s] + r] if col[s] >= 0 else None

    x = v[:n]
    y = np.empty((m, r), complex)
    for i in range(m):
        past = slot(m - i - 1)  # y_{i-m}, read only in the cut
        if maps.Yx is None:
            y[i] = maps.Cr[e] @ x
        else:
            y[i] = maps.Yx[e, i] @ x + (maps.Yh[e, i] @ past if past is not None else 0.0)
        if maps.cut[i]:
            after = slot(m - i - 2) if i < m - 1 else y[0]  # y_{i-m+1}
            x = P[i] @ x + R0[i] @ past + R1[i] @ after
        else:
            x = P[i] @ x
    return y / mu
