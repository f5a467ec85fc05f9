"""The step exponentials of the semi-discretization without forming Van Loan's block matrix
(spindlesim.chatter._expm.van_loan_blocks) against scipy.linalg.expm of that matrix, Z = [[F, G, 0], [0, 0, c I],
[0, 0, 0]]: its blocks are exp F, phi1(F) G and c phi2(F) G (Van Loan 1978, IEEE Trans. Autom. Control 23)."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as sla

from spindlesim.chatter._expm import van_loan_blocks


@pytest.mark.parametrize("scale", [1e-3, 0.05, 0.4, 1.5])
def test_blocks_equal_the_exponential_of_the_block_matrix(scale):
    rng = np.random.default_rng(7)
    k, n, r, c = 5, 6, 2, 2.0 ** -5
    F = scale * rng.standard_normal((k, n, n)) / n
    G = scale * rng.standard_normal((k, n, r)) / n
    norm = max(float(np.abs(F).sum(axis=-2).max()), float(np.abs(G).sum(axis=-2).max()), c)
    got = van_loan_blocks(F, G, norm)
    if got is None:  # a norm beyond the low Pade degrees: the caller falls back to the full matrix
        assert scale > 1.0
        return
    P, Phi1G, Phi2G = got
    for e in range(k):
        Z = np.zeros((n + 2 * r, n + 2 * r))
        Z[:n, :n], Z[:n, n:n + r], Z[n:n + r, n + r:] = F[e], G[e], c * np.eye(r)
        X = sla.expm(Z)
        assert np.allclose(P[e], X[:n, :n], rtol=1e-12, atol=1e-14)
        assert np.allclose(Phi1G[e], X[:n, n:n + r], rtol=1e-12, atol=1e-14 * scale)
        assert np.allclose(Phi2G[e], X[:n, n + r:] / c, rtol=1e-11, atol=1e-13 * scale)


def test_a_stack_in_chunks_gives_the_same_numbers(monkeypatch):
    """A long stack is worked on in pieces of CHUNK_BYTES (the sums of powers stay in the processor's cache):
    the degree is chosen once for the whole stack, so every block is the one a single piece gives, bit for bit,
    whatever the chunk (here 7 steps of 6 x 6 a chunk against all 50 at once)."""
    from spindlesim.chatter import _expm

    rng = np.random.default_rng(11)
    k, n, r = 50, 6, 2
    F = 0.3 * rng.standard_normal((k, n, n)) / n
    G = 0.3 * rng.standard_normal((k, n, r)) / n
    norm = float(np.abs(F).sum(axis=-2).max())
    monkeypatch.setattr(_expm, "CHUNK_BYTES", 1 << 30)
    whole = van_loan_blocks(F, G, norm)
    monkeypatch.setattr(_expm, "CHUNK_BYTES", 7 * 8 * n * n)
    pieces = van_loan_blocks(F, G, norm)
    for a, b in zip(whole, pieces):
        assert a.shape == b.shape and np.array_equal(a, b)
