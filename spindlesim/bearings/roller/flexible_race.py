"""Seed 000's roller bearing with a flexible (segmented) outer race: the model of a bearing with internal DOFs.

Bodies (seed 000 sec. 2, Figs. 1-2); the shaft and inner race are the rotor node (x, y), which
the rotor model carries (mass, damping, loads):
- N rollers: rigid bodies whose orbit angle and spin follow the cage kinematics (eqs. 1-4);
  each keeps one freedom, its radial position r_j (seed 000's "dummy body" radial joint).  Its
  equation in the rotating cage frame is m_r (r'' - r omega_c^2) = radial part of the contact
  forces; the tangential parts are carried by the cage constraint;
- outer race: n segments joined by co-rotational beams (eqs. 5-17, ``outer_race.SegmentedRing``),
  held in a fixed housing by a compliant contact per segment (normal, eq. 30) with a tangential
  stick spring, eq. 31 friction and the rocking stiffness of the segment's face on the bore
  (``HousingSupport``).

Contacts (eqs. 18-31): roller/inner race, circle against circle; roller/outer race through the
contact search of eqs. 18-29 on the race surface displaced by the segments and the eq. 17
deflection.  The contact load on the race is given to the two segments of the beam through the
transpose of the (linear, small-displacement) surface operator, so the elastic part of the model
is conservative (tested: energy is constant with damping and friction off and the shaft at rest).

Contract coordinates: q = [x, y | dr_1..dr_N, q_race (3n)] with dr_j = r_j - (R_i + R_r) (a
roller touching the centred inner race has dr = 0) and q_race the segment displacements from
the reference ring, so every internal DOF starts at zero.  ``generalized_force`` below is the
numpy reference of the compiled kernel (``flexible_race_kernel``), which the contract
(``bearing.FlexibleRaceBearing``) uses.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from ..base import RADIAL
from .contact_force import CompliantContact
from .contact_search import outer_race_contact
from .kinematics import CageKinematics
from .outer_race import SegmentedRing


@dataclass(frozen=True)
class HousingSupport:
    """Outer race to housing contact, per segment (seed 000: "surface contact").

    The segment's outer face (arc s) lies on the housing bore, so besides the radial force the
    surface resists rocking of the segment relative to the bore: with the radial stiffness k
    spread evenly over the arc, a rocking angle beta = Theta - phi_rot (segment rotation minus
    its angular position about the bearing centre) gives the moment -k s^2/12 beta.  Without it
    a segment rocks freely on a point support and the race under a roller between two segments
    is held only by beam bending (about 3e5 N/m for seed 000's race, 500 times softer than a
    roller contact).
    """

    contact: CompliantContact  # normal, eq. 30; friction eq. 31 on the tangential slip
    interference_m: float = 0.0  # radial fit overlap (unilateral contact only)
    tangential_stiffness_N_m: float = 1e7  # stick spring of the fit (no slip of the race in the housing)
    bilateral: bool = True  # a press fit keeps every segment seated: the contact also holds in tension
    rocking_arc_m: float = 0.0  # s of the rocking stiffness k s^2/12 (0: point support)

    @property
    def rocking_stiffness_Nm_rad(self) -> float:
        return self.contact.stiffness * self.rocking_arc_m ** 2 / 12.0

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
class FlexibleRace:
    """Seed 000's bearing with the rollers and race segments as internal DOFs: the model and the numpy
    reference of its force; the bearing contract is ``bearing.FlexibleRaceBearing``."""

    name: str
    node: int
    kinematics: CageKinematics
    rollers: int
    ring: SegmentedRing
    roller_contact: CompliantContact
    housing: HousingSupport
    roller_length_m: float
    roller_density_kg_m3: float = 7850.0
    cage_phase_rad: float = 0.0
    centrifugal: bool = True
    dof_names: tuple[str, ...] = RADIAL

    def __post_init__(self) -> None:
        if self.rollers < 3:
            raise ValueError("need at least 3 rollers")
        gap = self.ring.inner_radius_m - self.inner_radius_m - 2 * self.roller_radius_m
        if gap < -1e-9:
            raise ValueError(f"rollers do not fit between the races (gap {gap:.3e} m)")

    # geometry ---------------------------------------------------------------
    @property
    def inner_radius_m(self) -> float:
        return 0.5 * self.kinematics.inner_raceway_diameter_m

    @property
    def roller_radius_m(self) -> float:
        return 0.5 * self.kinematics.roller_diameter_m

    @property
    def roller_reference_radius_m(self) -> float:
        """r_j of a roller touching the centred inner race (dr_j = 0)."""
        return self.inner_radius_m + self.roller_radius_m

    @property
    def roller_mass_kg(self) -> float:
        return self.roller_density_kg_m3 * np.pi * self.roller_radius_m ** 2 * self.roller_length_m

    @cached_property
    def internal_mass(self) -> np.ndarray:
        return np.concatenate([[self.roller_mass_kg] * self.rollers, self.ring.mass_diagonal()])

    @property
    def n_pos(self) -> int:
        return 2 + self.rollers + 3 * self.ring.segments

    def roller_angles(self, shaft_angle_rad: float) -> np.ndarray:
        N = self.rollers
        return self.cage_phase_rad + 2 * np.pi * np.arange(N) / N + self.kinematics.cage_ratio * shaft_angle_rad

    def absolute(self, q: np.ndarray) -> np.ndarray:
        """Contract coordinates -> model positions [x, y, r_1..r_N, q_race]."""
        p = np.array(q, float)
        p[2:2 + self.rollers] += self.roller_reference_radius_m
        return p

    # numpy reference of the compiled force -----------------------------------------------
    def _split(self, p: np.ndarray):
        N = self.rollers
        return p[0:2], p[2:2 + N], p[2 + N:]

    def contact_state(self, pos: np.ndarray, vel: np.ndarray, speed: float, angle: float) -> dict:
        """Penetrations, rates and contact loads of every roller (inner and outer); pos absolute."""
        s, r, q = self._split(pos)
        sd, rd, qd = self._split(vel)
        psi = self.roller_angles(angle)
        f = np.column_stack([np.cos(psi), np.sin(psi)])
        tan = np.column_stack([-f[:, 1], f[:, 0]])
        wc = self.kinematics.cage_ratio * speed
        c = r[:, None] * f
        cd = rd[:, None] * f + (r * wc)[:, None] * tan
        dvec = c - s  # inner contact: circle (shaft) against circle (roller)
        dist = np.hypot(dvec[:, 0], dvec[:, 1])
        n_in = dvec / dist[:, None]
        d_in = self.inner_radius_m + self.roller_radius_m - dist
        dd_in = -np.sum(n_in * (cd - sd), axis=1)
        i, j, G = self.ring.surface_operator(psi)  # outer contact: eqs. 18-29 on the displaced race
        Q = q.reshape(-1, 3)
        Qd = qd.reshape(-1, 3)
        u = np.sum(G[:, 0:3] * Q[i], axis=1) + np.sum(G[:, 3:6] * Q[j], axis=1)
        ud = np.sum(G[:, 0:3] * Qd[i], axis=1) + np.sum(G[:, 3:6] * Qd[j], axis=1)
        oc = outer_race_contact(c, self.roller_radius_m, self.ring.inner_radius_m, u)
        d_out, dd_out = oc.penetration_m, rd - ud
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
        slip = ring.mean_radius_m * np.arctan2(P[:, 1], P[:, 0]) - ring.mean_radius_m * ring.phi
        slip = (slip + np.pi * ring.mean_radius_m) % (2 * np.pi * ring.mean_radius_m) - np.pi * ring.mean_radius_m
        vt = np.sum(t * Qd[:, 0:2], axis=1)
        rocking = Q[:, 2] - slip / ring.mean_radius_m  # Theta - phi_rot
        return {"e": e, "t": t, "rho": rho, "delta": delta, "ddelta": ddelta, "slip": slip, "vt": vt,
                "rocking": rocking, "Fn": self.housing.normal_force(delta, ddelta)}

    def generalized_force(self, pos: np.ndarray, vel: np.ndarray, speed: float, angle: float) -> np.ndarray:
        """All bearing forces on [x, y, r_j, q_race] (absolute positions): inner contacts on the
        shaft, roller radial equations (with centrifugal force), beams, contacts and housing."""
        N, n = self.rollers, self.ring.segments
        F = np.zeros(self.n_pos)
        s, r, q = self._split(pos)
        sd, rd, qd = self._split(vel)
        cs = self.contact_state(pos, vel, speed, angle)
        rc = self.roller_contact
        f, tan, n_in = cs["f"], cs["tan"], cs["n_in"]
        wc = self.kinematics.cage_ratio * speed
        w_abs = wc - self.kinematics.spin_ratio * speed  # absolute roller spin (eq. 4)
        t_in = np.column_stack([-n_in[:, 1], n_in[:, 0]])
        v_si = np.sum((cs["cd"] - sd) * t_in, axis=1) - w_abs * self.roller_radius_m - speed * self.inner_radius_m
        v_so = r * wc + w_abs * self.roller_radius_m
        Ff_in = rc.friction_force(cs["Q_in"], v_si)  # friction, eq. 31, on the roller along t_in
        Ff_out = rc.friction_force(cs["Q_out"], v_so)
        f_roller = cs["Q_in"][:, None] * n_in + Ff_in[:, None] * t_in
        F[2:2 + N] = np.sum(f_roller * f, axis=1) - cs["Q_out"]  # radial (tangential: the cage)
        if self.centrifugal:
            F[2:2 + N] += self.roller_mass_kg * r * wc ** 2
        F[0:2] = -np.sum(f_roller, axis=0)
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
        Mr = self.housing.rocking_stiffness_Nm_rad * hs["rocking"]  # U = k_r beta^2/2, d phi_rot/dP = t/rho
        Fq[:, 2] -= Mr
        Fq[:, 0:2] += (Mr / hs["rho"])[:, None] * hs["t"]
        F[2 + N:] = Fq.ravel()
        return F

    def potential_energy_J(self, pos: np.ndarray, angle: float) -> float:
        """Beam + contact + housing energy (absolute positions): with the kinetic energy of the
        rotor and the bearing, constant when damping and friction are off and the shaft is at rest."""
        zero = np.zeros_like(pos)
        s, r, q = self._split(pos)
        cs = self.contact_state(pos, zero, 0.0, angle)
        hs = self.housing_state(q, np.zeros_like(q))
        pe = self.ring.strain_energy_J(q)
        pe += float(np.sum(self.roller_contact.energy_J(cs["d_in"]) + self.roller_contact.energy_J(cs["d_out"])))
        pe += float(np.sum(self.housing.energy_J(hs["delta"])))
        pe += 0.5 * self.housing.tangential_stiffness_N_m * float(np.sum(hs["slip"] ** 2))
        pe += 0.5 * self.housing.rocking_stiffness_Nm_rad * float(np.sum(hs["rocking"] ** 2))
        return pe
