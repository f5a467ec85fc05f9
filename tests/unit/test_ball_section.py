"""Ball bearing deck keys: validation messages, unit conversion in build(), the default deck.

Also the shared fixtures of the ball tests (default_section, bearing).
"""

import math

import numpy as np
import pytest
import yaml
from pydantic import ValidationError

from spindlesim.bearings.ball import BallBearingEntry, BallSection, build, default_deck_text
from spindlesim.bearings.ball.bearing import BallBearing

RPM = math.pi / 30.0
BASE = dict(balls=18, ball_diameter_mm=12.7, pitch_diameter_mm=90.0, contact_angle_deg=15.0,
            inner_conformity=0.52, outer_conformity=0.53)


def default_section_dict() -> dict:
    return yaml.safe_load(default_deck_text())["bearing"]


def default_section(**changes) -> BallSection:
    d = default_section_dict()
    d.update(changes)
    return BallSection.model_validate(d)


def bearing(**changes) -> BallBearing:
    """The default deck's bearing (7014C-size DB pair), with deck-key changes (sweeps dropped)."""
    return build(default_section(sweeps={}, **changes))


def entry(**changes) -> BallBearingEntry:
    d = dict(BASE, type="ball", name="b", node=3)
    d.update(changes)
    return BallBearingEntry.model_validate(d)


def test_default_deck_parses_and_builds():
    sec = default_section()
    b = build(sec)
    g = b.geometry
    assert (g.balls, g.rows, g.arrangement) == (18, 2, "DB")
    assert g.ball_diameter_m == pytest.approx(12.7e-3, rel=1e-15)
    assert g.pitch_diameter_m == pytest.approx(90e-3, rel=1e-15)
    assert g.contact_angle_rad == pytest.approx(math.radians(15.0), rel=1e-15)
    assert b.preload.kind == "position" and b.preload.axial_m == pytest.approx(21e-6, rel=1e-15)
    assert g.row_z_m.tolist() == pytest.approx([-10e-3, 10e-3], rel=1e-15)
    assert g.row_sign.tolist() == [1, -1]  # DB: the row at z < 0 carries +z thrust
    assert sec.sweeps.speed_rpm.stop == 20000.0


def test_entry_node_is_zero_based_and_units_are_si():
    b = build(entry(radial_clearance_um=10.0, material={"E_GPa": 200.0, "poisson": 0.28, "density_kg_m3": 7800.0}))
    assert b.node == 2 and b.name == "b"
    g = b.geometry
    assert g.clearance_m == pytest.approx(10e-6, rel=1e-15)
    assert g.ring.E_Pa == pytest.approx(200e9, rel=1e-15) and g.ball.density_kg_m3 == 7800.0
    # E* of identical bodies: E / (2 (1 - nu^2))
    assert g.E_star_Pa == pytest.approx(200e9 / (2 * (1 - 0.28 ** 2)), rel=1e-12)


def test_ceramic_balls_change_mass_and_modulus_only():
    steel = build(entry()).geometry
    si3n4 = build(entry(ball_material={"E_GPa": 310.0, "poisson": 0.26, "density_kg_m3": 3200.0})).geometry
    assert si3n4.ball_mass_kg / steel.ball_mass_kg == pytest.approx(3200.0 / 7850.0, rel=1e-12)
    e_star = 1.0 / ((1 - 0.26 ** 2) / 310e9 + (1 - 0.3 ** 2) / 208e9)
    assert si3n4.E_star_Pa == pytest.approx(e_star, rel=1e-12)
    assert si3n4.inner.K > steel.inner.K


@pytest.mark.parametrize("changes, message", [
    (dict(inner_conformity=0.5), "inner_conformity"),
    (dict(outer_conformity=0.49), "outer_conformity"),
    (dict(balls=23), "do not fit"),
    (dict(ball_diameter_mm=46.0), "half the pitch diameter"),
    (dict(arrangement="DB"), "row_spacing_mm is required"),
    (dict(arrangement="DB", rows=5, row_spacing_mm=20.0), "rows"),
    (dict(arrangement="single", rows=2), "single has rows: 1"),
    (dict(preload={"kind": "position", "axial_um": 10.0}), "opposed rows"),
    (dict(arrangement="DT", rows=2, row_spacing_mm=20.0, preload={"kind": "position", "axial_um": 10.0}), "opposed rows"),
    (dict(arrangement="DB", rows=2, row_spacing_mm=20.0, axial_direction="-z"), "axial_direction"),
    (dict(radial_clearance_um=900.0), "radial_clearance_um"),
    (dict(preload={"kind": "spring", "axial_N": 0.0}), "greater than 0"),
    (dict(unknown_key=1.0), "Extra inputs"),
    (dict(contact_angle_deg=float("inf")), "finite"),
])
def test_invalid_entries_are_refused_with_the_key(changes, message):
    with pytest.raises(ValidationError, match=message):
        entry(**changes)


def test_section_preload_sweep_needs_a_preload():
    d = default_section_dict()
    d.pop("preload")
    with pytest.raises(ValidationError, match="sweeps.preload needs a preload"):
        BallSection.model_validate(d)


def test_three_row_sets_and_direction():
    b = build(entry(arrangement="DB", rows=3, row_spacing_mm=20.0, axial_direction="-z"))
    assert b.geometry.row_sign.tolist() == [1, -1, -1]
    b = build(entry(arrangement="DF", rows=3, row_spacing_mm=20.0))
    assert b.geometry.row_sign.tolist() == [-1, 1, 1]
    b = build(entry(arrangement="DT", rows=4, row_spacing_mm=20.0, axial_direction="-z"))
    assert b.geometry.row_sign.tolist() == [-1, -1, -1, -1]
    assert b.geometry.row_z_m.tolist() == pytest.approx([-30e-3, -10e-3, 10e-3, 30e-3], rel=1e-14)


def test_deep_groove_free_contact_angle_from_clearance():
    """Harris and Kotzalas (2007, Essential Concepts, eq. 2.11): cos(alpha_f) = 1 - P_d / (2 B D)."""
    g = build(entry(contact_angle_deg=0.0, radial_clearance_um=20.0)).geometry
    BD = (0.52 + 0.53 - 1.0) * 12.7e-3
    assert g.mounted_angle_rad == pytest.approx(math.acos(1.0 - 20e-6 / (2.0 * BD)), rel=1e-12)


def test_state_arrays_have_documented_shapes():
    b = bearing()
    st = b.solve(np.array([500.0, 0.0, 100.0, 0.0, 0.0]), 3000.0 * RPM)
    assert st.displacement.shape == (5,) and st.stiffness.shape == (5, 5)
    for name in ("element_load_inner_N", "element_load_outer_N", "contact_angle_inner_deg", "contact_angle_outer_deg",
                 "max_pressure_inner_Pa", "max_pressure_outer_Pa", "psi_rad", "centrifugal_force_N"):
        assert getattr(st, name).shape == (2, 18), name
    assert st.semi_axes_inner_m.shape == (2, 18, 2)
    assert st.life_L10_iso281_Mrev > 0 and st.life_L10r_iso16281_Mrev > 0
    assert st.applied_load().tolist() == [500.0, 0.0, 100.0, 0.0, 0.0]
