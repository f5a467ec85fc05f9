"""Mode tracking's assignment (analysis/campbell.py: assign) equals the Hungarian algorithm's.

The shortcut (each row's strict minimum in a column of its own) must give exactly what
scipy.optimize.linear_sum_assignment gives, and hand over to it whenever rows compete for a column."""

import numpy as np
from scipy.optimize import linear_sum_assignment

from spindlesim.analysis.campbell import assign


def _total(cost, rows, cols):
    return float(cost[rows, cols].sum())


def test_equals_the_hungarian_algorithm_on_random_and_tracking_like_matrices():
    rng = np.random.default_rng(7)
    shortcut = 0
    for trial in range(600):
        m = int(rng.integers(1, 9))
        n = m + int(rng.integers(0, 5))
        if trial % 2:  # tracking-like: a near-permutation of strong matches (MAC ~ 1) over weak ones
            cost = -0.2 * rng.random((m, n))
            cost[np.arange(m), rng.permutation(n)[:m]] -= 0.8
        else:
            cost = rng.random((m, n))
        rows, cols = assign(cost)
        r0, c0 = linear_sum_assignment(cost)
        assert np.array_equal(rows, r0)
        assert np.array_equal(cols, c0), (cost, cols, c0)
        shortcut += len(np.unique(np.argmin(cost, axis=1))) == m
    assert 250 < shortcut < 600  # both paths were exercised


def test_rows_competing_for_one_column_go_to_the_hungarian_algorithm():
    # both rows are nearest to column 0; the best total gives row 0 column 1 (1.0 - 0.1 < 0.0 + 1.9)
    cost = np.array([[0.0, 1.0, 5.0],
                     [0.0, 1.9, 5.0]])
    cost[1, 0] = -0.1
    rows, cols = assign(cost)
    assert list(cols) == [1, 0]
    assert _total(cost, rows, cols) == _total(cost, *linear_sum_assignment(cost))


def test_ties_are_not_taken_by_the_shortcut():
    cost = np.array([[0.0, 0.0, 1.0],
                     [1.0, 0.5, 0.0]])
    assert np.array_equal(assign(cost)[1], linear_sum_assignment(cost)[1])
