"""Issue 33, item 3: numbers the texts quote that the code computes are held to it, so that a change of model
cannot leave them behind.  Each entry: a file, the sentence's pattern with the numbers as groups, and what the
code gives for them (docs/validation.md names the test or the command behind each of its other numbers)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from spindlesim.deck import load_deck

ROOT = Path(__file__).parents[2]


def _numbers(path: Path, pattern: str) -> list[float]:
    text = " ".join(line.lstrip("# ").strip() for line in path.read_text().splitlines())
    m = re.search(pattern, text)
    assert m, f"{path.name}: the sentence {pattern!r} is gone (update this test with the text)"
    return [float(g.replace(",", "")) for g in m.groups()]


@pytest.mark.slow
@pytest.mark.parametrize("deck", ["decks/milling_spindle.yaml", "decks/tool_library.yaml",
                                  "spindlesim/decks/milling_spindle.yaml"])
def test_the_milling_decks_thermal_speed_limit_is_the_codes(deck):
    from spindlesim.runs.common import thermal_speed_limit

    lo, hi = _numbers(ROOT / deck, r"stable up to ([\d,]+) rpm and runs away from ([\d,]+) rpm")
    assert thermal_speed_limit(load_deck(ROOT / deck)) == pytest.approx((lo, hi), abs=0.5)
