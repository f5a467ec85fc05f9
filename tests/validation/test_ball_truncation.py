"""Truncation of the contact ellipse at the shoulder, against a hand calculation.

A single 7014C-size row under a pure thrust at rest: the contact angle from Jones' axial-load equation
(test_ball_closed_forms), the ball load Q = F_a / (Z sin a), the semi-axis along the groove a_H from Hertz
(point_contact, exact elliptic integrals); the ellipse reaches a + asin(a_H / (f D)) in the groove, and a
shoulder of height h ends the groove at arccos(1 - h / (f D)).  A shoulder 2 deg below the edge must warn
(state flag, run message, log), one 2 deg above must stay silent.
"""

import logging
import math

import numpy as np
import pytest
from scipy.optimize import brentq

from spindlesim.bearings.ball.sweeps import run
from spindlesim.contact.hertz import point_contact

from ..unit.test_ball_section import default_section
from .test_ball_closed_forms import E_STAR_STEEL, curvature_sums, series_constant

Z, D, DM, FI, FO, A0 = 18, 12.7e-3, 90e-3, 0.52, 0.53, math.radians(15.0)
FA = 20000.0


def hand_edges():
    """(contact angle, inner edge, outer edge) [deg] of the row under FA at rest."""
    BD = (FI + FO - 1.0) * D
    Kn = series_constant(D, DM, FI, FO, A0)
    a = brentq(lambda x: math.sin(x) * (math.cos(A0) / math.cos(x) - 1.0) ** 1.5 * BD ** 1.5 - FA / (Z * Kn),
               A0 + 1e-12, math.radians(89.0), xtol=1e-15, rtol=1e-15)
    Q = FA / (Z * math.sin(a))
    ai = point_contact(Q, *curvature_sums(D, DM, FI, A0, True), E_STAR_STEEL)[0]
    ao = point_contact(Q, *curvature_sums(D, DM, FO, A0, False), E_STAR_STEEL)[0]
    return (math.degrees(a), math.degrees(a + math.asin(ai / (FI * D))), math.degrees(a + math.asin(ao / (FO * D))))


def section(shoulders):
    return default_section(arrangement="single", rows=None, row_spacing_mm=None, preload=None, sweeps={},
                           load={"fz_N": FA}, speed_rpm=0.0, shoulders=shoulders)


def test_edge_angles_against_hand_calculation():
    alpha, edge_i, edge_o = hand_edges()
    st = run(section({})).state
    assert np.allclose(st.contact_angle_inner_deg, alpha, rtol=1e-9)
    assert np.allclose(st.edge_angle_inner_deg, edge_i, rtol=1e-9)
    assert np.allclose(st.edge_angle_outer_deg, edge_o, rtol=1e-9)
    assert edge_i == pytest.approx(43.25, abs=0.01)  # 24.49 deg + 18.76 deg of a 2.13 mm semi-axis
    # the default shoulders, 0.3 D on both rings: arccos(1 - 0.3 / f)
    assert st.shoulder_angle_inner_deg == pytest.approx(math.degrees(math.acos(1.0 - 0.3 / FI)), rel=1e-12)
    assert st.shoulder_angle_outer_deg == pytest.approx(math.degrees(math.acos(1.0 - 0.3 / FO)), rel=1e-12)
    assert st.truncated_contacts == 0


def test_a_shoulder_below_the_edge_warns(caplog):
    _, edge_i, _ = hand_edges()
    theta = math.radians(edge_i - 2.0)
    height_mm = FI * D * (1.0 - math.cos(theta)) * 1e3  # the same shoulder given as a height
    for shoulders in ({"inner_angle_deg": edge_i - 2.0}, {"inner_height_mm": height_mm}):
        caplog.clear()
        with caplog.at_level(logging.WARNING, logger="spindlesim.bearings.ball"):
            r = run(section(shoulders))
        st = r.state
        assert st.shoulder_angle_inner_deg == pytest.approx(edge_i - 2.0, rel=1e-12)
        assert np.all(st.truncated_inner) and not np.any(st.truncated_outer)
        assert st.truncated_contacts == Z
        assert len(r.truncation) == 1
        msg = r.truncation[0]
        assert "truncated" in msg and "18 contact(s)" in msg and "the inner contact of ball" in msg
        assert f"{edge_i:.3g} deg" in msg and "0 rpm" in msg and "Fz 20000 N" in msg
        assert any("truncated" in rec.getMessage() for rec in caplog.records)


def test_a_shoulder_above_the_edge_stays_silent(caplog):
    _, edge_i, edge_o = hand_edges()
    with caplog.at_level(logging.WARNING, logger="spindlesim.bearings.ball"):
        r = run(section({"inner_angle_deg": edge_i + 2.0, "outer_angle_deg": edge_o + 2.0}))
    assert r.state.truncated_contacts == 0 and r.truncation == ()
    assert not any("truncated" in rec.getMessage() for rec in caplog.records)


def test_issue_case_at_speed_truncates_only_with_the_tilt_free():
    """Issue 23: inner contact angles reach 41.6 deg on the 15 deg row under Fx 2 kN + Fz 1 kN at 20,000 rpm
    with its tilt free.  Against a 45 deg inner shoulder the ellipses of the most loaded balls run over it;
    with the tilt held (34.6 deg at most) they stay inside."""
    base = dict(arrangement="single", rows=None, row_spacing_mm=None, preload=None,
                load={"fx_N": 2000.0, "fz_N": 1000.0}, speed_rpm=20000.0, shoulders={"inner_angle_deg": 45.0})
    free = run(default_section(sweeps={}, **base))
    assert free.state.contact_angle_inner_deg.max() == pytest.approx(41.64, abs=0.01)
    assert free.state.truncated_contacts > 0 and "20000 rpm" in free.truncation[0]
    held = run(default_section(sweeps={}, held={"theta_x_mrad": 0.0, "theta_y_mrad": 0.0}, **base))
    assert held.state.contact_angle_inner_deg.max() < 35.0
    assert held.state.truncated_contacts == 0 and held.truncation == ()
