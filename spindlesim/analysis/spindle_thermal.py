"""Thermal equilibrium of the whole spindle: bearing and motor heat, temperatures, growth, preload, stiffness.

One loop (issue 22; seed 003 does it for a fluid film, eqs. 4-14), at a speed:

1. the temperatures T of the thermal network's nodes (start: the ambient, or a neighbouring speed's);
2. every bearing at its parts' temperatures (``at_temperatures``: grown rings and rolling elements, fits,
   the operating clearance and preload) and shifted axially by the different growth of shaft and housing
   between its seat and the housing's front face (``bearings.base.AxiallyShifted``):

       offset_k = int_{z_h}^{z_k} alpha_s (T_shaft(z) - T_ref) dz - int_{z_h}^{z_k} alpha_h (T_housing(z) - T_ref) dz

   (a common offset of every set moves the rotor rigidly and changes no load);
3. the rotor's static equilibrium at the speed on those bearings (``operating.operating_state``);
4. each bearing's heat at its operating point (``heat``: a ball set's spin, rolling and drag of the balls,
   a roller bearing's Palmgren moment; split to inner ring, rolling elements and outer ring) and the motor's
   losses;
5. the network's steady state with these sources and the contact conductances of the bearings' loads.

Repeated until no node's temperature changes by more than the tolerance (0.01 K by default).  When the heat
feeds the preload faster than the spindle can carry it away, the temperatures and the preload climb at every
step: the loop stops and says which bearing ran away at which speed (the speed limit of that arrangement).

A warm-up integrates the network's heat capacities through a speed profile (``SpindleNetwork.warm_up``), the
bearings' heat re-evaluated from their state at the current temperatures whenever a bearing's parts have moved
by more than ``REFRESH_K``.

The tool tip's axial drift (what ISO 230-3 measures) is its elastic axial displacement plus the free growth of
the shaft from the housing's front face to the tip (the holder and tool at the temperature of the nose); its
radial drift is its static deflection (x, y) in the state (the network is axisymmetric: the rings', shaft's and
housing's radial growth moves no axis, the bearings' stiffness and the loads move the tip).  Both are positions
against the cold, unloaded spindle: a warm-up's drift is their change from its first instant.
"""

from __future__ import annotations

import dataclasses
import logging
from dataclasses import dataclass

import numpy as np

from ..bearings.base import AxiallyShifted, HeatReport
from ..fe.assembly import ShaftMatrices, assemble_shaft
from ..model.rotor import Rotor
from ..model.thermal import SpindleThermalModel
from ..thermal.growth_bearings import BearingTemperatures
from ..thermal.properties import PropertyRangeError
from ..thermal.spindle_network import BearingContacts, BearingHeat, build_spindle_network
from ..thermal.transient import StepProfile
from .operating import RPM, OperatingState, operating_state

log = logging.getLogger(__name__)

#: the loop gives up after this many passes
MAX_ITERATIONS = 60
#: a bearing part this hot means the arrangement has run away (no lubricant survives it)
RUNAWAY_C = 250.0
#: a warm-up re-evaluates the bearings' heat when one of their parts has moved by this much [K], and at least
#: this often in time [s] (so that near its end the heat is that of the temperatures reached, not of a
#: moment before: the warm-up then ends in the steady state)
REFRESH_K = 0.25
REFRESH_S = 300.0


class ThermalRunawayError(ArithmeticError):
    """The spindle has no thermal equilibrium at a speed (the message names the bearing and the speed)."""


