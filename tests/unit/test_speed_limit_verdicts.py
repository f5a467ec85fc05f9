"""Issue 35, item 3: where a deck has a thermal section, the lobes never recommend a speed above the spindle's
thermal speed limit nor report their minimum there, and the lobes, Campbell and unbalance figures shade those
speeds; the limit is the `thermal` command's number."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from spindlesim.chatter.pockets import stability_pockets
from spindlesim.chatter.results import LobeDiagram
from spindlesim.chatter.stability import ChatterResult
from spindlesim.output.figures import new_figure, shade_above_speed_limit

ROOT = Path(__file__).parents[2]


def _diagram() -> LobeDiagram:
    """Two pockets: a deep one at 18,000 rpm, a shallower one at 9,000 rpm; the smallest limit at 21,000 rpm."""
    n = np.linspace(6000, 24000, 181)
    L = 1e-3 * (1.0 + 2.0 * np.exp(-((n - 9000) / 300) ** 2) + 4.0 * np.exp(-((n - 18000) / 300) ** 2)
                - 0.5 * np.exp(-((n - 21000) / 500) ** 2))
    return LobeDiagram(speed_rpm=n, limit_depth_m=L, chatter_frequency_hz=np.full(len(n), 1000.0), lobes=(),
                       method="zero_order", process="milling", capped=np.zeros(len(n), bool))


def test_no_recommendation_and_no_minimum_above_the_speed_limit():
    dg = _diagram()
    free = ChatterResult(dg, (), stability_pockets(dg))
    assert free.recommendation.speed_rpm == pytest.approx(18000, abs=100)
    assert free.minimum[0] == pytest.approx(21000, abs=100)
    held = ChatterResult(dg, (), stability_pockets(dg), speed_limit_rpm=12500.0)
    assert held.recommendation.speed_rpm == pytest.approx(9000, abs=100)
    assert held.minimum[0] <= 12500.0
    none = ChatterResult(dg, (), stability_pockets(dg), speed_limit_rpm=7000.0)
    assert none.recommendation is None


def test_the_shading_starts_at_the_limit_and_names_it():
    fig = new_figure()
    ax = fig.subplots()
    ax.plot([0, 24000], [0, 1])
    ax.set_xlim(0, 24000)
    shade_above_speed_limit([ax], 12500.0)
    patches = [p for p in ax.patches]
    assert len(patches) == 1 and "12,500 rpm" in patches[0].get_label()
    ext = patches[0].get_window_extent()  # in display units: from the limit to the axis' end
    x0, x1 = ax.transData.inverted().transform([[ext.x0, 0], [ext.x1, 0]])[:, 0]
    assert np.isclose(x0, 12500.0) and np.isclose(x1, 24000.0)
    assert ax.get_xlim() == (0.0, 24000.0)


@pytest.mark.slow
def test_the_limit_the_analyses_use_is_the_thermal_commands(tmp_path):
    from click.testing import CliRunner
    import h5py

    from spindlesim.cli import main
    from spindlesim.deck import load_deck
    from spindlesim.runs.common import thermal_speed_limit

    deck = ROOT / "decks" / "milling_spindle.yaml"
    lim = thermal_speed_limit(load_deck(deck))
    res = CliRunner().invoke(main, ["thermal", str(deck), "-o", str(tmp_path / "o"), "-q"])
    with h5py.File(tmp_path / "o" / "thermal.h5") as f:
        assert tuple(f["spindle_thermal"].attrs["speed_limit_rpm"]) == pytest.approx(lim, rel=1e-12)
    assert res.exit_code == 0
