"""Deck sections of the studies that change deck values by key path: ``calibration:`` (``spindlesim calibrate``)
and ``optimize:`` (``spindlesim optimize``).

A key path walks the deck as ``sweep`` does (``sweep/cases.py``): mapping keys by name, list items by 0-based
index or, for named items (bearings, disks, tools), by their ``name``: ``tool.joint.translational_N_m``,
``bearings.front.preload.axial_um``, ``shaft.elements.4.2``.  Whether a path exists and its bounds fit the key
is checked when the study starts, against the deck (a located error naming the entry).
"""

from __future__ import annotations

from typing import Annotated, Optional, Union

from pydantic import Field, model_validator

from ..chatter.section import FrfFileEntry
from ..fields import AnyNumber, DeckModel, NodeNumber, NonNegFloat, PositiveFloat


class Measurement(DeckModel):
    """A measured direct FRF (response and force at the same node and direction), e.g. a tap test."""

    file: FrfFileEntry
    """The measured FRF file (the chatter section's `file:` form: path, format csv or uff, direction x or y); a
    single direction is fitted, so give `direction` for a file that holds both."""
    node: NodeNumber
    """Node the FRF was measured at (response and force, direct): a node of the rotor, e.g. the tool tip."""
    speed_rpm: NonNegFloat = 0.0
    """Spindle speed during the measurement (0: a tap test at rest)."""


class CalibrationParameter(DeckModel):
    """A deck value the calibration fits, with its bounds (in the unit of the key it sets)."""

    path: Annotated[str, Field(min_length=1, max_length=500)]
    """Deck key path of the value, as `sweep` writes it: tool.joint.translational_N_m, bearings.front.K_N_m.0.0,
    shaft.elements.3.2 (mapping keys, list indices from 0, or the name of a named item)."""
    min: AnyNumber
    """Lower bound of the value (the key's unit). With min > 0 and max / min >= 10 the fit works on the
    logarithm of the value."""
    max: AnyNumber
    """Upper bound of the value (the key's unit); greater than min."""


class CalibrationSection(DeckModel):
    """Calibration of deck values to measured FRFs (`spindlesim calibrate`): bounded nonlinear least squares on
    the complex receptance, starting from the deck's values; writes calibrated.yaml and calibration.h5."""

    measurements: Annotated[list[Measurement], Field(min_length=1, max_length=50)]
    """The measured FRFs, each with the node (and speed) it was measured at."""
    parameters: Annotated[list[CalibrationParameter], Field(min_length=1, max_length=20)]
    """The deck values fitted, each a key path with its bounds."""
    band_hz: Optional[Annotated[list[PositiveFloat], Field(min_length=2, max_length=2)]] = None
    """[low, high]: only the measured frequencies in this band are fitted. None: every measured frequency."""
    max_evaluations: Annotated[int, Field(ge=10, le=100_000)] = 400
    """Most model evaluations the fit may spend (finite-difference Jacobians included) before it stops
    unconverged."""

    @model_validator(mode="after")
    def _band(self) -> "CalibrationSection":
        if self.band_hz is not None and not self.band_hz[0] < self.band_hz[1]:
            raise ValueError("band_hz: the low end must be below the high end")
        return self


# ---- optimize: (spindlesim optimize) ----------------------------------------------------------------------

#: a value a discrete variable may take: a number or a word (e.g. a preload kind)
Choice = Union[AnyNumber, Annotated[str, Field(min_length=1, max_length=100)]]


class TiedPath(DeckModel):
    """A deck value moved with a variable: its deck value plus factor times the variable's change."""

    path: Annotated[str, Field(min_length=1, max_length=500)]
    """Deck key path of the tied value (as `sweep` writes it)."""
    factor: AnyNumber = 1.0
    """Change of the tied value per unit change of the variable: -1 keeps the sum of the two (a node moved
    between two elements, the shaft's length kept), 1 keeps them equal."""


class OptimizeVariable(DeckModel):
    """A deck value the optimisation chooses: continuous between min and max, or one of `values`."""

    path: Annotated[str, Field(min_length=1, max_length=500)]
    """Deck key path of the value, as `sweep` writes it: bearings.front.preload.axial_um, shaft.elements.4.2."""
    min: Optional[AnyNumber] = None
    """Lower bound of a continuous variable (the key's unit)."""
    max: Optional[AnyNumber] = None
    """Upper bound of a continuous variable (the key's unit); greater than min."""
    values: Optional[Annotated[list[Choice], Field(min_length=2, max_length=100)]] = None
    """The values a discrete variable chooses from (instead of min and max), e.g. contact angles [15, 25]."""
    tied: Annotated[list[TiedPath], Field(max_length=20)] = []
    """Deck values moved with this one (each its deck value + factor x the variable's change); continuous
    variables only."""

    @model_validator(mode="after")
    def _kind(self) -> "OptimizeVariable":
        if self.values is None and (self.min is None or self.max is None):
            raise ValueError("give min and max (a continuous variable) or values (a discrete one)")
        if self.values is not None and (self.min is not None or self.max is not None):
            raise ValueError("give either min and max or values, not both")
        if self.values is not None and self.tied:
            raise ValueError("tied values follow a continuous variable (min and max), not a discrete one")
        return self


ResultName = Annotated[str, Field(min_length=1, max_length=100)]


class OptimizeObjective(DeckModel):
    """One objective: `maximize: NAME` or `minimize: NAME`, a named result (docs/deck-format.md, optimize)."""

    maximize: Optional[ResultName] = None
    """A named result to make as large as possible."""
    minimize: Optional[ResultName] = None
    """A named result to make as small as possible."""

    @model_validator(mode="after")
    def _one(self) -> "OptimizeObjective":
        if (self.maximize is None) == (self.minimize is None):
            raise ValueError("give one of maximize: NAME or minimize: NAME")
        return self


class OptimizeConstraint(DeckModel):
    """A named result held within bounds: min, max or both."""

    name: ResultName
    """The named result (docs/deck-format.md, optimize)."""
    min: Optional[AnyNumber] = None
    """The smallest value allowed (the result's unit)."""
    max: Optional[AnyNumber] = None
    """The largest value allowed (the result's unit)."""

    @model_validator(mode="after")
    def _bound(self) -> "OptimizeConstraint":
        if self.min is None and self.max is None:
            raise ValueError("give min, max or both")
        if self.min is not None and self.max is not None and not self.min < self.max:
            raise ValueError("max must be greater than min")
        return self


class OptimizeSection(DeckModel):
    """Design optimisation over deck values (`spindlesim optimize`): one objective, an optimum; two or three, a
    Pareto front; named results as objectives and constraints, each computed by the existing analyses at the
    deck's operating speed; writes optimize.h5 and optimized.yaml (pareto/ for a front)."""

    variables: Annotated[list[OptimizeVariable], Field(min_length=1, max_length=20)]
    """The deck values chosen, each a key path with bounds or a list of values."""
    objectives: Annotated[list[OptimizeObjective], Field(min_length=1, max_length=3)]
    """One objective (an optimum) or two or three (a Pareto front)."""
    constraints: Annotated[list[OptimizeConstraint], Field(max_length=20)] = []
    """Named results held within bounds (a design outside is infeasible)."""
    budget: Annotated[int, Field(ge=4, le=100_000)] = 200
    """The most evaluations (designs analysed) the study spends."""
    seed: Annotated[int, Field(ge=0, le=2**31 - 1)] = 1
    """Seed of the random choices of the global and evolutionary methods (the same seed: the same study)."""
