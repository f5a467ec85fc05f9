"""Build the SI rotor model from a validated deck (deck units -> SI happens here for the rotor,
in each bearing family's builder for its bearings: ``spindlesim.bearings.types``)."""

from __future__ import annotations

from typing import Any

import numpy as np

from ..bearings.types import BEARING_TYPES
from .dofs import DOFS_4, DOFS_5, DOFS_JOURNAL, DofMap
from .rotor import Disk, Joint, NodalLoad, Rotor, ShaftElements
from .shear import cowper_hollow_circle

RPM = np.pi / 30.0


def element_rows(rows, shear_coefficient=None, nodes: np.ndarray | None = None, viscous_s: float = 0.0,
                 hysteretic: float = 0.0) -> ShaftElements:
    """Deck rows [outer_dia_mm, inner_dia_mm, length_mm, density_kg_m3, E_GPa, G_GPa, poisson,
    axial_force_N] -> SI elements; ``nodes`` (0-based, one more than rows) chains them."""
    rows = np.asarray(rows, dtype=float).reshape(-1, 8)
    do, di, length, rho, e, g, nu, fa = rows.T
    do, di, length = do * 1e-3, di * 1e-3, length * 1e-3
    kappa = (np.full(len(do), shear_coefficient) if shear_coefficient is not None
             else cowper_hollow_circle(nu, di / do))
    a, b = (None, None) if nodes is None else (np.asarray(nodes[:-1]), np.asarray(nodes[1:]))
    return ShaftElements(
        outer_diameter_m=do, inner_diameter_m=di, length_m=length, density_kg_m3=rho,
        youngs_modulus_Pa=e * 1e9, shear_modulus_Pa=g * 1e9, poisson=nu, axial_force_N=fa,
        shear_coefficient=kappa, viscous_damping_s=viscous_s, hysteretic_loss_factor=hysteretic, node_a=a, node_b=b)


def shaft_elements(shaft: Any) -> ShaftElements:
    return element_rows(shaft.elements, shaft.shear_coefficient, viscous_s=shaft.internal_damping.viscous_s,
                        hysteretic=shaft.internal_damping.hysteretic)


def tool_parts(tool: Any, z: np.ndarray) -> tuple[ShaftElements, np.ndarray, tuple[Joint, ...], int]:
    """The ``tool:`` section: holder elements from the spindle nose outwards (towards -z), the holder-tool
    joint, the tool's elements from the holder's end; node numbers continue after the shaft's.
    Returns (elements, z of the new nodes, joints, tool-tip node)."""
    n = len(z)
    nose = tool.holder_node - 1
    out = -1.0 if nose == 0 else 1.0  # outwards: away from the rest of the shaft
    joints = []
    first = nose
    z_h = np.zeros(0)
    if tool.interface is not None:  # the holder's own first node, held on the nose by the interface joint
        first = n
        z_h = np.array([z[nose]])
        joints.append(_joint(tool.interface, nose, first))
    h = element_rows(tool.holder.elements)
    holder_nodes = np.concatenate([[first], first + 1 + np.arange(h.count)]) if first == n else \
        np.concatenate([[nose], n + np.arange(h.count)])
    h = element_rows(tool.holder.elements, nodes=holder_nodes)
    z_h = np.concatenate([z_h, z[nose] + out * np.cumsum(h.length_m)])
    base = int(holder_nodes[-1]) + 1  # the tool's first node: at the holder's end, held by the joint
    t0 = element_rows(tool.tool.elements)
    tool_nodes = base + np.arange(t0.count + 1)
    t = element_rows(tool.tool.elements, nodes=tool_nodes)
    z_t = z_h[-1] + out * np.concatenate([[0.0], np.cumsum(t.length_m)])
    joints.append(_joint(tool.joint, int(holder_nodes[-1]), base))
    return ShaftElements.join(h, t), np.concatenate([z_h, z_t]), tuple(joints), int(tool_nodes[-1])


def _joint(j: Any, a: int, b: int) -> Joint:
    return Joint(int(a), int(b), j.translational_N_m, j.rotational_Nm_rad, j.translational_Ns_m, j.rotational_Nms_rad)


def build_bearings(deck: Any, node_z_m: np.ndarray | None = None) -> tuple:
    """Every ``bearings:`` entry through its family's builder (the type table), placed on the shaft
    whose node positions are ``node_z_m`` (keys that depend on where a bearing sits)."""
    out = []
    for b in deck.bearings:
        kind = BEARING_TYPES[b.type]
        if node_z_m is not None and len(node_z_m) > 1:
            b = kind.placed(b, float(node_z_m[b.node - 1]), (float(node_z_m.min()), float(node_z_m.max())))
        out.append(kind.build(b))
    return tuple(out)


def build_rotor(deck: Any, speed_rpm: float | None = None) -> Rotor:
    """Rotor in SI from a validated deck (``LoadedDeck.deck``): a Timoshenko shaft (``shaft:``) or a
    rigid journal (``journal:``, one node with translations only)."""
    loads = tuple(NodalLoad(p.node - 1, (p.fx_N, p.fy_N, p.mx_Nm, p.my_Nm), p.fz_N) for p in deck.loads)
    op = deck.operating
    speed = op.speed_rpm if speed_rpm is None else speed_rpm
    gravity = op.g_m_s2 if op.gravity else 0.0
    if deck.shaft is None:
        j = deck.journal
        return Rotor(node_z_m=np.zeros(1), elements=ShaftElements.empty(), disks=(Disk(0, j.mass_kg, 0.0, 0.0, "journal"),),
                     bearings=build_bearings(deck), loads=loads, speed_rpm=speed, gravity_m_s2=gravity,
                     dofs=DofMap(1, DOFS_JOURNAL), ground_damping_Ns_m=j.damping_Ns_mm * 1e3)
    el = shaft_elements(deck.shaft)
    z = deck.shaft.start_z_mm * 1e-3 + np.concatenate([[0.0], np.cumsum(el.length_m)])
    bearings = build_bearings(deck, z)  # placed on the shaft (without the tool)
    joints: tuple[Joint, ...] = ()
    tip = None
    if deck.tool is not None:
        tel, tz, joints, tip = tool_parts(deck.tool, z)
        el, z = ShaftElements.join(el, tel), np.concatenate([z, tz])
    disks = tuple(Disk(d.node - 1, d.mass_kg, d.Ip_kg_m2, d.Id_kg_m2, d.name or f"disk{i + 1}")
                  for i, d in enumerate(deck.disks))
    # 5 DOF per node (axial z added) when a bearing acts axially (seed 001's DTRB) or an axial load is given
    axial = any("z" in b.dof_names for b in bearings) or any(p.fz_N for p in deck.loads)
    return Rotor(dofs=DofMap(len(z), DOFS_5 if axial else DOFS_4), node_z_m=z, elements=el, disks=disks,
                 bearings=bearings, loads=loads, speed_rpm=speed, gravity_m_s2=gravity, joints=joints, tool_tip=tip)
