"""Thermal network of a motor spindle built from a :class:`~spindlesim.thermal.layout.SpindleLayout`.

Nodes (names are stable; the coupling code refers to them):

- ``shaft[i]``: shaft segment i (capacity of the segment), axial conduction between the centres
  of neighbouring segments (two half-lengths in series);
- ``housing[j]``: housing segment j, axial conduction likewise, radial conduction through half its
  wall to the inner and the outer surface; outer surface to ``ambient`` by free convection of a
  horizontal cylinder (Churchill-Chu, at the current temperatures) and radiation;
- ``bearing:<name>:inner|balls|outer`` (``rollers`` for a roller bearing): inner ring -- the shaft segments its
  width overlaps, by share (seat contact in series with half the ring's radial conduction; a bearing on a node
  straddles the elements on both sides), inner ring -- balls and balls -- outer ring through the contacts and
  balls -- housing (the segments around the seat, by share) through the oil-air of the bearing cavity: the
  values the set's family gives (its ``contact_paths``: Hertz ellipses or lines, the EHL film, Whitaker;
  ``spindlesim/bearings/conductance.py``), outer ring -- housing segment (seat contact, half ring, half housing
  wall);
- ``jacket:coolant[k]``: coolant segments in flow order, fed by the boundary ``jacket:inlet``
  (advection m_dot c_p), each exchanging with the housing segment at its axial position (h from
  Gnielinski or Dittus-Boelter on the channel wall, wetted area per segment);
- ``motor:stator`` -- housing segments under it (shrink-fit contact, half the stator yoke),
  ``motor:rotor`` -- shaft segments under it (contact, half the rotor), stator -- rotor across the
  gap (Becker-Kaye); both split over segments by their axial overlap;
- shaft segments not under a bearing or the rotor: to the housing around them through the inner
  air (rotating annulus, Becker-Kaye, gap = half the radial clearance), or to ``ambient`` (rotating
  shaft in still air, Kendoush combined with Churchill-Chu);
- ``ambient``: boundary at ``ambient_C``.

Speed- and temperature-dependent conductances are overrides computed by
:meth:`SpindleNetwork.conductances`; the heat sources by :meth:`SpindleNetwork.sources` (bearing
heat split inner/balls/outer from the caller, motor losses from :mod:`spindlesim.thermal.motor`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Mapping

import numpy as np

from . import convection as cv
from .conduction import axial_conductance, conductance_in_series, cylindrical_shell_conductance
from .layout import SpindleLayout
from .motor import MotorLosses, motor_losses, windage_loss_W
from .network import Advection, Conductance, Network, Node, SteadyState
from .properties import clip_air_C, fluid
from .transient import StepProfile, TransientResult, solve_transient


@dataclass(frozen=True)
class BearingHeat:
    """Heat [W] generated in one bearing, split where it goes: inner ring, balls, outer ring."""

    inner_W: float = 0.0
    balls_W: float = 0.0
    outer_W: float = 0.0

    @property
    def total_W(self) -> float:
        return self.inner_W + self.balls_W + self.outer_W


@dataclass(frozen=True)
class BearingContacts:
    """Contact loads [N] per ball (arrays or scalars) and EHL film thickness [m] of one bearing."""

    inner_N: object
    outer_N: object
    film_inner_m: object = 0.0
    film_outer_m: object = 0.0


def _centres(lengths, start=0.0):
    edges = start + np.concatenate(([0.0], np.cumsum(lengths)))
    return edges, 0.5 * (edges[:-1] + edges[1:])


def _segment_at(edges: np.ndarray, z: float, what: str) -> int:
    if not edges[0] - 1e-12 <= z <= edges[-1] + 1e-12:
        raise ValueError(f"{what} at z = {z * 1e3:g} mm lies outside [{edges[0] * 1e3:g}, {edges[-1] * 1e3:g}] mm")
    return int(min(max(np.searchsorted(edges, z, side="right") - 1, 0), edges.size - 2))


def _seat(edges: np.ndarray, b, what: str) -> list[tuple[int, float]]:
    """[(segment, share)] of a bearing's width over the segments of ``edges`` (shares sum to 1); a bearing whose
    width lies outside every segment (a point) takes the segment at its centre."""
    over = _overlaps(edges, b.position_m - 0.5 * b.width_m, b.position_m + 0.5 * b.width_m)
    total = sum(w for _, w in over)
    if total <= 0.0:
        return [(_segment_at(edges, b.position_m, f"bearing {b.name!r}{what}"), 1.0)]
    _segment_at(edges, b.position_m, f"bearing {b.name!r}{what}")  # its centre must lie on the segments
    return [(k, w / total) for k, w in over]


def _overlaps(edges: np.ndarray, a: float, b: float) -> list[tuple[int, float]]:
    out = []
    for i in range(edges.size - 1):
        w = min(b, edges[i + 1]) - max(a, edges[i])
        if w > 1e-12:
            out.append((i, w))
    return out


@dataclass(frozen=True)
class SpindleNetwork:
    """The network of a spindle layout and the rules for its per-evaluation values."""

    layout: SpindleLayout
    network: Network
    _rules: tuple = field(repr=False, compare=False)
    #: each bearing's seats: ([(shaft segment, share of the width)], [(housing segment, share)])
    seats: dict = field(default_factory=dict, repr=False, compare=False)

    def seat_C(self, name: str, temperatures_C: Mapping[str, float]) -> tuple[float, float]:
        """(shaft, housing) seat temperatures of bearing ``name``: the means over the segments its width
        overlaps, by share."""
        s, h = self.seats[name]
        return (sum(f * temperatures_C[f"shaft[{i}]"] for i, f in s),
                sum(f * temperatures_C[f"housing[{j}]"] for j, f in h))

    # ------------------------------------------------------------------ values per evaluation
    def conductances(self, speed_rad_s: float, temperatures_C: np.ndarray | None = None,
                     contacts: Mapping[str, BearingContacts] | None = None) -> dict[str, float]:
        """Overrides {conductance name: W/K} at a speed; with ``temperatures_C`` (node order) the
        temperature-dependent ones (free convection, fluid properties) use them, else the nominal
        temperatures (ambient + 10 K for surfaces, inner air and coolant inlet for fluids)."""
        T = None if temperatures_C is None else np.asarray(temperatures_C, dtype=float)
        idx = self.network.index
        out = {}
        for name, kind, p in self._rules:
            if kind == "bearing":
                continue
            out[name] = p["fn"](speed_rad_s, T, idx)
        for b in self.layout.bearings:
            c = (contacts or {}).get(b.name)
            g = self._bearing(b, speed_rad_s, c, T)
            faces_i, faces_o = self._ring_faces(b, speed_rad_s)
            el = _suffix(b)
            out[f"bearing:{b.name}:inner--{el}"] = g.inner_balls_W_K + faces_i
            out[f"bearing:{b.name}:{el}--outer"] = g.balls_outer_W_K + faces_o
            for j, f in self.seats[b.name][1]:
                out[f"bearing:{b.name}:{el}--housing[{j}]"] = f * g.balls_cavity_W_K
        return out

    def _bearing(self, b, speed, c: BearingContacts | None, T):
        """The set's conductances: its family's answer (``b.contact_paths``) at the contact loads and films ``c``
        (None: the nominal load, no film) and the temperature of its rolling elements' air."""
        qi = np.asarray(b.nominal_contact_load_N if c is None else c.inner_N, dtype=float)
        qo = np.asarray(b.nominal_contact_load_N if c is None else c.outer_N, dtype=float)
        t_air = self._inner_air_C() if T is None else float(T[self.network.index(b.elements_node)])
        return b.contact_paths.conductances(b, speed, qi, qo, 0.0 if c is None else c.film_inner_m,
                                            0.0 if c is None else c.film_outer_m, t_air)

    def _ring_faces(self, b, speed: float) -> tuple[float, float]:
        """Convection [W/K] of the rings' free surfaces (side faces and shoulder lands, all rows) to the oil-air
        of the bearing cavity (the balls' node), in parallel with the ball contacts: the inner ring's as a
        rotating cylinder of its shoulder diameter in air (Kendoush, :func:`convection.rotating_shaft_h`), the
        outer ring's in the air the cage drags round at about 0.4 of the shaft speed.  Our estimate of a path
        the contact model leaves out; docs/theory.md."""
        t = self._inner_air_C()
        rows = max(1, round(b.width_m / (1.6 * b.ball_diameter_m)))
        land = 0.3 * b.width_m  # shoulder land width exposed, all rows
        a_i = rows * 2 * 0.25 * math.pi * (b.inner_shoulder_m ** 2 - b.bore_m ** 2) + math.pi * b.inner_shoulder_m * land
        a_o = (rows * 2 * 0.25 * math.pi * (b.outer_diameter_m ** 2 - b.outer_shoulder_m ** 2)
               + math.pi * b.outer_shoulder_m * land)
        h_i = cv.rotating_shaft_h(b.inner_shoulder_m, speed, t + 10.0, t)
        h_o = cv.rotating_shaft_h(b.outer_shoulder_m, 0.4 * speed, t + 10.0, t)
        return h_i * a_i, h_o * a_o

    def _inner_air_C(self) -> float:
        lay = self.layout
        return lay.internal_air_C if lay.internal_air_C is not None else lay.ambient_C + 20.0

    def motor_losses(self, speed_rad_s: float, *, load_fraction: float | None = None, power_W: float | None = None,
                     torque_Nm: float | None = None) -> MotorLosses | None:
        """Motor heat at a speed and load (windage included); None without a motor."""
        m = self.layout.motor
        if m is None:
            return None
        if load_fraction is None and power_W is None and torque_Nm is None:
            load_fraction = 0.0
        wind = windage_loss_W(0.5 * m.rotor_outer_diameter_m, m.gap_m, m.length_m, speed_rad_s, self._inner_air_C())
        return motor_losses(m.rating, speed_rad_s, load_fraction=load_fraction, power_W=power_W,
                            torque_Nm=torque_Nm, windage_W=wind)

    def sources(self, bearing_heat: Mapping[str, BearingHeat] | None = None,
                motor: MotorLosses | None = None) -> dict[str, float]:
        """Heat sources {node: W} from the bearings' split heat and the motor losses."""
        q: dict[str, float] = {}
        names = {b.name: b.elements_node for b in self.layout.bearings}
        for name, h in (bearing_heat or {}).items():
            if name not in names:
                raise KeyError(f"no bearing named {name!r} in the spindle layout (have {sorted(names)})")
            q[f"bearing:{name}:inner"] = float(h.inner_W)
            q[names[name]] = float(h.balls_W)
            q[f"bearing:{name}:outer"] = float(h.outer_W)
        if motor is not None:
            if self.layout.motor is None:
                raise ValueError("motor losses given for a layout without a motor")
            q["motor:stator"] = motor.stator_W
            q["motor:rotor"] = motor.rotor_W
        return q

    # ------------------------------------------------------------------ solves
    def steady(self, speed_rad_s: float, bearing_heat=None, *, load_fraction: float = 0.0,
               contacts: Mapping[str, BearingContacts] | None = None, temperature_dependent: bool = True,
               tol_K: float = 1e-6, max_iter: int = 100) -> SteadyState:
        """Steady temperatures at one speed.  ``bearing_heat``: a mapping {bearing: BearingHeat} or a
        callable ``f(T_by_name) -> mapping`` (heat that depends on the temperatures, e.g. through
        the preload); with it, or with ``temperature_dependent``, the solve iterates (Picard)."""
        motor = self.motor_losses(speed_rad_s, load_fraction=load_fraction)
        names = self.network.names
        if callable(bearing_heat):
            def src(T):
                return self.sources(bearing_heat(dict(zip(names, T))), motor)
        else:
            src = self.sources(bearing_heat, motor)
        if temperature_dependent:
            def g(T):
                return self.conductances(speed_rad_s, T, contacts)
        else:
            g = self.conductances(speed_rad_s, None, contacts)
        return self.network.solve_steady(src, conductances=g, tol_K=tol_K, max_iter=max_iter,
                                         initial_C=self.layout.ambient_C)

    def warm_up(self, speed_rad_s: StepProfile | float, t_end_s: float, bearing_heat=None, *,
                load_fraction: float | StepProfile = 0.0, initial_C: float | np.ndarray | None = None,
                temperature_dependent: bool = True, method: str = "BDF", rtol: float = 1e-6, atol: float = 1e-4,
                t_eval=None, dt_s: float | None = None, update_K: float = 0.5, contacts=None) -> TransientResult:
        """Warm-up through a speed profile (rad/s, e.g. the steps of an ISO 230-3 test).
        ``bearing_heat``: mapping, or callable ``f(speed_rad_s, T_by_name, t_s) -> mapping``; the
        profile's step times are breakpoints of the integration.  ``contacts``: the bearings' contact
        loads for their conductances (mapping, or a callable ``f(speed_rad_s, T_by_name, t_s)``; None:
        nominal).  Temperature-dependent conductances are re-evaluated when a node has moved by more than
        ``update_K`` since their last evaluation (0: at every evaluation; property changes over 0.5 K
        are ~0.1 %)."""
        prof = speed_rad_s if isinstance(speed_rad_s, StepProfile) else StepProfile((0.0,), (float(speed_rad_s),))
        load = load_fraction if isinstance(load_fraction, StepProfile) else StepProfile((0.0,), (float(load_fraction),))
        names = self.network.names
        cache: dict = {}

        def motor_at(t):
            key = (prof(t), load(t))
            if key not in cache:
                cache[key] = self.motor_losses(key[0], load_fraction=key[1])
            return cache[key]

        def src(t, T):
            bh = bearing_heat(prof(t), dict(zip(names, T)), t) if callable(bearing_heat) else bearing_heat
            return self.sources(bh, motor_at(t))

        if temperature_dependent:
            last: dict = {}

            def g(t, T):
                w = prof(t)
                if (last.get("w") != w or update_K <= 0.0
                        or float(np.max(np.abs(T - last["T"]))) > update_K):
                    c = contacts(w, dict(zip(names, T)), t) if callable(contacts) else contacts
                    last.update(w=w, T=T.copy(), g=self.conductances(w, T, c))
                return last["g"]
        else:
            gcache: dict = {}

            def g(t, T):
                w = prof(t)
                if w not in gcache:
                    c = contacts(w, dict(zip(names, T)), t) if callable(contacts) else contacts
                    gcache[w] = self.conductances(w, None, c)
                return gcache[w]

        t0 = self.layout.ambient_C if initial_C is None else initial_C
        return solve_transient(self.network, t0, t_end_s, sources=src, conductances=g,
                               breakpoints=tuple(prof.breakpoints) + tuple(load.breakpoints), method=method,
                               rtol=rtol, atol=atol, t_eval=t_eval, dt_s=dt_s)


