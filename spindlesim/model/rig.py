"""Seed 000's 2-DOF test rig (the deck section ``transient:``) as a rotor: a rigid journal of the
shaft mass in a ``type: roller`` bearing, under the rig's radial load (along -y)."""

from __future__ import annotations

from typing import Any

import numpy as np

from ..bearings.roller.section import RollerEntry
from ..bearings.types import BEARING_TYPES
from .dofs import DOFS_JOURNAL, DofMap
from .rotor import Disk, NodalLoad, Rotor, ShaftElements


def rig_bearing_entry(sec: Any, rollers: int | None = None, model: str | None = None) -> RollerEntry:
    """The rig's bearing as a rotor deck's ``type: roller`` entry at node 1."""
    keys = dict(sec.bearing)
    keys.update(type="roller", name="bearing", node=1, rollers=sec.rollers if rollers is None else rollers,
                model=sec.model if model is None else model, outer_race=sec.outer_race, contact=sec.contact,
                housing=sec.housing, waviness=list(sec.waviness))
    return RollerEntry.model_validate(keys)


def journal_rotor(bearings, mass_kg: float, damping_Ns_m: float = 0.0, load_N=(0.0, 0.0),
                  speed_rpm: float = 0.0) -> Rotor:
    """A rigid journal (one node, x and y) of ``mass_kg`` in ``bearings``, under a constant load."""
    loads = (NodalLoad(0, (float(load_N[0]), float(load_N[1]), 0.0, 0.0)),) if np.any(load_N) else ()
    return Rotor(node_z_m=np.zeros(1), elements=ShaftElements.empty(), disks=(Disk(0, mass_kg, 0.0, 0.0, "journal"),),
                 bearings=tuple(bearings), loads=loads, speed_rpm=speed_rpm, dofs=DofMap(1, DOFS_JOURNAL),
                 ground_damping_Ns_m=damping_Ns_m)


def rig_rotor(sec: Any, rollers: int | None = None, model: str | None = None) -> Rotor:
    """Rotor of the rig section ``sec`` (``deck.transient.TransientSection``); CLI options override rollers and model."""
    bearing = BEARING_TYPES["roller"].build(rig_bearing_entry(sec, rollers, model))
    return journal_rotor((bearing,), sec.shaft.mass_kg, sec.shaft.damping_Ns_mm * 1e3,
                         (0.0, -sec.shaft.radial_load_N), sec.speed_rpm)
