"""State-space eigen analysis (seed 003 eqs. 24-25), QR algorithm via LAPACK.

All eigenvalues by the QR algorithm (LAPACK dgeev through numpy.linalg.eig).
First-order form p' = A p, p = [q, q'], A = [[0, I], [-M^-1 K, -M^-1 C]].
An eigenvalue lambda = -zeta w_n + i w_d gives the damped frequency w_d / 2 pi,
damping ratio zeta = -Re(lambda) / |lambda| and log decrement
delta = 2 pi zeta / sqrt(1 - zeta^2) = -2 pi Re(lambda) / Im(lambda).
Roots with zeta >= 0.999 (real roots included, one of each conjugate pair) and
roots below 1 mHz (rigid-body) are reported apart from the mode list.
Whirl direction at a node from the complex (x, y) amplitudes: the orbit is the
sum of a forward circle of radius |x + i y| / 2 and a backward one of radius
|x - i y| / 2 (spin about +z); forward when the first is larger.  A mode whose lateral
translations are below a tenth of its axial one (rotors with the axial DOF) is "axial"; its shape
keeps the axial component z.
"""

from __future__ import annotations

import numpy as np
import scipy.linalg as sla

from ..model.dofs import DOFS_4
from ..model.rotor import Rotor
from .operating import SystemMatrices
from .results import ModalResult

RIGID_BODY_RAD_S = 1e-3 * 2 * np.pi  # roots below 1 mHz are rigid-body roots
OVERDAMPED_ZETA = 0.999  # damping ratio at or above this: reported with the overdamped roots
AXIAL_SHARE = 0.1  # largest lateral translation below this share of the axial one: an axial mode
#: |damping ratio| below this is an undamped mode: its computed damping is round-off (1e-16..1e-13 of |lambda|)
UNDAMPED_BELOW = 1e-10


def first_order(sysm: SystemMatrices, P: np.ndarray | None = None):
    """The one state-space form of M q'' + C q' + K q = P f, y = P^T q, with x = (q, q'):

        A = [[0, I], [-M^-1 K, -M^-1 C]],   B = [[0], [M^-1 P]],   C_out = [P^T, 0]

    (one solve with M for all three).  Returns (A, B, C_out); B and C_out are None without ``P``."""
    n = sysm.size
    rhs = [sysm.K, sysm.C] + ([P] if P is not None else [])
    sol = sla.solve(sysm.M, np.hstack(rhs), assume_a="pos", check_finite=False)
    A = np.zeros((2 * n, 2 * n))
    A[:n, n:] = np.eye(n)
    A[n:, :n] = -sol[:, :n]
    A[n:, n:] = -sol[:, n:2 * n]
    if P is None:
        return A, None, None
    B = np.zeros((2 * n, P.shape[1]))
    B[n:] = sol[:, 2 * n:]
    C = np.zeros((P.shape[1], 2 * n))
    C[:, :n] = P.T
    return A, B, C


def state_matrix(sysm: SystemMatrices) -> np.ndarray:
    """A of :func:`first_order`."""
    return first_order(sysm)[0]


def whirl_of(shapes_xy: np.ndarray, rel_floor: float = 1e-3) -> tuple[list[str], np.ndarray]:
    """Classify modes from their complex (x, y) amplitudes [mode, node, 2]: ("forward" / "backward" /
    "mixed" per mode, share of the moving nodes that whirl forward)."""
    x, y = shapes_xy[..., 0], shapes_xy[..., 1]
    fwd = np.abs(x + 1j * y)
    bwd = np.abs(x - 1j * y)
    size = np.maximum(fwd, bwd)
    active = size > rel_floor * size.max(axis=-1, keepdims=True)
    n_active = active.sum(axis=-1)
    share = np.where(n_active > 0, (active & (fwd >= bwd)).sum(axis=-1) / np.maximum(n_active, 1), 0.5)
    names = ["forward" if s == 1.0 else "backward" if s == 0.0 else "mixed" for s in share]
    return names, share


def shape_dofs(dofs) -> tuple[str, ...]:
    """The entries of a mode shape per node: x, y, theta_x, theta_y, and z last where the rotor has the
    axial DOF (so the first four mean the same for every rotor)."""
    return DOFS_4 + (("z",) if "z" in dofs.names else ())


