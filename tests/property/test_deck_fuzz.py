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

import pytest
from click.testing import CliRunner
from hypothesis import example, given, settings
from hypothesis import strategies as st

from spindlesim.cli import main

from .decks import (BOMB, NUMBER_MUTATIONS, TEXTS, assert_located, check_load, check_run, mutated_deck,
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
