"""The embedded decks (``<name>.yaml`` data files) and which command runs which one when given no DECK."""

#: command -> the embedded deck it runs when given no DECK.  The commands name their deck where they call
#: ``commands.common.load_or_default`` / ``run_and_report``; ``spindlesim decks`` lists this table, and
#: tests/cli/test_decks_command.py checks that it and the commands agree.
DEFAULT_DECKS: dict[str, str] = {
    "static": "spindle",
    "modal": "spindle",
    "campbell": "spindle",
    "frf": "spindle",
    "unbalance": "spindle",
    "thermal": "spindle",
    "coefficients": "spindle",
    "transient": "transient",
    "bearing": "bearing",
    "dtrb": "dtrb",
    "chatter": "milling_spindle",
    "contact": "contact",
    "run": "spindle",
    "sweep": "spindle",
}


def commands_using(deck: str) -> list[str]:
    """The commands that run the embedded deck ``deck`` when given no DECK, in the table's order."""
    return [command for command, name in DEFAULT_DECKS.items() if name == deck]
