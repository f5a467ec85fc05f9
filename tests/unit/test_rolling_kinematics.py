"""Cage kinematics, seed 000 eqs. 1-4, against the textbook cage and spin ratios."""

import numpy as np
import pytest

from spindlesim.bearings.roller.kinematics import CageKinematics

# seed 000 Table 1: raceways 18.738 / 28.262 mm, roller DIAMETER 4.762 mm (DESIGN.md sec. 1)
SEED000 = CageKinematics(18.738e-3, 28.262e-3, 4.762e-3)


def test_cage_ratio_matches_textbook_formula():
    # Harris, Rolling Bearing Analysis: cage ratio (1 - D/d_m)/2 at zero contact angle
    dm = 0.5 * (18.738 + 28.262)
    assert SEED000.cage_ratio == pytest.approx(0.5 * (1 - 4.762 / dm), rel=1e-12)
    assert SEED000.cage_ratio == pytest.approx(0.39868, abs=5e-6)  # REFERENCES.md


@pytest.mark.parametrize("rollers, f_rp", [(5, 166.1), (8, 265.8), (12, 398.7)])
def test_cage_and_roller_pass_frequency(rollers, f_rp):
    # REFERENCES.md: 0.39868 x 83.33 = 33.22 Hz; roller pass 166.1 / 265.8 / 398.7 Hz at 5000 rpm
    assert SEED000.cage_frequency_hz(5000) == pytest.approx(33.22, abs=0.005)
    assert SEED000.roller_pass_frequency_hz(5000, rollers) == pytest.approx(f_rp, abs=0.05)


def test_spin_ratio_matches_harris():
    # roller spin relative to the cage, stationary outer race (Harris ch. 7):
    # omega_R / omega_i = d_m / (2 D) (1 - (D/d_m)^2)
    dm, D = 23.5, 4.762
    assert SEED000.spin_ratio == pytest.approx(dm / (2 * D) * (1 - (D / dm) ** 2), rel=1e-12)


def test_slip_slows_the_cage():
    slipping = CageKinematics(18.738e-3, 28.262e-3, 4.762e-3, slip_inner=0.05)
    assert slipping.cage_ratio < SEED000.cage_ratio
    # eq. 3 by hand: 0.95*18.738 / (0.95*18.738 + 28.262)
    assert slipping.cage_ratio == pytest.approx(0.95 * 18.738 / (0.95 * 18.738 + 28.262), rel=1e-12)
    with pytest.raises(ValueError):
        CageKinematics(18.738e-3, 28.262e-3, 4.762e-3, slip_outer=1.0)


def test_roller_angles_advance_with_cage():
    w = 5000 * np.pi / 30
    th0 = SEED000.roller_angles(0.0, w, 8)
    th1 = SEED000.roller_angles(0.01, w, 8)
    assert np.allclose(np.diff(th0), 2 * np.pi / 8)
    assert np.allclose(th1 - th0, SEED000.cage_ratio * w * 0.01)
    assert SEED000.roller_angles(np.array([0.0, 0.01]), w, 8).shape == (2, 8)
