"""Issue 35, item 6: `--strict` after the subcommand, `sweep` without a deck runs a study of its own, no empty
output folder after a failure, damping-only entries without a "0, 0" reaction, no "-0.0" angle."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner

from spindlesim.cli import main
from spindlesim.deck import default_deck
from spindlesim.decks import DEFAULT_DECKS
from spindlesim.output.bearing_summary import _deg

ROOT = Path(__file__).parents[2]


def _warned_deck(tmp_path) -> Path:
    """The linear seed 003 deck with a joint-free plausibility warning: a bearing stiffness that looks like N/mm."""
    text = (ROOT / "decks" / "seed003_spindle_linear.yaml").read_text().replace("412.62e6", "412.62", 1)
    p = tmp_path / "warned.yaml"
    p.write_text(text)
    return p


def test_strict_after_the_subcommand_is_the_same_as_before_it(tmp_path):
    deck = _warned_deck(tmp_path)
    plain = CliRunner().invoke(main, ["modal", str(deck), "-o", str(tmp_path / "a"), "-q"])
    assert plain.exit_code == 0 and "warning" in plain.output
    before = CliRunner().invoke(main, ["--strict", "modal", str(deck), "-o", str(tmp_path / "b")])
    after = CliRunner().invoke(main, ["modal", str(deck), "--strict", "-o", str(tmp_path / "c")])
    assert before.exit_code == after.exit_code == 2, (before.output, after.output)
    assert "--strict" in after.output


def test_sweep_without_a_deck_has_a_study_to_run():
    assert DEFAULT_DECKS["sweep"] != "spindle"
    loaded = default_deck(DEFAULT_DECKS["sweep"])
    assert loaded.deck.sweep is not None and loaded.deck.sweep.parameters


def test_a_failed_command_leaves_no_empty_output_folder(tmp_path):
    out = tmp_path / "new" / "deeper"
    res = CliRunner().invoke(main, ["chatter", str(ROOT / "decks" / "seed003_spindle_linear.yaml"), "-o", str(out)])
    assert res.exit_code == 2
    assert not (tmp_path / "new").exists()


def test_damping_only_entries_have_no_reaction_line(tmp_path):
    text = (ROOT / "decks" / "seed003_spindle_linear.yaml").read_text().replace("operating:\n", (
        "  - {name: damper, node: 10, type: linear, K_N_m: [[0.0, 0.0], [0.0, 0.0]], "
        "C_Ns_m: [[500.0, 0.0], [0.0, 500.0]]}\noperating:\n"), 1)
    deck = tmp_path / "d.yaml"
    deck.write_text(text)
    res = CliRunner().invoke(main, ["static", str(deck), "-o", str(tmp_path / "o")])
    assert res.exit_code == 0, res.output
    assert "bearing damper" not in res.output
    assert "damper: damping only (no stiffness, no static reaction)" in res.output


def test_angles_never_print_minus_zero():
    assert _deg(-0.0) == "0.0" and _deg(-0.04) == "0.0" and _deg(-0.06) == "-0.1" and _deg(14.96) == "15.0"
