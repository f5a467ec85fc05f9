"""Matrix exponential of a stack of small matrices, vectorised over the stack (numpy only).

Scaling and squaring with Pade approximants (Higham, SIAM J. Matrix Anal. Appl. 26 (2005)
1179-1193), the algorithm of scipy.linalg.expm, applied to the whole stack at once: batched matmul
and solve run in compiled loops, whereas scipy.linalg.expm pays Python overhead per matrix.  The
degree is the smallest of 3, 5, 7, 9 whose bound theta_m covers the largest 1-norm of the stack
(backward error below the unit roundoff), else 13 with scaling (theta_13 = 5.37).  The
semi-discretization needs tens of thousands of 6 x 6 to 30 x 30 exponentials per lobe diagram,
of small norm (a step is a thirtieth of a chatter wave).
"""

from __future__ import annotations

import numpy as np

__all__ = ["expm_batch", "van_loan_blocks"]

#: bytes of one n x n stack that :func:`van_loan_blocks` works on at a time: the approximant's sums of powers
#: are passes over the whole stack, and a stack that stays in the processor's cache makes them about twice as fast
#: (benchmarks/bench_chatter.py: 54 x 54 steps 312 -> 190 us a step, 30 x 30 115 -> 54 us, 16 x 16 25 -> 17 us)
CHUNK_BYTES = 512 * 1024

_B = (64764752532480000.0, 32382376266240000.0, 7771770303897600.0, 1187353796428800.0,
      129060195264000.0, 10559470521600.0, 670442572800.0, 33522128640.0, 1323241920.0,
      40840800.0, 960960.0, 16380.0, 182.0, 1.0)
_THETA13 = 5.371920351148152
#: Pade [m/m] coefficients and Higham's theta_m for m = 3, 5, 7, 9
_LOW = ((1.495585217958292e-2, (120.0, 60.0, 12.0, 1.0)),
        (2.539398330063230e-1, (30240.0, 15120.0, 3360.0, 420.0, 30.0, 1.0)),
        (9.504178996162932e-1, (17297280.0, 8648640.0, 1995840.0, 277200.0, 25200.0, 1512.0, 56.0, 1.0)),
        (2.097847961257068, (17643225600.0, 8821612800.0, 2075673600.0, 302702400.0, 30270240.0,
                             2162160.0, 110880.0, 3960.0, 90.0, 1.0)))


