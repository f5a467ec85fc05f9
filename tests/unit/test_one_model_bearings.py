"""What a fluid-film bearing holds at its operating point, so that its linearization is the tangent of
the force the transient integrates (issue "One spindle model"; bearings/fluidfilm/bearing.py).

- A 360 deg bore fed at the maximum film (``feed="max_film"``) holds its film start at the operating
  point's maximum film: the force there is the max-film force, the tangent the static solver's
  coefficients (film start held), which the max-film force's own tangent is not (its film start turns
  with the journal).
- A film closed on itself (``feed="periodic"``) is invariant under rotation: the static Jacobian's
  tangential column is S f / eps, the tangent of the transient's force.
- The tabulated film of a transient carries the static load at the static position exactly.
"""

import math

import numpy as np
import pytest

from spindlesim.bearings.fluidfilm import coefficients as coef
from spindlesim.bearings.fluidfilm.equilibrium import solve_axisymmetric
from spindlesim.bearings.fluidfilm.film_force import ExactFilmForce, force_scale
from spindlesim.bearings.fluidfilm.geometry import fixed_feed_geometry, plain_geometry
from spindlesim.bearings.fluidfilm.reynolds import ReynoldsSolver
from spindlesim.deck import parse_deck
from spindlesim.model.build import build_rotor

GRID = (96, 8)
D, L, C = 0.05, 0.025, 75e-6
OMEGA, MU = 800.0, 0.01


def _static(feed: str, load=np.array([0.0, -95.0])):
    """Equilibrium of a 360 deg bore under ``load`` (dimensionless film solution in x, y)."""
    geo = plain_geometry(D, L, C, feed=feed)
    target = -load * C**2 / (MU * OMEGA * (D / 2) ** 4)
    return geo, solve_axisymmetric(ReynoldsSolver(geo, *GRID), target)


def test_fixed_feed_holds_the_max_film_force_and_has_the_static_coefficients():
    geo, eq = _static("max_film")
    q = np.array([eq.X, eq.Y]) * C
    gamma = math.atan2(eq.Y, eq.X)
    held = ExactFilmForce(fixed_feed_geometry(geo, gamma + math.pi), *GRID)
    turning = ExactFilmForce(geo, *GRID)
    f, K, Cd = held.force_and_tangent(q, np.zeros(2), OMEGA, MU)
    f_turn, K_turn, _ = turning.force_and_tangent(q, np.zeros(2), OMEGA, MU)
    Ks, Cs = coef.dimensional(eq.film.jac_position, eq.film.jac_velocity, MU, OMEGA, D / 2, C)
    # the same discrete problem on a grid turned by the feed angle: round-off apart (measured 1e-15)
    tol = 1e-9 * np.abs(f).max()
    np.testing.assert_allclose(f, OMEGA * force_scale(geo, MU) * eq.film.force, rtol=0, atol=tol)
    np.testing.assert_allclose(f, f_turn, rtol=0, atol=tol)
    assert np.abs(K - Ks).max() <= 1e-8 * np.abs(Ks).max()
    assert np.abs(Cd - Cs).max() <= 1e-8 * np.abs(Cs).max()
    # the turning film start is another tangent: measured 8.3 % of max|K| apart at e/Cb 0.22 here
    assert np.abs(K_turn - Ks).max() > 0.01 * np.abs(Ks).max()


def test_fixed_feed_geometry_is_for_max_film_bores_only():
    with pytest.raises(ValueError):
        fixed_feed_geometry(plain_geometry(D, L, C, feed="periodic"), 1.0)
    with pytest.raises(ValueError):
        fixed_feed_geometry(plain_geometry(D, L, C, grooves=2), 1.0)
    assert not fixed_feed_geometry(plain_geometry(D, L, C), 1.0).axisymmetric


def test_periodic_film_coefficients_are_the_tangent_of_the_film_force():
    geo, eq = _static("periodic")
    q = np.array([eq.X, eq.Y]) * C
    _, K, _ = ExactFilmForce(geo, *GRID).force_and_tangent(q, np.zeros(2), OMEGA, MU)
    Ks, _ = coef.dimensional(eq.film.jac_position, eq.film.jac_velocity, MU, OMEGA, D / 2, C)
    # measured 2e-16 (the grid's own tangential difference is 0.82 % of max|K| apart here)
    assert np.abs(K - Ks).max() <= 1e-9 * np.abs(Ks).max()


DECK = """title: journal on a fluid-film bearing
journal: {mass_kg: 9.7}
bearings:
  - {name: b, node: 1, type: TYPE, diameter_mm: 50, width_mm: 25, clearance_mm: 0.075,
     oil: {viscosity_Pa_s: 0.01}, transient_film: FILM, grid: {circumferential: 48, axial: 4}}
operating: {speed_rpm: 6000, gravity: true}
"""


@pytest.mark.parametrize("kind, film", [("plain", "reynolds"), ("three_lobe", "table"), ("three_lobe", "reynolds")])
def test_transient_film_is_in_equilibrium_at_the_static_position(kind, film, tmp_path, monkeypatch):
    monkeypatch.setenv("SPINDLESIM_CACHE", str(tmp_path))  # a coarse table (48 x 4 grid), built here
    text = DECK.replace("TYPE", kind).replace("FILM", film)
    rotor = build_rotor(parse_deck(text, "j.yaml").deck)
    b, W = rotor.bearings[0], rotor.speed_rpm * math.pi / 30
    load = np.array([0.0, -9.7 * 9.80665])
    q0 = b.static_displacement(W, load)
    held = b.at_operating_point(W, load, transient=True)
    assert held.film_method == film and held.geometry.fixed_feed == (kind == "plain")
    f = held.force(q0, np.zeros(2), 0.0, W)
    # measured 0 (the table's own error at this point, 2.7e-3 of the load, removed by the offset)
    assert np.abs(f + load).max() <= 1e-9 * np.abs(load).max()
    assert (held.force_offset_N != (0.0, 0.0)) == (film == "table")
    assert held.free() == b  # what the deck gives, nothing held
