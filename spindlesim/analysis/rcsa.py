"""Receptance coupling substructure analysis (RCSA): a tool's tip receptance from the spindle's receptances at
the nose and the tool's own, free-free.

Substructure A is the spindle without a tool (shaft, disks, bearings at the operating point), B a tool (holder,
holder-tool joint, tool; ``model.tool_library``).  They meet at the coupling node: the nose on A, the holder's
first node on B, every DOF of a node (x, y, theta_x, theta_y, and z where the rotor has it), joined by the
interface joint's dynamic stiffness K_j(w) = k + j w c per DOF (translational on x, y, z, rotational on the
tilts), or rigidly.  With H_aa A's receptance at the nose (displacements and rotations per force and moment,
[m x m], gyroscopic and bearing cross terms included), H_bb, H_bt, H_tb, H_tt B's at its coupling node (b) and
tip (t), the interface force lambda = K_j (u_b - u_a) solves

    u_a = H_aa lambda,   u_b = -H_bb lambda + H_bt F,   u_b - u_a = K_j^-1 lambda

so that the tip receptance of the assembly is (Schmitz and Duncan 2005; Park, Altintas and Movahhedy 2003)

    G_tt = H_tt - H_tb (H_aa + H_bb + K_j^-1)^-1 H_bt          (K_j^-1 = 0 for a rigid mounting)

exact for linear substructures: it equals the assembled rotor's tip receptance when A is linearised at the same
static state.  That state carries the tool's weight: B hangs from one node, so its static load on the nose is
its gravity load condensed to the coupling node, g_c - K_co K_oo^-1 g_o (the tool's weight and its moment about
the nose, exact for a linear tool), and A's static state is solved with it (``operating.operating_state``).

B is taken with its coupling node clamped (no rigid-body roots: its state-space eigendecomposition is well
conditioned) and condensed there: with D(w) = K(W) - w^2 M + j w C(W) its dynamic stiffness at the spin speed
W (its own gyroscopic terms included), Y = D_oo^-1 the clamped receptance at the tip t and the DOFs J next to
the coupling node c (the only rows of D_oc that are not zero), and W_a = H_aa + K_j^-1,

    S_B = D_cc - D_cJ Y_JJ D_Jc,      G_tt = Y_tt + Y_tJ D_Jc W_a (I + S_B W_a)^-1 D_cJ Y_Jt

which is the formula above (B's free receptances are the clamped ones corrected by S_B) without a free-free
part's rigid-body roots, and without inverting H_aa.  A's receptances come from its state-space
eigendecomposition (``port_receptance``), as the rotor's FRF.
"""

from __future__ import annotations

import logging

import numpy as np
import scipy.linalg as sla

from ..chatter.state_space import _off_poles
from ..fe.assembly import ShaftMatrices
from ..model.rotor import Joint
from .modal import first_order
from .operating import SystemMatrices

log = logging.getLogger(__name__)

_COND_LIMIT = 1e10


def port_receptance(sysm: SystemMatrices, idx, omega: np.ndarray) -> np.ndarray:
    """Receptance [f, m, m] between the DOFs ``idx`` (response i per force j) of M q'' + C q' + K q = f at
    angular frequencies ``omega``: through the state-space eigendecomposition (one for every frequency), a
    frequency on an undamped pole taken POLE_GAP off it; solved at each frequency when the eigenvectors are
    ill-conditioned."""
    idx = np.asarray(idx, int)
    w = np.atleast_1d(np.asarray(omega, float))
    P = np.eye(sysm.size)[:, idx]
    A, B, C = first_order(sysm, P)
    lam, V = sla.eig(A, check_finite=False)
    lu = sla.lu_factor(V, check_finite=False)
    gecon = sla.get_lapack_funcs("gecon", (V,))
    rcond, info = gecon(lu[0], np.linalg.norm(V, 1), norm="1")  # LAPACK's 1-norm estimate
    if info == 0 and rcond >= 1.0 / _COND_LIMIT:
        left = sla.lu_solve(lu, B.astype(complex), check_finite=False)  # V^-1 B [2n, m]
        CV = C @ V  # [m, 2n]
        m = len(idx)
        residues = (CV.T[:, :, None] * left[:, None, :]).reshape(len(lam), m * m)
        d = _off_poles(1j * w[:, None] - lam[None, :], lam)  # a new array
        np.divide(1.0, d, out=d)  # in place
        return (d @ residues).reshape(len(w), m, m)
    log.info("port receptance: ill-conditioned eigenvectors; solved at every frequency")
    D = _dynamic(sysm.K, sysm.M, sysm.C, w)
    E = np.zeros((sysm.size, len(idx)))
    E[idx, np.arange(len(idx))] = 1.0
    return np.linalg.solve(D, np.broadcast_to(E, (len(w),) + E.shape))[:, idx, :]