def modal_from_matrices(sysm: SystemMatrices, dofs, node_z_m: np.ndarray, n_modes: int,
                        speed_rpm: float, expand: np.ndarray | None = None) -> ModalResult:
    """Modes of assembled matrices; ``dofs`` is the rotor's DofMap (mode shapes: :func:`shape_dofs`).
    ``expand`` maps the matrices' coordinates to the rotor's DOFs (a reduced model's basis T)."""
    n_nodes = dofs.n_nodes
    A = state_matrix(sysm)
    # numpy's geev wrapper releases the GIL (scipy's does not), so Campbell sweeps can use threads
    lam, vec = np.linalg.eig(A)
    n = sysm.size
    mag = np.abs(lam)
    rigid = mag < RIGID_BODY_RAD_S
    # real roots, and roots so close to critical damping that a "damped frequency" is meaningless
    real = (~rigid) & (-lam.real >= OVERDAMPED_ZETA * mag) & (lam.imag >= 0)
    osc = (~rigid) & (~real) & (lam.imag > 0)
    order = np.flatnonzero(osc)[np.argsort(lam.imag[osc])][:n_modes]
    lam_m = lam[order]
    q = vec[:n, order] if expand is None else expand @ vec[:n, order]
    per_node = q.T.reshape(len(order), n_nodes, -1)
    names = shape_dofs(dofs)
    shapes = np.zeros((len(order), n_nodes, len(names)), complex)  # absent DOFs (a rigid journal's) stay 0
    for k, d in enumerate(names):
        if d in dofs.names:
            shapes[:, :, k] = per_node[:, :, dofs.names.index(d)]
    # normalise: the largest translation (x, y, or z where the rotor has it) becomes 1 + 0j
    trans = np.concatenate([shapes[:, :, :2].reshape(len(order), -1), shapes[:, :, 4:].reshape(len(order), -1)],
                           axis=1)
    ref = trans[np.arange(len(order)), np.argmax(np.abs(trans), axis=1)]
    shapes = shapes / ref[:, None, None]
    lateral = np.max(np.abs(shapes[:, :, :2]).reshape(len(order), -1), axis=1) if len(order) else np.zeros(0)
    whirls, shares = whirl_of(shapes[:, :, :2])
    axial_mode = lateral < AXIAL_SHARE
    whirls = ["axial" if ax else w for w, ax in zip(whirls, axial_mode)]
    shares = np.where(axial_mode, 0.5, shares)
    zeta = -lam_m.real / np.abs(lam_m)
    # an undamped mode (an axial mode with no axial damping, a rotor without damping): its computed damping is
    # the eigen-solver's round-off, of either sign; it is zero, not a stability verdict
    lam_m = np.where(np.abs(zeta) < UNDAMPED_BELOW, 1j * lam_m.imag, lam_m)
    zeta = np.where(np.abs(zeta) < UNDAMPED_BELOW, 0.0, zeta)
    return ModalResult(
        speed_rpm=speed_rpm, eigenvalues=lam_m, frequency_hz=lam_m.imag / (2 * np.pi),
        undamped_frequency_hz=np.abs(lam_m) / (2 * np.pi), damping_ratio=zeta,
        log_dec=-2 * np.pi * lam_m.real / lam_m.imag + 0.0, whirl=tuple(whirls),  # + 0.0: no -0 of an undamped mode
        forward_fraction=np.array(shares, dtype=float), mode_shape=shapes, node_z_m=node_z_m,
        overdamped_roots=lam[real][np.argsort(-lam[real].real)], rigid_body_roots=lam[rigid], unstable=zeta < 0,
    )


def solve_modal(rotor: "Rotor | OperatingPoints", speed_rpm: float | None = None, n_modes: int = 8) -> ModalResult:
    """Damped modes at ``speed_rpm`` (default: the rotor's operating speed), bearings linearised at the
    static equilibrium of that speed (the operating points' state there)."""
    from .points import OperatingPoints

    points = OperatingPoints.of(rotor)
    r = points.rotor
    speed = r.speed_rpm if speed_rpm is None else speed_rpm
    sysm = points.system(points.state(speed))
    return modal_from_matrices(sysm, r.dofs, r.node_z_m, n_modes, speed)
