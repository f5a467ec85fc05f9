"""Seed 000's roller bearing with a flexible (segmented) outer race, assembled.

Bodies (seed 000 sec. 2, Figs. 1-2):
- shaft + inner race: planar translation (x, y), driven at constant speed
  omega_s, mass m_s, viscous damping c_s, constant radial load;
- N rollers: rigid bodies whose orbit angle and spin follow the cage
  kinematics (eqs. 1-4); each keeps one freedom, its radial position r_j
  (seed 000's "dummy body" radial joint).  Its equation in the rotating cage
  frame is m_r (r'' - r omega_c^2) = radial part of the contact forces; the
  tangential parts are carried by the cage constraint;
- outer race: n segments joined by co-rotational beams (eqs. 5-17,
  ``outer_race.SegmentedRing``), held in a fixed housing by a compliant
  contact per segment (normal, eq. 30) with a tangential stick spring,
  eq. 31 friction and the rocking stiffness of the segment's face on the
  bore (``HousingSupport``).

Contacts (eqs. 18-31): roller/inner race, circle against circle;
roller/outer race through the contact search of eqs. 18-29 on the race
surface displaced by the segments and the eq. 17 deflection.  The contact
load on the race is given to the two segments of the beam through the
transpose of the (linear, small-displacement) surface operator, so the
elastic part of the model is conservative: with damping and friction off and
the shaft at rest, the total energy is constant (tested).

State: [x, y, r_1..r_N, q (3n), x', y', r'_1..r'_N, q' (3n)], q the segment
displacements from the reference ring.
"""

from __future__ import annotations

import dataclasses
import logging
from dataclasses import dataclass
from functools import cached_property

import numpy as np
from scipy.optimize import root

from .contact_force import CompliantContact
from .contact_search import outer_race_contact
from .kinematics import CageKinematics
from .outer_race import SegmentedRing

log = logging.getLogger(__name__)


@dataclass(frozen=True)
class HousingSupport:
    """Outer race to housing contact, per segment (seed 000: "surface contact").

    The segment's outer face (arc s) lies on the housing bore, so besides the
    radial force the surface resists rocking of the segment relative to the
    bore: with the radial stiffness k spread evenly over the arc, a rocking
    angle beta = Theta - phi_rot (segment rotation minus its angular position
    about the bearing centre, i.e. the rotation it would have if it slid
    along the bore) gives the moment -k s^2/12 beta.  Without it a segment
    rocks freely on a point support and the race under a roller between two
    segments is held only by beam bending (about 3e5 N/m for seed 000's race,
    500 times softer than a roller contact).
    """

    contact: CompliantContact  # normal, eq. 30; friction eq. 31 on the tangential slip
    interference_m: float = 0.0  # radial fit overlap (unilateral contact only)
    tangential_stiffness_N_m: float = 1e7  # stick spring of the fit (no slip of the race in the housing)
    bilateral: bool = True  # a press fit keeps every segment seated: the contact also holds in tension
    rocking_arc_m: float = 0.0  # s of the rocking stiffness k s^2/12 (0: point support, no rocking stiffness)

    @property
    def rocking_stiffness_Nm_rad(self) -> float:
        return self.contact.stiffness * self.rocking_arc_m**2 / 12.0

    def normal_force(self, delta: np.ndarray, delta_dot: np.ndarray) -> np.ndarray:
        """Change of the fit force on each segment (bilateral) or the eq. 30 force (unilateral)."""
        if not self.bilateral:
            return self.contact.normal_force(delta, delta_dot)
        c = self.contact
        return c.stiffness * np.sign(delta) * np.abs(delta) ** c.exponent + c.damping * delta_dot

    def energy_J(self, delta: np.ndarray) -> np.ndarray:
        if not self.bilateral:
            return self.contact.energy_J(delta)
        c = self.contact
        return c.stiffness * np.abs(delta) ** (c.exponent + 1.0) / (c.exponent + 1.0)


