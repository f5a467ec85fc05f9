"""The rotor at an operating point: static equilibrium with every bearing's full nonlinear
reaction (the one static solver), and the linear system about it.

Static equilibrium at a speed Omega (angle 0, t = 0), unknowns the rotor DOFs q and every
bearing's internal DOFs z_b::

    K_s(Omega) q = Q + sum_b f_b(q_b, z_b),   0 = f_b,internal(q_b, z_b)

solved by the damped Newton of the statics (``bearings.statics.damped_newton``) with the bearings'
tangents (``force_and_tangent``, the contract): undamped at first, a step that raises |R| halved (up to 29
times) before the Levenberg-Marquardt damping grows (contact laws have zero stiffness at first touch), and
a position a bearing refuses (a journal at the bore) a refused step.

The operating point of each bearing (a fluid film's thermal-equilibrium viscosity) depends on
its load, which the equilibrium gives: the loads start from a solve on stiff supports (exact
for a statically determinate rotor), the bearings are frozen there (``at_operating_point``),
and the freeze is repeated with the new loads until they change by less than 1e-6.

The linear system at the operating point adds each bearing's ``linearized(speed, load)`` to the
shaft matrices (seed 003 eq. 21): M q'' + C q' + K q = Q.
"""

from __future__ import annotations

import logging
import warnings
from dataclasses import dataclass
from functools import cached_property

import numpy as np
import scipy.linalg as sla

from ..bearings.statics import damped_newton
from ..fe.assembly import ShaftMatrices, assemble_shaft, load_vector
from ..model.rotor import Rotor

log = logging.getLogger(__name__)
RPM = np.pi / 30.0
#: relative change of the bearing loads below which the frozen operating points are kept
LOAD_TOL = 1e-6


class EquilibriumError(ArithmeticError):
    """The rotor's static equilibrium was not found (what was tried is in the message)."""


class SingularRotorError(ValueError):
    """The rotor is not held against rigid-body motion in the direction of its loads."""

    #: where the deck holds what to correct (its supports), for a located message
    deck_key = ("bearings",)


class BearingSolveError(ValueError):
    """A bearing's own solver failed at an operating point; the message names the bearing and the speed."""


def _freeze(b, speed: float, load, transient: bool):
    """``b.at_operating_point`` with a failure named by bearing and speed (a thermal equilibrium not
    found, a film that cannot carry the load ...)."""
    try:
        return b.at_operating_point(speed, load, transient)
    except (ValueError, ArithmeticError, RuntimeError, np.linalg.LinAlgError) as exc:
        text = str(exc)
        own = f"bearing {b.name!r}: "
        text = text[len(own):] if text.startswith(own) else text  # the bearing named once
        raise BearingSolveError(f"bearing {b.name!r} at {speed / RPM:.6g} rpm: {text}") from exc


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


@dataclass(frozen=True)
class OperatingState:
    """Static equilibrium of the rotor at one speed and its bearings there."""

    speed_rad_s: float
    q: np.ndarray  # rotor DOFs at static equilibrium
    internal: tuple[np.ndarray, ...]  # each bearing's internal DOFs there (empty for most)
    bearings: tuple  # the rotor's bearings frozen at their operating points
    loads: tuple[np.ndarray, ...]  # what the shaft puts on each bearing, on its dof_names (= -f_b)
    operating_loads: tuple[np.ndarray, ...]  # the loads the bearings were frozen and are linearised at
    coefficients: tuple[tuple[np.ndarray, np.ndarray], ...]  # each bearing's linearized() there (K, C)
    bearing_index: tuple[np.ndarray, ...]  # rotor DOF indices of each bearing's dof_names
    Q: np.ndarray  # static load vector
    shaft: ShaftMatrices
    newton_iterations: int

    def load_of(self, name: str) -> np.ndarray:
        for b, w in zip(self.bearings, self.loads):
            if b.name == name:
                return w
        raise KeyError(name)


def bearing_indices(rotor: Rotor) -> tuple[np.ndarray, ...]:
    """Rotor DOF indices of every bearing's ``dof_names`` at its node."""
    return tuple(rotor.dofs.at(b.node, b.dof_names) for b in rotor.bearings)