@dataclass(frozen=True)
class ThermalState:
    """The spindle at its thermal equilibrium (or at an instant of a warm-up) at one speed."""

    speed_rpm: float
    temperatures_C: dict[str, float]  # every network node
    heat_W: dict[str, float]  # per source: "bearing:<name>", "motor:stator", "motor:rotor"
    bearings: dict[str, HeatReport]  # each bearing's heat, preload (row thrust) and contact angles
    parts_C: dict[str, BearingTemperatures]  # each bearing's parts
    axial_offsets_m: dict[str, float]
    operating: OperatingState  # the rotor's static state on the bearings at temperature
    tool_tip_axial_drift_m: float | None
    iterations: int
    converged: bool = True
    time_s: float | None = None  # an instant of a warm-up
    removed_W: dict[str, float] | None = None  # heat carried to each boundary (ambient, coolant inlet)
    stored_W: float = 0.0  # generated - removed: zero at a steady state, what warms the parts in a warm-up
    tool_tip_radial_m: tuple[float, float] | None = None  # the tip's static deflection x, y (module note)

    @property
    def total_heat_W(self) -> float:
        return float(sum(self.heat_W.values()))


class SpindleThermal:
    """The coupled model (module note) of a rotor and its :class:`~spindlesim.model.thermal.SpindleThermalModel`."""

    def __init__(self, rotor: Rotor, model: SpindleThermalModel, shaft: ShaftMatrices | None = None):
        self.rotor, self.model = rotor, model
        self.shaft = assemble_shaft(rotor) if shaft is None else shaft
        self.network = build_spindle_network(model.layout)
        lay = model.layout
        self._names = self.network.network.names
        self._s_edges = lay_edges([s.length_m for s in lay.shaft], 0.0)
        self._h_edges = lay_edges([h.length_m for h in lay.housing], lay.housing_start_m)
        self._by_name = {b.name: b for b in rotor.bearings}
        missing = [n for n in model.bearings if n not in self._by_name]
        if missing:
            raise ValueError(f"spindle_thermal: bearing(s) {missing} are not on the rotor")
        self._z0 = float(rotor.node_z_m[0])
        self._tip_z = None if rotor.tool_tip is None else float(rotor.node_z_m[rotor.tool_tip]) - self._z0
        self._cache: dict = {}
        #: each set's nodes: inner ring, rolling elements (balls or rollers), outer ring
        self._parts = {b.name: (f"bearing:{b.name}:inner", b.elements_node, f"bearing:{b.name}:outer")
                       for b in lay.bearings}

    # ---- temperatures -> bearings ------------------------------------------------------------------
    def parts(self, T: dict[str, float], name: str) -> BearingTemperatures:
        inner, elements, outer = self._parts[name]
        shaft, housing = self.network.seat_C(name, T)
        return BearingTemperatures(T[inner], T[outer], T[elements], self.model.reference_C, shaft, housing)

    def offsets(self, T: dict[str, float]) -> dict[str, float]:
        """Axial offset of each bearing's housing seat against its shaft seat (module note) [m]."""
        lay, m = self.model.layout, self.model
        out = {}
        for b in lay.bearings:
            s = _growth(self._s_edges, [T[f"shaft[{i}]"] for i in range(len(lay.shaft))], m.shaft_expansion_1_K,
                        m.reference_C, lay.housing_start_m, b.position_m)
            h = _growth(self._h_edges, [T[f"housing[{j}]"] for j in range(len(lay.housing))], m.housing_expansion_1_K,
                        m.reference_C, lay.housing_start_m, b.position_m)
            out[b.name] = s - h
        return out

    def rotor_at(self, T: dict[str, float]) -> tuple[Rotor, dict, dict]:
        """(the rotor on its bearings at the temperatures T, parts' temperatures, axial offsets)."""
        parts = {n: self.parts(T, n) for n in self.model.bearings}
        offsets = self.offsets(T)
        hot = []
        for b in self.rotor.bearings:
            if b.name in parts:
                warm = b.at_temperatures(parts[b.name])
                b = AxiallyShifted(warm, offsets[b.name]) if "z" in warm.dof_names else warm
            hot.append(b)
        return dataclasses.replace(self.rotor, bearings=tuple(hot)), parts, offsets

    # ---- one pass of the loop -------------------------------------------------------------------------
    def _pass(self, T: dict[str, float], speed_rpm: float, start: OperatingState | None, linearize: bool = True):
        rotor, parts, offsets = self.rotor_at(T)
        om = speed_rpm * RPM
        st = operating_state(rotor, speed_rpm, self.shaft, start=start, linearize=linearize)
        reports: dict[str, HeatReport] = {}
        for b, load, idx in zip(st.bearings, st.loads, st.bearing_index):
            if b.name in parts:
                r = b.heat(om, load, self.model.lubrication, T[self._parts[b.name][1]], displacement=st.q[idx])
                if r is not None:
                    reports[b.name] = r
        return st, parts, offsets, reports

    def _network_step(self, om: float, T: dict[str, float], reports: dict[str, HeatReport]) -> dict[str, float]:
        """The network's temperatures with the heat of ``reports`` and the conductances of the temperatures T
        (one linear solve: the loop around it follows their temperature dependence, with the bearings')."""
        heat, contacts = self._sources(reports)
        motor = self._motor(om)
        Tv = np.array([T[n] for n in self._names])
        g = self.network.conductances(om, Tv, contacts)
        return self.network.network.solve_steady(self.network.sources(heat, motor), conductances=g).as_dict()

    def _motor(self, om: float):
        key = ("motor", om)
        if key not in self._cache:
            self._cache[key] = self.network.motor_losses(om, load_fraction=self.model.load_fraction)
        return self._cache[key]

    def _sources(self, reports: dict[str, HeatReport]):
        heat = {n: BearingHeat(r.inner_W, r.elements_W, r.outer_W) for n, r in reports.items()}
        contacts = {n: BearingContacts(r.inner_contact_N, r.outer_contact_N, r.film_inner_m, r.film_outer_m)
                    for n, r in reports.items()}
        return heat, contacts

    def steady(self, speed_rpm: float, start: ThermalState | None = None) -> ThermalState:
        """The spindle's thermal equilibrium at ``speed_rpm`` (module note); ``start``: a neighbouring speed's."""
        m = self.model
        T = dict(start.temperatures_C) if start is not None else {n: m.layout.ambient_C for n in self._names}
        st = start.operating if start is not None else None
        om = speed_rpm * RPM
        history = []
        for it in range(1, MAX_ITERATIONS + 1):
            try:
                st, parts, offsets, reports = self._pass(T, speed_rpm, st, linearize=False)
            except (ValueError, ArithmeticError) as exc:
                raise self._runaway(speed_rpm, history, T, f"the bearings' equilibrium failed ({exc})") from exc
            try:
                new = self._network_step(om, T, reports)
            except PropertyRangeError as exc:
                raise self._runaway(speed_rpm, history, T, f"the network's fluids left their tables ({exc})") from exc
            change = max(abs(new[n] - T[n]) for n in self._names)
            history.append((it, {n: r.row_thrust_N for n, r in reports.items()}, max(new.values()), change))
            T = new
            hottest = max(T[p] for n in m.bearings for p in self._parts[n])
            if hottest > RUNAWAY_C:
                raise self._runaway(speed_rpm, history, T, f"a bearing part reached {hottest:.0f} C")
            if len(history) >= 8 and all(h[3] >= history[-8][3] for h in history[-4:]):
                raise self._runaway(speed_rpm, history, T, "the temperatures keep rising from pass to pass")
            if change <= m.tolerance_K:
                break
        else:
            raise self._runaway(speed_rpm, history, T, f"no equilibrium within {MAX_ITERATIONS} passes "
                                                       f"(last change {history[-1][3]:.3g} K)")
        st, parts, offsets, reports = self._pass(T, speed_rpm, st)  # the bearings at the final temperatures
        return self._state(speed_rpm, T, st, parts, offsets, reports, it)

    def _state(self, speed_rpm, T, st, parts, offsets, reports, iterations, time_s=None) -> ThermalState:
        om = speed_rpm * RPM
        heat = {f"bearing:{n}": r.total_W for n, r in reports.items()}
        motor = self.network.motor_losses(om, load_fraction=self.model.load_fraction)
        if motor is not None:
            heat.update({"motor:stator": motor.stator_W, "motor:rotor": motor.rotor_W})
        bearing_heat, contacts = self._sources(reports)
        Tv = np.array([T[n] for n in self._names])
        balance = self.network.network.heat_flows(Tv, self.network.sources(bearing_heat, motor),
                                                  conductances=self.network.conductances(om, Tv, contacts))
        return ThermalState(speed_rpm, dict(T), heat, reports, parts, offsets, st, self._tip_drift(T, st), iterations,
                            time_s=time_s, removed_W=dict(balance.removed_W), stored_W=balance.stored_W,
                            tool_tip_radial_m=self._tip_radial(st))

    def _tip_radial(self, st: OperatingState) -> tuple[float, float] | None:
        """The tool tip's static deflection (x, y) [m] in the state (module note)."""
        tip = self.rotor.tool_tip
        if tip is None:
            return None
        d = self.rotor.dofs
        return float(st.q[d.index(tip, "x")]), float(st.q[d.index(tip, "y")])

    def _tip_drift(self, T: dict[str, float], st: OperatingState) -> float | None:
        """Axial position change of the tool tip against the housing's front face [m] (module note)."""
        if self._tip_z is None or not self.rotor.dofs.has("z"):
            return None
        lay, m = self.model.layout, self.model
        temps = [T[f"shaft[{i}]"] for i in range(len(lay.shaft))]
        grow = _growth(self._s_edges, temps, m.shaft_expansion_1_K, m.reference_C, lay.housing_start_m, self._tip_z)
        q_z = float(st.q[self.rotor.dofs.index(self.rotor.tool_tip, "z")])
        return q_z + grow

    def _runaway(self, speed_rpm, history, T, why: str) -> ThermalRunawayError:
        names = self.model.bearings
        hot = max(names, key=lambda n: T[f"bearing:{n}:inner"] - T[f"bearing:{n}:outer"]) if names else "?"
        first = history[0][1].get(hot) if history else None
        last = history[-1][1].get(hot) if history else None
        rise = ""
        if first is not None and last is not None and len(first) and len(last):
            rise = f"; its rows' thrust went from {np.max(first):.0f} N to {np.max(last):.0f} N"
        return ThermalRunawayError(
            f"thermal runaway of bearing {hot!r} at {speed_rpm:g} rpm: {why} after {len(history)} passes of the "
            f"heat-temperature-preload loop (inner ring {T.get(f'bearing:{hot}:inner', float('nan')):.0f} C, "
            f"outer ring {T.get(f'bearing:{hot}:outer', float('nan')):.0f} C{rise}): the arrangement cannot run "
            f"at this speed with this preload and cooling")

    def at(self, T: dict[str, float], speed_rpm: float, time_s: float | None = None) -> ThermalState:
        """The spindle with its parts at the temperatures ``T`` at ``speed_rpm``: the bearings at T, the rotor's
        static state on them, their heat (no loop: an instant of a warm-up)."""
        st, parts, offsets, reports = self._pass(T, speed_rpm, None)
        return self._state(speed_rpm, T, st, parts, offsets, reports, 0, time_s=time_s)

    def temperatures_at(self, time_s: float) -> dict[str, float]:
        """The network's temperatures at ``time_s`` of the model's warm-up (the ambient at 0)."""
        w = self.model.warm_up
        if w is None:
            raise ValueError("the spindle's thermal model has no warm-up")
        if time_s <= 0.0:
            return {n: self.model.layout.ambient_C for n in self._names}
        return dict(self.warm_up(w.times_s, w.speeds_rpm, float(time_s), samples=2)[-1].temperatures_C)

    # ---- warm-up ---------------------------------------------------------------------------------------
    def warm_up(self, times_s, speeds_rpm, duration_s: float, samples: int = 25,
                progress=None) -> tuple[ThermalState, ...]:
        """The spindle from cold (the ambient) through speed steps (``times_s``, ``speeds_rpm``) for
        ``duration_s``: its state at ``samples`` evenly spaced instants and on both sides of every step within
        the duration (the same temperatures, first at the speed before the step, then at the speed after it;
        module note)."""
        m = self.model
        rpm = StepProfile(tuple(float(t) for t in times_s), tuple(float(s) for s in speeds_rpm))  # as the deck gives it
        prof = StepProfile(rpm.times_s, tuple(s * RPM for s in rpm.values))
        cache: dict = {}

        def bearing_heat(w, T, t):
            key_T = np.array([T[p] for n in m.bearings for p in self._parts[n]])
            last = cache.get("last")
            if (last is None or last[0] != w or float(np.max(np.abs(key_T - last[1]))) > REFRESH_K
                    or abs(t - last[3]) > REFRESH_S):
                st, _, _, reports = self._pass(T, w / RPM, cache.get("st") if last and last[0] == w else None,
                                               linearize=False)
                cache["st"] = st
                heat, contacts = self._sources(reports)
                cache["last"] = (w, key_T, heat, t, contacts)
            return cache["last"][2]

        def contacts(w, T, t):
            bearing_heat(w, T, t)  # the contacts of the same bearing states as the heat
            return cache["last"][4]

        t_eval = np.linspace(0.0, duration_s, samples)
        try:
            res = self.network.warm_up(prof, duration_s, bearing_heat, load_fraction=m.load_fraction, t_eval=t_eval,
                                       update_K=0.1, contacts=contacts)
        except (PropertyRangeError, ThermalRunawayError, ArithmeticError, ValueError) as exc:
            last = cache.get("last")
            when = "" if last is None else f" at {last[3] / 60.0:.1f} min ({last[0] / RPM:g} rpm)"
            raise ThermalRunawayError(f"the warm-up ran away{when}: {exc}") from exc
        # each instant at ``rpm`` (no round trip through rad/s); a step's instant comes twice (the network's
        # temperatures do not jump there, its sources do): first at the speed before the step
        times = [float(t) for t in res.times_s]
        out = []
        for k, t in enumerate(times):
            T = {n: float(res.temperatures_C[k, i]) for i, n in enumerate(self._names)}
            before = k + 1 < len(times) and times[k + 1] == t and t in prof.breakpoints
            out.append(self.at(T, rpm.before(t) if before else rpm(t), time_s=t))
            if progress is not None:
                progress(k + 1, len(res.times_s))
        return tuple(out)


