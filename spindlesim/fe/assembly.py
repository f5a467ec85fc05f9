"""Assembly of the rotor's global matrices (dense, SI) from element and disk matrices.

Bearings are not assembled here: every analysis adds them through the bearing contract
(``spindlesim.analysis.operating``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..model.dofs import DOFS_4, DofMap
from ..model.rotor import Rotor
from .timoshenko import ElementMatrices, lateral_element_matrices


@dataclass(frozen=True)
class ShaftMatrices:
    """Speed-independent global matrices of shaft and disks (bearings excluded).

    Equation of motion (seed 003 eq. 21 before adding bearings):
    M q'' + (C_g + eta_v K_B + Omega G) q' + (a_h K_B + K_A + (eta_v Omega + b_h) K_C) q = Q,
    a_h = (1 + eta_h)/sqrt(1 + eta_h^2), b_h = eta_h/sqrt(1 + eta_h^2); C_g is damping to ground
    (a rigid journal's).
    """

    M: np.ndarray
    G: np.ndarray
    K_B: np.ndarray
    K_A: np.ndarray
    K_C: np.ndarray
    C_ground: np.ndarray  # damping to ground and in joints (a tool in its holder)
    K_J: np.ndarray  # stiffness of joints
    gravity_unit: np.ndarray  # load vector per (m/s^2) of gravity along -y
    eta_v: float
    eta_h: float

    def stiffness(self, speed_rad_s: float) -> np.ndarray:
        """Shaft stiffness incl. axial load and the circulatory term of internal damping."""
        a_h = (1 + self.eta_h) / np.sqrt(1 + self.eta_h**2)
        b_h = self.eta_h / np.sqrt(1 + self.eta_h**2)
        K = a_h * self.K_B + self.K_A + self.K_J
        circ = self.eta_v * speed_rad_s + b_h
        if circ:
            K = K + circ * self.K_C
        return K

    def damping(self, speed_rad_s: float) -> np.ndarray:
        """Shaft damping: ground, internal viscous eta_v K_B and gyroscopic Omega G."""
        C = self.C_ground + speed_rad_s * self.G
        if self.eta_v:
            C = C + self.eta_v * self.K_B
        return C


def oriented_nodes(rotor: Rotor) -> tuple[np.ndarray, np.ndarray]:
    """Each element's (first, second) node with the first at the smaller z.

    The element matrices are written for an element pointing along +z from its first node (the
    slopes' signs depend on it); a chain built outwards towards -z (a tool and holder in front of
    a nose at node 1) is therefore taken from its far end."""
    el = rotor.elements
    a, b = np.asarray(el.node_a, dtype=int), np.asarray(el.node_b, dtype=int)
    flip = rotor.node_z_m[b] < rotor.node_z_m[a]
    return np.where(flip, b, a), np.where(flip, a, b)


def _scatter(dofs: DofMap, node_a: np.ndarray, node_b: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Global (row, col) index arrays for every element's 8x8 lateral block."""
    idx = np.array([[dofs.index(int(nd), d) for nd in (a, b) for d in DOFS_4] for a, b in zip(node_a, node_b)],
                   dtype=int)
    return idx[:, :, None], idx[:, None, :]


def assemble_shaft(rotor: Rotor) -> ShaftMatrices:
    """Assemble shaft elements and rigid disks into global matrices."""
    el = rotor.elements
    dofs = rotor.dofs
    n = dofs.size
    M, G, KB, KA, KC = (np.zeros((n, n)) for _ in range(5))
    grav = np.zeros(n)
    if el.count:
        with np.errstate(all="ignore"):  # a non-finite result is checked just below and named
            em: ElementMatrices = lateral_element_matrices(
                el.length_m, el.area_m2, el.second_moment_m4, el.density_kg_m3,
                el.youngs_modulus_Pa, el.shear_modulus_Pa, el.shear_coefficient, el.axial_force_N,
            )
        bad = [e + 1 for e in range(el.count) if not all(np.all(np.isfinite(m[e])) for m in (
            em.mass, em.stiffness_bending, em.gyroscopic))]
        if bad:
            raise ValueError(f"the matrices of shaft element(s) {bad[:10]} are not finite: their dimensions or moduli "
                             "are beyond what a beam element can hold (check the rows' units)")
        node_a, node_b = oriented_nodes(rotor)
        rows, cols = _scatter(dofs, node_a, node_b)
        for out, e in ((M, em.mass), (G, em.gyroscopic), (KB, em.stiffness_bending), (KA, em.stiffness_axial),
                       (KC, em.circulatory)):
            np.add.at(out, (np.broadcast_to(rows, e.shape), np.broadcast_to(cols, e.shape)), e)
        np.add.at(grav, rows[:, :, 0], em.gravity_unit)
    if dofs.has("z"):  # axial bar: K = EA/L [[1,-1],[-1,1]], M = rho A L/6 [[2,1],[1,2]] (consistent)
        ea_l = el.youngs_modulus_Pa * el.area_m2 / el.length_m
        m6 = el.density_kg_m3 * el.area_m2 * el.length_m / 6
        for e in range(el.count):
            ij = np.ix_(*(2 * [[dofs.index(int(el.node_a[e]), "z"), dofs.index(int(el.node_b[e]), "z")]]))  # symmetric
            KB[ij] += ea_l[e] * np.array([[1.0, -1.0], [-1.0, 1.0]])
            M[ij] += m6[e] * np.array([[2.0, 1.0], [1.0, 2.0]])
    for disk in rotor.disks:
        ix, iy = dofs.index(disk.node, "x"), dofs.index(disk.node, "y")
        M[ix, ix] += disk.mass_kg
        M[iy, iy] += disk.mass_kg
        grav[iy] -= disk.mass_kg
        if dofs.has("theta_x"):
            itx, ity = dofs.index(disk.node, "theta_x"), dofs.index(disk.node, "theta_y")
            M[itx, itx] += disk.diametral_inertia_kg_m2
            M[ity, ity] += disk.diametral_inertia_kg_m2
            # Id th_x'' + Ip Omega th_y' = M_x ;  Id th_y'' - Ip Omega th_x' = M_y
            G[itx, ity] += disk.polar_inertia_kg_m2
            G[ity, itx] -= disk.polar_inertia_kg_m2
        if dofs.has("z"):
            M[dofs.index(disk.node, "z"), dofs.index(disk.node, "z")] += disk.mass_kg
    Cg = np.zeros((n, n))
    if rotor.ground_damping_Ns_m:
        for d in ("x", "y"):
            i = dofs.component(d)
            Cg[i, i] += rotor.ground_damping_Ns_m
    KJ = np.zeros((n, n))
    for j in rotor.joints:  # springs and dampers between two nodes
        trans = ("x", "y", "z") if dofs.has("z") else ("x", "y")  # axially as translationally stiff
        for names, k, c in ((trans, j.translational_N_m, j.translational_Ns_m),
                            (("theta_x", "theta_y"), j.rotational_Nm_rad, j.rotational_Nms_rad)):
            for d in names:
                ij = np.ix_(*(2 * [[dofs.index(j.node_a, d), dofs.index(j.node_b, d)]]))
                KJ[ij] += k * np.array([[1.0, -1.0], [-1.0, 1.0]])
                Cg[ij] += c * np.array([[1.0, -1.0], [-1.0, 1.0]])
    return ShaftMatrices(M=M, G=G, K_B=KB, K_A=KA, K_C=KC, C_ground=Cg, K_J=KJ, gravity_unit=grav,
                         eta_v=el.viscous_damping_s, eta_h=el.hysteretic_loss_factor)


def load_vector(rotor: Rotor, shaft: ShaftMatrices) -> np.ndarray:
    """Static load vector: point loads plus gravity (if on)."""
    Q = rotor.gravity_m_s2 * shaft.gravity_unit
    dofs = rotor.dofs
    for load in rotor.loads:
        for name, value in zip(DOFS_4, load.force_N):
            if value:
                Q[dofs.index(load.node, name)] += value
        if load.axial_N:
            Q[dofs.index(load.node, "z")] += load.axial_N
    return Q
