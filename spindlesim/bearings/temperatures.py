"""Prescribed part temperatures of a rolling bearing in a deck (``temperatures_C``), shared by the families
whose operating preload or clearance follows from them (DTRB, cylindrical roller; the ball bearing has its
own, with shaft and housing seats: ``ball/section_thermal.py``).  Deck model only; the growth itself is each
family's (``dtrb/thermal.py``, ``roller/thermal.py``) on :mod:`spindlesim.thermal.growth_bearings`."""

from __future__ import annotations

from typing import Annotated, Optional

from pydantic import Field

from ..fields import DeckModel

PartC = Annotated[float, Field(gt=-273.15, le=2000.0)]
Expansion = Optional[Annotated[float, Field(gt=0.0, le=1e-4)]]


class PartTemperatures(DeckModel):
    """Prescribed uniform temperatures of the parts [C] (as in MESYS): the bearing is computed with the
    preload or clearance its growth gives (every part grows about the bearing centre by its own strain)."""

    inner_ring: PartC
    """Uniform temperature of the inner ring (a DTRB's cones) [C]."""
    outer_ring: PartC
    """Uniform temperature of the outer ring (a DTRB's cup) [C]."""
    rolling_elements: PartC
    """Uniform temperature of the rollers [C]."""
    reference: PartC = 20.0
    """Temperature [C] at which the geometry, the preload and the clearance are given (the cold assembly)."""

    def si(self):
        """As :class:`spindlesim.thermal.growth_bearings.BearingTemperatures`."""
        from ..thermal.growth_bearings import BearingTemperatures

        return BearingTemperatures(self.inner_ring, self.outer_ring, self.rolling_elements, self.reference)


def body(E_Pa: float, poisson: float, density_kg_m3: float, expansion_1_K: float | None):
    """Rings' and rolling elements' ``ThermoElastic`` (expansion: the deck's, else bearing steel's 11.5e-6)."""
    from ..thermal.growth import BEARING_STEEL, ThermoElastic

    alpha = BEARING_STEEL.expansion_1_K if expansion_1_K is None else expansion_1_K
    return ThermoElastic(E_Pa, poisson, density_kg_m3, alpha)
