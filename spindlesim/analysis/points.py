"""The spindle at its operating points, solved once: the one object every rotor analysis reads.

An operating point is a speed (and, with the thermal model, a temperature state).  :class:`OperatingPoints`
is built from a rotor and

* assembles the shaft once (``fe.assembly``);
* solves the static state at each operating point once (``operating.operating_state``: every bearing's
  nonlinear reaction, its operating point frozen), keeps it, and along a list of speeds starts each from
  its neighbour's (:meth:`along`) with one failure policy: what was solved is kept, the failing point is
  named (a bearing that cannot carry its load at rest is left out at 0 rpm only, with a warning); a
  Ctrl-C keeps what was solved too, marked as interrupted; a long list of bearings solved by iteration is
  shared with a forked child (the second half; equal states to the solvers' tolerances, the same policy);
* gives the linear system at a state (:meth:`system`, seed 003 eq. 21) and, for many speeds, one reduced
  basis checked against the full model with a criterion given by the analysis (:meth:`basis`: the
  Campbell diagram's roots, the tool point's dominant modes), built once per criterion.

Analyses take an ``OperatingPoints`` (or a rotor, from which they make one): a run builds it once and
every analysis of that run, the FRF and the tool-point model of one ``frf`` command, a Campbell
diagram and its frozen comparison, the lobes at every speed and at the deck speed, reads the same
states.  The counters ``assemblies`` and ``solves`` tell how much was computed (the tests hold them).
"""

from __future__ import annotations

import dataclasses
import functools
import logging
from dataclasses import dataclass
from typing import Callable

import numpy as np

from ..fe.assembly import ShaftMatrices, assemble_shaft
from ..model.rotor import Rotor
from .operating import RPM, OperatingState, SystemMatrices, operating_state, system_matrices

log = logging.getLogger(__name__)

#: what a failing static state raises (a bearing that cannot carry its load, no equilibrium found)
SOLVE_ERRORS = (ValueError, ArithmeticError, RuntimeError, np.linalg.LinAlgError)
#: a list of at least this many speeds still to solve is shared with a forked child (``OperatingPoints.along``)
SHARE_MIN = 16


@dataclass(frozen=True)
class Sweep:
    """Static states along a list of speeds: those solved, in order, and why the list stopped short."""

    speeds_rpm: np.ndarray  # the speeds whose states were found
    states: tuple[OperatingState, ...]
    stopped: str = ""  # "" (every speed solved) or "stopped at ... rpm: ..." / "interrupted at ..."
    first: int = 0  # index, in the speeds asked for, of the first one solved (0 rpm may be left out)
    interrupted: bool = False  # stopped by Ctrl-C

    def __len__(self) -> int:
        return len(self.states)


