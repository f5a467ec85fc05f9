"""Every number, list and count a deck can hold is bounded (issue 16: no deck can crash, hang or exhaust memory).

The schema audit walks every model of the deck: a float needs a unit suffix with a physical range
(``spindlesim.fields.UNIT_RANGES``) or both bounds in its Field; an int needs an upper bound; a list
or mapping needs a maximum length.  A new key without limits fails here, not in a fuzzer.
"""

from __future__ import annotations

import re
import typing
from types import UnionType

import annotated_types as at
import pytest
from pydantic import BaseModel

from spindlesim.deck import DeckError, parse_deck
from spindlesim.deck.document import deck_model
from spindlesim.deck.limits import MAX_ROTOR_ELEMENTS, MAX_TRANSIENT_STEPS
from spindlesim.fields import unit_range


def _bounds(meta) -> tuple[bool, bool, bool]:
    lo = any(isinstance(m, (at.Gt, at.Ge)) for m in meta)
    hi = any(isinstance(m, (at.Lt, at.Le)) for m in meta)
    length = any(isinstance(m, at.MaxLen) for m in meta)
    return lo, hi, length


def _check(name: str, ann, meta: list, where: str, out: list[str], seen: set) -> None:
    origin = typing.get_origin(ann)
    if origin is typing.Annotated:
        base, *extra = typing.get_args(ann)
        more = []
        for e in extra:
            more += list(getattr(e, "metadata", [])) if hasattr(e, "metadata") else [e]
        _check(name, base, meta + more, where, out, seen)
        return
    if origin in (typing.Union, UnionType):
        for a in typing.get_args(ann):
            if a is not type(None):
                _check(name, a, meta, where, out, seen)
        return
    if origin is typing.Literal or ann in (bool, str, type(None), typing.Any):
        return
    lo, hi, length = _bounds(meta)
    if ann is float:
        if unit_range(name) is None and not (lo and hi):
            out.append(f"{where}: float without a unit range or both bounds")
    elif ann is int:
        if not hi:
            out.append(f"{where}: int without an upper bound")
    elif origin in (list, dict):
        if not length:
            out.append(f"{where}: {origin.__name__} without max_length")
        args = typing.get_args(ann)
        _check(name, args[-1], [], where + "[]", out, seen)
    elif isinstance(ann, type) and issubclass(ann, BaseModel):
        _walk(ann, where, out, seen)
    else:
        out.append(f"{where}: unexpected type {ann!r}")


def _walk(model: type[BaseModel], where: str, out: list[str], seen: set) -> None:
    if model in seen:
        return
    seen.add(model)
    for name, f in model.model_fields.items():
        _check(name, f.annotation, list(f.metadata), f"{model.__name__}.{name}", out, seen)


def schema_gaps() -> list[str]:
    out: list[str] = []
    _walk(deck_model(), "Deck", out, set())
    return out


def test_every_key_of_the_schema_is_bounded():
    gaps = schema_gaps()
    assert not gaps, "\n".join(gaps)


# -- hostile decks: each ends in located issues (file:line:col), quickly ----------------------------

GOOD = """title: ok
shaft:
  elements:
    - [52.6, 22.0, 28.0, 7833, 206.8, 80.0, 0.3, 0.0]
    - [57.6, 22.0, 28.0, 7833, 206.8, 80.0, 0.3, 0.0]
bearings:
  - {name: a, node: 1, type: linear, K_N_m: [[1.0e8, 0], [0, 1.0e8]]}
  - {name: b, node: 3, type: linear, K_N_m: [[1.0e8, 0], [0, 1.0e8]]}
operating:
  speed_rpm: 2170
"""


def issues(text: str) -> list[str]:
    with pytest.raises(DeckError) as exc:
        parse_deck(text, "deck.yaml")
    return [str(i) for i in exc.value.issues]


def _bomb(levels: int) -> str:
    text = "x-a0: &a0 [lol, lol, lol, lol, lol, lol, lol, lol, lol, lol]\n"
    for i in range(1, levels):
        text += f"x-a{i}: &a{i} [" + ", ".join([f"*a{i - 1}"] * 10) + "]\n"
    return text


