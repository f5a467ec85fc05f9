"""Build the SI rotor model from a validated deck (deck units -> SI happens only here)."""

from __future__ import annotations

from typing import Any, Callable

import numpy as np

from ..bearings.linear import LinearBearing
from .dofs import DOFS_4, DOFS_5, DofMap
from .rotor import Disk, NodalLoad, Rotor, ShaftElements
from .shear import cowper_hollow_circle

RPM = np.pi / 30.0

# bearing type -> builder(deck_entry, deck) returning an object with .linearized()
_BEARING_BUILDERS: dict[str, Callable[[Any, Any], Any]] = {}


def register_bearing_builder(type_name: str, builder: Callable[[Any, Any], Any]) -> None:
    """Let a bearing package turn its deck entry into a bearing object."""
    _BEARING_BUILDERS[type_name] = builder


def _linear(entry: Any, deck: Any) -> LinearBearing:
    if entry.table is not None:
        t = entry.table
        return LinearBearing(entry.name, entry.node - 1, np.asarray(t.speed_rpm) * RPM,
                             np.asarray(t.K_N_m, float), np.asarray(t.C_Ns_m, float))
    C = entry.C_Ns_m if entry.C_Ns_m is not None else [[0.0, 0.0], [0.0, 0.0]]
    return LinearBearing(entry.name, entry.node - 1, np.array([0.0]),
                         np.asarray([entry.K_N_m], float), np.asarray([C], float))


register_bearing_builder("linear", _linear)


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


def build_rotor(deck: Any, speed_rpm: float | None = None) -> Rotor:
    """Rotor in SI from a validated deck (``LoadedDeck.deck``)."""
    el = shaft_elements(deck.shaft)
    z = deck.shaft.start_z_mm * 1e-3 + np.concatenate([[0.0], np.cumsum(el.length_m)])
    disks = tuple(Disk(d.node - 1, d.mass_kg, d.Ip_kg_m2, d.Id_kg_m2, d.name or f"disk{i + 1}")
                  for i, d in enumerate(deck.disks))
    bearings = tuple(_BEARING_BUILDERS[b.type](b, deck) for b in deck.bearings)
    loads = tuple(NodalLoad(p.node - 1, (p.fx_N, p.fy_N, p.mx_Nm, p.my_Nm), p.fz_N) for p in deck.loads)
    op = deck.operating
    # 5 DOF per node (axial z added) when a bearing acts axially (seed 001's DTRB) or an axial load is given
    axial = any("z" in getattr(b, "dof_names", ()) for b in bearings) or any(p.fz_N for p in deck.loads)
    return Rotor(
        dofs=DofMap(len(z), DOFS_5 if axial else DOFS_4),
        node_z_m=z, elements=el, disks=disks, bearings=bearings, loads=loads,
        speed_rpm=op.speed_rpm if speed_rpm is None else speed_rpm,
        gravity_m_s2=op.g_m_s2 if op.gravity else 0.0,
    )
