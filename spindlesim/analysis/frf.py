"""Frequency response H(w) = (-w^2 M + j w C + K)^-1 (seed 003 eq. 23); unbalance response: .unbalance.

The receptance is the state-space model's (``modal.first_order`` with the input and output DOFs as its
ports), evaluated by :class:`~spindlesim.chatter.state_space.ToolPointModel`: through the complete
eigendecomposition A = V diag(lambda) V^-1,

    H_oi(w) = sum_r (C V)[o, r] (V^-1 B)[r, i] / (j w - lambda_r)

which is exact (no modal truncation) and costs one eigendecomposition for any number of frequencies;
when V is ill-conditioned (defective or rigid-body roots) the resolvent is solved at every frequency
instead.  The tool-point FRF of a chatter analysis is the same model with the tool tip's x and y.
"""

from __future__ import annotations

import logging

import numpy as np

from ..chatter.state_space import ToolPointModel
from ..model.rotor import Rotor
from .modal import first_order, modal_from_matrices
from .operating import SingularRotorError, SystemMatrices, _solve
from .points import OperatingPoints
from .resonance import frequency_refinement
from .results import FrfResult, ModesInRange

log = logging.getLogger(__name__)


def receptance(sysm: SystemMatrices, out_index: int, in_index: int, omega: np.ndarray) -> np.ndarray:
    """Complex receptance [m/N] from force at DOF ``in_index`` to displacement at ``out_index``."""
    P = np.eye(sysm.size)[:, [in_index, out_index]]  # ports: 0 the input, 1 the output
    return ToolPointModel(*first_order(sysm, P)).receptance(np.asarray(omega, float))[:, 1, 0]


def solve_frf(rotor: "Rotor | OperatingPoints", frequencies_hz: np.ndarray, input_node: int, input_dof: str,
              output_node: int, output_dof: str, speed_rpm: float | None = None, refine: bool = False,
              tool_point: bool = False) -> FrfResult:
    """Receptance between (1-based) input and output node/DOF at the rotor speed, and the static
    compliance K^-1 there.  With ``refine`` the frequency grid gets points around every mode whose
    half-power band reaches into it (:func:`.resonance.frequency_refinement`), so that no peak falls
    between two points; ``added`` marks them.  With ``tool_point`` and a rotor with a tool, also the tool
    tip's 2 x 2 receptance on the same grid (``tool_point``: what a chatter analysis at that speed uses)."""
    points = OperatingPoints.of(rotor)
    r = points.rotor
    speed = r.speed_rpm if speed_rpm is None else speed_rpm
    sysm = points.system(points.state(speed))
    f = np.asarray(frequencies_hz, float)
    i_out, i_in = r.dofs.index(output_node - 1, output_dof), r.dofs.index(input_node - 1, input_dof)
    added = modes = None
    if refine and f.size:
        modes = modes_in_range(modal_from_matrices(sysm, r.dofs, r.node_z_m, sysm.size, speed),
                               float(f.min()), float(f.max()))
        f, added = frequency_refinement(f, modes.undamped_frequency_hz, modes.damping_ratio)
        log.info("FRF grid: %d points added around %d modes in range", int(added.sum()), len(modes.frequency_hz))
    h = receptance(sysm, i_out, i_in, 2 * np.pi * f)
    tool = None
    if tool_point and r.tool_tip is not None:
        from .tool_point import tool_point_model

        tool = tool_point_model(points, speed).frf(f)
    return FrfResult(frequency_hz=f, receptance_m_N=h, input_node=input_node, input_dof=input_dof,
                     output_node=output_node, output_dof=output_dof, speed_rpm=speed, added=added, modes=modes,
                     static_compliance_m_N=static_compliance(sysm.K, i_out, i_in), tool_point=tool)


def modes_in_range(m, lo_hz: float, hi_hz: float, reach: float = 3.0) -> ModesInRange:
    """The modes of ModalResult ``m`` whose band f_n (1 +- ``reach`` zeta) overlaps [lo, hi] Hz."""
    fn, z = m.undamped_frequency_hz, np.abs(m.damping_ratio)
    sel = (fn * (1 + reach * z) >= lo_hz) & (fn * (1 - reach * z) <= hi_hz)
    return ModesInRange(frequency_hz=m.frequency_hz[sel], undamped_frequency_hz=fn[sel],
                        damping_ratio=m.damping_ratio[sel], whirl=tuple(w for w, k in zip(m.whirl, sel) if k))


def static_compliance(K: np.ndarray, out_index: int, in_index: int) -> float | None:
    """K^-1 [out, in] [m/N]: the receptance at 0 Hz (damping and gyroscopics drop out); None where the
    stiffness does not hold the input direction (a rigid-body motion)."""
    e = np.zeros(K.shape[0])
    e[in_index] = 1.0
    try:
        c = float(_solve(K, e, "the rotor at the FRF's operating point")[out_index])
    except SingularRotorError:
        return None
    return c if np.isfinite(c) else None


from .unbalance import solve_unbalance  # noqa: E402,F401  (its home was this module)
