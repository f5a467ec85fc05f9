"""A solver failure part-way through a Campbell sweep (issue 16, item 3): it names the bearing and the
speed, writes the speeds done before it marked incomplete, and exits non-zero (3)."""

from pathlib import Path

import h5py
from click.testing import CliRunner

from spindlesim.cli import main

DECK = Path(__file__).parents[2] / "decks" / "seed003_three_lobe.yaml"


def test_campbell_stops_at_the_failing_speed_and_says_where(tmp_path):
    # the seed 003 spindle on plain journals: their film overheats (no thermal equilibrium below
    # 250 C) between 19,000 and 20,000 rpm
    text = DECK.read_text().replace("type: three_lobe", "type: plain")
    text = "\n".join(ln for ln in text.splitlines() if "preload: 0.5" not in ln and "lobes: {count" not in ln)
    deck = tmp_path / "plain.yaml"
    deck.write_text(text + "\n")
    res = CliRunner().invoke(main, ["campbell", str(deck), "--speeds", "12000:30000:4", "-o", str(tmp_path / "o")])
    assert res.exit_code == 3, res.output
    assert "bearing 'rear' at 24000 rpm" in res.output or "bearing 'front' at 24000 rpm" in res.output, res.output
    with h5py.File(tmp_path / "o" / "campbell.h5") as f:
        assert not f.attrs["complete"]
        assert "stopped at 24000 rpm" in f.attrs["incomplete_reason"]
        assert list(f["campbell/speed_rpm"][:]) == [12000.0, 18000.0]


def test_rest_is_left_out_for_a_fluid_film_rotor(tmp_path):
    """`campbell --speeds 0:...` on a fluid-film deck: a film carries no load at 0 rpm, so that speed
    is left out with a warning and the diagram starts at the first positive speed (exit 0, complete)."""
    out = tmp_path / "out"
    r = CliRunner().invoke(main, ["campbell", "--speeds", "0:2000:3", "-o", str(out)])
    assert r.exit_code == 0, r.output
    with h5py.File(out / "campbell.h5") as f:
        assert list(f["campbell/speed_rpm"][:]) == [1000.0, 2000.0]
        assert bool(f.attrs["complete"])
