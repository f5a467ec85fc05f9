"""The semi-discretization's history keeps only the outputs a period reads.

Out of the cut a step's delayed terms are zero (D_i = -B K_i C with K_i = 0), so the history slots that no step in
the cut reads are zero columns of the monodromy matrix: their only contribution to its spectrum is a zero
multiplier.  The multipliers that decide stability come from the block of the slots read, whose order at 5 %
radial immersion is about a third of the full matrix's.  Checked against the full matrix (every slot kept, as the
semi-discretization of Insperger and Stepan writes it): the largest multipliers agree to the eigen-solvers'
round-off, for both orders, with a static feed-through (a rotor's reduced model), and for a cut with no free
flight (nothing dropped: the same matrix bit for bit).
"""

import numpy as np
import pytest

from spindlesim.chatter import MillingProcess, Mode, ToolPointModel
from spindlesim.chatter.sd_model import SdModel
from spindlesim.chatter.period_map import used_slots
from spindlesim.chatter.semi_discretization import SdProblem, _dominant_eigenpair, _largest_multipliers

MODES = [Mode("x", 922.0, 0.011, 0.03993 * (2 * np.pi * 922.0) ** 2),
         Mode("y", 1100.0, 0.02, 0.05 * (2 * np.pi * 1100.0) ** 2),
         Mode("x", 2500.0, 0.03, 0.02 * (2 * np.pi * 2500.0) ** 2)]
TOOL = ToolPointModel.from_modes(MODES)
FEED = SdModel(TOOL.A, TOOL.B, TOOL.C, np.array([[2e-8, 3e-9], [3e-9, 1.5e-8]]))
LOW = MillingProcess(2, 20e-3, 1e-3, "down", 6e8, 1 / 3)  # 5 % immersion: 14 % of the tooth period in the cut
QUARTER = MillingProcess(4, 16e-3, 2e-3, "up", 7.67e8, 0.22)
SLOT = MillingProcess(3, 20e-3, 20e-3, "down", 6e8, 1 / 3)  # a tooth always cuts: no free flight


def test_the_slots_read_are_those_of_the_steps_in_the_cut_and_the_one_before():
    """Step i reads y_{i-m} (slot m - i - 1) and y_{i-m+1} (slot m - i - 2); steps 1 and 2 of 5 cut: slots 1-3."""
    cut = np.array([False, True, True, False, False])
    assert np.array_equal(used_slots(cut), [False, True, True, True, False])
    last = np.array([False, False, False, False, True])  # the last step reads y_{-1} and y_0 (from x_0)
    assert np.array_equal(used_slots(last), [True, False, False, False, False])


@pytest.mark.parametrize("process", [LOW, QUARTER], ids=["5 %", "12.5 %"])
@pytest.mark.parametrize("model", [TOOL, FEED], ids=["modes", "feed-through"])
@pytest.mark.parametrize("order", [0, 1])
@pytest.mark.parametrize("steps", [40, 150])
def test_the_kept_history_has_the_multipliers_of_the_full_one(process, model, order, steps):
    prob = SdProblem(process, [model], np.array([9000.0, 14000.0, 18000.0, 22000.0]), steps, order)
    s = np.array([0, 1, 2, 3, 2])
    depth = np.array([0.5e-3, 1e-3, 2e-3, 3e-3, 1e-6])
    full, kept = prob.monodromy(s, depth, full=True), prob.monodromy(s, depth, full=False)
    assert kept.shape[1] < 0.6 * full.shape[1]
    mu_full = _largest_multipliers(full, model.A.shape[0])
    mu_kept = _largest_multipliers(kept, model.A.shape[0])
    for a, b in zip(mu_full[:, :4], mu_kept):  # each multiplier has its twin among the six (pairs in either order)
        assert np.max(np.min(np.abs(a[:, None] - b[None, :]), axis=1)) < 1e-9 * abs(a[0])
    # the rest of the full matrix's spectrum beyond the kept block is zero (dense check on the small case)
    if steps == 40:
        ev_full = np.sort(np.abs(np.linalg.eigvals(full[0])))[::-1]
        ev_kept = np.sort(np.abs(np.linalg.eigvals(kept[0])))[::-1]
        assert np.allclose(ev_full[:len(ev_kept)], ev_kept, rtol=1e-8, atol=1e-10)
        assert np.max(ev_full[len(ev_kept):]) < 1e-6


def test_without_free_flight_nothing_is_dropped():
    prob = SdProblem(SLOT, [FEED], np.array([9000.0, 14000.0]), 60, 1)
    s, depth = np.array([0, 1]), np.array([1e-3, 2e-3])
    assert np.array_equal(prob.monodromy(s, depth, full=True), prob.monodromy(s, depth, full=False))


