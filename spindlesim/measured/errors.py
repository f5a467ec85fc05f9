"""What the measured-data analyses raise: a bad input (exit 2, nothing run) or an analysis that finds nothing
(exit 1); spindlesim/commands/exits.py maps them."""

from __future__ import annotations

__all__ = ["MeasurementInputError", "IdentificationError"]


class MeasurementInputError(ValueError):
    """Measurements that cannot be analysed as given: a band outside the data or with too few samples, impacts of
    different rates or lengths, every impact rejected, a direction that is not x or y."""


class IdentificationError(ValueError):
    """The FRF gives no modes: no pole is stable in the band, or every stable one is computational."""
