"""Static deflection (seed 003 eq. 22, K q = Q) with every bearing's full nonlinear reaction.

The deflection is the rotor's static equilibrium (``analysis.operating``): for linear bearings
exactly q = K^-1 Q, for fluid films, rolling and DTRB bearings the equilibrium of their
nonlinear reactions.  The static stiffness at a node is the inverse compliance of the system
linearised there.
"""

from __future__ import annotations

import numpy as np

from ..model.rotor import Rotor
from .operating import EquilibriumError, SingularRotorError, _solve
from .points import OperatingPoints
from .results import StaticResult


def _component(rotor: Rotor, q: np.ndarray, dof: str) -> np.ndarray:
    return q[rotor.dofs.component(dof)] if rotor.dofs.has(dof) else np.zeros(rotor.n_nodes)


def solve_static(rotor: "Rotor | OperatingPoints", stiffness_node: int = 0, stiffness_dof: str = "x",
                 speed_rpm: float | None = None) -> StaticResult:
    """Static equilibrium at ``speed_rpm`` (default: the rotor's); bearing reactions on the shaft; the
    static stiffness at (``stiffness_node``, ``stiffness_dof``) and, with a tool, at the tool tip (x, y
    and, where the model has it, axial z)."""
    points = OperatingPoints.of(rotor)
    rotor = points.rotor
    st = points.state(speed_rpm)
    q = st.q
    disp = np.stack([_component(rotor, q, "x"), _component(rotor, q, "y")], axis=1)
    slope = np.stack([_component(rotor, q, "theta_x"), _component(rotor, q, "theta_y")], axis=1)
    forces = np.array([-w[:2] for w in st.loads]).reshape(-1, 2)
    applied = np.array([st.Q[rotor.dofs.component("x")].sum(), st.Q[rotor.dofs.component("y")].sum()])
    K = points.system(st).K
    compliance = _compliance(rotor, K, stiffness_node, stiffness_dof, held=True)
    if compliance is None:
        raise EquilibriumError(f"no positive static compliance at node {stiffness_node + 1} {stiffness_dof}")
    tip = rotor.tool_tip
    tip_k = None
    if tip is not None:
        tip_c = {d: _compliance(rotor, K, tip, d) for d in ("x", "y", "z") if rotor.dofs.has(d)}
        tip_k = {d: 1.0 / c for d, c in tip_c.items() if c is not None}  # z left out when axially free
    axial = st.Q[rotor.dofs.component("z")].sum() if rotor.dofs.has("z") else 0.0
    return StaticResult(
        node_z_m=rotor.node_z_m, displacement_m=disp, slope_rad=slope,
        bearing_names=tuple(b.name for b in rotor.bearings),
        bearing_nodes=np.array([b.node for b in rotor.bearings], dtype=int),
        bearing_force_N=forces, applied_force_N=applied, stiffness_node=stiffness_node,
        stiffness_dof=stiffness_dof, static_stiffness_N_m=float(1.0 / compliance),
        speed_rpm=st.speed_rad_s * 30 / np.pi, state=st,
        damping_only=tuple(b.name for b, (kb, _) in zip(rotor.bearings, st.coefficients)
                           if kb is not None and not np.any(kb)),
        axial_displacement_m=_component(rotor, q, "z") if rotor.dofs.has("z") else None,
        applied_axial_force_N=float(axial), tool_tip_node=tip, tool_tip_stiffness_N_m=tip_k,
        gravity_m_s2=float(rotor.gravity_m_s2),
    )


def _compliance(rotor: Rotor, K: np.ndarray, node: int, dof: str, held: bool = False) -> float | None:
    """Direct static compliance at (node, dof) of the linearised rotor; None where it is not positive
    and finite.  A direction the bearings do not hold raises SingularRotorError when ``held`` (the
    compliance asked for), else gives None."""
    k = rotor.dofs.index(node, dof)
    e = np.zeros(rotor.dofs.size)
    e[k] = 1.0
    try:
        c = float(_solve(K, e, "the linearised rotor")[k])
    except SingularRotorError:
        if held:
            raise
        return None
    return c if np.isfinite(c) and c > 0 else None
