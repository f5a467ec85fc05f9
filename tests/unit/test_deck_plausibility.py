"""What a new user meets: unit-mistake warnings (and --strict), "did you mean", tabs, a deck without bearings."""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner

from spindlesim.cli import main
from spindlesim.deck import DeckError, parse_deck, require_rotor
from spindlesim.deck.loader import SUPPORTED_ANALYSES

ROOT = Path(__file__).resolve().parents[2]
DECKS = sorted([*ROOT.glob("decks/*.yaml"), *ROOT.glob("decks/validation/*.yaml"), *ROOT.glob("decks/studies/*.yaml"),
                *ROOT.glob("spindlesim/decks/*.yaml")])
LINEAR = (ROOT / "decks/seed003_spindle_linear.yaml").read_text()
THREE_LOBE = (ROOT / "spindlesim/decks/spindle.yaml").read_text()


def warnings(text: str) -> list[str]:
    return [str(w) for w in parse_deck(text, "deck.yaml").warnings]


def line_of(text: str, needle: str) -> int:
    return text[:text.index(needle)].count("\n") + 1


@pytest.mark.parametrize("path", DECKS, ids=lambda p: p.relative_to(ROOT).as_posix())
def test_no_shipped_deck_triggers_a_warning(path):
    assert warnings(path.read_text()) == []


def test_a_shaft_in_metres_under_mm_keys():
    text = LINEAR.replace("[52.6, 22.0, 28.0", "[0.06, 0.02, 28.0", 1)
    n = line_of(text, "[0.06")
    assert any(w.startswith(f"deck.yaml:{n}:") and "shaft.elements[0][0]: warning: outer_dia_mm 0.06 is less than 1 mm: "
               "was it given in metres? (0.06 m = 60 mm)" in w for w in warnings(text))


def test_a_clearance_over_one_percent_of_the_journal_diameter():
    text = THREE_LOBE.replace("clearance_mm: 0.012", "clearance_mm: 12.0", 1)
    n = line_of(text, "clearance_mm: 12.0")
    assert any(w.startswith(f"deck.yaml:{n}:") and "bearings[0].clearance_mm: warning: clearance_mm 12 is 17.2 % of "
               "the journal diameter" in w for w in warnings(text))


def test_a_stiffness_below_1e5_N_per_m():
    text = LINEAR.replace("412.62e6", "412.62", 1)
    n = line_of(text, "412.62,")
    assert any(w.startswith(f"deck.yaml:{n}:") and "bearings[0].K_N_m[0][0]: warning: stiffness 412.62 N/m is below "
               "100000 N/m" in w for w in warnings(text))


def test_damping_in_the_wrong_unit():
    text = LINEAR.replace("3245.15e3", "3245.15e6", 1)
    assert any("bearings[0].C_Ns_m[0][0]: warning: damping 3.24515e+09 N s/m" in w and "is the damping in N s/m?" in w
               for w in warnings(text))


def _cli(tmp_path, text, *args):
    deck = tmp_path / "deck.yaml"
    deck.write_text(text)
    return CliRunner().invoke(main, [*args, str(deck), "-o", str(tmp_path / "out"), "-q"])


def test_warnings_exit_0_and_strict_makes_them_errors(tmp_path):
    text = LINEAR.replace("412.62e6", "412.62", 1)
    ok = _cli(tmp_path, text, "static")
    assert ok.exit_code == 0, ok.output
    assert "bearings[0].K_N_m[0][0]: warning: stiffness 412.62 N/m" in ok.stderr
    assert (tmp_path / "out" / "static.h5").exists()
    strict = _cli(tmp_path, text, "--strict", "static")
    assert strict.exit_code == 2
    assert "bearings[0].K_N_m[0][0]: stiffness 412.62 N/m" in strict.stderr  # no longer marked "warning:"
    assert "(--strict: plausibility warnings are errors); nothing was written" in strict.stderr


@pytest.mark.parametrize("old,new,expect", [
    ("operating:", "operatin:", "operatin: unknown key; did you mean 'operating'?"),
    ("speed_rpm: 2170", "sped_rpm: 2170", "operating.sped_rpm: unknown key; did you mean 'speed_rpm'?"),
    ("    type: linear\n", "    typ: linear\n", "bearings[0]: a bearing needs a type"),
    ("    K_N_m: [[412", "    k_n_m: [[412", "bearings[0].k_n_m: unknown key; did you mean 'K_N_m'?"),
    ("title:", "tilte:", "tilte: unknown key; did you mean 'title'?"),
])
def test_unknown_keys_suggest_the_closest_schema_key(old, new, expect):
    assert old in LINEAR
    with pytest.raises(DeckError) as exc:
        parse_deck(LINEAR.replace(old, new, 1), "deck.yaml")
    msgs = [str(i) for i in exc.value.issues]
    assert any(m.startswith("deck.yaml:") and expect in m for m in msgs), msgs


def test_a_tab_in_the_indentation_says_use_spaces():
    text = LINEAR.replace("\n  speed_rpm: 2170", "\n\tspeed_rpm: 2170", 1)
    n = line_of(text, "\tspeed_rpm")
    with pytest.raises(DeckError) as exc:
        parse_deck(text, "deck.yaml")
    assert str(exc.value.issues[0]) == (f"deck.yaml:{n}:1: invalid YAML: line {n} is indented with a tab; "
                                        "YAML indentation must use spaces")


def _without_bearings(text: str) -> str:
    start = text.index("\nbearings:")
    end = text.index("\noperating:")
    return text[:start] + text[end:]


@pytest.mark.parametrize("analysis", SUPPORTED_ANALYSES)
def test_a_rotor_without_bearings_is_a_deck_error(analysis):
    loaded = parse_deck(_without_bearings(LINEAR), "deck.yaml")
    with pytest.raises(DeckError) as exc:
        require_rotor(loaded, analysis)
    assert str(exc.value.issues[0]).startswith(f"deck.yaml:1:1: bearings: the {analysis} analysis needs bearings "
                                               "that hold the rotor")


@pytest.mark.parametrize("command", ["static", "modal", "frf"])
def test_a_rotor_without_bearings_exits_2_with_a_located_message(tmp_path, command):
    result = _cli(tmp_path, _without_bearings(LINEAR), command)
    assert result.exit_code == 2
    assert f"deck.yaml:1:1: bearings: the {command} analysis needs bearings" in result.stderr
    assert "singular" not in result.stderr.replace("has a singular stiffness matrix", "")
