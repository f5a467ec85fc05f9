"""Frequency response H(w) = (-w^2 M + j w C + K)^-1 (seed 003 eq. 23) and unbalance response.

The receptance is evaluated through the complete state-space eigendecomposition
A = V diag(lambda) V^-1 of p' = A p + B f:

    H_oi(w) = sum_r V[o, r] (V^-1 B)[r, i] / (j w - lambda_r)

which is exact (no modal truncation) and costs one eigendecomposition for any
number of frequencies. When V is ill-conditioned (defective or rigid-body
roots) the dynamic stiffness is solved directly at every frequency instead.
"""

from __future__ import annotations

import logging

import numpy as np
import scipy.linalg as sla

from ..fe.assembly import assemble_shaft
from ..model.rotor import Rotor
from .modal import state_matrix
from .operating import system_matrices
from .results import FrfResult, UnbalanceResult

log = logging.getLogger(__name__)
_COND_LIMIT = 1e10


def receptance(sysm, out_index: int, in_index: int, omega: np.ndarray) -> np.ndarray:
    """Complex receptance [m/N] from force at DOF ``in_index`` to displacement at ``out_index``."""
    n = sysm.size
    A = state_matrix(sysm)
    lam, V = sla.eig(A, check_finite=False)
    if np.linalg.cond(V) < _COND_LIMIT:
        b = np.zeros(2 * n)
        b[n:] = sla.solve(sysm.M, np.eye(n)[:, in_index], assume_a="pos")
        w = sla.solve(V, b.astype(complex))
        return (V[out_index, :] * w) @ (1.0 / (1j * omega[None, :] - lam[:, None]))
    log.info("state-space modes are ill-conditioned; solving the dynamic stiffness directly")
    e = np.zeros(n, complex)
    e[in_index] = 1.0
    out = np.empty(len(omega), complex)
    for k, w in enumerate(omega):
        out[k] = np.linalg.solve(-(w**2) * sysm.M + 1j * w * sysm.C + sysm.K, e)[out_index]
    return out


def solve_frf(rotor: Rotor, frequencies_hz: np.ndarray, input_node: int, input_dof: str,
              output_node: int, output_dof: str, speed_rpm: float | None = None) -> FrfResult:
    """Receptance between (1-based) input and output node/DOF at the rotor speed."""
    speed = rotor.speed_rpm if speed_rpm is None else speed_rpm
    sysm = system_matrices(rotor, speed)
    f = np.asarray(frequencies_hz, float)
    h = receptance(sysm, rotor.dofs.index(output_node - 1, output_dof),
                   rotor.dofs.index(input_node - 1, input_dof), 2 * np.pi * f)
    return FrfResult(frequency_hz=f, receptance_m_N=h, input_node=input_node, input_dof=input_dof,
                     output_node=output_node, output_dof=output_dof, speed_rpm=speed)


def solve_unbalance(rotor: Rotor, speeds_rpm: np.ndarray, node: int, unbalance_kg_m: float,
                    phase_deg: float, output_node: int, output_dof: str) -> UnbalanceResult:
    """Steady synchronous response to a rotating unbalance m e at (1-based) ``node``.

    The unbalance force m e W^2 (cos(W t + a), sin(W t + a)) is the real part of
    F e^{j W t} with F_x = m e W^2 e^{j a}, F_y = -j m e W^2 e^{j a}; at every
    speed the matrices (gyroscopics, speed-dependent bearings) are rebuilt and
    (-W^2 M + j W C(W) + K(W)) q = F is solved.
    """
    shaft = assemble_shaft(rotor)
    speeds = np.asarray(speeds_rpm, float)
    resp = np.empty((len(speeds), rotor.n_nodes, 2), complex)
    ix, iy = rotor.dofs.index(node - 1, "x"), rotor.dofs.index(node - 1, "y")
    for k, s in enumerate(speeds):
        W = s * np.pi / 30
        sysm = system_matrices(rotor, s, shaft=shaft)
        F = np.zeros(sysm.size, complex)
        amp = unbalance_kg_m * W**2 * np.exp(1j * np.deg2rad(phase_deg))
        F[ix], F[iy] = amp, -1j * amp
        q = sla.solve(-(W**2) * sysm.M + 1j * W * sysm.C + sysm.K, F, check_finite=False)
        resp[k, :, 0] = q[rotor.dofs.component("x")]
        resp[k, :, 1] = q[rotor.dofs.component("y")]
    return UnbalanceResult(speed_rpm=speeds, response_m=resp, unbalance_kg_m=unbalance_kg_m,
                           unbalance_node=node, output_node=output_node, output_dof=output_dof,
                           node_z_m=rotor.node_z_m)
