"""The semi-discretization's depth search, its cap, and the speed recommended from the diagram.

Before: the search stopped at 1.25 x min(max a_ZOA, 3 min a_ZOA): on the Insperger-Stepan slotting
benchmark (2 teeth, f_n 922 Hz, zeta 0.011, k 1.34e6 N/m, Kt 6e8, Kn 2e8 N/m^2, 20 mm; 41 speeds
5,000-25,000 rpm) that is 1.118 mm, so 24 of the 41 speeds came out NaN ("stable over the whole depth
range") where the limits reach 3.96 mm, and the summary recommended the largest value left, 1.02 mm
at 18,500 rpm, a point on a steep flank.  Now the range grows (doubling) until every speed has its
boundary or the cap (20 x the smallest zero-order limit, or the deck's depth_max_mm) is reached; the
speeds at the cap are listed; the recommendation is the middle of a stability pocket, with the
speed interval over which the limit keeps the recommended depth.  Checked against the independent
reference of tests/validation/sd_reference.py.
"""

import h5py
import numpy as np
import pytest
from click.testing import CliRunner

from spindlesim.chatter import (MillingProcess, Mode, ToolPointModel, best_pocket, stability_lobes,
                                stability_pockets)
from spindlesim.cli import main

from .sd_reference import MillingReference

FN, ZETA, MT = 922.0, 0.011, 0.03993
K1 = MT * (2 * np.pi * FN) ** 2
TOOL = ToolPointModel.from_modes([Mode("x", FN, ZETA, K1)])
SLOT = MillingProcess(2, 20e-3, 20e-3, "down", 6e8, 1 / 3)
SPEEDS = np.linspace(5000.0, 25000.0, 41)


SLOT_DECK = """
chatter:
  operation: milling
  speeds_rpm: {start: 15000, stop: 25000, count: 21}
  Kt_N_mm2: 600.0
  Kn_N_mm2: 200.0
  teeth: 2
  tool_diameter_mm: 20.0
  radial_depth_mm: 20.0
  mode: down
  frf:
    modes:
      - {direction: x, frequency_hz: 922.0, damping_ratio: 0.011, stiffness_N_m: 1.34e6}
"""


@pytest.mark.slow
def test_slotting_benchmark_has_every_boundary_and_a_robust_recommendation():
    """41 speeds: every limit found (0.319 mm at 16,000 rpm to 3.96 mm at 23,000 rpm; none capped).
    Recommended: 23,757 rpm +- 1,243 rpm at 3.56 mm (90 % of the 3.96 mm pocket, interval to the end
    of the range); the reference keeps at least that depth across the interval (3.57-3.96 mm at
    22,600, 23,757 and 24,900 rpm).  The old pick, 18,500 rpm, sits on a flank: the reference limit
    there is 1.02 mm, and 0.87 mm 1 % lower in speed."""
    d = stability_lobes(SLOT, TOOL, SPEEDS)
    assert not d.capped.any() and np.all(np.isfinite(d.limit_depth_m))
    assert np.nanmax(d.limit_depth_m) > 3.9e-3
    rec = best_pocket(stability_pockets(d))
    assert rec is not None and rec.speed_min_rpm < rec.speed_rpm < rec.speed_max_rpm
    inside = (SPEEDS >= rec.speed_min_rpm) & (SPEEDS <= rec.speed_max_rpm)
    assert np.all(d.limit_depth_m[inside] >= rec.depth_m * (1 - 1e-9))
    assert rec.tolerance_rpm >= 0.01 * rec.speed_rpm and rec.depth_m <= 0.9 * rec.peak_depth_m + 1e-12
    ref = MillingReference(2, 1.0, "down", 6e8, 2e8, FN, ZETA, K1)
    for s in (rec.speed_min_rpm + 0.05 * rec.width_rpm, rec.speed_rpm, rec.speed_max_rpm - 0.05 * rec.width_rpm):
        a, bound = ref.limit(s, 2.0 * rec.peak_depth_m, k=40, grid=40)
        assert a + bound >= 0.98 * rec.depth_m, (s, a, rec.depth_m)
    old, _ = ref.limit(18500.0, 3e-3, k=40, grid=40)
    below, _ = ref.limit(0.99 * 18500.0, 3e-3, k=40, grid=40)
    assert old == pytest.approx(1.02e-3, rel=0.01) and below < 0.9 * old  # the old pick: a steep flank


