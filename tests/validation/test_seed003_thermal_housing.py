"""Seed 003's thermal equilibrium with the housing its own Table 1 implies.

Source: seed 003 (Cho, Kim, Lee, Kim, 3-lobe sliding-bearing grinding spindle), Table 1: mean film
temperature 38.542 C (front) and 38.337 C (rear) at 2170 rpm, 20 C ambient, 25 C inlet.  The
housing's heat removal a A = H2 / (theta - theta_E) follows from the same table (front: H = 1.130 N m
x 227.2 rad/s = 256.8 W, H1 = c rho q dT = 93.1 W, so a A = 163.7 W / 18.54 K = 8.83 W/K; rear 8.12
W/K); the deck's housing areas give exactly those at 15 W/m2K.  Required (issue "What a new user
meets", item 13): within 5 C of the paper for both bearings.  Measured: 36.57 C and 37.39 C (-1.97 and
-0.95 C); with the generic housing (5 pi D L, 1.15 W/K) the front was 57.6 C.
"""

from __future__ import annotations

import math

import pytest

from spindlesim.deck import default_deck
from spindlesim.model.build import build_bearings

PAPER_MEAN_C = {"front": 38.542, "rear": 38.337}


def test_default_deck_heat_balance_lands_near_the_paper():
    loaded = default_deck("spindle")
    bearings = {b.name: b for b in build_bearings(loaded.deck)}
    speed = 2170 * math.pi / 30
    for name, paper in PAPER_MEAN_C.items():
        b = bearings[name]
        res = b.analyze(speed)
        assert res.housing_conductance_W_K == pytest.approx({"front": 8.83, "rear": 8.12}[name], rel=0.01)
        T = res.temperature_mean_C
        assert abs(T - paper) <= 5.0, f"{name}: {T:.2f} C vs paper {paper} C"
        # the heat balance closes: film loss = heat to oil + heat to housing
        assert res.heat_generated_W == pytest.approx(res.heat_to_oil_W + res.heat_to_housing_W, rel=1e-6)
