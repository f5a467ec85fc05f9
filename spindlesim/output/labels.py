"""Words for the engine's keys on figures and in summaries (no physics).

A transient names its characteristic frequencies ``<bearing>.<kind>`` (``front.roller_pass``); a reader
sees "roller pass (front)", or "roller pass" when the run has one bearing (the transient rig's only
bearing is called "bearing" internally: no name to show).
"""

from __future__ import annotations

from typing import Iterable

_KINDS = {"roller_pass": "roller pass", "ball_pass_outer": "ball pass (outer race)", "cage": "cage"}


def frequency_label(key: str, bearing_names: Iterable[str] = ()) -> str:
    """``front.roller_pass`` -> ``roller pass (front)``; without the bearing's name on a one-bearing run."""
    owner, dot, kind = key.rpartition(".")
    words = _KINDS.get(kind, kind.replace("_", " "))
    if not dot or len(set(bearing_names)) <= 1:
        return words
    return f"{words} ({owner})"


def bearing_label(name: str, bearing_names: Iterable[str] = ()) -> str:
    """"bearing 'front'" on a run with several bearings, "bearing" on a one-bearing run."""
    return "bearing" if len(set(bearing_names)) <= 1 else f"bearing {name!r}"


def readable_keys(text: str, bearing_names: Iterable[str]) -> str:
    """``text`` (an engine's note) with every ``<bearing>.<kind>`` key in words (:func:`frequency_label`)."""
    names = list(bearing_names)
    for name in names:
        for kind in _KINDS:
            text = text.replace(f"{name}.{kind}", frequency_label(f"{name}.{kind}", names))
    return text