def _suffix(b) -> str:
    """"balls" or "rollers": the last part of the set's rolling elements' node name."""
    return b.elements_node.rsplit(":", 1)[1]


def _film(T, idx, a: str, b: str, default: float) -> float:
    if T is None:
        return default
    return clip_air_C(0.5 * (T[idx(a)] + T[idx(b)]))


def build_spindle_network(layout: SpindleLayout) -> SpindleNetwork:
    """Nodes, conductances and advection of ``layout`` (module docstring)."""
    lay = layout
    if not lay.shaft or not lay.housing:
        raise ValueError("a spindle layout needs shaft and housing segments")
    ks, kh = lay.shaft_material.conductivity_W_mK, lay.housing_material.conductivity_W_mK
    nodes = [Node("ambient", fixed_C=lay.ambient_C)]
    conds: list[Conductance] = []
    advs: list[Advection] = []
    rules: list = []
    s_edges, s_mid = _centres([s.length_m for s in lay.shaft])
    h_edges, h_mid = _centres([h.length_m for h in lay.housing], lay.housing_start_m)
    air_ref = lay.ambient_C + 20.0 if lay.internal_air_C is None else lay.internal_air_C

    def add(a, b, g, name=None):
        conds.append(Conductance(a, b, float(g), name or f"{a}--{b}"))

    for i, s in enumerate(lay.shaft):
        area = 0.25 * math.pi * (s.outer_diameter_m ** 2 - s.inner_diameter_m ** 2)
        nodes.append(Node(f"shaft[{i}]", lay.shaft_material.volumetric_heat_J_m3K * area * s.length_m))
        if i:
            p = lay.shaft[i - 1]
            a0 = 0.25 * math.pi * (p.outer_diameter_m ** 2 - p.inner_diameter_m ** 2)
            add(f"shaft[{i - 1}]", f"shaft[{i}]", conductance_in_series(
                axial_conductance(0.5 * p.length_m, a0, ks), axial_conductance(0.5 * s.length_m, area, ks)))
    h_half = []
    for j, h in enumerate(lay.housing):
        area = 0.25 * math.pi * (h.outer_diameter_m ** 2 - h.inner_diameter_m ** 2)
        nodes.append(Node(f"housing[{j}]", lay.housing_material.volumetric_heat_J_m3K * area * h.length_m))
        rm = 0.25 * (h.inner_diameter_m + h.outer_diameter_m)
        h_half.append(rm)
        if j:
            p = lay.housing[j - 1]
            a0 = 0.25 * math.pi * (p.outer_diameter_m ** 2 - p.inner_diameter_m ** 2)
            add(f"housing[{j - 1}]", f"housing[{j}]", conductance_in_series(
                axial_conductance(0.5 * p.length_m, a0, kh), axial_conductance(0.5 * h.length_m, area, kh)))
        # outer surface: free convection (+ radiation), through half the wall
        wall = cylindrical_shell_conductance(rm, 0.5 * h.outer_diameter_m, h.length_m, kh)
        area_o = math.pi * h.outer_diameter_m * h.length_m
        name = f"housing[{j}]--ambient"
        add(f"housing[{j}]", "ambient", 0.0, name)

        def f_out(w, T, idx, j=j, d=h.outer_diameter_m, wall=wall, area_o=area_o):
            ts = lay.ambient_C + 10.0 if T is None else T[idx(f"housing[{j}]")]
            ts = ts if abs(ts - lay.ambient_C) > 0.1 else lay.ambient_C + 0.1
            h_c = cv.free_cylinder_h(d, clip_air_C(ts), lay.ambient_C)
            if lay.housing_emissivity > 0.0:
                h_c += cv.radiation_h(ts, lay.ambient_C, lay.housing_emissivity)
            return conductance_in_series(wall, h_c * area_o)
        rules.append((name, "fn", {"fn": f_out}))

    covered = np.zeros(len(lay.shaft))   # shaft length under bearings / rotor per segment
    shares = {}
    for b in lay.bearings:
        pre = f"bearing:{b.name}"
        el = _suffix(b)
        nodes += [Node(f"{pre}:inner", b.inner_mass_kg() * b.ring.specific_heat_J_kgK),
                  Node(b.elements_node, b.balls_mass_kg() * b.ball.specific_heat_J_kgK),
                  Node(f"{pre}:outer", b.outer_mass_kg() * b.ring.specific_heat_J_kgK)]
        seat_s = _seat(s_edges, b, "")
        seat_h = _seat(h_edges, b, " (housing)")
        shares[b.name] = (seat_s, seat_h)
        for k, w in _overlaps(s_edges, b.position_m - 0.5 * b.width_m, b.position_m + 0.5 * b.width_m):
            covered[k] += w
        kr = b.ring.conductivity_W_mK
        for i, f in seat_s:  # the seat straddles the segments it overlaps (a bearing on a node: both sides)
            w = f * b.width_m
            add(f"shaft[{i}]", f"{pre}:inner", conductance_in_series(
                b.inner_seat_W_m2K * math.pi * b.bore_m * w,
                cylindrical_shell_conductance(0.5 * b.bore_m, 0.25 * (b.bore_m + b.inner_shoulder_m), w, kr)))
        for j, f in seat_h:
            w, hs = f * b.width_m, lay.housing[j]
            add(f"{pre}:outer", f"housing[{j}]", conductance_in_series(
                cylindrical_shell_conductance(0.25 * (b.outer_diameter_m + b.outer_shoulder_m),
                                              0.5 * b.outer_diameter_m, w, kr),
                b.outer_seat_W_m2K * math.pi * b.outer_diameter_m * w,
                cylindrical_shell_conductance(0.5 * hs.inner_diameter_m, h_half[j], w, kh)
                if h_half[j] > 0.5 * hs.inner_diameter_m else math.inf))
            add(b.elements_node, f"housing[{j}]", 0.0, f"{pre}:{el}--housing[{j}]")
        add(f"{pre}:inner", b.elements_node, 0.0, f"{pre}:inner--{el}")
        add(b.elements_node, f"{pre}:outer", 0.0, f"{pre}:{el}--outer")
        rules.append((f"{pre}", "bearing", {}))

    if lay.motor is not None:
        _motor(lay, nodes, add, rules, s_edges, h_edges, h_half, covered, air_ref)
    if lay.jacket is not None:
        _jacket(lay, nodes, add, advs, rules, h_edges)
    _shaft_surfaces(lay, add, rules, s_edges, h_edges, covered, air_ref)
    net = Network(tuple(nodes), tuple(conds), tuple(advs))
    sn = SpindleNetwork(lay, net, tuple(rules), shares)
    nominal = sn.conductances(0.0)   # the network alone holds the values at rest, nominal temperatures
    conds = [Conductance(c.a, c.b, nominal.get(c.name, c.value_W_K), c.name) for c in conds]
    return SpindleNetwork(lay, Network(tuple(nodes), tuple(conds), tuple(advs)), tuple(rules), shares)


