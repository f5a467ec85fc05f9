"""Deck sections of the studies that change deck values by key path: ``calibration:`` (``spindlesim calibrate``).

A key path walks the deck as ``sweep`` does (``sweep/cases.py``): mapping keys by name, list items by 0-based
index or, for named items (bearings, disks, tools), by their ``name``: ``tool.joint.translational_N_m``,
``bearings.front.preload.axial_um``, ``shaft.elements.4.2``.  Whether a path exists and its bounds fit the key
is checked when the study starts, against the deck (a located error naming the entry).
"""

from __future__ import annotations

from typing import Annotated, Optional

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