def speed_limit(thermal: SpindleThermal, stable: ThermalState, runaway_rpm: float,
                rel: float = 0.02) -> tuple[float, float]:
    """(highest speed found stable, lowest found to run away) [rpm] between a stable equilibrium and a speed
    that ran away, by bisection until they are within ``rel`` of each other."""
    lo, hi, near = stable.speed_rpm, float(runaway_rpm), stable
    while hi - lo > rel * hi:
        mid = 0.5 * (lo + hi)
        try:
            near = thermal.steady(mid, start=near)
            lo = mid
        except ThermalRunawayError:
            hi = mid
    return lo, hi


def lay_edges(lengths, start: float) -> np.ndarray:
    return start + np.concatenate([[0.0], np.cumsum(lengths)])


def _growth(edges: np.ndarray, temps, alpha: float, ref_C: float, z_from: float, z_to: float) -> float:
    """int_{z_from}^{z_to} alpha (T(z) - T_ref) dz over piecewise-constant segment temperatures (a point
    beyond the segments takes the end segment's temperature)."""
    lo, hi, sign = (z_from, z_to, 1.0) if z_to >= z_from else (z_to, z_from, -1.0)
    ext = edges.copy()
    ext[0], ext[-1] = min(ext[0], lo), max(ext[-1], hi)
    total = 0.0
    for i, t in enumerate(temps):
        a, b = max(ext[i], lo), min(ext[i + 1], hi)
        if b > a:
            total += alpha * (t - ref_C) * (b - a)
    return sign * total