def _stiff_support_loads(rotor: Rotor, shaft: ShaftMatrices, K_s: np.ndarray, Q: np.ndarray,
                         idx: tuple[np.ndarray, ...]) -> list[np.ndarray]:
    """Bearing loads with every bearing replaced by stiff springs on its DOFs."""
    K = K_s.copy()
    k_stiff = 1e3 * max(float(np.max(np.abs(np.diag(K_s)))) if K_s.size else 1.0, 1e6)
    for i in idx:
        K[i, i] += k_stiff
    q = _solve(K, Q, "the rotor on stiff supports")
    return [k_stiff * q[i] for i in idx]


def _solve(K: np.ndarray, r: np.ndarray, what: str) -> np.ndarray:
    """K q = r; a singular K is accepted when r has no part along its null space (an unloaded rigid-body
    direction, e.g. the axial motion of a rotor without axial load), else SingularRotorError."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sla.LinAlgWarning)  # singularity is checked and reported below
        lu = sla.lu_factor(K, check_finite=False)
    piv = np.abs(np.diag(lu[0]))
    if np.all(np.isfinite(piv)) and piv.min() > 1e-11 * piv.max():
        return sla.lu_solve(lu, r, check_finite=False)
    d = np.abs(np.diag(K))
    if np.all(d > 0) and np.all(np.isfinite(d)):  # badly scaled rather than singular (a thin tool's tilts against
        s = 1.0 / np.sqrt(d)                       # stiff supports): the same test on the equilibrated matrix
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", sla.LinAlgWarning)
            lu = sla.lu_factor(s[:, None] * K * s[None, :], check_finite=False)
        piv = np.abs(np.diag(lu[0]))
        if np.all(np.isfinite(piv)) and piv.min() > 1e-11 * piv.max():
            rs = np.asarray(r).reshape(len(r), -1) * s[:, None]
            return (sla.lu_solve(lu, rs, check_finite=False) * s[:, None]).reshape(np.shape(r))
    q = np.linalg.lstsq(K, r, rcond=1e-11)[0]
    res = (K @ q - r).reshape(len(r), -1)  # each right-hand side on its own
    rr = np.asarray(r).reshape(len(r), -1)
    if all(np.linalg.norm(res[:, k]) <= 1e-9 * max(float(np.linalg.norm(rr[:, k])), 1e-300) or not np.any(rr[:, k])
           for k in range(rr.shape[1])):
        return q
    raise SingularRotorError(f"the stiffness matrix of {what} is singular: the rotor is not held against "
                             "rigid-body motion in the direction of its loads (the bearings must support x and y "
                             "at two nodes, or at one node with moment stiffness; an axial load needs an axial "
                             "support), or its stiffnesses differ by more than 1e11 (a unit mistake: shaft "
                             "dimensions in metres under _mm keys, a stiffness in N/mm under an N/m key)")


def operating_state(rotor: Rotor, speed_rpm: float | None = None, shaft: ShaftMatrices | None = None,
                    tol: float = 1e-10, max_iter: int = 100, freeze: bool = True,
                    transient: bool = False, start: OperatingState | None = None,
                    linearize: bool = True) -> OperatingState:
    """Static equilibrium at ``speed_rpm`` (default: the rotor's) with the bearings' nonlinear reactions.

    ``freeze=False`` takes the bearings as they are (already frozen at an operating point, e.g.
    the deck speed's, for the start of a run-up); ``transient=True`` freezes them for a time
    integration (the contract's ``at_operating_point``); ``start`` is the state of a neighbouring
    speed to start from (a Campbell diagram's previous speed).;
    ``linearize=False`` leaves the bearings' coefficients out (None: a state only the loads of which are read,
    e.g. a pass of the spindle's thermal loop)."""
    speed = (rotor.speed_rpm if speed_rpm is None else speed_rpm) * RPM
    shaft = assemble_shaft(rotor) if shaft is None else shaft
    K_s = shaft.stiffness(speed)
    Q = load_vector(rotor, shaft)
    idx = bearing_indices(rotor)
    n = K_s.shape[0]
    if start is None:
        loads = _stiff_support_loads(rotor, shaft, K_s, Q, idx)
        internal = [np.zeros(b.internal_mass.size) for b in rotor.bearings]
        q = None
        K_lin = None
    else:
        loads, q, internal = list(start.operating_loads), start.q.copy(), [z.copy() for z in start.internal]
        K_lin = None  # the first pass starts affinely with the neighbour's coefficients, which sets it
    coef = None
    total = 0
    frozen = None
    for outer in range(10):
        previous = frozen
        frozen = tuple(_freeze(b, speed, w, transient) if freeze else b for b, w in zip(rotor.bearings, loads))
        if previous is not None and all(a is b for a, b in zip(frozen, previous)):
            break  # nothing the loads set has changed: the equilibrium found stands
        if q is None:
            q, internal, K_lin, coef = _affine_start(frozen, idx, K_s, Q, loads, speed)
        elif start is not None and outer == 0 and start.coefficients[0] is None:
            K_lin = K_s  # a neighbour without coefficients (a thermal pass): Newton from its displacements
        elif start is not None and outer == 0:
            # the affine start is exact when the loads the bearings were frozen at are the answer (a
            # neighbouring speed's loads often are): better than the neighbour's displacements
            q, internal, K_lin, _ = _affine_start(frozen, idx, K_s, Q, loads, speed, start.coefficients,
                                                  _displacements(start.q, start.internal, idx))
        q, internal, f, its = _newton(rotor, frozen, idx, K_s, Q, q, internal, speed, tol, max_iter, np.diag(K_lin))
        total += its
        new = [-fb[: len(i)] for fb, i in zip(f, idx)]
        scale = max(max((float(np.max(np.abs(w))) for w in new), default=0.0), 1e-9)
        change = max((float(np.max(np.abs(a - b))) for a, b in zip(new, loads)), default=0.0) / scale
        if change > LOAD_TOL:
            coef = None  # the coefficients of the start are no longer those of the operating loads
        loads = new if change > LOAD_TOL else loads
        if change <= LOAD_TOL or not freeze:
            break
    else:
        log.warning("bearing loads still change by %.2g after 10 operating-point updates", change)
    if coef is None and linearize:  # each bearing from its displacement in the state (the answer when the
        # loads are those it carries, as they are to LOAD_TOL)
        coef = [b.linearized(speed, w, start=d) for b, w, d in zip(frozen, loads, _displacements(q, internal, idx))]
    elif coef is None:
        coef = [None] * len(frozen)
    return OperatingState(speed, q, tuple(internal), frozen, tuple(new), tuple(loads), tuple(coef), idx, Q, shaft,
                          total)


def _displacements(q, internal, idx) -> list[np.ndarray]:
    """Each bearing's displacement in a state: its node DOFs of q, then its internal DOFs."""
    return [np.concatenate([q[i], z]) for i, z in zip(idx, internal)]


def _affine_start(bearings, idx, K_s, Q, loads, speed, near_coef=None, near=None):
    """Start of Newton: each bearing replaced by f_b = -W_b - K_b (q_b - d_b) about the displacement
    d_b that carries its estimated load W_b (``static_displacement``, from the neighbouring speed's
    displacement ``near`` when given): exact when the loads are, whatever K_b; ``near_coef`` (a
    neighbouring speed's coefficients) saves the ``linearized`` calls, which otherwise start from d_b."""
    K, r = K_s.copy(), Q.copy()
    internal, coef = [], []
    for k, (b, i, w) in enumerate(zip(bearings, idx, loads)):
        d = b.static_displacement(speed, w, start=None if near is None else near[k])
        kb, cb = b.linearized(speed, w, start=d) if near_coef is None else near_coef[k]
        coef.append((kb, cb))
        K[np.ix_(i, i)] += kb
        r[i] += kb @ d[: len(i)] - w
        internal.append(np.asarray(d[len(i):], float))
    # one factorisation for both: the loads themselves must be carried (raises when a direction is not
    # held), and the start
    q = _solve(K, np.column_stack([Q, r]), "the rotor on its linearised bearings")[:, 1]
    return q, internal, K, coef


def _newton(rotor, bearings, idx, K_s, Q, q, internal, speed, tol, max_iter, k_diag):
    """The damped Newton of the statics (``bearings.statics.damped_newton``) on [q, z_1, z_2, ...] (module
    note); ``k_diag`` (rotor DOFs) scales the damping where the tangent has no stiffness yet (a journal in
    its clearance)."""
    n = q.size
    sizes = [z.size for z in internal]
    offs = np.cumsum([n] + sizes)
    N = int(offs[-1])
    gidx = [np.concatenate([i, np.arange(o - s, o)]) for i, s, o in zip(idx, sizes, offs[1:])]
    f_scale = max(float(np.max(np.abs(Q))) if Q.size else 0.0, 1.0)

    def evaluate(x):
        R = np.zeros(N)
        R[:n] = Q - K_s @ x[:n]
        J = np.zeros((N, N))
        J[:n, :n] = K_s
        forces = []
        for b, gi in zip(bearings, gidx):
            fb, kt, _ = b.force_and_tangent(x[gi], np.zeros(gi.size), 0.0, speed, 0.0)
            R[gi] += fb
            J[np.ix_(gi, gi)] += kt
            forces.append(fb)
        return R, J, (x, forces)

    last = [None, np.inf]  # the point converged() saw last and its |R|: the step since, the stall

    def converged(R, data):
        x, forces = data
        scale = _force_scale(f_scale, forces)
        r, rn = float(np.max(np.abs(R))), float(np.linalg.norm(R))
        before, rn_before = last
        last[:] = data, rn
        if before is None or before is data:  # the start, or the same point after a refused step
            return r <= 1e-3 * tol * scale
        if rn > 0.5 * rn_before and r <= 1e-7 * scale:
            return True  # a step taken that hardly lowered a residual at the round-off floor
        # the residual at round-off and the last step small (a Newton step of 1e-6 of the displacement with
        # the residual already below tol leaves the next one at ~1e-12: not worth a solve)
        small_step = np.max(np.abs(x - before[0])) <= 1e-6 * max(float(np.max(np.abs(x))), 1e-12)
        return r <= tol * scale and (small_step or r <= 1e-3 * tol * scale)

    x0 = np.concatenate([q] + list(internal))
    first = evaluate(x0)
    dj = np.abs(np.diag(first[1]))
    dj[:n] = np.maximum(dj[:n], np.abs(k_diag))
    damping = np.maximum(dj, 1e-12 * max(float(np.max(dj)), 1.0))
    out = damped_newton(evaluate, x0, converged=converged, merit=lambda R: float(np.linalg.norm(R)), cap=np.inf,
                        damping=damping, lam0=0.0, shrink=0.1, lam_min=0.0, grow=10.0, lam_restart=1e-6,
                        lam_max=1e8, max_iter=max_iter, backtrack=29, refuse=(ValueError, ArithmeticError),
                        evaluated=first, floor=lambda R, d: np.max(np.abs(R)) <= 1e-6 * _force_scale(f_scale, d[1]))
    x, forces = out.data
    if out.converged:
        return x[:n], [x[o - s:o] for s, o in zip(sizes, offs[1:])], forces, out.iterations
    names = ", ".join(b.name for b in bearings) or "none"
    why = "the iteration limit" if out.iterations >= max_iter else "the damping limit (every step refused)"
    raise EquilibriumError(
        f"static equilibrium at {speed / RPM:.6g} rpm did not converge: damped Newton with the nonlinear "
        f"reactions of the bearings ({names}) stopped at {why} after {out.iterations} of {max_iter} iterations, "
        f"residual {np.max(np.abs(out.R)):.3g} N (largest at DOF {int(np.argmax(np.abs(out.R)))})")


def _force_scale(load_scale: float, forces) -> float:
    """The largest force in the balance (loads and bearing forces): the residual's round-off scale."""
    return max(load_scale, max((float(np.max(np.abs(fb))) for fb in forces if fb.size), default=0.0))


def system_matrices(rotor: Rotor, speed_rpm: float | None = None, state: OperatingState | None = None,
                    shaft: ShaftMatrices | None = None) -> SystemMatrices:
    """M, C, K with every bearing linearised at the static equilibrium of that speed."""
    st = operating_state(rotor, speed_rpm, shaft) if state is None else state
    K = st.shaft.stiffness(st.speed_rad_s).copy()
    C = st.shaft.damping(st.speed_rad_s).copy()
    for (kb, cb), i in zip(st.coefficients, st.bearing_index):
        K[np.ix_(i, i)] += kb
        C[np.ix_(i, i)] += cb
    return SystemMatrices(M=st.shaft.M, C=C, K=K, speed_rad_s=st.speed_rad_s)
