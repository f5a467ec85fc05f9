"""Driver, deck-to-result flow and tool forms (model, sampled FRF, one per speed)."""

import numpy as np
import pytest

from spindlesim.chatter import (ChatterSection, MillingProcess, Mode, ToolPointModel, TurningProcess, build_chatter,
                                run_chatter, stability_lobes, write_frf_csv)
from spindlesim.chatter.stability import METHODS

TOOL = ToolPointModel.from_modes([Mode("x", 922.0, 0.011, 1.34e6), Mode("y", 1010.0, 0.02, 2.0e6)])


def test_auto_method_per_process():
    """auto: zero order only for a constant directional matrix (full slot, 4 teeth), semi-discretization
    for the rest; the diagram says which method produced each speed and why it was chosen."""
    speeds = np.linspace(8000, 12000, 5)
    low = MillingProcess(2, 20e-3, 1e-3, "down", 6e8, 1 / 3)
    half = MillingProcess(2, 20e-3, 10e-3, "down", 6e8, 1 / 3)
    slot4 = MillingProcess(4, 20e-3, 20e-3, "down", 6e8, 1 / 3)
    d = stability_lobes(low, TOOL, speeds, n_depths=6, steps=40)
    assert d.method == "semi_discretization" and list(d.method_per_speed) == ["semi_discretization"] * 5
    assert d.selection.startswith("auto: semi-discretization") and "fluctuates by 614 %" in d.selection
    assert stability_lobes(half, TOOL, speeds, n_depths=6).method == "semi_discretization"
    z = stability_lobes(slot4, TOOL, speeds)
    assert z.method == "zero_order" and set(z.method_per_speed) == {"zero_order"} and "constant" in z.selection
    assert stability_lobes(slot4, TOOL, speeds, "semi_discretization", n_depths=6).selection == \
        "semi-discretization (Insperger-Stepan), as requested"
    forced = stability_lobes(half, TOOL, speeds, "zero_order")
    assert forced.selection.startswith("zero order (Altintas-Budak), as requested; CAUTION")
    assert stability_lobes(TurningProcess(2e9, 1.2), TOOL, speeds).method == "oriented_frf"
    with pytest.raises(ValueError, match="does not apply"):
        stability_lobes(half, TOOL, speeds, "oriented_frf")
    assert set(METHODS) == {"oriented_frf", "zero_order", "semi_discretization"}


def test_semi_discretization_on_a_sampled_frf_fits_modes_first():
    p = MillingProcess(2, 20e-3, 20e-3, "down", 6e8, 1 / 3)
    speeds = np.array([10000.0, 16000.0])
    a = stability_lobes(p, TOOL, speeds, "semi_discretization", depth_max_m=1e-3, n_depths=10, steps=40)
    b = stability_lobes(p, TOOL.frf(np.arange(400.0, 2000.0, 0.5)), speeds, "semi_discretization",
                        depth_max_m=1e-3, n_depths=10, steps=40)
    assert np.allclose(a.limit_depth_m, b.limit_depth_m, rtol=1e-4)


def test_semi_discretization_with_a_model_per_speed():
    p = MillingProcess(2, 20e-3, 20e-3, "down", 6e8, 1 / 3)
    speeds = np.array([10000.0, 16000.0])
    models = [ToolPointModel.from_modes([Mode("x", 922.0 * (1 - 0.05 * i), 0.011, 1.34e6)]) for i in range(2)]
    d = stability_lobes(p, models, speeds, "semi_discretization", depth_max_m=1e-3, n_depths=10, steps=40)
    assert d.frf_at_each_speed
    for i, s in enumerate(speeds):
        single = stability_lobes(p, models[i], [s], "semi_discretization", depth_max_m=1e-3, n_depths=10, steps=40)
        assert d.limit_depth_m[i] == pytest.approx(single.limit_depth_m[0], rel=1e-6)


def test_deck_to_result_with_measured_file(tmp_path):
    write_frf_csv(tmp_path / "tap.csv", TOOL.frf(np.arange(300.0, 2500.0, 1.0)))
    sec = ChatterSection.model_validate({
        "operation": "milling", "speeds_rpm": {"start": 9000.0, "stop": 11000.0, "count": 3},
        "Kt_N_mm2": 600.0, "Kr": 1 / 3, "teeth": 2, "tool_diameter_mm": 20.0, "radial_depth_mm": 10.0,
        "mode": "up", "frf": {"file": {"path": "tap.csv", "format": "csv"}},
        "simulate": {"points": [{"speed_rpm": 10000.0, "depth_mm": 0.1}], "tooth_periods": 100}})
    spec = build_chatter(sec, tmp_path)
    res = run_chatter(spec)
    assert res.diagram.method == "semi_discretization" and np.all(np.isfinite(res.diagram.limit_depth_m))
    assert len(res.simulations) == 1 and res.simulations[0].stable
    rotor = build_chatter(ChatterSection.model_validate({**sec.model_dump(), "frf": "rotor", "simulate": None}))
    with pytest.raises(ValueError, match="rotor"):
        run_chatter(rotor)
    d = run_chatter(rotor, tool=lambda n: TOOL).diagram  # the lead's rotor coupling: a model per speed
    assert d.frf_at_each_speed and np.allclose(d.limit_depth_m, res.diagram.limit_depth_m, rtol=2e-3)