@dataclass(frozen=True)
class FlexibleRaceModel:
    """The assembled seed 000 model; a ``TransientSystem``."""

    kinematics: CageKinematics
    rollers: int
    ring: SegmentedRing
    roller_contact: CompliantContact
    housing: HousingSupport
    shaft_speed_rad_s: float
    shaft_mass_kg: float
    shaft_damping_Ns_m: float
    load_N: tuple[float, float]
    roller_length_m: float
    roller_density_kg_m3: float = 7850.0
    cage_phase_rad: float = 0.0
    centrifugal: bool = True
    load_ramp_s: float = 0.0  # >0: the load grows linearly from 0 over this time (quasi-static loading)
    model_name: str = "flexible_race"

    def load_at(self, t: float) -> np.ndarray:
        f = np.asarray(self.load_N, dtype=float)
        return f * min(t / self.load_ramp_s, 1.0) if self.load_ramp_s > 0 else f

    def __post_init__(self) -> None:
        if self.rollers < 3:
            raise ValueError("need at least 3 rollers")
        gap = self.ring.inner_radius_m - self.inner_radius_m - 2 * self.roller_radius_m
        if gap < -1e-9:
            raise ValueError(f"rollers do not fit between the races (gap {gap:.3e} m)")

    # geometry ----------------------------------------------------------
    @property
    def inner_radius_m(self) -> float:
        return 0.5 * self.kinematics.inner_raceway_diameter_m

    @property
    def roller_radius_m(self) -> float:
        return 0.5 * self.kinematics.roller_diameter_m

    @property
    def roller_mass_kg(self) -> float:
        return self.roller_density_kg_m3 * np.pi * self.roller_radius_m**2 * self.roller_length_m

    @property
    def cage_speed_rad_s(self) -> float:
        return self.kinematics.cage_ratio * self.shaft_speed_rad_s

    @property
    def roller_spin_rad_s(self) -> float:
        """Absolute roller spin: cage rate minus the spin relative to the cage (eq. 4)."""
        return self.cage_speed_rad_s - self.kinematics.spin_ratio * self.shaft_speed_rad_s

    @property
    def cage_frequency_hz(self) -> float:
        return self.cage_speed_rad_s / (2 * np.pi)

    @property
    def roller_pass_frequency_hz(self) -> float:
        return self.rollers * self.cage_frequency_hz

    @property
    def n_pos(self) -> int:
        return 2 + self.rollers + 3 * self.ring.segments

    @property
    def n_state(self) -> int:
        return 2 * self.n_pos

    @cached_property
    def mass_diagonal(self) -> np.ndarray:
        return np.concatenate([[self.shaft_mass_kg] * 2, [self.roller_mass_kg] * self.rollers,
                               self.ring.mass_diagonal()])

    def angles(self, t: float) -> np.ndarray:
        N = self.rollers
        return self.cage_phase_rad + 2 * np.pi * np.arange(N) / N + self.cage_speed_rad_s * t

    # forces ----------------------------------------------------------------
    def _split(self, p: np.ndarray):
        N = self.rollers
        return p[0:2], p[2:2 + N], p[2 + N:]

    def contact_state(self, t: float, pos: np.ndarray, vel: np.ndarray) -> dict[str, np.ndarray]:
        """Penetrations, rates and contact loads of every roller (inner and outer)."""
        s, r, q = self._split(pos)
        sd, rd, qd = self._split(vel)
        psi = self.angles(t)
        f = np.column_stack([np.cos(psi), np.sin(psi)])
        tan = np.column_stack([-f[:, 1], f[:, 0]])
        wc = self.cage_speed_rad_s
        c = r[:, None] * f
        cd = rd[:, None] * f + (r * wc)[:, None] * tan
        # inner contact: circle (shaft) against circle (roller)
        dvec = c - s
        dist = np.hypot(dvec[:, 0], dvec[:, 1])
        n_in = dvec / dist[:, None]
        d_in = self.inner_radius_m + self.roller_radius_m - dist
        dd_in = -np.sum(n_in * (cd - sd), axis=1)
        # outer contact: eqs. 18-29 on the displaced race surface
        i, j, G = self.ring.surface_operator(psi)
        Q = q.reshape(-1, 3)
        Qd = qd.reshape(-1, 3)
        u = np.sum(G[:, 0:3] * Q[i], axis=1) + np.sum(G[:, 3:6] * Q[j], axis=1)
        ud = np.sum(G[:, 0:3] * Qd[i], axis=1) + np.sum(G[:, 3:6] * Qd[j], axis=1)
        oc = outer_race_contact(c, self.roller_radius_m, self.ring.inner_radius_m, u)
        d_out = oc.penetration_m
        dd_out = rd - ud
        rc = self.roller_contact
        return {"psi": psi, "f": f, "tan": tan, "n_in": n_in, "d_in": d_in, "dd_in": dd_in,
                "d_out": d_out, "dd_out": dd_out, "Q_in": rc.normal_force(d_in, dd_in),
                "Q_out": rc.normal_force(d_out, dd_out), "i": i, "j": j, "G": G, "u": u, "cd": cd}

    def housing_state(self, q: np.ndarray, qd: np.ndarray) -> dict[str, np.ndarray]:
        ring = self.ring
        Q = q.reshape(-1, 3)
        Qd = qd.reshape(-1, 3)
        P = ring.ref_positions + Q[:, 0:2]
        rho = np.hypot(P[:, 0], P[:, 1])
        e = P / rho[:, None]
        t = np.column_stack([-e[:, 1], e[:, 0]])
        delta = rho - ring.mean_radius_m + self.housing.interference_m
        ddelta = np.sum(e * Qd[:, 0:2], axis=1)
        # tangential displacement of the segment along the housing (stick spring)
        slip = ring.mean_radius_m * np.arctan2(P[:, 1], P[:, 0]) - ring.mean_radius_m * ring.phi
        slip = (slip + np.pi * ring.mean_radius_m) % (2 * np.pi * ring.mean_radius_m) - np.pi * ring.mean_radius_m
        vt = np.sum(t * Qd[:, 0:2], axis=1)
        rocking = Q[:, 2] - slip / ring.mean_radius_m  # Theta - phi_rot
        return {"e": e, "t": t, "rho": rho, "delta": delta, "ddelta": ddelta, "slip": slip, "vt": vt,
                "rocking": rocking, "Fn": self.housing.normal_force(delta, ddelta)}

    def generalized_force(self, t: float, pos: np.ndarray, vel: np.ndarray) -> np.ndarray:
        """All forces on the position DOFs (beams, contacts, housing, load, damping, centrifugal)."""
        N, n = self.rollers, self.ring.segments
        F = np.zeros(self.n_pos)
        s, r, q = self._split(pos)
        sd, rd, qd = self._split(vel)
        cs = self.contact_state(t, pos, vel)
        rc = self.roller_contact
        f, tan, n_in = cs["f"], cs["tan"], cs["n_in"]
        # friction, eq. 31: slip of the roller surface over each race
        w_abs = self.roller_spin_rad_s
        t_in = np.column_stack([-n_in[:, 1], n_in[:, 0]])
        v_si = np.sum((cs["cd"] - sd) * t_in, axis=1) - w_abs * self.roller_radius_m \
            - self.shaft_speed_rad_s * self.inner_radius_m
        v_so = r * self.cage_speed_rad_s + w_abs * self.roller_radius_m
        Ff_in = rc.friction_force(cs["Q_in"], v_si)  # on the roller, along t_in
        Ff_out = rc.friction_force(cs["Q_out"], v_so)  # on the roller, along tan
        # roller radial equation (tangential parts go to the cage)
        f_roller = cs["Q_in"][:, None] * n_in + Ff_in[:, None] * t_in
        F[2:2 + N] = np.sum(f_roller * f, axis=1) - cs["Q_out"]
        if self.centrifugal:
            F[2:2 + N] += self.roller_mass_kg * r * self.cage_speed_rad_s**2
        # shaft: reaction of the inner contacts, load, damping
        F[0:2] = -np.sum(f_roller, axis=0) + self.load_at(t) - self.shaft_damping_Ns_m * sd
        # race: beams + roller loads through G^T + friction split on the two segments + housing
        Fq = self.ring.internal_force(q).reshape(n, 3)
        G = cs["G"]
        np.add.at(Fq, cs["i"], cs["Q_out"][:, None] * G[:, 0:3])
        np.add.at(Fq, cs["j"], cs["Q_out"][:, None] * G[:, 3:6])
        _, x = self.ring.locate(cs["psi"])
        ff = -Ff_out[:, None] * tan
        np.add.at(Fq[:, 0:2], cs["i"], (1 - x)[:, None] * ff)
        np.add.at(Fq[:, 0:2], cs["j"], x[:, None] * ff)
        hs = self.housing_state(q, qd)
        hc = self.housing.contact
        Ft = -self.housing.tangential_stiffness_N_m * hs["slip"] + hc.friction_force(hs["Fn"], hs["vt"])
        Fq[:, 0:2] += -hs["Fn"][:, None] * hs["e"] + Ft[:, None] * hs["t"]
        # rocking on the bore: U = k_r beta^2 / 2, beta = Theta - phi_rot, d phi_rot / dP = t / rho
        Mr = self.housing.rocking_stiffness_Nm_rad * hs["rocking"]
        Fq[:, 2] -= Mr
        Fq[:, 0:2] += (Mr / hs["rho"])[:, None] * hs["t"]
        F[2 + N:] = Fq.ravel()
        return F

    def rhs(self, t: float, y: np.ndarray) -> np.ndarray:
        m = self.n_pos
        out = np.empty_like(y)
        out[:m] = y[m:]
        out[m:] = self.generalized_force(t, y[:m], y[m:]) / self.mass_diagonal
        return out

    # setup and outputs ---------------------------------------------------------
    def _roller_radii_at_rest(self, t: float, pos: np.ndarray) -> np.ndarray:
        """Radial roller positions where each roller is in equilibrium for fixed shaft and race.

        h(r) = Q_in n_in.f - Q_out + m r omega_c^2 decreases with r, so a bisection
        finds the root; a roller with a gap on both sides ends somewhere in the gap
        with no force, which is all the static problem needs.
        """
        N = self.rollers
        s = pos[0:2]
        q = pos[2 + N:]
        psi = self.angles(t)
        f = np.column_stack([np.cos(psi), np.sin(psi)])
        i, j, G = self.ring.surface_operator(psi)
        Q = q.reshape(-1, 3)
        u = np.sum(G[:, 0:3] * Q[i], axis=1) + np.sum(G[:, 3:6] * Q[j], axis=1)
        rc = self.roller_contact
        zero = np.zeros(N)

        def h(r: np.ndarray) -> np.ndarray:
            dvec = r[:, None] * f - s
            dist = np.hypot(dvec[:, 0], dvec[:, 1])
            q_in = rc.normal_force(self.inner_radius_m + self.roller_radius_m - dist, zero)
            q_out = rc.normal_force(r + self.roller_radius_m - self.ring.inner_radius_m - u, zero)
            out = q_in * np.sum(dvec * f, axis=1) / dist - q_out
            if self.centrifugal:
                out = out + self.roller_mass_kg * r * self.cage_speed_rad_s**2
            return out

        r0 = self.inner_radius_m + self.roller_radius_m
        lo, hi = np.full(N, r0 - 2e-5), np.full(N, r0 + 2e-5)
        for _ in range(48):  # 4e-5 m / 2^48 = 1.4e-19 m
            mid = 0.5 * (lo + hi)
            pos_side = h(mid) > 0
            lo = np.where(pos_side, mid, lo)
            hi = np.where(pos_side, hi, mid)
        return 0.5 * (lo + hi)

    def static_equilibrium(self, t: float = 0.0) -> np.ndarray:
        """Positions with zero velocity where all forces balance.

        Unloaded rollers at rest have no stiffness (k delta^m1 has zero slope at
        delta = 0), so the rollers are condensed out: for a shaft and race
        position each roller is put where its own forces balance
        (``_roller_radii_at_rest``), and Powell's hybrid method solves the
        remaining shaft and race equations.  If it does not converge, the best
        point is returned and the transient's settling time (excluded from
        spectrum and Poincare map) absorbs the remainder.
        """
        N = self.rollers
        zero_v = np.zeros(self.n_pos)
        fscale = 1.0 / max(1.0, float(np.hypot(*self.load_N)))
        keep = np.r_[0:2, 2 + N:self.n_pos]
        sc_all = self.state_scale()[:self.n_pos]

        def full(z: np.ndarray, sc: np.ndarray) -> np.ndarray:
            p = np.zeros(self.n_pos)
            p[keep] = sc * z
            p[2:2 + N] = self._roller_radii_at_rest(t, p)
            return p

        best, best_res = None, np.inf
        for fac in (1.0, 0.1, 10.0):
            sc = sc_all[keep] * fac

            def fun(z: np.ndarray, sc: np.ndarray = sc) -> np.ndarray:
                return self.generalized_force(t, full(z, sc), zero_v)[keep] * fscale

            sol = root(fun, np.zeros(keep.size), method="hybr", options={"xtol": 1e-13})
            p = full(sol.x, sc)
            res = float(np.max(np.abs(self.generalized_force(t, p, zero_v)))) * fscale
            if res < best_res:
                best, best_res = p, res
            # at speed the residual keeps the contact damping of the rollers' orbital motion about a
            # displaced shaft (c delta' with delta' ~ r omega_c e / r, ~1e-5 of the load), which the
            # condensed roller positions leave out; the settling time absorbs it
            if res < 1e-8 or (sol.success and res < 1e-4):
                break
        if best_res >= 1e-4:  # relative to the load
            log.warning("static equilibrium residual %.3g N; the settling time absorbs the rest",
                        best_res / fscale)
        return best

    def initial_state(self) -> np.ndarray:
        """Static equilibrium under the load at rest; with a load ramp, under no load."""
        model = dataclasses.replace(self, load_N=(0.0, 0.0)) if self.load_ramp_s > 0 else self
        return np.concatenate([model.static_equilibrium(0.0), np.zeros(self.n_pos)])

    def state_scale(self) -> np.ndarray:
        """Typical state magnitudes for absolute tolerances: 1e-7 m, 1 rad x 1e-5, velocities x 1e3/s."""
        N, n = self.rollers, self.ring.segments
        pos = np.concatenate([[1e-7] * 2, [1e-7] * N, np.tile([1e-7, 1e-7, 1e-5], n)])
        return np.concatenate([pos, pos * 3e3])

    def compiled_stepper(self):
        """Compiled RK4 loop with this model's parameters (``flexible_race_kernel``; ``fixed_step.Stepper``)."""
        from . import flexible_race_kernel as kernel

        params = kernel.pack(self)
        return lambda y, t0, h, n, every, samples: kernel.rk4(y, t0, h, n, every, *params, samples)

    def default_step_s(self, y: np.ndarray) -> float:
        """RK4 step from the stability limit at state y (``fixed_step.stability_step_s``), at most 2 us.

        The segment-on-housing and beam modes (about 200 kHz with the default
        housing) bound the step, not the accuracy of the kHz response: halving
        it changes the roller-pass line by far less than a bin (tested).
        """
        from ...analysis.fixed_step import stability_step_s

        return min(2e-6, stability_step_s(self.rhs, y, self.state_scale()))

    def shaft_displacement(self, Y: np.ndarray) -> np.ndarray:
        return Y[:, 0:2]

    def shaft_velocity(self, Y: np.ndarray) -> np.ndarray:
        return Y[:, self.n_pos:self.n_pos + 2]

    def roller_forces(self, t: np.ndarray, Y: np.ndarray) -> np.ndarray:
        """[t, N] roller to outer race contact load."""
        from . import flexible_race_kernel as kernel

        return kernel.outer_loads(np.asarray(t, float), np.ascontiguousarray(Y, dtype=float), *kernel.pack(self))

    def race_deflection(self, t: np.ndarray, Y: np.ndarray) -> np.ndarray:
        """[t, n] outward radial displacement of every segment."""
        n = self.ring.segments
        N = self.rollers
        Q = Y[:, 2 + N:2 + N + 3 * n].reshape(len(Y), n, 3)
        er = np.column_stack([np.cos(self.ring.phi), np.sin(self.ring.phi)])
        return np.einsum("tik,ik->ti", Q[:, :, 0:2], er)

    def energy_J(self, t: float, y: np.ndarray) -> float:
        """Kinetic + beam + contact + housing + load potential (constant when conservative)."""
        m = self.n_pos
        pos, vel = y[:m], y[m:]
        ke = 0.5 * float(np.sum(self.mass_diagonal * vel**2))
        s, r, q = self._split(pos)
        cs = self.contact_state(t, pos, vel)
        hs = self.housing_state(q, vel[2 + self.rollers:])
        pe = self.ring.strain_energy_J(q)
        pe += float(np.sum(self.roller_contact.energy_J(cs["d_in"]) + self.roller_contact.energy_J(cs["d_out"])))
        pe += float(np.sum(self.housing.energy_J(hs["delta"])))
        pe += 0.5 * self.housing.tangential_stiffness_N_m * float(np.sum(hs["slip"] ** 2))
        pe += 0.5 * self.housing.rocking_stiffness_Nm_rad * float(np.sum(hs["rocking"] ** 2))
        return ke + pe - float(np.dot(self.load_at(t), s))
