"""`spindlesim decks` says which command runs which embedded deck when given no DECK, and that table
(spindlesim/decks/__init__.py) agrees with what the commands load."""

from __future__ import annotations

from importlib import resources

import pytest
from click.testing import CliRunner

import spindlesim.deck
from spindlesim.cli import COMMANDS, main
from spindlesim.decks import DEFAULT_DECKS, commands_using
from spindlesim.registry import file_commands

EMBEDDED = sorted(p.name[:-5] for p in resources.files("spindlesim.decks").iterdir() if p.name.endswith(".yaml"))


class _Asked(Exception):
    """Raised by the stand-in for ``default_deck``: the name a command asked for."""


def _asked(name: str = "spindle"):
    raise _Asked(name)


def test_every_command_that_takes_a_deck_has_a_default_in_the_table():
    assert set(DEFAULT_DECKS) == set(COMMANDS) - {"decks", "schema"} - set(file_commands())
    assert set(DEFAULT_DECKS.values()) <= set(EMBEDDED)


@pytest.mark.parametrize("command", list(DEFAULT_DECKS))
def test_the_table_names_the_deck_the_command_loads(command, monkeypatch, tmp_path):
    monkeypatch.setattr(spindlesim.deck, "default_deck", _asked)
    res = CliRunner().invoke(main, [command, "-o", str(tmp_path)])
    assert isinstance(res.exception, _Asked), res.output
    assert res.exception.args[0] == DEFAULT_DECKS[command]


def test_decks_lists_each_deck_with_the_commands_that_use_it():
    res = CliRunner().invoke(main, ["decks"])
    assert res.exit_code == 0, res.output
    lines = res.output.splitlines()
    for name in EMBEDDED:
        i = next(k for k, line in enumerate(lines) if line.split()[0] == name)
        users = commands_using(name)
        expected = f"default of: {', '.join(users)}" if users else "example (no command's default)"
        assert lines[i + 1].strip() == expected
    assert "default of: chatter" in res.output and "example" in res.output
