"""The semi-discretization of a large tool-point model: dominant modes plus the others' compliance.

A made-up 'rotor' tool point: the flexible mode of the Insperger-Stepan example along x (922 Hz, zeta
0.011, 1.34e6 N/m) and a y mode (1,100 Hz), plus twelve stiff modes (6 to 40 kHz, 2e8 to 9e8 N/m),
28 states in all.  The stiff modes add 1.6 % to the static compliance along x.
"""

import numpy as np
import pytest

from spindlesim.chatter import MillingProcess, Mode, ToolPointModel, stability_lobes
from spindlesim.chatter._expm import expm_batch
from spindlesim.chatter.sd_model import SdModel, dominant_modes, models_for_sd

FLEX = [Mode("x", 922.0, 0.011, 1.34e6), Mode("y", 1100.0, 0.02, 3.0e6)]
STIFF = [Mode(d, f, 0.02, k) for d, f, k in zip("xyxyxyxyxyxy", np.geomspace(6e3, 4e4, 12), np.linspace(2e8, 9e8, 12))]
BIG = ToolPointModel.from_modes(FLEX + STIFF)
PROC = MillingProcess(4, 20e-3, 10e-3, "down", 6e8, 1 / 3)


def test_reduced_model_keeps_the_receptance_and_the_limits():
    """Kept: the two flexible modes; the stiff ones' compliance enters as D.  The SD limits of the
    reduced model equal the full model's within 0.1 % (measured -0.06 .. +0.04 %); without D they are
    0.3-0.4 % low."""
    red, note = models_for_sd([BIG], PROC.mean_directional())
    (r,) = red
    assert isinstance(r, SdModel) and r.A.shape == (4, 4) and "2 dominant modes" in note
    assert r.D[0, 0] == pytest.approx(sum(1 / m.stiffness_N_m for m in STIFF if m.direction == "x"), rel=0.05)
    w = 2 * np.pi * np.linspace(300.0, 3000.0, 200)
    H = BIG.receptance(w)
    assert np.max(np.abs(r.receptance(w) - H)) < 2e-3 * np.max(np.abs(H))
    speeds = np.array([9000.0, 14000.0, 18000.0])
    opts = {"n_depths": 12, "error_tol": np.inf, "steps": 80}
    full = stability_lobes(PROC, BIG, speeds, "semi_discretization", reduce_model=False, **opts).limit_depth_m
    reduced = stability_lobes(PROC, r.dynamic, speeds, "semi_discretization", **opts).limit_depth_m
    auto = stability_lobes(PROC, BIG, speeds, "semi_discretization", **opts)
    assert any("dominant modes" in n for n in auto.notes)
    assert np.allclose(auto.limit_depth_m, full, rtol=1e-3)
    # the stiff modes' positive compliance makes Re H less negative at the chatter frequency: without
    # it the limits come out lower
    assert np.all(reduced / full - 1 < -2e-3)


def test_small_models_are_used_as_they_are_and_dominant_modes_order():
    small = ToolPointModel.from_modes(FLEX)
    assert models_for_sd([small], PROC.mean_directional()) == ([small], "")
    one = dominant_modes(BIG, 1)
    assert one.A.shape == (2, 2)
    f = one.significant_modes(0.0)[0].frequency_hz
    assert f == pytest.approx(922.0, rel=1e-9)


def test_expm_low_degree_matches_scipy():
    import scipy.linalg as sla

    rng = np.random.default_rng(3)
    for norm in (0.01, 0.2, 0.9, 2.0, 9.0):
        A = rng.normal(size=(20, 8, 8))
        A *= norm / np.abs(A).sum(axis=1).max(axis=1)[:, None, None]
        ref = np.array([sla.expm(a) for a in A])
        assert np.max(np.abs(expm_batch(A) - ref)) < 1e-13 * np.max(np.abs(ref))


def test_a_short_tool_that_needs_many_modes_is_still_reduced():
    """decks/tool_library.yaml's em12_shrink_45 on the milling spindle at its operating speed (250 states):
    the peak-compliance levels down to 0.01 of the largest (23 pairs) leave the depth curve 2 % off; the
    finer levels find 27 pairs within 0.13 % (the full model, which the semi-discretization was left with
    before, takes minutes a speed at 350 steps a period)."""
    from spindlesim.analysis.points import OperatingPoints
    from spindlesim.analysis.tool_point import tool_point_model
    from spindlesim.chatter import build_chatter
    from spindlesim.deck import deck_folder, load_deck
    from spindlesim.deck.document import library_tools
    from spindlesim.model.thermal import build_spindle_thermal
    from spindlesim.model.tool_library import with_tool
    from pathlib import Path

    loaded = load_deck(Path(__file__).parents[2] / "decks" / "tool_library.yaml")
    d = loaded.deck
    section = dict(library_tools(d))["em12_shrink_45"]
    rotor = with_tool(d, section)
    thermal = build_spindle_thermal(d, rotor)
    points = OperatingPoints(rotor, thermal if thermal is not None and thermal.analyses != "none" else None)
    model = tool_point_model(points, float(d.operating.speed_rpm))
    spec = build_chatter(d.chatter, deck_folder(loaded))
    (r,), note = models_for_sd([model], spec.process.mean_directional())
    assert model.A.shape[0] > 200
    assert isinstance(r, SdModel) and r.A.shape[0] <= 60, note
    assert "within 0.13 %" in note


def test_the_depth_curve_in_closed_form_is_lapacks():
    """The reduction check's zero-order depth per frequency takes the two eigenvalues of each 2 x 2 matrix in
    closed form (issue "Lobes in seconds": LAPACK per 2 x 2 matrix was a third of the check's time); they are
    LAPACK's to round-off on the model's whole grid, and to the eigenvalues' own conditioning (sqrt of the unit
    round-off, 1.5e-8) on near-degenerate matrices."""
    from spindlesim.chatter.sd_model import _depth_curve

    K0 = PROC.mean_directional()
    H = BIG.receptance(2 * np.pi * BIG.frequency_grid())
    rng = np.random.default_rng(3)
    # -K0 H near -1e-7 I: a double eigenvalue, split by 1e-9 of it
    near = 1e-7 * np.linalg.inv(K0) @ (np.eye(2) + 1e-9 * (rng.normal(size=(50, 2, 2)) + 1j * rng.normal(size=(50, 2, 2))))
    for h, rtol in ((H, 1e-9), (near, 1e-7)):
        lam = np.linalg.eigvals(-np.einsum("ij,fjk->fik", K0, h)).real.min(axis=1)
        want = np.where(lam < 0, -0.5 / np.where(lam < 0, lam, -1.0), np.inf)
        got = _depth_curve(K0, h)
        assert np.array_equal(np.isfinite(got), np.isfinite(want)) and np.isfinite(want).any()
        np.testing.assert_allclose(got[np.isfinite(want)], want[np.isfinite(want)], rtol=rtol)