def _motor(lay, nodes, add, rules, s_edges, h_edges, h_half, covered, air_ref):
    m = lay.motor
    k = m.material.conductivity_W_mK
    nodes += [Node("motor:stator", m.stator_mass() * m.material.specific_heat_J_kgK),
              Node("motor:rotor", m.rotor_mass() * m.material.specific_heat_J_kgK)]
    a, b = m.start_m, m.start_m + m.length_m
    r_ri, r_ro = 0.5 * m.rotor_inner_diameter_m, 0.5 * m.rotor_outer_diameter_m
    r_si, r_so = 0.5 * m.stator_bore_m, 0.5 * m.stator_outer_diameter_m
    for i, w in _overlaps(s_edges, a, b):
        covered[i] += w
        add("motor:rotor", f"shaft[{i}]", conductance_in_series(
            m.rotor_seat_W_m2K * 2.0 * math.pi * r_ri * w, cylindrical_shell_conductance(r_ri, 0.5 * (r_ri + r_ro), w, k)))
    hs = _overlaps(h_edges, a, b)
    if not hs:
        raise ValueError("the motor lies outside the housing")
    for j, w in hs:
        hj = lay.housing[j]
        rh = 0.5 * hj.inner_diameter_m
        add("motor:stator", f"housing[{j}]", conductance_in_series(
            m.stator_seat_W_m2K * 2.0 * math.pi * r_so * w, cylindrical_shell_conductance(0.5 * (r_si + r_so), r_so, w, k),
            cylindrical_shell_conductance(rh, h_half[j], w, lay.housing_material.conductivity_W_mK)
            if h_half[j] > rh else math.inf))
    add("motor:stator", "motor:rotor", 0.0, "motor:gap")

    def f_gap(w, T, idx):
        t = _film(T, idx, "motor:stator", "motor:rotor", air_ref)
        h = cv.gap_h(m.rotor_outer_diameter_m, m.gap_m, w, t)
        return h * math.pi * (r_ro + r_si) * m.length_m
    rules.append(("motor:gap", "fn", {"fn": f_gap}))