def _pade_low(X: np.ndarray, b: tuple[float, ...]) -> np.ndarray:
    ident = np.eye(X.shape[-1])
    X2 = X @ X
    powers = [ident, X2]
    for _ in range((len(b) - 1) // 2 - 1):
        powers.append(powers[-1] @ X2)
    U = X @ sum(b[2 * k + 1] * P for k, P in enumerate(powers))
    V = sum(b[2 * k] * P for k, P in enumerate(powers))
    return np.linalg.solve(V - U, V + U)


def expm_batch(A: np.ndarray) -> np.ndarray:
    """exp(A[..., n, n]) for a stack of real matrices."""
    A = np.asarray(A, float)
    shape = A.shape
    X = A.reshape((-1,) + shape[-2:])
    if X.shape[0] == 0:
        return A.copy()
    norm = np.abs(X).sum(axis=1).max(axis=1)  # 1-norm of each matrix
    top = float(norm.max())
    for theta, b in _LOW:
        if top <= theta:
            return _pade_low(X, b).reshape(shape)
    s = np.where(norm > _THETA13, np.ceil(np.log2(np.maximum(norm, 1e-300) / _THETA13)), 0).astype(int)
    X = X / (2.0 ** s)[:, None, None]
    b = _B
    ident = np.eye(shape[-1])
    X2 = X @ X
    X4 = X2 @ X2
    X6 = X4 @ X2
    U = X @ (X6 @ (b[13] * X6 + b[11] * X4 + b[9] * X2) + b[7] * X6 + b[5] * X4 + b[3] * X2 + b[1] * ident)
    V = X6 @ (b[12] * X6 + b[10] * X4 + b[8] * X2) + b[6] * X6 + b[4] * X4 + b[2] * X2 + b[0] * ident
    R = np.linalg.solve(V - U, V + U)
    for i in range(int(s.max(initial=0))):
        sq = s > i
        R[sq] = R[sq] @ R[sq]
    return R.reshape(shape)


def _poly(powers: list, coef) -> np.ndarray:
    """sum coef[k] powers[k] over a stack; powers[0] is the identity (added on the diagonal only)."""
    n = powers[1].shape[-1]
    out = np.zeros_like(powers[1])
    for c, P in zip(coef[1:], powers[1:]):
        out += c * P
    out[..., np.arange(n), np.arange(n)] += coef[0]
    return out


def van_loan_blocks(F: np.ndarray, G: np.ndarray, norm: np.ndarray):
    """(exp F, phi1(F) G, phi2(F) G) for stacks F [k, n, n] and G [k, n, r], phi1(x) = (e^x - 1) / x,
    phi2(x) = (e^x - 1 - x) / x^2: the blocks (1, 1), (1, 2) and (1, 3) / c of exp Z,
    Z = [[F, G, 0], [0, 0, c I], [0, 0, 0]], from the same Pade approximant [m/m] of Z as
    :func:`expm_batch` (m chosen from ``norm``, the largest 1-norm of the Z, as there) without forming
    Z.  With N = [[0, c I], [0, 0]] (N^2 = 0) a polynomial p(Z) has the blocks p(F), sum p_k F^(k-1) G
    and c sum p_k F^(k-2) G; the approximant's block-triangular solve q(Z) X = p(Z) has
    X22 = I + 2 (b1 / b0) N and needs q(F) alone (order n instead of n + 2 r):
    X12 = q(F)^-1 2 odd(F) G, X13 / c = q(F)^-1 2 (F odd3(F) G - (b1 / b0) (F even1(F) G - odd(F) G)),
    U = F odd(F^2), odd3 and even1 the odd and even sums without their first term, over F^2.  None when
    the norm needs the degree 13 with scaling (then use :func:`expm_batch`)."""
    for theta, b in _LOW:
        if norm <= theta:
            break
    else:
        return None
    n = F.shape[-1]
    size = max(1, CHUNK_BYTES // (8 * n * n))
    if F.ndim != 3 or len(F) <= size:
        return _van_loan(F, G, b)
    out = (np.empty(F.shape), np.empty(G.shape), np.empty(G.shape))
    for a in range(0, len(F), size):  # the same degree for every chunk: the same numbers as in one piece
        for o, x in zip(out, _van_loan(F[a:a + size], G[a:a + size], b)):
            o[a:a + size] = x
    return out


def _van_loan(F: np.ndarray, G: np.ndarray, b: tuple[float, ...]):
    """:func:`van_loan_blocks` with the Pade coefficients ``b`` chosen."""
    n, r = F.shape[-1], G.shape[-1]
    F2 = F @ F
    powers = [None, F2]  # I, F^2, F^4, ...
    for _ in range((len(b) - 1) // 2 - 1):
        powers.append(powers[-1] @ F2)
    odd = _poly(powers, b[1::2])
    even = _poly(powers, b[0::2])
    U = F @ odd
    PG = [G] + [P @ G for P in powers[1:]]  # F^(2j) G

    def comb(coef):
        return sum(c * X for c, X in zip(coef, PG))

    oG, odd3G, even1G = comb(b[1::2]), comb(b[3::2]), comb(b[2::2])
    rhs = np.empty(F.shape[:-1] + (n + 2 * r,))
    rhs[..., :n] = even + U
    rhs[..., n:n + r] = 2.0 * oG
    rhs[..., n + r:] = 2.0 * (F @ odd3G - (b[1] / b[0]) * (F @ even1G - oG))
    X = np.linalg.solve(even - U, rhs)
    return X[..., :n], X[..., n:n + r], X[..., n + r:]
