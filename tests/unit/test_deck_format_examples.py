"""The examples of docs/deck-format.md's sections load: each YAML example, put into a deck that has the rest
of what it needs (an embedded or example deck without the section the example replaces), is a valid deck."""

from __future__ import annotations

import re
from importlib import resources
from pathlib import Path

import pytest

from spindlesim.deck import parse_deck

ROOT = Path(__file__).parents[2]
GUIDE = (ROOT / "docs" / "deck-format.md").read_text(encoding="utf-8")


def _example(heading: str, n: int = 0) -> str:
    section = GUIDE.split(heading, 1)[1].split("\n## ", 1)[0]
    return re.findall(r"```yaml\n(.*?)```", section, re.S)[n]


def _without(text: str, keys: set[str]) -> str:
    """``text`` without its top-level sections ``keys``."""
    out, skip = [], False
    for line in text.splitlines():
        if re.match(r"^\S", line):
            skip = line.split(":")[0] in keys
        if not skip:
            out.append(line)
    return "\n".join(out) + "\n"


def _embedded(name: str) -> str:
    return (resources.files("spindlesim.decks") / f"{name}.yaml").read_text()


CASES = {
    "tool": lambda: _without(_embedded("milling_spindle"), {"tool"}) + _example("## Holder and tool"),
    "journal": lambda: "title: journal\n" + _example("## Rigid journal"),
    "compare_frozen_rpm": lambda: _without(_embedded("spindle_linear"), {"campbell"}) + _example("## Campbell diagram"),
    "ball entries": lambda: _without(_embedded("milling_spindle"), {"bearings"}) + _example("## Ball bearing entries"),
    "bearing section": lambda: "title: ball\n" + _example("## Ball bearing section"),
    "bearing section held": lambda: "title: ball\n" + _example("## Ball bearing section", 1),
    "roller entries": lambda: (_without(_embedded("spindle_linear"), {"bearings"})
                               + _example("## Cylindrical roller bearing entries")),
    "chatter milling": lambda: _without(_embedded("milling_spindle"), {"chatter"}) + _example("## Chatter (", 0),
    "chatter turning": lambda: "title: turning\n" + _example("## Chatter (", 1),
    "time loads": lambda: (_without((ROOT / "decks" / "validation" / "spindle_runup.yaml").read_text(),
                                    {"rotor_transient"}) + _example("### Time loads and speed ramps")),
}


@pytest.mark.parametrize("name", list(CASES))
def test_guide_example_is_a_valid_deck(name):
    loaded = parse_deck(CASES[name](), f"<deck-format: {name}>")
    assert not loaded.warnings, [str(w) for w in loaded.warnings]