@pytest.mark.parametrize("text,expect", [
    # RecursionError before; the project's limit or PyYAML's own (6.0.4 and later stop at 1000 levels)
    ("a: " + "[" * 5000 + "]" * 5000, re.compile(r"^deck\.yaml:1:\d+: .*nest")),
    ("title: !!int abc\n", "deck.yaml:1:8: title: cannot read 'abc' as an integer (!!int)"),
    ("title: !!python/object/apply:os.getcwd []\n", "deck.yaml:1:8: title: YAML tag !!python/object/apply:os.getcwd is not supported"),
    (_bomb(9), "the deck holds more than 250000 values (aliases expanded)"),
    ("42\n", "deck.yaml:1:1: the deck is a single value (int); it must be a mapping of sections"),
    ("- 1\n- 2\n", "deck.yaml:1:1: the deck is a list; it must be a mapping of sections"),
    ('title: ok\n"": 1\n', "deck.yaml:2:1: a key is missing before ':' (empty key)"),
    (GOOD.replace("206.8", "1e30", 1), "deck.yaml:4:32: shaft.elements[0][4]: must be <= 1e+15, got 1e+30"),
    (GOOD + "campbell:\n  speeds_rpm: {start: 0, stop: .inf, count: 10}\n", "deck.yaml:12:26: campbell.speeds_rpm.stop: Input should be a finite number"),
    (GOOD.replace("node: 3", "node: 9200000000000000000"), "deck.yaml:8:15: bearings[1].node: must be <= 100000, got 9.2e+18"),
    (GOOD.replace("speed_rpm: 2170", "speed_rpm: 1e12"), "deck.yaml:10:3: operating.speed_rpm: speed_rpm = 1e+12 is outside"),
    (GOOD + "rotor_transient:\n  record_node: 4\n  perturbation: {node: 7}\n",
     "deck.yaml:12:3: rotor_transient.record_node: node 4 is out of range: the rotor has nodes 1..3"),
    (GOOD + "rotor_transient:\n  perturbation: {node: 7}\n",
     "deck.yaml:12:18: rotor_transient.perturbation.node: node 7 is out of range"),
    ("title: ok\nshaft:\n  elements: [" + ", ".join(["[52.6, 22.0, 28.0, 7833, 206.8, 80.0, 0.3, 0.0]"] * 501) + "]\n",
     "deck.yaml:3:3: shaft.elements: List should have at most 500 items"),
    ("contact:\n  load_N: 1000\n  profile: straight\n  raceway: flat\n  grid: {nx: 4096, ny: 4096}\n",
     "deck.yaml:5:3: contact.grid: nx x ny = 16777216 cells; the limit is 131072"),
])
def test_hostile_decks_end_in_located_issues(text, expect):
    import time

    t0 = time.perf_counter()
    msgs = issues(text)
    assert time.perf_counter() - t0 < 60.0  # bounded work (exponential blow-ups take hours), not a timing
    found = (lambda m: expect.search(m)) if isinstance(expect, re.Pattern) else (lambda m: expect in m)
    assert any(found(m) for m in msgs), msgs
    assert all(m.startswith("deck.yaml:") and m.split(":")[1].isdigit() for m in msgs), msgs


def test_dtrb_work_is_bounded_before_the_roller_loops():
    from pathlib import Path

    text = (Path(__file__).parents[2] / "spindlesim/decks/dtrb.yaml").read_text()
    text = text.replace("slices: 30", "slices: 500")
    text = text.replace("count: 50}", "count: 2000}")
    msgs = issues(text)
    assert any(m.startswith("deck.yaml:") and ": dtrb: " in m and "the limit is 2e+06" in m for m in msgs), msgs


def test_long_lists_are_refused_at_their_line():
    text = GOOD + "loads: [" + ", ".join(["{node: 1, fx_N: 1}"] * 1001) + "]\n"
    assert any(m.startswith("deck.yaml:11:1: loads: List should have at most 1000 items") for m in issues(text))


def test_rotor_element_limit_counts_shaft_holder_and_tool():
    row = "[52.6, 22.0, 28.0, 7833, 206.8, 80.0, 0.3, 0.0]"
    text = ("shaft:\n  elements: [" + ", ".join([row] * 400) + "]\n"
            "tool:\n  holder: {elements: [" + ", ".join([row] * 60) + "]}\n"
            "  joint: {translational_N_m: 1.0e8, rotational_Nm_rad: 1.0e6}\n"
            "  tool: {elements: [" + ", ".join([row] * 60) + "]}\n")
    assert any(f"the rotor has 520 elements (shaft, holder and tool); the limit is {MAX_ROTOR_ELEMENTS}" in m
               for m in issues(text))


def test_transient_steps_are_bounded():
    text = GOOD + "rotor_transient:\n  duration_s: 1000\n  method: rk4\n"
    assert any(f"the limit is {MAX_TRANSIENT_STEPS:g}" in m and m.startswith("deck.yaml:12:3: rotor_transient.duration_s")
               for m in issues(text))


def test_merge_keys_and_shared_parts_work():
    text = """title: shared parts
x-row: &row [52.6, 22.0, 28.0, 7833, 206.8, 80.0, 0.3, 0.0]
x-bearing: &brg {type: linear, K_N_m: [[1.0e8, 0], [0, 1.0e8]]}
shaft:
  elements: [*row, *row]
bearings:
  - {<<: *brg, name: a, node: 1}
  - <<: [*brg]
    name: b
    node: 3
    K_N_m: [[2.0e8, 0], [0, 2.0e8]]
operating: {speed_rpm: 100}
"""
    d = parse_deck(text, "deck.yaml").deck
    assert [b.name for b in d.bearings] == ["a", "b"]
    assert d.bearings[0].K_N_m[0][0] == 1.0e8 and d.bearings[1].K_N_m[0][0] == 2.0e8  # written keys win
    assert len(d.shaft.elements) == 2
    # an error inside the shared part is reported where the part is written (line 3), under the user's path
    bad = text.replace("type: linear, K_N_m", "type: linear, colour: red, K_N_m")
    assert any(m.startswith("deck.yaml:3:") and "bearings[0].colour: unknown key" in m for m in issues(bad))


def test_an_unknown_top_level_key_is_still_an_error():
    assert any(m.startswith("deck.yaml:11:1: shared: unknown key") for m in issues(GOOD + "shared: &s {a: 1}\n"))
