"""The embedded decks (``<name>.yaml`` data files) and which command runs which one when given no DECK."""

from ..registry import default_decks

#: command -> the embedded deck it runs when given no DECK (from the registry, spindlesim/registry.py;
#: ``commands.common.run_and_report`` loads it).  ``spindlesim decks`` lists this table, and
#: tests/cli/test_decks_command.py checks that it and the deck each command loads agree.
DEFAULT_DECKS: dict[str, str] = default_decks()


def commands_using(deck: str) -> list[str]:
    """The commands that run the embedded deck ``deck`` when given no DECK, in the table's order."""
    return [command for command, name in DEFAULT_DECKS.items() if name == deck]
