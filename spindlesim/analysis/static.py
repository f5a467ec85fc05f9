"""Static deflection q = K^-1 Q (seed 003 eq. 22) with non-symmetric bearing stiffness."""

from __future__ import annotations

import warnings

import numpy as np
import scipy.linalg as sla

from ..fe.assembly import assemble_shaft, bearing_static_loads, load_vector, system_matrices
from ..model.rotor import Rotor
from ..results import StaticResult


def solve_static(rotor: Rotor, stiffness_node: int = 0, stiffness_dof: str = "x") -> StaticResult:
    """Solve K q = Q at the rotor's speed; bearing reactions R_b = -K_b q_b."""
    shaft = assemble_shaft(rotor)
    loads = bearing_static_loads(rotor, shaft)
    sysm = system_matrices(rotor, shaft, rotor.speed_rad_s, loads)
    Q = load_vector(rotor, shaft)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sla.LinAlgWarning)  # singularity is checked and reported below
        lu = sla.lu_factor(sysm.K, check_finite=True)
    pivots = np.abs(np.diag(lu[0]))
    if pivots.min() <= 1e-12 * pivots.max():
        raise ValueError("the stiffness matrix is singular: the rotor is not held against rigid-body motion "
                         "(check that the bearings support both x and y at two nodes, or one node with moment stiffness)")
    q = sla.lu_solve(lu, Q)
    dofs = rotor.dofs
    disp = np.stack([q[dofs.component("x")], q[dofs.component("y")]], axis=1)
    slope = np.stack([q[dofs.component("theta_x")], q[dofs.component("theta_y")]], axis=1)
    forces = []
    for b in rotor.bearings:
        kb, _ = b.linearized(rotor.speed_rad_s, None if loads is None else loads.get(b.name))
        idx = [dofs.index(b.node, d) for d in getattr(b, "dof_names", ("x", "y"))]
        forces.append((-kb @ q[idx])[:2])
    applied = np.array([Q[dofs.component("x")].sum(), Q[dofs.component("y")].sum()])
    e = np.zeros(dofs.size)
    e[dofs.index(stiffness_node, stiffness_dof)] = 1.0
    compliance = sla.lu_solve(lu, e)[dofs.index(stiffness_node, stiffness_dof)]
    return StaticResult(
        node_z_m=rotor.node_z_m, displacement_m=disp, slope_rad=slope,
        bearing_names=tuple(b.name for b in rotor.bearings),
        bearing_nodes=np.array([b.node for b in rotor.bearings], dtype=int),
        bearing_force_N=np.array(forces).reshape(-1, 2), applied_force_N=applied,
        stiffness_node=stiffness_node, stiffness_dof=stiffness_dof,
        static_stiffness_N_m=float(1.0 / compliance), speed_rpm=rotor.speed_rpm,
    )
