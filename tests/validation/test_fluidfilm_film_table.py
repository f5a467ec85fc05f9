"""Reduced (table) film force against the exact Reynolds LCP solve (film_table.py).

Small tables on a small grid keep this fast; the full-size study (default grid 192 x 12,
table 16 x 16 x 48) is benchmarks/bench_film_force.py: seed 003 3-lobe force error max 0.40 %,
RMS 0.07 % of the exact force over e/Cb <= 0.9 and |v| <= omega Cb (omega = 0 included).

Here (grid 96 x 8, table 12 x 12 x 40, 150 random states of the same region, seed 3) the
measured force errors are: 3-lobe max 1.1 % / RMS 0.24 %, 360 deg plain max 0.45 % /
RMS 0.10 %, 2-groove plain (table containing the centre of curvature) max 1.5 % / RMS 0.25 %.
The bounds below leave about a factor 1.5-2 on those.
"""

import math
from pathlib import Path

import numpy as np
import pytest

from spindlesim.bearings.fluidfilm import film_table
from spindlesim.bearings.fluidfilm.film_force import ExactFilmForce
from spindlesim.bearings.fluidfilm.film_model import FilmForceModel
from spindlesim.bearings.fluidfilm.film_table import TableFilmForce, TableResolution
from spindlesim.bearings.fluidfilm.geometry import multilobe_geometry, plain_geometry
from spindlesim.bearings.fluidfilm.reynolds import ReynoldsError

GRID = (96, 8)
RES = TableResolution(12, 12, 40)
D = 0.069965
OMEGA = 227.0
MU = 0.002

CASES = {  # geometry, max and RMS bound of the relative force error
    "three_lobe": (multilobe_geometry(D, D, 12e-6, 0.5, 3), 0.02, 0.005),
    "plain_360": (plain_geometry(0.05, 0.025, 40e-6), 0.01, 0.003),
    "plain_grooved": (plain_geometry(0.05, 0.025, 40e-6, grooves=2), 0.03, 0.005),
}


def states(n, omega, eps_max=0.9, seed=0):
    """Random (X, X_r, omega): |X| <= eps_max, |X_r| <= omega (whirl at the clearance), 20 %
    of them at omega = 0 (same sampling as benchmarks/bench_film_force.py)."""
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < n:
        X = rng.uniform(-eps_max, eps_max, 2)
        if X @ X > eps_max**2:
            continue
        vm, d = rng.uniform(0.0, 1.0) * omega, rng.uniform(0.0, 2 * math.pi)
        out.append((X, vm * np.array([math.cos(d), math.sin(d)]), omega if len(out) < 0.8 * n else 0.0))
    return out


@pytest.fixture(scope="module")
def cache(tmp_path_factory):
    return tmp_path_factory.mktemp("film_tables")


@pytest.fixture(scope="module")
def tables(cache):
    return {k: TableFilmForce(v[0], *GRID, RES, cache) for k, v in CASES.items()}


@pytest.mark.slow
@pytest.mark.parametrize("name", list(CASES))
def test_table_force_within_bounds_of_exact(name, tables):
    geo, max_err, rms_err = CASES[name]
    table, exact = tables[name], ExactFilmForce(geo, *GRID)
    c = geo.clearance_m
    ef, ec = [], []
    for X, V, w in states(150, OMEGA, seed=3):
        fe, _, Ce = exact.force_and_tangent(X * c, V * c, w, MU)
        ft, _, Ct = table.force_and_tangent(X * c, V * c, w, MU)
        ef.append(np.hypot(*(ft - fe)) / np.hypot(*fe))
        ec.append(np.abs(Ct - Ce).max() / np.abs(Ce).max())
    ef, ec = np.array(ef), np.array(ec)
    assert ef.max() < max_err
    assert math.sqrt(np.mean(ef**2)) < rms_err
    assert math.sqrt(np.mean(ec**2)) < 0.05  # tangent: RMS 1.5-3 % at this size


@pytest.mark.parametrize("name", list(CASES))
@pytest.mark.parametrize("X, V, w", [((0.3, -0.5), (0.2, 0.4), OMEGA), ((0.3, -0.5), (0.2, 0.4), 0.0),
                                     ((-0.6, 0.1), (0.0, 0.0), OMEGA), ((0.05, 0.02), (-0.5, 0.3), -OMEGA)])
def test_table_tangent_is_derivative_of_table_force(name, tables, X, V, w):
    """K_t, C_t of the table are the derivatives of its own force (consistent Newton)."""
    geo = CASES[name][0]
    t, c = tables[name], geo.clearance_m
    q, v = np.array(X) * c, np.array(V) * OMEGA * c
    f, K, C = t.force_and_tangent(q, v, w, MU)
    hq, hv = 1e-6 * c, 1e-6 * OMEGA * c
    for j in range(2):
        e = np.zeros(2)
        e[j] = hq
        Kf = -(t.force_and_tangent(q + e, v, w, MU)[0] - t.force_and_tangent(q - e, v, w, MU)[0]) / (2 * hq)
        e = np.zeros(2)
        e[j] = hv
        Cf = -(t.force_and_tangent(q, v + e, w, MU)[0] - t.force_and_tangent(q, v - e, w, MU)[0]) / (2 * hv)
        assert np.abs(K[:, j] - Kf).max() < 1e-5 * np.abs(K).max()
        assert np.abs(C[:, j] - Cf).max() < 1e-5 * np.abs(C).max()