@pytest.mark.parametrize("model", [TOOL, FEED], ids=["modes", "feed-through"])
def test_the_outputs_of_a_period_run_from_the_kept_eigenvector_are_the_full_eigenvectors(model):
    """The critical multiplier's chatter frequency is read from the outputs of a whole period (free flight
    included); from the matrix of the slots read they come from running the steps from its eigenvector.  They
    equal the full matrix's eigenvector's history (up to its scale), and so do kind and frequency."""
    from spindlesim.chatter.period_map import monodromy_matrix, period_history

    prob = SdProblem(LOW, [model], np.array([14000.0, 18000.0, 22000.0]), 150, 1)
    s, depth = np.array([0, 1, 2]), np.array([1.5e-3, 2e-3, 2.5e-3])
    maps = prob.step_maps(s, depth)
    full, kept = monodromy_matrix(maps, full=True), monodromy_matrix(maps, full=False)
    n, r = model.A.shape[0], 2
    for e in range(3):
        mu_f, v_f = _dominant_eigenpair(full[e], n)
        mu_k, v_k = _dominant_eigenpair(kept[e], n)
        if mu_f.imag < 0:
            mu_f, v_f = mu_f.conjugate(), v_f.conj()
        if mu_k.imag < 0:
            mu_k, v_k = mu_k.conjugate(), v_k.conj()
        assert abs(mu_f - mu_k) < 1e-9
        want = v_f[n:].reshape(150, r)[::-1]
        got = period_history(maps, e, mu_k, v_k)
        scale = np.vdot(got.ravel(), want.ravel()) / np.vdot(got.ravel(), got.ravel())
        assert np.max(np.abs(scale * got - want)) < 1e-8 * np.max(np.abs(want))
        a, b = prob._critical(int(s[e]), mu_f, want), prob._critical(int(s[e]), mu_k, got)
        assert a.kind == b.kind and a.chatter_frequency_hz == pytest.approx(b.chatter_frequency_hz, rel=1e-9)


def test_the_models_are_balanced_so_that_a_step_needs_no_squaring(monkeypatch):
    """A tap test's modes in (q, q') coordinates have a state matrix of 1-norm w^2 (here 6.7e8 /s for the 4.1 kHz
    mode) against w for the balanced form: the steps' exponentials then needed the degree-13 approximant with ten
    squarings (``_expm.expm_batch``).  Balanced by a diagonal similarity of powers of two (exact), every step takes a
    low-degree Pade approximant, and the multipliers are those of any other state basis (a diagonal similarity of
    arbitrary scales gives the same to 1e-9)."""
    import spindlesim.chatter.semi_discretization as sd

    modes = [Mode("xy"[k % 2], f, 0.02, 5e7) for k, f in enumerate([700, 900, 1300, 1600, 2100, 2600, 3400, 4100])]
    tool = ToolPointModel.from_modes(modes)
    calls = []
    real = sd.expm_batch
    monkeypatch.setattr(sd, "expm_batch", lambda Z: calls.append(len(Z)) or real(Z))
    proc = MillingProcess(4, 16e-3, 0.8e-3, "down", 7.67e8, 0.22)
    s, depth = np.array([0, 1]), np.array([3e-3, 5e-3])
    mu = SdProblem(proc, [tool], np.array([12000.0, 20000.0]), 150, 1).multipliers(s, depth)
    assert not calls
    scale = np.exp(np.random.default_rng(3).uniform(-4.0, 4.0, tool.A.shape[0]))  # x = S x~, S = diag(scale)
    other = ToolPointModel(tool.A * scale[None, :] / scale[:, None], tool.B / scale[:, None], tool.C * scale[None, :])
    mu_other = SdProblem(proc, [other], np.array([12000.0, 20000.0]), 150, 1).multipliers(s, depth)
    for a, b in zip(mu[:, :4], mu_other):
        assert np.max(np.min(np.abs(a[:, None] - b[None, :]), axis=1)) < 1e-9 * abs(a[0])


def test_arnoldi_keeps_a_basis_as_large_as_the_structure(monkeypatch):
    """ARPACK's basis is the structure's states n + 12, without the former bound of 30: a 48-state tool-point model
    (24 lightly damped modes 600-6000 Hz) has about n multipliers outside the cluster near zero, and with 30 vectors
    ARPACK restarted until it had made 150-160 products with each 288-state monodromy matrix; with 60 it makes 61.
    The six largest multipliers are the dense eigenvalues' either way (within 1e-12)."""
    import scipy.sparse.linalg as spla

    import spindlesim.chatter.semi_discretization as sd

    rng = np.random.default_rng(3)
    freqs = np.geomspace(600.0, 6000.0, 24)
    modes = [Mode("xy"[i % 2], f, 0.01 + 0.02 * rng.random(), (0.5 + rng.random()) * 1e7 * f / 600.0)
             for i, f in enumerate(freqs)]
    tool = ToolPointModel.from_modes(modes)
    n = tool.A.shape[0]
    prob = SdProblem(MillingProcess(4, 16e-3, 8e-3, "down", 7.67e8, 0.22), [tool], np.array([9000.0, 15000.0]),
                     120, 1)
    products = [0]

    def counted(A, **kw):
        def matvec(x):
            products[0] += 1
            return A @ x
        return spla.eigs(spla.LinearOperator(A.shape, matvec=matvec, dtype=A.dtype), **kw)

    monkeypatch.setattr(sd, "eigs", counted)
    for depth in (0.2e-3, 1e-3, 2e-3):  # stable, near the limit, unstable
        Phi = prob.monodromy(np.array([0, 1]), np.array([depth, depth]), full=False)
        products[0] = 0
        mu = _largest_multipliers(Phi, n)
        assert products[0] <= 2 * 80
        dense = np.sort(np.abs(np.linalg.eigvals(Phi)), axis=1)[:, ::-1][:, :6]
        assert np.max(np.abs(np.abs(mu) - dense)) < 1e-12
