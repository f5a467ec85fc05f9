"""Build the SI rotor model from a validated deck (deck units -> SI happens here for the rotor,
in each bearing family's builder for its bearings: ``spindlesim.bearings.types``)."""

from __future__ import annotations

from typing import Any

import numpy as np

from ..bearings.types import BEARING_TYPES
from .dofs import DOFS_4, DOFS_5, DOFS_JOURNAL, DofMap
from .rotor import Disk, NodalLoad, Rotor, ShaftElements
from .shear import cowper_hollow_circle

RPM = np.pi / 30.0


def shaft_elements(shaft: Any) -> ShaftElements:
    rows = np.asarray(shaft.elements, dtype=float)
    do, di, length, rho, e, g, nu, fa = rows.T
    do, di, length = do * 1e-3, di * 1e-3, length * 1e-3
    kappa = (np.full(len(do), shaft.shear_coefficient) if shaft.shear_coefficient is not None
             else cowper_hollow_circle(nu, di / do))
    return ShaftElements(
        outer_diameter_m=do, inner_diameter_m=di, length_m=length, density_kg_m3=rho,
        youngs_modulus_Pa=e * 1e9, shear_modulus_Pa=g * 1e9, poisson=nu, axial_force_N=fa,
        shear_coefficient=kappa, viscous_damping_s=shaft.internal_damping.viscous_s,
        hysteretic_loss_factor=shaft.internal_damping.hysteretic,
    )


def build_bearings(deck: Any) -> tuple:
    """Every ``bearings:`` entry through its family's builder (the type table)."""
    return tuple(BEARING_TYPES[b.type].build(b) for b in deck.bearings)


def build_rotor(deck: Any, speed_rpm: float | None = None) -> Rotor:
    """Rotor in SI from a validated deck (``LoadedDeck.deck``): a Timoshenko shaft (``shaft:``) or a
    rigid journal (``journal:``, one node with translations only)."""
    bearings = build_bearings(deck)
    loads = tuple(NodalLoad(p.node - 1, (p.fx_N, p.fy_N, p.mx_Nm, p.my_Nm), p.fz_N) for p in deck.loads)
    op = deck.operating
    speed = op.speed_rpm if speed_rpm is None else speed_rpm
    gravity = op.g_m_s2 if op.gravity else 0.0
    if deck.shaft is None:
        j = deck.journal
        return Rotor(node_z_m=np.zeros(1), elements=ShaftElements.empty(), disks=(Disk(0, j.mass_kg, 0.0, 0.0, "journal"),),
                     bearings=bearings, loads=loads, speed_rpm=speed, gravity_m_s2=gravity,
                     dofs=DofMap(1, DOFS_JOURNAL), ground_damping_Ns_m=j.damping_Ns_mm * 1e3)
    el = shaft_elements(deck.shaft)
    z = deck.shaft.start_z_mm * 1e-3 + np.concatenate([[0.0], np.cumsum(el.length_m)])
    disks = tuple(Disk(d.node - 1, d.mass_kg, d.Ip_kg_m2, d.Id_kg_m2, d.name or f"disk{i + 1}")
                  for i, d in enumerate(deck.disks))
    # 5 DOF per node (axial z added) when a bearing acts axially (seed 001's DTRB) or an axial load is given
    axial = any("z" in b.dof_names for b in bearings) or any(p.fz_N for p in deck.loads)
    return Rotor(dofs=DofMap(len(z), DOFS_5 if axial else DOFS_4), node_z_m=z, elements=el, disks=disks,
                 bearings=bearings, loads=loads, speed_rpm=speed, gravity_m_s2=gravity)
