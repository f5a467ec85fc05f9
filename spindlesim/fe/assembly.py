"""Assembly of the rotor's global matrices (dense, SI) from element and disk matrices."""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from ..model.dofs import DOFS_4, DofMap
from ..model.rotor import Rotor
from .timoshenko import ElementMatrices, lateral_element_matrices


@dataclass(frozen=True)
class ShaftMatrices:
    """Speed-independent global matrices of shaft and disks (bearings excluded).

    Equation of motion (seed 003 eq. 21 before adding bearings):
    M q'' + (eta_v K_B + Omega G) q' + (a_h K_B + K_A + (eta_v Omega + b_h) K_C) q = Q,
    a_h = (1 + eta_h)/sqrt(1 + eta_h^2), b_h = eta_h/sqrt(1 + eta_h^2).
    """

    M: np.ndarray
    G: np.ndarray
    K_B: np.ndarray
    K_A: np.ndarray
    K_C: np.ndarray
    gravity_unit: np.ndarray  # load vector per (m/s^2) of gravity along -y
    eta_v: float
    eta_h: float

    def stiffness(self, speed_rad_s: float) -> np.ndarray:
        """Shaft stiffness incl. axial load and the circulatory term of internal damping."""
        a_h = (1 + self.eta_h) / np.sqrt(1 + self.eta_h**2)
        b_h = self.eta_h / np.sqrt(1 + self.eta_h**2)
        K = a_h * self.K_B + self.K_A
        circ = self.eta_v * speed_rad_s + b_h
        if circ:
            K = K + circ * self.K_C
        return K

    def damping(self, speed_rad_s: float) -> np.ndarray:
        """Shaft damping: internal viscous eta_v K_B plus gyroscopic Omega G."""
        C = speed_rad_s * self.G
        if self.eta_v:
            C = C + self.eta_v * self.K_B
        return C


