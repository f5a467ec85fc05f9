"""`spindlesim run` without an `analyses:` list runs every analysis the deck has the sections for: its
help text names exactly that, in the order the runs table (spindlesim.runs.DEFAULT_RUN) applies."""

from __future__ import annotations

import re
from importlib import resources
from pathlib import Path

from click.testing import CliRunner

from spindlesim.cli import main
from spindlesim.deck import load_deck, parse_deck
from spindlesim.runs import DEFAULT_RUN, default_analyses

DECKS = Path(__file__).parents[2] / "decks"


def _embedded(name: str, title: bool = True) -> str:
    text = (resources.files("spindlesim.decks") / f"{name}.yaml").read_text()
    return text if title else "\n".join(line for line in text.splitlines() if not line.startswith("title:")) + "\n"


def _help_rows() -> list[tuple[str, str]]:
    text = CliRunner().invoke(main, ["run", "--help"]).output
    block = text.split("in this order:", 1)[1].split("A sweep section", 1)[0]
    return [tuple(re.split(r"\s{2,}", line.strip(), maxsplit=1)) for line in block.splitlines() if line.strip()]


def test_help_text_names_what_runs_without_an_analyses_list():
    assert _help_rows() == [(", ".join(names), needs) for names, needs in DEFAULT_RUN]


TOOLS = ("tools:\n  - {name: t, holder: {elements: [[40.0, 16.0, 50.0, 7850.0, 210.0, 80.8, 0.3, 0.0]]}, "
         "joint: {translational_N_m: 4.0e8, rotational_Nm_rad: 2.0e6}, "
         "tool: {elements: [[16.0, 0.0, 50.0, 14500.0, 580.0, 240.0, 0.22, 0.0]]}}\n")


def test_a_deck_with_every_section_runs_every_analysis_in_the_help_order():
    text = (_embedded("spindle") + "rotor_transient: {duration_s: 0.01}\n" + TOOLS
            + "".join(_embedded(n, title=False) for n in ("bearing", "dtrb", "contact", "transient")))
    loaded = parse_deck(text)
    help_names = [n for row, _ in _help_rows() for n in row.split(", ")]
    assert help_names == [n for names, _ in DEFAULT_RUN for n in names]
    # the one exception: spindle_thermal writes thermal.h5 too, and a spindle_thermal section needs rolling bearings
    # (the milling deck below): with fluid-film bearings thermal.h5 is theirs
    assert default_analyses(loaded) == [n for n in help_names if n != "spindle_thermal"]
    milling = [n for n in default_analyses(load_deck(DECKS / "milling_spindle.yaml"))]
    assert milling == [n for n in help_names if n in milling] and milling[0] == "spindle_thermal"
    assert "thermal" not in milling


def test_analyses_of_one_file_are_alternatives_the_deck_picks():
    """The thermal command (and a deck listing `thermal`) runs the spindle's thermal model on a deck with a
    spindle_thermal section, the fluid-film bearings' equilibrium on the others; `spindlesim run` runs only the
    first of them a deck with both has the sections for."""
    from spindlesim.runs import analysis_for

    milling = load_deck(DECKS / "milling_spindle.yaml")
    three_lobe = load_deck(DECKS / "seed003_three_lobe.yaml")
    assert analysis_for("thermal", milling.deck) == "spindle_thermal"
    assert analysis_for("thermal", three_lobe.deck) == "thermal"
    assert analysis_for("spindle_thermal", three_lobe.deck) == "spindle_thermal"  # asked for by name: itself
    assert analysis_for("coefficients", milling.deck) == "coefficients"
    text = milling.text.replace("  - name: rear\n", "  - {name: film, node: 2, type: plain, diameter_mm: 50.0, "
                                "width_mm: 25.0, clearance_mm: 0.05, oil: {viscosity_Pa_s: 0.01}}\n  - name: rear\n", 1)
    assert "name: film" in text
    both = parse_deck(text)
    assert analysis_for("thermal", both.deck) == "spindle_thermal"
    names = default_analyses(both)
    assert "spindle_thermal" in names and "thermal" not in names and "coefficients" in names


def test_each_rule_of_the_default():
    linear = load_deck(DECKS / "seed003_spindle_linear.yaml")
    assert default_analyses(linear) == ["static", "modal", "campbell", "frf", "unbalance"]
    three_lobe = load_deck(DECKS / "seed003_three_lobe.yaml")
    assert default_analyses(three_lobe) == ["thermal", "coefficients", "static", "modal", "campbell", "frf",
                                            "unbalance", "chatter"]
    # fluid-film bearings without load_N: thermal and coefficients load them from the rotor's statics
    plain = load_deck(DECKS / "validation" / "jeffcott_plain.yaml")
    assert default_analyses(plain)[:2] == ["thermal", "coefficients"]
    assert default_analyses(load_deck(DECKS / "seed001_dtrb_rotor.yaml"))[-1] == "transient"
    for name in ("bearing", "dtrb", "contact", "transient"):
        assert default_analyses(parse_deck(_embedded(name))) == [name]


def test_a_rotor_without_operating_runs_nothing_and_says_so(tmp_path, caplog):
    text = _embedded("spindle_linear")
    text = re.sub(r"(?ms)^operating:.*?(?=^\S)", "", text)
    assert "operating:" not in text
    assert default_analyses(parse_deck(text)) == []
    assert "no 'operating' section" in caplog.text
    deck = tmp_path / "no_operating.yaml"
    deck.write_text(text)
    res = CliRunner().invoke(main, ["run", str(deck), "-o", str(tmp_path / "out")])
    assert res.exit_code == 2, res.output
    assert "nothing to run" in res.output
    assert not (tmp_path / "out").exists()
