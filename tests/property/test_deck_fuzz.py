"""Property tests: no deck, however broken or hostile, crashes, hangs or exhausts the loader or a cheap analysis.

Each test states what it checks in its name; the oracle is tests/property/decks.py (check_load, check_run):
a deck loads or fails with located issues only (``file:line:col: ...``, never an empty key), within
PARSE_SECONDS; the static and modal analyses of a loaded deck end with exit code 0, 1 (a reported
error with a message) or 2 (a located deck error), within RUN_SECONDS.  The number of examples comes
from the Hypothesis profile (tests/property/conftest.py: ``SPINDLESIM_FUZZ=fuzz`` for ``make fuzz``).
"""

from __future__ import annotations

import tempfile
from pathlib import Path

import yaml

import pytest
from click.testing import CliRunner
from hypothesis import example, given, settings
from hypothesis import strategies as st

from spindlesim.cli import main

from .decks import (BOMB, NUMBER_MUTATIONS, ROOT, TEXTS, assert_located, check_load, check_run, mutated_deck,
                    schema_deck, text_mutated_deck)

#: share of the profile's examples for the tests that run analyses (up to a few seconds each)
_RUN_SHARE = 0.4


def _fewer(share: float):
    return settings(max_examples=max(3, int(settings().max_examples * share)))


@given(mutated_deck())
@example("a: " + "[" * 5000 + "]" * 5000)
@example("title: !!int abc\n")
@example(BOMB + "x-boom: [" + ", ".join(["*l8"] * 10) + "]\n")
@example("42\n")
@example("- 1\n- 2\n")
@example('"": 1\n')
@example("title: x\nshaft:\n\telements: []\n")
def test_mutated_example_decks_load_or_fail_located(text):
    check_load(text)


@given(text_mutated_deck())
def test_example_decks_with_text_damage_load_or_fail_located(text):
    check_load(text)


@given(schema_deck())
def test_schema_generated_decks_load_or_fail_located(text):
    check_load(text)


@_fewer(_RUN_SHARE)
@given(st.one_of(mutated_deck(data_mutations=(1, 2), text_mutation=False, kinds=NUMBER_MUTATIONS, rotor_only=True),
                 mutated_deck(data_mutations=(1, 2), text_mutation=False, rotor_only=True), schema_deck()))
def test_static_and_modal_of_loaded_decks_end_in_exit_0_1_or_2(text):
    loaded = check_load(text)
    if loaded is None:
        return
    with tempfile.TemporaryDirectory() as tmp:
        for name in ("static", "modal"):
            assert check_run(name, loaded, Path(tmp) / name) in (0, 1, 2)


@_fewer(_RUN_SHARE)
@given(st.one_of(mutated_deck(), st.binary(max_size=200)), st.sampled_from(["static", "modal"]))
@example(b"\xff\xfe\x00garbage", "static")
def test_command_line_exit_code_is_0_1_or_2_with_a_message(content, command):
    with tempfile.TemporaryDirectory() as tmp:
        deck = Path(tmp) / "deck.yaml"
        deck.write_bytes(content if isinstance(content, bytes) else content.encode("utf-8", "surrogatepass"))
        result = CliRunner().invoke(main, [command, str(deck), "-o", str(Path(tmp) / "out"), "-q"])
    assert result.exit_code in (0, 1, 2), (result.exit_code, result.output, result.exception)
    assert result.exception is None or isinstance(result.exception, SystemExit), repr(result.exception)
    if result.exit_code == 2:
        issues = [line for line in result.stderr.splitlines() if line.startswith(str(deck))]
        assert issues, result.stderr
        for line in issues:
            assert_located(line)
    elif result.exit_code == 1:
        assert result.stderr.strip(), "exit code 1 without a message"


@pytest.mark.parametrize("name", sorted(TEXTS))
def test_every_example_deck_loads(name):
    """The mutations start from valid decks: each example loads as it is."""
    assert check_load(TEXTS[name], name) is not None


# --- issue 33, item 1: the defect kinds the fuzzer found last round, each a property of its own ---

@given(st.sampled_from(["title", "shaft", "bearings", "x"]), st.sampled_from(["\n", "\t", "\r", "\x0b", " "]),
       st.booleans())
@example("title", "\n", True)
def test_a_key_with_a_control_character_is_shown_escaped_on_one_line(key, char, at_end):
    odd = key + char if at_end else char + key
    text = f"{yaml.safe_dump({odd: 1}).strip()}\ntitle: t\n"
    loaded = check_load(text)
    if loaded is None:  # refused: check_load verified every issue is located; each is one line
        from spindlesim.deck import DeckError, parse_deck

        try:
            parse_deck(text, "fuzz.yaml")
        except DeckError as exc:
            for issue in exc.issues:
                assert "\n" not in str(issue) and "\r" not in str(issue), repr(str(issue))


@given(st.sampled_from(["outer_dia_mm", "length_mm"]),
       st.floats(min_value=1e-300, max_value=9.9e-4, allow_subnormal=False))
@example("outer_dia_mm", 1e-300)
@example("length_mm", 1e-300)
def test_a_vanishing_element_is_a_deck_error_and_no_warning_escapes(column, value):
    text = TEXTS["decks/seed003_spindle_linear.yaml"]
    row = "- [52.6, 22.0, 28.0,"
    assert row in text
    new = {"outer_dia_mm": f"- [{value!r}, 0.0, 28.0,", "length_mm": f"- [52.6, 22.0, {value!r},"}[column]
    with tempfile.TemporaryDirectory() as tmp:
        deck = Path(tmp) / "deck.yaml"
        deck.write_text(text.replace(row, new, 1))
        result = CliRunner().invoke(main, ["static", str(deck), "-o", str(Path(tmp) / "out")])
    assert result.exit_code == 2, result.output
    assert "Warning" not in result.output and "RuntimeWarning" not in result.output, result.output
    assert "the smallest a beam element may be" in result.output


@given(st.sampled_from(["dir", "socket", "fifo"]))
def test_a_deck_path_that_is_not_a_file_is_one_located_line(kind):
    import os
    import socket

    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "deck"
        if kind == "dir":
            path.mkdir()
        elif kind == "socket":
            s = socket.socket(socket.AF_UNIX)
            s.bind(str(path))
            s.close()
        else:
            os.mkfifo(path)
        result = CliRunner().invoke(main, ["modal", str(path), "-o", str(Path(tmp) / "out")])
    assert result.exit_code == 2, result.output
    lines = [ln for ln in result.output.splitlines() if ln.startswith(str(path))]
    assert len(lines) == 1 and "Usage" not in result.output, result.output
    assert_located(lines[0])


@_fewer(0.1)
@given(st.floats(min_value=1.01e10, max_value=1.7e308, allow_subnormal=False) | st.just(float("inf")))
@example(1.8e308)
def test_a_sweep_value_outside_its_keys_range_stops_every_case_before_one_runs(value):
    with tempfile.TemporaryDirectory() as tmp:
        deck = ROOT / "decks" / "studies" / "seed001_crowning.yaml"
        out = Path(tmp) / "out"
        result = CliRunner().invoke(main, ["sweep", str(deck), "--set",
                                           f"bearings.dtrb.geometry.crown_radius_mm=1300,{value!r}", "-o", str(out)])
        assert result.exit_code == 2, result.output
        assert "crown_radius_mm" in result.output
        assert not (out / "cases").exists()
