"""Questions about a validated deck that several layers ask (which bearings of which type, a short
description of the operating point): answered here, in the deck layer, so the layers above never look
at a deck entry's type or attributes themselves."""

from __future__ import annotations

import math
from typing import Any

#: deck types of the fluid-film bearings (the thermal and coefficients analyses)
FLUID_FILM_TYPES = ("three_lobe", "plain")


def bearing_entries(deck: Any, *types: str) -> list[tuple[int, Any]]:
    """(index in ``bearings:``, entry) of every bearing entry of one of ``types``."""
    return [(i, b) for i, b in enumerate(getattr(deck, "bearings", ()) or ()) if b.type in types]


def operating_text(deck) -> str:
    """Applied load and oil temperature of a deck, for the titles ("" when the deck gives neither)."""
    parts = []
    rig = getattr(deck, "transient", None)
    if rig is not None and deck.shaft is None and getattr(deck, "journal", None) is None:
        load = getattr(getattr(rig, "shaft", None), "radial_load_N", None)
        if load:
            parts.append(f"radial load {load:g} N")
    else:
        loads = list(getattr(deck, "loads", None) or [])
        radial = math.hypot(sum(ld.fx_N for ld in loads), sum(ld.fy_N for ld in loads))
        axial = sum(ld.fz_N for ld in loads)
        if radial or axial:
            parts.append("load " + ", ".join(f"{v:.4g} N {k}" for k, v in (("radial", radial), ("axial", axial)) if v))
        op = getattr(deck, "operating", None)
        if op is not None and getattr(op, "gravity", False):
            parts.append("gravity")
    temps = sorted({b.oil.inlet_C for _, b in bearing_entries(deck, *FLUID_FILM_TYPES)
                    if getattr(b.oil, "inlet_C", None) is not None})
    if temps:
        parts.append("oil inlet " + "/".join(f"{t:g}" for t in temps) + " degC")
    return ", ".join(parts)


def operating_range(deck) -> tuple[float, float] | None:
    """(operating speed, maximum continuous speed) [rpm] of a deck, None without an operating speed."""
    op = getattr(deck, "operating", None)
    if op is None or not op.speed_rpm:
        return None
    top = op.max_continuous_rpm if op.max_continuous_rpm is not None else op.speed_rpm
    return float(op.speed_rpm), float(max(top, op.speed_rpm))