class OperatingPoints:
    """The rotor at its operating points (module note).  Mutable only in its caches."""

    def __init__(self, rotor: Rotor, thermal_model=None, shaft: ShaftMatrices | None = None):
        self.rotor = rotor
        self.shaft: ShaftMatrices = assemble_shaft(rotor) if shaft is None else shaft  # shared: the same rotor's
        self.assemblies = 1 if shaft is None else 0
        self.solves = 0
        self._states: dict[float, OperatingState] = {}
        self._bases: dict[tuple, object] = {}
        #: with a spindle thermal model (``model.thermal``), every operating point is the thermal equilibrium of
        #: its speed: the bearings at the temperatures their heat and the motor's give (``spindle_thermal``)
        self.thermal = None
        self._thermal_states: dict[float, object] = {}
        self._warm_T: dict | None = None  # analyses "warm_up": the temperatures of that instant, computed once
        if thermal_model is not None:
            from .spindle_thermal import SpindleThermal

            self.thermal = SpindleThermal(rotor, thermal_model, self.shaft)

    @classmethod
    def of(cls, source: "Rotor | OperatingPoints") -> "OperatingPoints":
        """``source`` itself, or the operating points of a rotor."""
        return source if isinstance(source, OperatingPoints) else cls(source)

    # ---- static states ------------------------------------------------------------------------
    def state(self, speed_rpm: float | None = None, start: OperatingState | None = None) -> OperatingState:
        """The static state at ``speed_rpm`` (default: the rotor's speed), solved on first use and kept;
        ``start``: a neighbouring speed's state to start from."""
        rpm = float(self.rotor.speed_rpm if speed_rpm is None else speed_rpm)
        st = self._states.get(rpm)
        if st is None:
            if self._states and self._speed_free:  # the state solved at another speed, at this one
                st = dataclasses.replace(next(iter(self._states.values())), speed_rad_s=rpm * RPM)
                self._states[rpm] = st
                return st
            if self.thermal is not None:
                st = self.thermal_state(rpm).operating
            else:
                st = operating_state(self.rotor, rpm, self.shaft, start=start)
            self.solves += 1
            self._states[rpm] = st
        return st

    @functools.cached_property
    def _speed_free(self) -> bool:
        """Whether the static state is the same at every speed: no thermal model, every bearing speed-independent
        (the contract's ``speed_independent``: a linear bearing without a speed table) and no speed in the
        shaft's stiffness (no rotating internal damping, whose circulatory term grows with speed).  The loads do
        not depend on speed (``fe.assembly.load_vector``).  Such a rotor's Campbell diagram, FRF and lobes at many
        speeds solve its statics once."""
        return (self.thermal is None and self.shaft.eta_v == 0.0
                and all(b.speed_independent for b in self.rotor.bearings))

    def thermal_state(self, speed_rpm: float):
        """The spindle's thermal equilibrium at ``speed_rpm`` (``spindle_thermal.ThermalState``), started from
        the nearest speed solved, or with ``analyses: warm_up`` the spindle at the temperatures of that instant
        of the warm-up at ``speed_rpm``; needs the thermal model."""
        if self.thermal is None:
            raise ValueError("these operating points have no thermal model (deck section spindle_thermal)")
        rpm = float(speed_rpm)
        ts = self._thermal_states.get(rpm)
        if ts is None:
            at_s = self.thermal.model.analyses_at_s if self.thermal.model.analyses == "warm_up" else None
            if at_s is not None:  # the temperatures of an instant of the warm-up, at this speed
                if self._warm_T is None:
                    self._warm_T = self.thermal.temperatures_at(at_s)
                ts = self.thermal.at(self._warm_T, rpm, time_s=at_s)
            else:
                ts = self.thermal.steady(rpm, start=self._thermal_start(rpm))
            self._thermal_states[rpm] = ts
        return ts

    def _thermal_start(self, rpm: float):
        """Where the loop at ``rpm`` starts: the nearest speed solved, its temperatures extrapolated to ``rpm``
        through it and the next nearest on the same side (a parabola through three where they exist, within
        one spacing of the nearest; a sweep's passes fall from about 7 to 3 a speed; the equilibrium is the
        same to the loop's tolerance)."""
        solved = sorted(self._thermal_states, key=lambda s: abs(s - rpm))
        if not solved:
            return None
        near = self._thermal_states[solved[0]]
        side = [s for s in solved[1:] if (s - solved[0]) * (solved[0] - rpm) > 0][:2]
        if not side or not 0.0 < (rpm - solved[0]) / (solved[0] - side[0]) <= 1.0:
            return near
        xs = [solved[0]] + side
        weights = [np.prod([(rpm - xj) / (xi - xj) for xj in xs if xj != xi]) for xi in xs]  # Lagrange
        states = [self._thermal_states[x] for x in xs]
        T = {n: sum(w * st.temperatures_C[n] for w, st in zip(weights, states)) for n in near.temperatures_C}
        return dataclasses.replace(near, temperatures_C=T)

    def along(self, speeds_rpm, tick: Callable[[], None] | None = None,
              on_state: Callable[[OperatingState, float], None] | None = None, what: str = "") -> Sweep:
        """Static states at every speed, each started from its neighbour's (module note's failure policy);
        ``tick()`` after each speed, ``on_state(state, rpm)`` told of each state found; ``what`` names the
        analysis in the messages.  The first speed's failure is raised (nothing to show).

        A long list of bearings solved by iteration is shared with a forked child once the first speed is solved
        (:meth:`_shared`): the child solves the second half, its first speed from the states known at the fork
        instead of from its neighbour (the same state to the solvers' tolerances); where the child stops short, this
        process goes on from there as it would have alone."""
        speeds = np.asarray(speeds_rpm, float)
        label = f"{what}: " if what else ""
        states: list[OperatingState] = []
        st, first, k, end, other = None, 0, 0, len(speeds), None
        try:
            while k < end:
                s = speeds[k]
                try:
                    st = self.state(s, start=st)
                except KeyboardInterrupt:
                    if not states:
                        raise
                    return self._partial(speeds, states, first, f"interrupted by the user at {s:g} rpm", True, label)
                except SOLVE_ERRORS as exc:
                    if not states and s <= 0 and len(speeds) > 1:  # e.g. a fluid film carries nothing at rest
                        log.warning("%s%g rpm left out (%s)", label, s, exc)
                        first, k = first + 1, k + 1
                        if tick is not None:
                            tick()
                        continue
                    if not states:
                        raise
                    return self._partial(speeds, states, first, f"stopped at {s:g} rpm", False, label, exc)
                states.append(st)
                k += 1
                if not self._told(st, float(s), on_state, tick):
                    return self._partial(speeds, states, first, f"interrupted by the user after {s:g} rpm", True,
                                         label)
                if other is None and len(states) == 1:
                    end, other = self._shared(speeds, k)
                if k == end and other is not None:  # the child's half: its states, then on from where it stopped
                    try:
                        theirs = other.result()
                    except KeyboardInterrupt:
                        return self._partial(speeds, states, first, f"interrupted by the user after {s:g} rpm",
                                             True, label)
                    other, end = None, len(speeds)
                    for st in theirs:
                        states.append(st)
                        k += 1
                        if not self._told(st, float(speeds[k - 1]), on_state, tick):
                            return self._partial(speeds, states, first, "interrupted by the user after "
                                                 f"{speeds[k - 1]:g} rpm", True, label)
        finally:
            if other is not None:
                other.cancel()
        return Sweep(speeds[first:first + len(states)], tuple(states), "", first)

    @staticmethod
    def _told(st: OperatingState, rpm: float, on_state, tick) -> bool:
        """``on_state`` and ``tick`` of :meth:`along` told of a state; False on a Ctrl-C meanwhile (the states found
        are kept)."""
        try:
            if on_state is not None:
                on_state(st, rpm)
            if tick is not None:
                tick()
        except KeyboardInterrupt:
            return False
        return True

    def _shared(self, speeds: np.ndarray, k: int):
        """(where this process stops, the child solving the rest) for :meth:`along` with speeds ``k:`` to go:
        (len(speeds), None) unless they are at least SHARE_MIN, a bearing is solved by iteration (the
        contract's ``iterative``) or the spindle's thermal model sets the states, and a child can be forked."""
        from .aside import Aside, Then, available

        rest = len(speeds) - k
        iterative = self.thermal is not None or any(b.iterative for b in self.rotor.bearings)
        if rest < SHARE_MIN or not iterative or not available():
            return len(speeds), None
        cut = k + rest // 2
        return cut, Then(Aside(_solve_run, self, speeds[cut:]), self._received)

    def _received(self, got) -> list[OperatingState]:
        """The child's states (:func:`_solve_run`) kept here as if solved here."""
        out = []
        for rpm, st, ts in zip(*got):
            st = dataclasses.replace(st, shaft=self.shaft)
            if ts is not None:
                self._thermal_states.setdefault(rpm, dataclasses.replace(ts, operating=st))
                st = self._thermal_states[rpm].operating
            if rpm not in self._states:
                self.solves += 1
                self._states[rpm] = st
            out.append(self._states[rpm])
        return out

    def _partial(self, speeds, states, first, where, interrupted, label, exc=None) -> Sweep:
        done = (states[0].speed_rad_s / RPM, states[-1].speed_rad_s / RPM)
        reason = f"{where} (speeds from {done[0]:g} to {done[1]:g} rpm done)" + (f": {exc}" if exc else "")
        log.warning("%s%s", label, reason)
        return Sweep(speeds[first:first + len(states)], tuple(states), reason, first, interrupted)

    def held(self, frozen_rpm: float, speeds_rpm) -> tuple[OperatingState, ...]:
        """The bearings' state at ``frozen_rpm`` with the shaft (gyroscopics, rotating damping) at every
        speed: a Campbell diagram without the speed effects of the bearings."""
        held = self.state(frozen_rpm)
        return tuple(dataclasses.replace(held, speed_rad_s=float(s) * RPM) for s in np.asarray(speeds_rpm, float))

    # ---- linear systems -------------------------------------------------------------------------
    def system(self, state: OperatingState) -> SystemMatrices:
        """M, C, K of the full model with every bearing linearised at ``state``."""
        return system_matrices(self.rotor, state=state)

    def basis(self, key: tuple, build: Callable[[], object]):
        """The reduced basis an analysis checked with its own criterion, built once per ``key`` (the
        criterion first, then what it was checked at): ``build()`` makes it (None: the full model is used)."""
        if key not in self._bases:
            self._bases[key] = build()
        return self._bases[key]

    def last_basis(self, kind: str):
        """The basis most recently built for a key starting with ``kind`` (None if none was, or it was the
        full model): a candidate another diagram of the same rotor tries first."""
        for key in reversed(list(self._bases)):
            if key[0] == kind and self._bases[key] is not None:
                return self._bases[key]
        return None


def _solve_run(points: OperatingPoints, speeds: np.ndarray) -> tuple[list, list, list]:
    """(speeds [rpm], states, thermal states or None) at ``speeds``, each state from the previous one's, the first
    from the states known (what the child of :meth:`OperatingPoints.along` computes): up to the first that fails
    (this process goes on from there).  The
    shaft's matrices are left out of what is sent back (this process has them; :meth:`OperatingPoints._received` puts
    them back), with the thermal states that set them."""
    out: list[OperatingState] = []
    st = None
    for s in speeds:
        try:
            st = points.state(s, start=st)
        except SOLVE_ERRORS:
            break
        out.append(st)
    thermal = [points._thermal_states.get(float(s)) for s in speeds[:len(out)]]
    return ([float(s) for s in speeds[:len(out)]], [dataclasses.replace(x, shaft=None) for x in out],
            [None if t is None else dataclasses.replace(t, operating=None) for t in thermal])
