"""`spindlesim contact`: deck section, HDF5 contract (DESIGN.md section 5), PNGs, bad decks."""

from pathlib import Path

import pytest
from click.testing import CliRunner

from spindlesim.commands.contact import command
from spindlesim.deck import DeckError, parse_deck

SHAFT = """shaft:
  elements:
    - [50.0, 0.0, 100.0, 7850.0, 208.0, 80.0, 0.3, 0.0]
operating:
  speed_rpm: 0
"""


def _run(args):
    return CliRunner().invoke(command, [str(a) for a in args], catch_exceptions=False)


def test_default_deck_writes_contract(tmp_path):
    h5py = pytest.importorskip("h5py")
    res = _run(["-o", tmp_path, "--nx", "32", "--ny", "64"])
    assert res.exit_code == 0, res.output
    for name in ("contact.h5", "contact_pressure.png", "contact_roller.png"):
        assert (tmp_path / name).stat().st_size > 0
    with h5py.File(tmp_path / "contact.h5") as f:
        g = f["contact"]
        x, y, p = g["x_m"][()], g["y_m"][()], g["pressure_Pa"][()]
        assert p.shape == (x.size, y.size) == (32, 64)
        for k in g:
            assert "units" in g[k].attrs
        assert g.attrs["load_N"] == pytest.approx(10e3, rel=1e-9)
        assert g.attrs["max_pressure_Pa"] == pytest.approx(p.max())
        assert g.attrs["load_N"] == pytest.approx(p.sum() * (x[1] - x[0]) * (y[1] - y[0]), rel=1e-12)
        assert "deck_sha256" in f.attrs
        assert not bool(g.attrs["edge_singular"])  # the 300 mm crown keeps the ends clear


def test_example_deck_flags_edge_singularity(tmp_path):
    h5py = pytest.importorskip("h5py")
    deck = Path(__file__).parents[2] / "decks" / "contact_roller.yaml"
    res = _run([deck, "-o", tmp_path, "--nx", "32", "--ny", "64"])
    assert res.exit_code == 0, res.output
    with h5py.File(tmp_path / "contact.h5") as f:
        a = f["contact"].attrs
        assert bool(a["edge_singular"])
        assert "singularity" in a["message"]
        # Stribeck load 4.08 * 35 kN / 14 rollers
        assert a["load_N"] == pytest.approx(4.08 * 35e3 / 14, rel=1e-9)
        assert a["max_location_m"][1] > 0  # tilt loads the +y end


def test_ball_section_and_cli_overrides(tmp_path):
    h5py = pytest.importorskip("h5py")
    deck = tmp_path / "ball.yaml"
    deck.write_text(SHAFT + "contact:\n  load_N: 1000\n  ball: {rx_mm: 5.0}\n")
    res = _run([deck, "-o", tmp_path / "out", "--nx", "64", "--ny", "64", "--load", "500"])
    assert res.exit_code == 0, res.output
    with h5py.File(tmp_path / "out" / "contact.h5") as f:
        # Hertz sphere on flat at 500 N: p0 = 4.6585 GPa * (1/2)^(1/3)
        assert f["contact"].attrs["max_pressure_Pa"] == pytest.approx(4.6585e9 * 0.5 ** (1 / 3), rel=5e-3)


@pytest.mark.parametrize("body, key", [
    ("contact:\n  load_N: 1000\n  roller_radius_mm: 5\n  crown_radius_mm: -3\n", "crown_radius_mm"),
    ("contact:\n  load_N: 1000\n  roller_radius_mm: 5\n  roler_length_mm: 10\n", "roler_length_mm"),
])
def test_bad_section_is_located(body, key):
    with pytest.raises(DeckError) as exc:
        parse_deck(SHAFT + body, "bad.yaml")
    text = "\n".join(str(i) for i in exc.value.issues)
    assert key in text and "bad.yaml:" in text


def test_section_consistency_rules():
    with pytest.raises(DeckError, match="exactly one of load_N"):
        parse_deck(SHAFT + "contact:\n  crown_radius_mm: 300\n  raceway: flat\n", "d.yaml")
    with pytest.raises(DeckError, match="needs crown_radius_mm"):
        parse_deck(SHAFT + "contact:\n  load_N: 1\n  raceway: flat\n", "d.yaml")


def test_bad_deck_exits_2_and_writes_nothing(tmp_path):
    deck = tmp_path / "bad.yaml"
    deck.write_text(SHAFT + "contact:\n  load_N: -5\n")
    res = CliRunner().invoke(command, [str(deck), "-o", str(tmp_path / "o")])
    assert res.exit_code == 2
    assert not (tmp_path / "o").exists()


def test_pressure_map_title_reads_the_load_in_newtons():
    from types import SimpleNamespace

    import numpy as np

    from spindlesim.contact.plots import pressure_map_figure

    x, y = np.linspace(-1e-4, 1e-4, 5), np.linspace(-1e-3, 1e-3, 9)
    p = np.outer(1 - (x / 1e-4) ** 2, 1 - (y / 1e-3) ** 2) * 1e9
    r = SimpleNamespace(x_m=x, y_m=y, pressure_Pa=p, edge_singular=False, max_location_m=(0.0, 0.0),
                        max_pressure_Pa=1e9, load_N=10e3)
    assert pressure_map_figure(r).axes[0].get_title() == "Contact pressure: load 10,000 N"  # old: 1e+04 N
    assert pressure_map_figure(SimpleNamespace(**{**vars(r), "load_N": 250.0})).axes[0].get_title().endswith("250 N")
