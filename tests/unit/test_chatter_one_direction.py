"""A tool flexible in one direction only (the classic single-DOF turning or milling case).

Until this was fixed, `spindlesim chatter` on a deck whose modal table had x modes only computed the
lobes and then failed writing them ("spindlesim chatter: Singular matrix", exit 1, no files): the
writer inverted the 2 x 2 receptance, whose y row and column are zero.
"""

import h5py
import numpy as np
import pytest
from click.testing import CliRunner

from spindlesim.cli import main
from spindlesim.output.rotor_writers import dynamic_stiffness

MILLING_X_ONLY = """
chatter:
  operation: milling
  speeds_rpm: {start: 8000, stop: 20000, count: 5}
  Kt_N_mm2: 600.0
  Kn_N_mm2: 200.0
  teeth: 2
  tool_diameter_mm: 20.0
  radial_depth_mm: 10.0
  mode: down
  frf:
    modes:
      - {direction: x, frequency_hz: 922.0, damping_ratio: 0.011, stiffness_N_m: 1.34e6}
"""

TURNING_Y_ONLY = """
chatter:
  operation: turning
  speeds_rpm: {start: 1000, stop: 4000, count: 7}
  Ks_N_mm2: 2000.0
  force_angle_deg: 70.0
  feed_direction_deg: 90.0
  frf:
    modes:
      - {direction: y, frequency_hz: 500.0, damping_ratio: 0.03, stiffness_N_m: 2.0e7}
"""


def test_dynamic_stiffness_of_a_one_direction_receptance():
    f = np.array([100.0, 900.0])
    H = np.zeros((2, 2, 2), complex)
    H[:, 0, 0] = [1e-6 - 1e-7j, -2e-6 - 5e-6j]
    Z = dynamic_stiffness(H)
    assert np.allclose(Z[:, 0, 0], 1 / H[:, 0, 0], rtol=1e-14)
    assert np.all(np.isnan(Z[:, 1, :])) and np.all(np.isnan(Z[:, :, 1]))
    full = H.copy()
    full[:, 1, 1] = 3e-7
    full[:, 0, 1] = full[:, 1, 0] = 1e-8
    assert np.allclose(dynamic_stiffness(full), np.linalg.inv(full), rtol=1e-12)
    assert len(f) == len(Z)


@pytest.mark.parametrize("section, flexible", [(MILLING_X_ONLY, 0), (TURNING_Y_ONLY, 1)])
def test_chatter_command_with_modes_in_one_direction(tmp_path, section, flexible):
    deck = tmp_path / "one.yaml"
    deck.write_text(section)
    res = CliRunner().invoke(main, ["chatter", str(deck), "-o", str(tmp_path / "out")])
    assert res.exit_code == 0, res.output
    with h5py.File(tmp_path / "out" / "chatter.h5") as f:
        g = f["chatter"]
        assert np.all(np.isfinite(g["limit_depth_m"][:])) and np.all(g["limit_depth_m"][:] > 0)
        for name in ("speed_rpm", "limit_depth_m", "chatter_frequency_hz", "boundary_kind", "method", "capped",
                     "frf/frequency_hz", "frf/receptance_m_N", "frf/dynamic_stiffness_N_m"):
            assert name in g, name
        if g.attrs["operation"] == "milling":  # auto: semi-discretization (half immersion, 2 teeth)
            assert g.attrs["method"] == "semi_discretization" and "steps_per_period" in g
            assert "stability_map" not in g and g.attrs["stability_map"].startswith("not computed")  # not asked
        H = g["frf/receptance_m_N"][:]
        Z = g["frf/dynamic_stiffness_N_m"][:]
        d = flexible
        assert np.allclose(Z[:, d, d], 1 / H[:, d, d], rtol=1e-12)
        assert np.all(np.isnan(Z[:, 1 - d, :])) and np.all(np.isnan(Z[:, :, 1 - d]))
    for png in ("chatter_lobes.png", "chatter_frf.png"):
        assert (tmp_path / "out" / png).stat().st_size > 0