def _jacket(lay, nodes, add, advs, rules, h_edges):
    jk = lay.jacket
    n = int(jk.segments)
    if n < 1 or jk.channels < 1 or jk.flow_m3_s <= 0.0:
        raise ValueError("cooling jacket: need segments >= 1, channels >= 1, flow > 0")
    p_in = fluid(jk.coolant, jk.inlet_C)
    nodes.append(Node("jacket:inlet", fixed_C=jk.inlet_C))
    vol = jk.channels * jk.area_m2 * jk.channel_length_m / n
    wet = jk.channels * math.pi * jk.hydraulic_diameter_m * jk.channel_length_m / n
    velocity = jk.flow_m3_s / (jk.channels * jk.area_m2)
    mcp = cv.capacity_rate_W_K(jk.flow_m3_s, p_in)
    prev = "jacket:inlet"
    for k in range(n):
        name = f"jacket:coolant[{k}]"
        nodes.append(Node(name, p_in.density_kg_m3 * p_in.specific_heat_J_kgK * vol))
        advs.append(Advection(prev, name, mcp, f"{prev}->{name}"))
        prev = name
        z = jk.start_m + (k + 0.5) * jk.length_m / n
        j = _segment_at(h_edges, z, "cooling jacket")
        cname = f"{name}--housing[{j}]"
        add(name, f"housing[{j}]", 0.0, cname)

        def f_j(w, T, idx, name=name):
            t = jk.inlet_C if T is None else float(T[idx(name)])
            p = fluid(jk.coolant, t)
            return cv.channel_h(jk.hydraulic_diameter_m, velocity, p, "flux", jk.correlation) * wet
        rules.append((cname, "fn", {"fn": f_j}))