def _dynamic(K: np.ndarray, M: np.ndarray, C: np.ndarray, w: np.ndarray) -> np.ndarray:
    """K - w^2 M + j w C [f, r, c] of small blocks."""
    out = np.empty((len(w),) + K.shape, complex)
    out.real = K[None] - (w**2)[:, None, None] * M[None]
    out.imag = w[:, None, None] * C[None]
    return out


def tool_tip_receptance(shaft: ShaftMatrices, speed_rad_s: float, coupling, tip, H_aa: np.ndarray,
                        joint_inv: np.ndarray, omega: np.ndarray) -> np.ndarray:
    """G_tt [f, p, p] at the part's ``tip`` DOFs (p of them) coupled at its ``coupling`` DOFs onto a structure
    whose receptance there is ``H_aa`` [f, m, m] through a joint of compliance ``joint_inv`` [f, m, m]
    (module note); ``shaft`` the part's free matrices."""
    w = np.atleast_1d(np.asarray(omega, float))
    c = np.asarray(coupling, int)
    n = shaft.M.shape[0]
    o = np.setdiff1d(np.arange(n), c)
    K, C, M = shaft.stiffness(speed_rad_s), shaft.damping(speed_rad_s), shaft.M
    linked = np.any(np.abs(K[np.ix_(o, c)]) + np.abs(M[np.ix_(o, c)]) + np.abs(C[np.ix_(o, c)]) > 0, axis=1)
    J_local = np.flatnonzero(linked)  # positions in o
    t_local = np.searchsorted(o, np.asarray(tip, int))
    ports = np.concatenate([t_local, J_local])
    clamped = SystemMatrices(M=M[np.ix_(o, o)], C=C[np.ix_(o, o)], K=K[np.ix_(o, o)], speed_rad_s=speed_rad_s)
    Y = port_receptance(clamped, ports, w)  # [f, p + j, p + j]
    p = len(t_local)
    Y_tt, Y_tJ, Y_Jt, Y_JJ = Y[:, :p, :p], Y[:, :p, p:], Y[:, p:, :p], Y[:, p:, p:]
    J = o[J_local]
    D_Jc = _dynamic(K[np.ix_(J, c)], M[np.ix_(J, c)], C[np.ix_(J, c)], w)
    D_cJ = _dynamic(K[np.ix_(c, J)], M[np.ix_(c, J)], C[np.ix_(c, J)], w)
    S_B = _dynamic(K[np.ix_(c, c)], M[np.ix_(c, c)], C[np.ix_(c, c)], w) - D_cJ @ Y_JJ @ D_Jc
    W_a = H_aa + joint_inv
    eye = np.eye(len(c))[None]
    X = W_a @ np.linalg.solve(eye + S_B @ W_a, D_cJ @ Y_Jt)
    return Y_tt + Y_tJ @ D_Jc @ X


def condensed_load(shaft: ShaftMatrices, speed_rad_s: float, load: np.ndarray, coupling) -> np.ndarray:
    """The static load a part hanging from its coupling DOFs puts on what holds it: ``load`` (its DOFs)
    condensed to ``coupling``, g_c - K_co K_oo^-1 g_o (module note)."""
    c = np.asarray(coupling, int)
    o = np.setdiff1d(np.arange(len(load)), c)
    K = shaft.stiffness(speed_rad_s)
    if not len(o):
        return load[c].copy()
    return load[c] - K[np.ix_(c, o)] @ np.linalg.solve(K[np.ix_(o, o)], load[o])


def joint_compliance(joint: Joint | None, names: tuple[str, ...], omega: np.ndarray) -> np.ndarray:
    """K_j(w)^-1 [f, m, m] of a joint on a node's DOFs ``names`` (0 for a rigid mounting, None)."""
    w = np.atleast_1d(np.asarray(omega, float))
    out = np.zeros((len(w), len(names), len(names)), complex)
    if joint is None:
        return out
    for k, name in enumerate(names):
        rot = name.startswith("theta")
        kk = joint.rotational_Nm_rad if rot else joint.translational_N_m
        cc = joint.rotational_Nms_rad if rot else joint.translational_Ns_m
        out[:, k, k] = 1.0 / (kk + 1j * w * cc)
    return out
