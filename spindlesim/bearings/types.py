"""The table of bearing types: deck ``type`` -> what the family answers for itself.

One explicit table (no registries filled as a side effect of imports).  A row holds the deck model of one
``bearings:`` entry and its builder (the one place where a family's deck keys become SI; it returns an object
that follows the bearing contract, ``bearings/base.py``), and what the layers above ask of a deck entry
without asking which family it is: whether it acts on x and y only, whether it holds the rotor axially, its
plausibility checks, whether and how it enters the spindle's thermal network.  The functions below the table
are how they ask (``deck/loader.py``, ``deck/plausibility.py``, ``model/thermal.py``; tests/unit/
test_family_switches.py fails for a switch on the family anywhere else).  Only pydantic models are imported
here; a family's physics is imported by its builder and hooks when they run, so loading a deck stays light.
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


Found = list[tuple[tuple[Any, ...], str]]


def _unplaced(entry: Any, node_z_m: float, shaft_z_m: tuple[float, float]) -> Any:
    return entry


def _never(entry: Any) -> bool:
    return False


def _nothing(entry: Any, at: tuple) -> Found:
    return []


def _admitted(entry: Any) -> str | None:
    return None


def _no_checks(entry: Any) -> Found:
    return []


@dataclass(frozen=True)
class BearingType:
    entry: type[BaseModel]  # deck model of one entry; its ``type`` literal is the tag
    build: Callable[[Any], Any]  # deck entry -> bearing (SI)
    summary: str
    #: (entry, z of its node [m], (z_min, z_max) of the shaft [m]) -> entry with the keys that depend on
    #: where the bearing sits resolved (a spring-preloaded ball set's outboard side)
    placed: Callable[[Any, float, tuple[float, float]], Any] = _unplaced
    #: its entries act on x and y only (no tilt or axial stiffness): two of them at one node let the shaft tilt
    radial_only: bool = False
    #: entry -> whether it holds the rotor axially (an axial load needs one that does)
    holds_axially: Callable[[Any], bool] = _never
    #: (entry, its key path) -> likely unit mistakes [(key path, message)] (``bearings/plausible.py``): warnings
    plausibility: Callable[[Any, tuple], Found] = _nothing
    #: entry -> checks between its keys that pydantic cannot place on a key [(key path in the entry, message)]:
    #: deck errors the loader locates
    located_checks: Callable[[Any], Found] = _no_checks
    #: (entry, z of its centre from the nose [m]) -> its ``thermal.layout.BearingSet`` in the spindle's thermal
    #: network (with its family's contact paths); None: the family has no part in the network (a fluid film keeps
    #: its own heat balance, a linear bearing has none)
    thermal_set: Callable[[Any, float], Any] | None = None
    #: entry -> why it cannot be in the thermal network although its family can (None: it can)
    thermal_refusal: Callable[[Any], str | None] = _admitted


BEARING_TYPES: dict[str, BearingType] = {
    "linear": BearingType(linear.LinearEntry, linear.build, "stiffness and damping coefficients (optionally per speed)",
                          radial_only=True, plausibility=linear.plausibility),
    "three_lobe": BearingType(fluidfilm.ThreeLobeBearing, fluidfilm.build,
                              "n-lobe fluid-film bearing (Reynolds equation, thermal equilibrium)",
                              radial_only=True, plausibility=fluidfilm.plausibility),
    "plain": BearingType(fluidfilm.PlainBearing, fluidfilm.build,
                         "plain fluid-film journal bearing (360 deg or grooved)",
                         radial_only=True, plausibility=fluidfilm.plausibility),
    "roller": BearingType(roller.RollerEntry, roller.build,
                          "cylindrical roller bearing, rigid or flexible outer race (Jung et al. 2007)",
                          radial_only=True, plausibility=roller.plausibility, thermal_set=roller.thermal_set,
                          thermal_refusal=roller.thermal_refusal),
    "ball": BearingType(ball.BallBearingEntry, ball.build,
                        "angular-contact / deep-groove ball bearing or set, quasi-static with speed effects (Jones 1960)",
                        ball.placed, holds_axially=ball.holds_axially, plausibility=ball.plausibility,
                        located_checks=ball.located_checks, thermal_set=ball.thermal_set),
    "dtrb": BearingType(dtrb.DtrbBearingEntry, dtrb.build,
                        "double-row tapered roller bearing, quasi-static (Kim et al. 2023)",
                        holds_axially=dtrb.holds_axially, plausibility=dtrb.plausibility, thermal_set=dtrb.thermal_set),
}


def family(entry: Any) -> BearingType:
    """The row of the deck entry's family."""
    return BEARING_TYPES[entry.type]


def acts_radially_only(entry: Any) -> bool:
    """The entry acts on x and y of its node only (no tilt or axial stiffness)."""
    return family(entry).radial_only


def holds_axially(entry: Any) -> bool:
    """The entry holds the rotor axially (an axial load needs one that does)."""
    return family(entry).holds_axially(entry)


def located_checks(entry: Any) -> Found:
    """The entry's located deck errors [(key path in the entry, message)]."""
    return family(entry).located_checks(entry)


def bearing_plausibility(entry: Any, at: tuple) -> Found:
    """The entry's likely unit mistakes [(key path, message)], ``at`` its key path."""
    return family(entry).plausibility(entry, at)


def network_types() -> tuple[str, ...]:
    """The deck types whose entries may enter the spindle's thermal network."""
    return tuple(sorted(name for name, t in BEARING_TYPES.items() if t.thermal_set is not None))


def network_bearings(bearings) -> tuple[list, list]:
    """The rotor's bearing entries in the spindle's thermal network and those that cannot be:
    ([(index, entry)], [(index, entry, why)]).  In it: the entries of the families with a ``thermal_set`` that
    do not refuse (a roller entry needs rigid races and rollers)."""
    sets, refused = [], []
    for i, b in enumerate(bearings):
        kind = family(b)
        if kind.thermal_set is None:
            continue
        why = kind.thermal_refusal(b)
        if why is None:
            sets.append((i, b))
        else:
            refused.append((i, b, why))
    return sets, refused


def thermal_set(entry: Any, z_m: float):
    """The entry's ``BearingSet`` in the spindle's thermal network, centred at ``z_m`` from the nose [m]."""
    make = family(entry).thermal_set
    if make is None:
        raise ValueError(f"bearing {entry.name!r}: its family has no part in the spindle's thermal network")
    return make(entry, z_m)