@pytest.mark.slow
def test_speeds_stable_up_to_the_cap_are_reported_and_are_stable_there(tmp_path):
    """5 % immersion up milling: at 24,000-25,000 rpm the limit exceeds the default cap, 20 x the
    smallest zero-order limit (29.8 mm): those speeds are flagged, listed in the notes, and the
    reference finds no instability below the cap there (its limit at 24,000 rpm: 34.0 mm).  A deck
    cap (depth_max_mm) replaces the default; the summary prints the capped speeds."""
    p = MillingProcess(2, 20e-3, 1e-3, "up", 6e8, 1 / 3)
    d = stability_lobes(p, TOOL, SPEEDS)
    zoa = stability_lobes(p, TOOL, SPEEDS, "zero_order")
    assert d.depth_cap_m == pytest.approx(20 * np.nanmin(zoa.limit_depth_m))  # 29.8 mm
    assert list(SPEEDS[d.capped]) == [24000.0, 24500.0, 25000.0]
    assert any("24,000-25,000 rpm" in n and "depth cap" in n for n in d.notes)
    ref = MillingReference(2, 0.05, "up", 6e8, 2e8, FN, ZETA, K1)
    for s in SPEEDS[d.capped]:
        a, _ = ref.limit(s, 1.02 * d.depth_cap_m, k=30, grid=40)
        assert a >= 0.98 * d.depth_cap_m
    for s in (22000.0, 23000.0, 23500.0):  # below the cap: 16.2 to 26.0 mm, found
        a_sd = d.limit_depth_m[SPEEDS == s][0]
        a, bound = ref.limit(s, 1.5 * a_sd, k=30, grid=40)
        assert abs(a_sd / a - 1) < 0.01 + bound / a
    deck = tmp_path / "five.yaml"
    deck.write_text(SLOT_DECK.replace("radial_depth_mm: 20.0", "radial_depth_mm: 1.0").replace("mode: down", "mode: up")
                    .replace("{start: 15000, stop: 25000, count: 21}", "{start: 22000, stop: 25000, count: 7}")
                    + "  semi_discretization: {depth_max_mm: 29.8}\n")
    res = CliRunner().invoke(main, ["chatter", str(deck), "-o", str(tmp_path / "out")])
    assert res.exit_code == 0, res.output
    assert "3 speed(s) stable up to the depth cap 29.8 mm" in res.output and "24,000-25,000 rpm" in res.output
    few = SPEEDS[-8:]
    capped = stability_lobes(p, TOOL, few, depth_max_m=10e-3, n_depths=20)
    assert capped.depth_cap_m == 10e-3 and capped.capped.sum() >= 3
    assert np.all(capped.limit_depth_m[~capped.capped] <= 10e-3)




@pytest.mark.slow
def test_summary_and_file_say_method_cap_and_recommendation(tmp_path):
    """chatter.h5 records the method per speed and why it was chosen, the cap, every pocket and the
    recommendation as attributes; the summary only reads them ("recommended: ... +- ... rpm at up
    to ... mm (stability pocket ...)"), and no longer prints a "best in range" point."""
    deck = tmp_path / "slot.yaml"
    deck.write_text(SLOT_DECK)
    res = CliRunner().invoke(main, ["chatter", str(deck), "-o", str(tmp_path / "out")])
    assert res.exit_code == 0, res.output
    assert "method: auto: semi-discretization" in res.output and "best in range" not in res.output
    assert "recommended: " in res.output and "stability pocket" in res.output
    with h5py.File(tmp_path / "out" / "chatter.h5") as f:
        g = f["chatter"]
        a = g.attrs
        assert list(g["method"].asstr()[:]) == ["semi_discretization"] * 21
        assert "fluctuates" in a["method_selection"] and a["capped_speeds"] == 0 and a["depth_cap_m"] > 0
        assert a["pocket_speed_min_rpm"] < a["recommended_speed_rpm"] < a["pocket_speed_max_rpm"]
        assert a["recommended_speed_tolerance_rpm"] == pytest.approx(
            0.5 * (a["pocket_speed_max_rpm"] - a["pocket_speed_min_rpm"]))
        n, lim = g["speed_rpm"][:], g["limit_depth_m"][:]
        inside = (n >= a["pocket_speed_min_rpm"]) & (n <= a["pocket_speed_max_rpm"])
        assert np.all(lim[inside] >= a["recommended_depth_m"] * (1 - 1e-9))
        assert len(g["pockets/depth_m"]) >= 1 and g["pockets/depth_m"][0] == pytest.approx(a["recommended_depth_m"])
        assert "stability_map" not in g and "stability map: not computed (ask with" in res.output
        summary = f"{a['recommended_speed_rpm']:,.0f} rpm +- {a['recommended_speed_tolerance_rpm']:,.0f} rpm"
    assert summary in res.output
    # with --map: the map too, and the same limits (the march and the continued brackets, to the search tolerance)
    res = CliRunner().invoke(main, ["chatter", str(deck), "--map", "-o", str(tmp_path / "map")])
    assert res.exit_code == 0, res.output
    assert "stability map: written" in res.output and (tmp_path / "map" / "chatter_stability_map.png").is_file()
    with h5py.File(tmp_path / "map" / "chatter.h5") as f:
        g = f["chatter"]
        assert np.isnan(g["stability_map/spectral_radius"][:]).any()  # evaluated up to the crossing only
        assert np.allclose(g["limit_depth_m"][:], lim, rtol=2e-4)
