"""Every number, list and count a deck can hold is bounded (issue 16: no deck can crash, hang or exhaust memory).

The schema audit walks every model of the deck: a float needs a unit suffix with a physical range
(``spindlesim.fields.UNIT_RANGES``) or both bounds in its Field; an int needs an upper bound; a list
or mapping needs a maximum length.  A new key without limits fails here, not in a fuzzer.
"""

from __future__ import annotations

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
