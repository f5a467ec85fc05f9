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

from ..chatter.state_space import ToolPointModel
from ..model.rotor import Rotor
from .modal import first_order
from .operating import EquilibriumError, OperatingState, SystemMatrices, system_matrices
from .points import OperatingPoints
from .reduced import checked_basis, on_cores

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
    """The module note's (A, B, C) of M, C, K with force/response map ``P`` [n, 2] (modal.first_order)."""
    return ToolPointModel(*first_order(sysm, P), source)


def tool_point_model(rotor: "Rotor | OperatingPoints", speed_rpm: float | None = None,
                     node: int | None = None) -> ToolPointModel:
    """The full model's tool-point state space at one speed (default: the rotor's)."""
    points = OperatingPoints.of(rotor)
    r = points.rotor
    speed = r.speed_rpm if speed_rpm is None else float(speed_rpm)
    n, tip = point_dofs(r, node)
    sysm = points.system(points.state(speed))
    return state_space(sysm, np.eye(sysm.size)[:, tip], f"rotor model, node {n}, {speed:g} rpm")


class ToolPointModesMatch:
    """Criterion of the reduced basis for tool-point models (module note): the dominant modes at the
    point have reduced twins within ``FREQ_RTOL`` in frequency and ``PEAK_RTOL`` in peak compliance."""

    def __init__(self, tip: np.ndarray):
        self.tip = np.asarray(tip)

    def reference(self, rotor: Rotor, states) -> list:
        eye = np.eye(rotor.dofs.size)[:, self.tip]
        # each a full eigenproblem with eigenvectors, which releases the interpreter lock: side by side
        return on_cores(lambda st: state_space(system_matrices(rotor, state=st), eye).significant_modes(rel=DOMINANT),
                        states)

    def accepts(self, basis, states, reference) -> tuple[bool, str]:
        P = basis.T[self.tip].T
        df = dp = 0.0
        for st, modes in zip(states, reference):
            reduced = state_space(basis.system(st), P).modes()
            for m in modes:
                twin = min(reduced, key=lambda r: abs(r.frequency_hz - m.frequency_hz))
                df = max(df, abs(twin.frequency_hz / m.frequency_hz - 1))
                dp = max(dp, abs(twin.peak_compliance_m_N / m.peak_compliance_m_N - 1))
        return df <= FREQ_RTOL and dp <= PEAK_RTOL, (f"dominant tool-point modes within {df:.1e} in frequency, "
                                                     f"{dp:.1e} in peak compliance")


def tool_point_series(rotor: "Rotor | OperatingPoints", speeds_rpm, node: int | None = None, exact: bool = False,
                      progress: Callable[[int, int], None] | None = None) -> ToolPointSeries:
    """Tool-point models at every speed (static states warm-started from the neighbouring speed)."""
    points = OperatingPoints.of(rotor)
    r = points.rotor
    speeds = np.asarray(speeds_rpm, float)
    n_node, tip = point_dofs(r, node)
    total = 2 * len(speeds)
    done = [0]

    def tick():
        done[0] += 1
        if progress is not None:
            progress(done[0], total)

    sweep = points.along(speeds, tick, what="tool-point models")
    if sweep.interrupted:
        raise KeyboardInterrupt
    if sweep.stopped or sweep.first:
        raise EquilibriumError(f"tool-point models: {sweep.stopped or 'no static state at 0 rpm'}")
    states = sweep.states
    size = points.shaft.M.shape[0]
    basis, model = None, "full state space"
    if not exact and len(speeds) > 2:
        check = (float(speeds[0]), float(speeds[-1]))
        basis = points.basis(("tool point", n_node, check), lambda: checked_basis(
            r, points.shaft, list(states), 8, extra_dofs=tuple(tip), criterion=ToolPointModesMatch(tip),
            candidate=points.last_basis("tool point")))
        if basis is not None:
            model = f"reduced: {basis.size} of {size} coordinates"
    eye = np.eye(size)[:, tip]
    models = []
    for s, st in zip(speeds, states):
        m = state_space(points.system(st), eye) if basis is None else state_space(basis.system(st), basis.T[tip].T)
        models.append(ToolPointModel(m.A, m.B, m.C, f"rotor model ({model}), node {n_node}, {s:g} rpm"))
        tick()
    return ToolPointSeries(speeds, tuple(models), n_node, model, tuple(states))


#: bearings whose coefficients change more than this over the speed range are speed-dependent
COEFFICIENT_RTOL = 1e-3


def coefficients_change(rotor: "Rotor | OperatingPoints", speeds_rpm) -> bool:
    """Whether any bearing's stiffness or damping changes by more than COEFFICIENT_RTOL between the first and
    the last of ``speeds_rpm`` (then a lobe diagram needs the tool-point FRF at every speed)."""
    points = OperatingPoints.of(rotor)
    a, b = points.state(float(speeds_rpm[0])), points.state(float(speeds_rpm[-1]))
    for (ka, ca), (kb, cb) in zip(a.coefficients, b.coefficients):
        for x, y in ((ka, kb), (ca, cb)):
            scale = max(float(np.max(np.abs(x))), float(np.max(np.abs(y))))
            if scale > 0 and float(np.max(np.abs(x - y))) > COEFFICIENT_RTOL * scale:
                return True
    return False