def _scatter(dofs: DofMap, elem: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Global (row, col) index arrays for every element's 8x8 lateral block."""
    n_elem = elem.shape[0]
    idx = np.array([[dofs.index(e + a, d) for a in (0, 1) for d in DOFS_4] for e in range(n_elem)])
    return idx[:, :, None], idx[:, None, :]


def assemble_shaft(rotor: Rotor) -> ShaftMatrices:
    """Assemble shaft elements and rigid disks into global matrices."""
    el = rotor.elements
    em: ElementMatrices = lateral_element_matrices(
        el.length_m, el.area_m2, el.second_moment_m4, el.density_kg_m3,
        el.youngs_modulus_Pa, el.shear_modulus_Pa, el.shear_coefficient, el.axial_force_N,
    )
    dofs = rotor.dofs
    n = dofs.size
    rows, cols = _scatter(dofs, em.mass)

    def glob(e: np.ndarray) -> np.ndarray:
        out = np.zeros((n, n))
        np.add.at(out, (np.broadcast_to(rows, e.shape), np.broadcast_to(cols, e.shape)), e)
        return out

    M, G, KB, KA, KC = (glob(m) for m in (em.mass, em.gyroscopic, em.stiffness_bending, em.stiffness_axial, em.circulatory))
    grav = np.zeros(n)
    np.add.at(grav, rows[:, :, 0], em.gravity_unit)
    if "z" in dofs.names:  # axial bar: K = EA/L [[1,-1],[-1,1]], M = rho A L/6 [[2,1],[1,2]] (consistent)
        ea_l = el.youngs_modulus_Pa * el.area_m2 / el.length_m
        m6 = el.density_kg_m3 * el.area_m2 * el.length_m / 6
        for e in range(el.count):
            i, j = dofs.index(e, "z"), dofs.index(e + 1, "z")
            ij = np.ix_([i, j], [i, j])
            KB[ij] += ea_l[e] * np.array([[1.0, -1.0], [-1.0, 1.0]])
            M[ij] += m6[e] * np.array([[2.0, 1.0], [1.0, 2.0]])
    for disk in rotor.disks:
        ix, iy, itx, ity = dofs.lateral(disk.node)
        M[ix, ix] += disk.mass_kg
        M[iy, iy] += disk.mass_kg
        M[itx, itx] += disk.diametral_inertia_kg_m2
        M[ity, ity] += disk.diametral_inertia_kg_m2
        # Id th_x'' + Ip Omega th_y' = M_x ;  Id th_y'' - Ip Omega th_x' = M_y
        G[itx, ity] += disk.polar_inertia_kg_m2
        G[ity, itx] -= disk.polar_inertia_kg_m2
        grav[iy] -= disk.mass_kg
        if "z" in dofs.names:
            M[dofs.index(disk.node, "z"), dofs.index(disk.node, "z")] += disk.mass_kg
    return ShaftMatrices(M=M, G=G, K_B=KB, K_A=KA, K_C=KC, gravity_unit=grav,
                         eta_v=el.viscous_damping_s, eta_h=el.hysteretic_loss_factor)


def add_bearings(
    rotor: Rotor, K: np.ndarray, C: np.ndarray, speed_rad_s: float, static_loads: dict | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """Add each bearing's linearised 2x2 K and C at its node's (x, y) DOFs; returns new arrays."""
    K = K.copy()
    C = C.copy()
    for b in rotor.bearings:
        load = None if static_loads is None else static_loads.get(b.name)
        kb, cb = b.linearized(speed_rad_s, load)
        # a bearing acts on (x, y) unless it names its DOFs, e.g. ("x", "y", "z", "theta_x", "theta_y")
        names = getattr(b, "dof_names", ("x", "y"))
        i = np.array([rotor.dofs.index(b.node, d) for d in names])
        K[np.ix_(i, i)] += kb
        C[np.ix_(i, i)] += cb
    return K, C


@dataclass(frozen=True)
class SystemMatrices:
    """M q'' + C q' + K q = Q at one spin speed, bearings included (seed 003 eq. 21)."""

    M: np.ndarray
    C: np.ndarray
    K: np.ndarray
    speed_rad_s: float

    @cached_property
    def size(self) -> int:
        return self.M.shape[0]


def bearing_static_loads(rotor: Rotor, shaft: ShaftMatrices) -> dict | None:
    """Force of the shaft on each bearing at static equilibrium, for bearings whose coefficients depend
    on load and that have no load of their own (``load_N is None``); entries follow each bearing's
    ``dof_names`` ((x, y), or (x, y, z, theta_x, theta_y) with moments).

    First the rotor is solved with its load-independent bearings at their own stiffness and the
    load-dependent ones as stiff supports (exact for two radial bearings, statically determinate). If some bearings are nonlinear (they have
    ``force_and_tangent``, e.g. the DTRB), the static equilibrium is then solved with their
    full nonlinear reaction (Newton) and the other bearings linearised at the first loads.
    """
    if not any(getattr(b, "load_N", 0.0) is None for b in rotor.bearings):
        return None
    Q = load_vector(rotor, shaft)
    K0 = shaft.stiffness(0.0)
    K = K0.copy()
    k_stiff = 1e3 * max(np.max(np.abs(np.diag(K))), 1.0)
    idx = {b.name: [rotor.dofs.index(b.node, d) for d in getattr(b, "dof_names", ("x", "y"))] for b in rotor.bearings}
    load_dependent = [b for b in rotor.bearings if getattr(b, "load_N", 0.0) is None]
    for b in rotor.bearings:
        if b in load_dependent:
            for i in idx[b.name]:
                K[i, i] += k_stiff
        else:
            K[np.ix_(idx[b.name], idx[b.name])] += b.linearized(0.0, None)[0]
    q = np.linalg.solve(K, Q)
    loads = {b.name: k_stiff * q[idx[b.name]] for b in load_dependent}
    nonlinear = [b for b in rotor.bearings if hasattr(b, "force_and_tangent")]
    if not nonlinear:
        return loads
    W = rotor.speed_rad_s
    Kl = shaft.stiffness(W).copy()
    for b in rotor.bearings:
        if b in nonlinear:
            continue
        kb, _ = b.linearized(W, loads.get(b.name))
        Kl[np.ix_(idx[b.name], idx[b.name])] += kb
    q = np.zeros(len(Q))
    for it in range(60):
        R = Q - Kl @ q
        J = Kl.copy()
        forces = {}
        for b in nonlinear:
            f, kt, _ = b.force_and_tangent(q[idx[b.name]], np.zeros(len(idx[b.name])), 0.0)
            forces[b.name] = f
            R[idx[b.name]] += f
            J[np.ix_(idx[b.name], idx[b.name])] += kt
        dq = np.linalg.solve(J, R)
        big = np.max(np.abs(dq[rotor.dofs.component("x")])) + np.max(np.abs(dq[rotor.dofs.component("y")]))
        if big > 2e-5:  # limit steps to 20 um: contact stiffness changes fast near zero load
            dq *= 2e-5 / big
        q += dq
        if np.max(np.abs(R)) <= 1e-8 * max(np.max(np.abs(Q)), 1.0) and np.max(np.abs(dq)) < 1e-13:
            break
    else:
        raise ArithmeticError(f"static equilibrium with nonlinear bearings did not converge in 60 Newton "
                              f"iterations (residual {np.max(np.abs(R)):.3g} N)")
    for b in nonlinear:
        loads[b.name] = -forces[b.name]
    return loads


def system_matrices(rotor: Rotor, shaft: ShaftMatrices, speed_rad_s: float, static_loads: dict | None = None) -> SystemMatrices:
    if static_loads is None:
        static_loads = bearing_static_loads(rotor, shaft)
    K, C = add_bearings(rotor, shaft.stiffness(speed_rad_s), shaft.damping(speed_rad_s), speed_rad_s, static_loads)
    return SystemMatrices(M=shaft.M, C=C, K=K, speed_rad_s=speed_rad_s)


def load_vector(rotor: Rotor, shaft: ShaftMatrices) -> np.ndarray:
    """Static load vector: point loads plus gravity (if on)."""
    Q = rotor.gravity_m_s2 * shaft.gravity_unit
    Q = Q.copy()
    for load in rotor.loads:
        Q[rotor.dofs.lateral(load.node)] += np.asarray(load.force_N)
        if load.axial_N:
            Q[rotor.dofs.index(load.node, "z")] += load.axial_N
    return Q