def _shaft_surfaces(lay, add, rules, s_edges, h_edges, covered, air_ref):
    for i, s in enumerate(lay.shaft):
        free = s.length_m - covered[i]
        if s.surroundings == "none" or free <= 1e-9:
            continue
        if s.surroundings not in ("housing", "ambient"):
            raise ValueError(f"shaft[{i}]: surroundings must be 'housing', 'ambient' or 'none'")
        zc = 0.5 * (s_edges[i] + s_edges[i + 1])
        inside = s.surroundings == "housing" and h_edges[0] <= zc <= h_edges[-1]
        d = s.outer_diameter_m
        area = math.pi * d * free
        if inside:
            j = _segment_at(h_edges, zc, f"shaft[{i}]")
            gap = 0.5 * (lay.housing[j].inner_diameter_m - d)
            if gap <= 0.0:
                continue
            name = f"shaft[{i}]--housing[{j}]"
            add(f"shaft[{i}]", f"housing[{j}]", 0.0, name)
            r_h = 0.5 * lay.housing[j].inner_diameter_m

            def f_in(w, T, idx, i=i, j=j, d=d, gap=gap, free=free, r_h=r_h):
                t = _film(T, idx, f"shaft[{i}]", f"housing[{j}]", air_ref)
                return cv.gap_h(d, gap, w, t) * math.pi * (0.5 * d + r_h) * free
            rules.append((name, "fn", {"fn": f_in}))
        else:
            name = f"shaft[{i}]--ambient"
            add(f"shaft[{i}]", "ambient", 0.0, name)

            def f_amb(w, T, idx, i=i, d=d, area=area):
                ts = lay.ambient_C + 10.0 if T is None else float(T[idx(f"shaft[{i}]")])
                ts = ts if abs(ts - lay.ambient_C) > 0.1 else lay.ambient_C + 0.1
                return cv.rotating_shaft_h(d, w, clip_air_C(ts), lay.ambient_C) * area
            rules.append((name, "fn", {"fn": f_amb}))

