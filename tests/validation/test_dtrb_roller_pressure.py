"""Most loaded roller of the seed 001 rotor's DTRB with the half-space solver (issue 6 item 4)."""

from pathlib import Path

import numpy as np
import pytest

from spindlesim.bearings.dtrb.roller_pressure import most_loaded_roller_pressure
from spindlesim.deck import parse_deck
from spindlesim.analysis.operating import operating_state
from spindlesim.model.build import build_rotor

DECK = Path(__file__).parents[2] / "decks" / "seed001_dtrb_rotor.yaml"


def _pressure(crown: str):
    text = DECK.read_text().replace("crown_radius_mm: 2680.0", f"crown_radius_mm: {crown}")
    rotor = build_rotor(parse_deck(text, "seed001.yaml").deck)
    st = operating_state(rotor)
    dtrb = next(b for b in rotor.bearings if b.name == "dtrb")
    state = dtrb.solve(dtrb.full_load(st.load_of("dtrb")), rotor.speed_rad_s)
    return most_loaded_roller_pressure(dtrb.geometry, state, nx=48, ny=192)


@pytest.fixture(scope="module")
def by_crown():
    return {c: _pressure(c) for c in ("1300.0", "2680.0", "1.0e9")}


def test_load_balance_and_agreement_with_the_slice_model(by_crown):
    """The half-space solution carries the roller's Q_i, and its load per length at mid-roller agrees with
    the DTRB's own sliced line-contact law (seed 001 eq. 27) to 15% (two different contact models)."""
    rp = by_crown["2680.0"]
    c = rp.contact
    assert c.load_N == pytest.approx(rp.roller_load_N, rel=1e-4)
    dx = c.x_m[1] - c.x_m[0]
    per_length = c.pressure_Pa.sum(axis=0) * dx  # N/m along y
    mid_y = np.argmin(np.abs(c.y_m))
    mid_slice = np.argmin(np.abs(rp.slice_z_m - rp.slice_z_m.mean()))
    assert per_length[mid_y] == pytest.approx(rp.slice_load_N_m[mid_slice], rel=0.15)


def test_edge_stress_rises_with_crown_radius(by_crown):
    """Seed 001 Fig. 20 trend: a small crown radius keeps the contact off the roller ends; a straight
    roller is edge-loaded, and that peak is flagged as a grid-dependent singularity, not a stress."""
    small, straight = by_crown["1300.0"].contact, by_crown["1.0e9"].contact
    assert not small.edge_singular
    assert straight.edge_singular and "singularity" in straight.message
    assert straight.max_pressure_Pa > 1.5 * small.max_pressure_Pa
    end = lambda c: max(c.centreline_pressure_Pa[0], c.centreline_pressure_Pa[-1])  # noqa: E731
    assert end(straight) > end(by_crown["2680.0"].contact) >= end(small)
