"""The vocabulary of deck keys: the pydantic base model and the number types every deck section uses.

A leaf module (it imports only pydantic), so that a bearing family or the contact solver can
define its own deck section next to its physics without importing the deck loader
(docs/decisions.md, "Layers").  Key names carry their units (``length_mm``, ``E_GPa``); the
conversion to SI happens in one builder per section.

Every float is finite: ``.inf`` and ``.nan`` are refused at validation with the key's line.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import BaseModel, ConfigDict, Field


class DeckModel(BaseModel):
    """Base of every deck section: unknown keys rejected, strict types, immutable, finite floats."""

    model_config = ConfigDict(extra="forbid", frozen=True, strict=True, allow_inf_nan=False)


PositiveFloat = Annotated[float, Field(gt=0)]
NonNegFloat = Annotated[float, Field(ge=0)]
Fraction = Annotated[float, Field(ge=0.0, lt=1.0)]
NodeNumber = Annotated[int, Field(ge=1, le=100_000, description="1-based node number")]
Matrix2 = Annotated[
    list[Annotated[list[float], Field(min_length=2, max_length=2)]],
    Field(min_length=2, max_length=2),
]
Dof = Literal["x", "y", "theta_x", "theta_y"]


class Range(DeckModel):
    """An evenly spaced range ``{start, stop, count}`` (both ends included)."""

    start: NonNegFloat
    stop: PositiveFloat
    count: Annotated[int, Field(ge=2, le=1_000_000)]