def test_table_homogeneity_and_rest(tables):
    geo = CASES["three_lobe"][0]
    t, c = tables["three_lobe"], geo.clearance_m
    q, v = np.array([0.2, -0.4]) * c, np.array([0.3, -0.1]) * OMEGA * c
    f1, K1, C1 = t.force_and_tangent(q, v, OMEGA, MU)
    f2, K2, C2 = t.force_and_tangent(q, 2.5 * v, 2.5 * OMEGA, MU)
    np.testing.assert_allclose(f2, 2.5 * f1, rtol=1e-12)
    np.testing.assert_allclose(K2, 2.5 * K1, rtol=1e-12)
    np.testing.assert_allclose(C2, C1, rtol=1e-12)
    # at rest: no force, no stiffness, describing-function damping (positive diagonal)
    f0, K0, C0 = t.force_and_tangent(q, np.zeros(2), 0.0, MU)
    assert np.all(f0 == 0.0) and np.all(K0 == 0.0)
    assert C0[0, 0] > 0 and C0[1, 1] > 0 and np.linalg.det(C0) > 0


def test_centred_journal_of_plain_grooved_bearing(tables):
    """The table containing the centre of curvature is single-valued and smooth there."""
    geo = CASES["plain_grooved"][0]
    t, ex, c = tables["plain_grooved"], ExactFilmForce(geo, *GRID), geo.clearance_m
    v = np.array([0.3, -0.2]) * OMEGA * c
    f0 = t.force_and_tangent(np.zeros(2), v, OMEGA, MU)[0]
    for d in (1e-9, 1e-7):
        for ang in np.linspace(0, 2 * math.pi, 5):
            q = d * c * np.array([math.cos(ang), math.sin(ang)])
            assert np.hypot(*(t.force_and_tangent(q, v, OMEGA, MU)[0] - f0)) < 1e-5 * np.hypot(*f0)
    fe = ex.force_and_tangent(np.zeros(2), v, OMEGA, MU)[0]
    assert np.hypot(*(f0 - fe)) < 0.01 * np.hypot(*fe)


def test_table_cache_is_reused(cache, tables, monkeypatch):
    geo = CASES["three_lobe"][0]
    files = sorted(Path(cache).glob("film_table_*.npz"))
    assert len(files) == 3  # one land shape per bearing here (the 3 lobes share one)
    assert not list(Path(cache).glob("*.tmp"))
    film_table.land_table.cache_clear()  # forget the in-process tables

    def no_build(*args, **kwargs):
        raise AssertionError("table rebuilt although cached on disk")

    monkeypatch.setattr(film_table, "build_table", no_build)
    again = FilmForceModel(geo, *GRID, method="table", resolution=RES, cache_dir=cache)
    q, v = np.array([0.1, -0.3]) * geo.clearance_m, np.array([1e-4, 2e-4])
    np.testing.assert_array_equal(again.force_and_tangent(q, v, OMEGA, MU)[0],
                                  tables["three_lobe"].force_and_tangent(q, v, OMEGA, MU)[0])
    # a different resolution is a different key (would build)
    with pytest.raises(AssertionError, match="rebuilt"):
        TableFilmForce(geo, *GRID, TableResolution(12, 12, 42), cache)


def test_beyond_table_uses_exact_and_bore_raises(tables):
    geo = CASES["three_lobe"][0]
    t, ex, c = tables["three_lobe"], ExactFilmForce(geo, *GRID), geo.clearance_m
    q, v = np.array([0.0, -0.97]) * c, np.array([0.1, 0.0]) * OMEGA * c
    for a, b in zip(t.force_and_tangent(q, v, OMEGA, MU), ex.force_and_tangent(q, v, OMEGA, MU)):
        np.testing.assert_allclose(a, b, rtol=1e-12)
    with pytest.raises(ReynoldsError, match="touches the bore"):
        t.force_and_tangent(np.array([0.0, -1.02]) * c, v, OMEGA, MU)


def test_plain_bore_table_reaches_a_whirl_orbit_near_the_bore(cache):
    # an oil whirl above its threshold circles at e/Cb 0.97-0.98 (benchmarks/bench_whirl.py): a plain bore's
    # table reaches 0.99 (a multilobe's keeps 0.95), so the orbit stays on it; measured here (table
    # 18 x 40 on the 96 x 8 grid, the default's node spacing in ln(1 - e)), 80 states at e/Cb 0.95-0.985:
    # force error max 0.15 %, RMS 0.06 %
    geo = CASES["plain_360"][0]
    assert film_table.default_resolution(geo).eccentricity_max == 0.99
    assert film_table.default_resolution(CASES["three_lobe"][0]) == TableResolution()
    table = TableFilmForce(geo, *GRID, TableResolution(18, 12, 40, 0.99), cache)
    exact = ExactFilmForce(geo, *GRID)
    rng = np.random.default_rng(5)
    c = geo.clearance_m
    err = []
    for _ in range(80):
        e, th = rng.uniform(0.95, 0.985), rng.uniform(0, 2 * math.pi)
        X = e * np.array([math.cos(th), math.sin(th)])
        V = rng.uniform(0.0, 0.6) * OMEGA * np.array([-math.sin(th), math.cos(th)])  # whirl-like, tangential
        ft = table.force_and_tangent(X * c, V * c, OMEGA, MU)[0]
        fe = exact.force_and_tangent(X * c, V * c, OMEGA, MU)[0]
        err.append(np.hypot(*(ft - fe)) / np.hypot(*fe))
    assert table._exact is None  # every state on the table, none solved in full
    rms = math.sqrt(np.mean(np.square(err)))
    assert max(err) < 0.003 and rms < 0.001, (max(err), rms)
