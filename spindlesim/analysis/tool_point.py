"""The rotor's tool-point dynamics as a state-space model at one or many spindle speeds.

At a speed the rotor (bearings linearised at that speed's static state) is, in the coordinates of
a basis T (the identity, or the reduced basis of ``reduced``),

    M_r q'' + C_r q' + K_r q = P f,    y = P^T q,    P = T[tip, :]^T  (tip = x and y of the point),

and with x = (q, q'):  A = [[0, I], [-M_r^-1 K_r, -M_r^-1 C_r]],  B = [[0], [M_r^-1 P]],
C = [P^T, 0], so that C (j w I - A)^-1 B is the 2 x 2 receptance (xx, xy; yx, yy) of the point:
the tool-point FRF a chatter analysis needs, as :class:`~spindlesim.chatter.ToolPointModel`.

Many speeds (a lobe diagram with the FRF recomputed at every speed) use the reduced basis with
the tool point's DOFs in its interface, built once.  It is accepted when, at the first and the last
speed, every mode of the full model whose peak compliance at the point is at least a tenth of the
largest (the modes a chatter frequency sits on) has a reduced twin within ``FREQ_RTOL`` in
frequency and ``PEAK_RTOL`` in peak compliance (a limit depth of cut scales with 1/peak);
otherwise the full model is used at every speed.  (A pointwise FRF comparison would be ruled by
the lightly damped modes far above the cut, whose peaks move with any frequency change.)
"""

from __future__ import annotations

import logging
from dataclasses import dataclass
from typing import Callable

import numpy as np
import scipy.linalg as sla

from ..chatter.state_space import ToolPointModel
from ..fe.assembly import assemble_shaft
from ..model.rotor import Rotor
from .operating import OperatingState, SystemMatrices, operating_state, system_matrices
from .reduced import FACTORS, MAX_SHARE, reduced_basis

log = logging.getLogger(__name__)

FREQ_RTOL = 1e-4
PEAK_RTOL = 5e-3
DOMINANT = 0.1  # modes with this share of the largest peak compliance are checked


@dataclass(frozen=True)
class ToolPointSeries:
    """Tool-point models at each speed, and which model of the rotor gave them."""

    speeds_rpm: np.ndarray
    models: tuple[ToolPointModel, ...]
    node: int  # 1-based
    model: str  # "full state space" or "reduced: m of n coordinates"
    states: tuple[OperatingState, ...]


def point_dofs(rotor: Rotor, node: int | None) -> tuple[int, np.ndarray]:
    """(1-based node, its x and y DOF indices): ``node``, else the tool tip, else node 1."""
    n = node if node is not None else (rotor.tool_tip + 1 if rotor.tool_tip is not None else 1)
    return n, np.array([rotor.dofs.index(n - 1, "x"), rotor.dofs.index(n - 1, "y")])


def state_space(sysm: SystemMatrices, P: np.ndarray, source: str = "") -> ToolPointModel:
    """The module note's (A, B, C) of M, C, K with force/response map ``P`` [n, 2]."""
    n = sysm.size
    MinvKCP = sla.solve(sysm.M, np.hstack([sysm.K, sysm.C, P]), assume_a="pos", check_finite=False)
    A = np.zeros((2 * n, 2 * n))
    A[:n, n:] = np.eye(n)
    A[n:, :n] = -MinvKCP[:, :n]
    A[n:, n:] = -MinvKCP[:, n:2 * n]
    B = np.zeros((2 * n, 2))
    B[n:] = MinvKCP[:, 2 * n:]
    C = np.zeros((2, 2 * n))
    C[:, :n] = P.T
    return ToolPointModel(A, B, C, source)


def tool_point_model(rotor: Rotor, speed_rpm: float | None = None, node: int | None = None) -> ToolPointModel:
    """The full model's tool-point state space at one speed (default: the rotor's)."""
    speed = rotor.speed_rpm if speed_rpm is None else float(speed_rpm)
    n, tip = point_dofs(rotor, node)
    sysm = system_matrices(rotor, speed)
    return state_space(sysm, np.eye(sysm.size)[:, tip], f"rotor model, node {n}, {speed:g} rpm")


def tool_point_series(rotor: Rotor, speeds_rpm, node: int | None = None, exact: bool = False,
                      progress: Callable[[int, int], None] | None = None) -> ToolPointSeries:
    """Tool-point models at every speed (static states warm-started from the neighbouring speed)."""
    speeds = np.asarray(speeds_rpm, float)
    n_node, tip = point_dofs(rotor, node)
    shaft = assemble_shaft(rotor)
    total = 2 * len(speeds)
    states, st = [], None
    for k, s in enumerate(speeds):
        st = operating_state(rotor, s, shaft, start=st)
        states.append(st)
        if progress is not None:
            progress(k + 1, total)
    size = shaft.M.shape[0]
    eye = np.eye(size)[:, tip]

    def full(st):
        return state_space(system_matrices(rotor, state=st), eye)

    basis, model = None, "full state space"
    if not exact and len(speeds) > 2:
        basis = _checked_basis(rotor, shaft, states, tip, full)
        if basis is not None:
            model = f"reduced: {basis.size} of {size} coordinates"
    models = []
    for k, (s, st) in enumerate(zip(speeds, states)):
        if basis is None:
            m = full(st)
        else:
            m = state_space(basis.system(st), basis.T[tip].T)
        models.append(ToolPointModel(m.A, m.B, m.C, f"rotor model ({model}), node {n_node}, {s:g} rpm"))
        if progress is not None:
            progress(len(speeds) + k + 1, total)
    return ToolPointSeries(speeds, tuple(models), n_node, model, tuple(states))


def _checked_basis(rotor, shaft, states, tip, full):
    """The smallest reduced basis (cut-offs of ``reduced.FACTORS``) whose dominant tool-point modes at
    the first and last speed match the full model's (module note); None if none pays."""
    check = [states[0], states[-1]]
    reference = [full(st).significant_modes(rel=DOMINANT) for st in check]
    size = shaft.M.shape[0]
    for factor in FACTORS:
        basis = reduced_basis(rotor, shaft, states[0], 8, tuple(tip), factor=factor)
        if basis.size > MAX_SHARE * size:
            break
        P = basis.T[tip].T
        df = dp = 0.0
        for st, modes in zip(check, reference):
            reduced = state_space(basis.system(st), P).modes()
            for m in modes:
                twin = min(reduced, key=lambda r: abs(r.frequency_hz - m.frequency_hz))
                df = max(df, abs(twin.frequency_hz / m.frequency_hz - 1))
                dp = max(dp, abs(twin.peak_compliance_m_N / m.peak_compliance_m_N - 1))
        log.debug("tool-point model, reduced basis of %d: frequency %.1e, peak compliance %.1e", basis.size, df, dp)
        if df <= FREQ_RTOL and dp <= PEAK_RTOL:
            log.info("tool-point model: reduced, %d of %d coordinates (dominant modes within %.1e in frequency, "
                     "%.1e in peak compliance at the first and last speed)", basis.size, size, df, dp)
            return basis
    log.info("tool-point model: full (a reduced one as accurate needs more than %d of %d coordinates)",
             int(MAX_SHARE * size), size)
    return None
