"""Sweep cases: deck overrides by key path, as a grid (Cartesian product) or a list (zipped).

A path walks the deck's YAML: mapping keys by name, list items by 0-based index or,
for lists of named items (bearings, disks), by their ``name``:

    operating.speed_rpm            bearings.front.K_N_m.0.0        shaft.elements.3.2

Values: ``5,8,12`` (a list, each item read as YAML), or ``start:stop:count``
(evenly spaced; integers when start and stop are integers and the step is whole).
"""

from __future__ import annotations

import copy
import hashlib
import itertools
import json
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import yaml

from ..deck.yamlmarks import DeckLoader


@dataclass(frozen=True)
class Case:
    """One resolved case: its parameter values, the full deck text, and a hash that names it."""

    index: int
    parameters: dict[str, Any]
    deck_text: str
    analysis: str
    options: dict[str, Any] = field(default_factory=dict)

    @property
    def key(self) -> str:
        payload = json.dumps({"deck": self.deck_text, "analysis": self.analysis, "options": self.options},
                             sort_keys=True, default=str)
        return hashlib.sha256(payload.encode()).hexdigest()[:16]


def _scalar(text: str) -> Any:
    return yaml.load(text, Loader=DeckLoader)


def parse_values(text: str) -> list[Any]:
    """``a,b,c`` or ``start:stop:count``."""
    text = text.strip()
    if text.count(":") == 2 and "," not in text and not text.startswith(("[", "{")):
        a, b, n = (s.strip() for s in text.split(":"))
        start, stop, count = _scalar(a), _scalar(b), int(_scalar(n))
        if count < 1:
            raise ValueError(f"range {text!r}: count must be >= 1")
        vals = np.linspace(float(start), float(stop), count)
        if isinstance(start, int) and isinstance(stop, int) and np.allclose(vals, np.round(vals)):
            return [int(round(v)) for v in vals]
        return [float(v) for v in vals]
    return [_scalar(t) for t in _split_top_level(text)]


def _split_top_level(text: str) -> list[str]:
    """Split on commas outside brackets, so ``[[1,0],[0,1]],[[2,0],[0,2]]`` gives two matrices."""
    out, depth, cur = [], 0, ""
    for ch in text:
        if ch in "[{":
            depth += 1
        elif ch in "]}":
            depth -= 1
        if ch == "," and depth == 0:
            out.append(cur)
            cur = ""
        else:
            cur += ch
    out.append(cur)
    return [t.strip() for t in out if t.strip()]


def parse_set_option(option: str) -> tuple[str, list[Any]]:
    """``path=values`` from the command line."""
    if "=" not in option:
        raise ValueError(f"--set {option!r}: expected PATH=VALUES, e.g. operating.speed_rpm=1000:6000:11")
    path, values = option.split("=", 1)
    vals = parse_values(values)
    if not path.strip() or not vals:
        raise ValueError(f"--set {option!r}: empty path or no values")
    return path.strip(), vals


def set_path(data: Any, path: str, value: Any) -> None:
    """Set ``value`` at dotted ``path`` in the YAML data (in place); raise KeyError naming the bad part.

    A mapping the path passes through that the deck leaves out (a key with a default, e.g. a bearing's
    ``damping``) is created empty: the case's deck is validated before it runs, so a misspelt key is still
    reported there."""
    parts = path.split(".")
    cur = data
    for i, part in enumerate(parts):
        last = i == len(parts) - 1
        where = ".".join(parts[: i + 1])
        if isinstance(cur, dict):
            if last:
                cur[part] = value
                return
            if part not in cur or cur[part] is None:
                cur[part] = {}
            cur = cur[part]
        elif isinstance(cur, list):
            idx = _list_index(cur, part, where)
            if last:
                cur[idx] = value
                return
            cur = cur[idx]
        else:
            raise KeyError(f"{where}: cannot descend into a {type(cur).__name__}")


def _list_index(items: list, part: str, where: str) -> int:
    if part.lstrip("-").isdigit():
        idx = int(part)
        if not -len(items) <= idx < len(items):
            raise KeyError(f"{where}: index out of range (list has {len(items)} items)")
        return idx
    named = [i for i, it in enumerate(items) if isinstance(it, dict) and it.get("name") == part]
    if not named:
        raise KeyError(f"{where}: no item named {part!r}")
    return named[0]


def build_cases(deck_text: str, parameters: dict[str, list[Any]], analysis: str, mode: str = "grid",
                options: dict[str, Any] | None = None) -> list[Case]:
    """All cases of a sweep: the Cartesian product of the values (grid) or their zip (list)."""
    base = yaml.load(deck_text, Loader=DeckLoader)
    base.pop("sweep", None)
    names = list(parameters)
    if mode == "grid":
        combos = list(itertools.product(*(parameters[n] for n in names)))
    elif mode == "list":
        lengths = {len(parameters[n]) for n in names}
        if len(lengths) > 1:
            raise ValueError(f"list mode needs equally many values per parameter, got {sorted(lengths)}")
        combos = list(zip(*(parameters[n] for n in names)))
    else:
        raise ValueError(f"unknown sweep mode {mode!r}: grid or list")
    cases = []
    for i, combo in enumerate(combos):
        data = copy.deepcopy(base)
        for name, value in zip(names, combo):
            set_path(data, name, value)
        text = yaml.safe_dump(data, sort_keys=False, default_flow_style=None, width=120)
        cases.append(Case(i, dict(zip(names, combo)), text, analysis, dict(options or {})))
    return cases
