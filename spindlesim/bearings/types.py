"""The table of bearing types: deck ``type`` -> (deck model of one ``bearings:`` entry, builder).

One explicit table (no registries filled as a side effect of imports).  A builder is the one
place where a family's deck keys become SI; it returns an object that follows the bearing
contract (``bearings/base.py``).  Only pydantic models are imported here; a family's physics is
imported by its builder when a rotor is built, so loading a deck stays light.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable

from pydantic import BaseModel

from .ball import section as ball
from .dtrb import section as dtrb
from .fluidfilm import section as fluidfilm
from .linear import section as linear
from .roller import section as roller


def _unplaced(entry: Any, node_z_m: float, shaft_z_m: tuple[float, float]) -> Any:
    return entry


@dataclass(frozen=True)
class BearingType:
    entry: type[BaseModel]  # deck model of one entry; its ``type`` literal is the tag
    build: Callable[[Any], Any]  # deck entry -> bearing (SI)
    summary: str
    #: (entry, z of its node [m], (z_min, z_max) of the shaft [m]) -> entry with the keys that depend on
    #: where the bearing sits resolved (a spring-preloaded ball set's outboard side)
    placed: Callable[[Any, float, tuple[float, float]], Any] = _unplaced


BEARING_TYPES: dict[str, BearingType] = {
    "linear": BearingType(linear.LinearEntry, linear.build, "stiffness and damping coefficients (optionally per speed)"),
    "three_lobe": BearingType(fluidfilm.ThreeLobeBearing, fluidfilm.build,
                              "n-lobe fluid-film bearing (Reynolds equation, thermal equilibrium)"),
    "plain": BearingType(fluidfilm.PlainBearing, fluidfilm.build,
                         "plain fluid-film journal bearing (360 deg or grooved)"),
    "roller": BearingType(roller.RollerEntry, roller.build,
                          "cylindrical roller bearing, rigid or flexible outer race (Jung et al. 2007)"),
    "ball": BearingType(ball.BallBearingEntry, ball.build,
                        "angular-contact / deep-groove ball bearing or set, quasi-static with speed effects (Jones 1960)",
                        ball.placed),
    "dtrb": BearingType(dtrb.DtrbBearingEntry, dtrb.build,
                        "double-row tapered roller bearing, quasi-static (Kim et al. 2023)"),
}
