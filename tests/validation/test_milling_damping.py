"""The milling deck with its ball sets' damping (issue 30 item 4): no mode below 0.2 % damping at the deck
speed and over the Campbell range, the axial mode at beta omega / 2; zero beta brings back the undamped axial
mode; a sweep reaches beta by its key path."""

from pathlib import Path

import numpy as np
import pytest

from spindlesim.analysis.campbell import solve_campbell
from spindlesim.analysis.modal import solve_modal
from spindlesim.deck import load_deck, parse_deck
from spindlesim.model.build import build_rotor
from spindlesim.sweep import build_cases, run_sweep

MILLING = str(Path(__file__).parents[2] / "decks" / "milling_spindle.yaml")
FLOOR = 0.002


def _rotor(text=None):
    return build_rotor((load_deck(MILLING) if text is None else parse_deck(text)).deck)


def test_no_mode_of_the_milling_deck_below_the_floor_and_the_axial_mode_at_beta_omega_over_2():
    m = solve_modal(_rotor(), n_modes=8)  # the deck speed, 18000 rpm, the 8 modes of `spindlesim modal`
    assert m.damping_ratio.min() >= FLOOR
    axial = list(m.whirl).index("axial")
    # the axial mode lives in the ball sets' axial stiffness: zeta = beta omega / 2 within 1 %
    assert m.damping_ratio[axial] == pytest.approx(1.0e-5 * 2 * np.pi * m.frequency_hz[axial] / 2, rel=0.01)


@pytest.mark.slow
def test_no_mode_below_the_floor_over_the_campbell_range():
    c = solve_campbell(_rotor(), np.linspace(0.0, 24000.0, 7), n_modes=8)
    assert not c.incomplete_reason
    assert np.nanmin(c.damping_ratio) >= FLOOR


def test_zero_beta_is_the_undamped_bearing_of_before():
    text = open(MILLING).read()
    for pre in ("    preload: {kind: position, axial_um: 15.0}\n", "    preload: {kind: spring, axial_N: 300.0}\n"):
        text = text.replace(pre, pre + "    damping: {stiffness_proportional_s: 0.0}\n")
    m = solve_modal(_rotor(text), n_modes=8)
    axial = list(m.whirl).index("axial")
    assert m.damping_ratio[axial] < 1e-4  # only the tool joints' damping reaches it (1.5e-5 before issue 30)


@pytest.mark.slow
def test_sweep_over_the_damping_key(tmp_path):
    path = "bearings.front.damping.stiffness_proportional_s"
    cases = build_cases(open(MILLING).read(), {path: [0.5e-5, 2.0e-5]}, "modal", options={"plots": False})
    for case, beta in zip(cases, (0.5e-5, 2.0e-5)):
        front = parse_deck(case.deck_text).deck.bearings[0]
        assert front.name == "front" and front.damping.stiffness_proportional_s == beta
    res = run_sweep(cases, tmp_path, workers=1)
    assert [r["status"] for r in res.records] == ["done", "done"]
    zeta = [r["scalars"]["modal/zeta1"] for r in res.records]
    assert zeta[1] > 2.0 * zeta[0] > 0.0  # the axial mode (mode 1) follows the front pair's beta
