"""Outer race as rigid segments joined by planar beam elements (seed 000, eqs. 5-17).

n rigid segments sit on the mean radius R of the race (segment i at angle
phi_i = 2 pi i / n, planar DOFs X_i, Y_i, Theta_i).  Beam i joins segment i
and segment i+1 (cyclic); its local frame has xi along the line from segment i
to i+1 and eta 90 deg counter-clockwise from xi (towards the centre for the
counter-clockwise numbering).  Large rotation is handled co-rotationally, as
seed 000 eqs. 12-13 prescribe: in the beam frame the deformation vector is

    delta_i     = [0, 0, Theta_i - Theta_i0 - (gamma_i - gamma_i0)]          (eq. 12)
    delta_{i+1} = [l_i - l_0i, 0, Theta_{i+1} - Theta_{i+1,0} - (gamma_i - gamma_i0)]  (eq. 13)

with gamma_i the current angle of the chord (the reference orientations
Theta_0, gamma_0 are subtracted so the undeformed ring is stress free), and
the element force S_i = K_i eps_i (eq. 10) with the Euler-Bernoulli frame
stiffness of eq. 11 (the matrix printed in seed 000 is garbled in our copy;
we use the standard 2-D frame element it describes, e.g. Przemieniecki,
Theory of Matrix Structural Analysis, 1968, which has the entries 12 EI/l^3,
6 EI/l^2, 4 EI/l, 2 EI/l and EA/l shown in eq. 11).  The forces on the
segments are -S rotated to the inertial frame.  Because S is the gradient of
U = eps^T K eps / 2 with respect to the co-rotational deformations, the
forces are conservative (exactly, for any rotation).

Deflection between segments, eq. 17: with RN = RN'_i and QN = QN'_{i+1} the
end moments of S and beta the distance from segment i along the chord,
integrating eq. 14 twice with the moment of eq. 16 and v(0) = v(L) = 0 gives

    v(beta) = [(RN + QN) beta^3 / L - 3 RN beta^2 + (2 RN - QN) L beta] / (6 E I).

(Seed 000 prints eq. 17 with every term multiplied by L, which is not
dimensionally consistent; the form above is the integral of its eqs. 14-16.)
It equals the cubic Hermite shape L [phi1 (x - 2x^2 + x^3) + phi2 (x^3 - x^2)],
x = beta/L, of the end rotations phi1, phi2 (eta direction).

Segment inertia: mass rho A R (2 pi / n); rotary inertia of a block of arc
length s = 2 pi R / n and radial thickness h, m (s^2 + h^2) / 12.

Reference for the free ring check: thin ring in-plane bending, mode n,
w_n = sqrt(E I / (rho A R^4)) n (n^2 - 1) / sqrt(n^2 + 1) (Rao, Vibration of
Continuous Systems, 2007, ch. 12; Hoppe 1871).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np


def frame_stiffness(E: float, A: float, I: float, l: float) -> np.ndarray:
    """6x6 Euler-Bernoulli frame element stiffness in its own frame, seed 000 eq. 11.

    DOF order [u_i, v_i, phi_i, u_j, v_j, phi_j] (eq. 9).
    """
    a, b, c, d, e = E * A / l, 12 * E * I / l**3, 6 * E * I / l**2, 4 * E * I / l, 2 * E * I / l
    return np.array([
        [a, 0, 0, -a, 0, 0],
        [0, b, c, 0, -b, c],
        [0, c, d, 0, -c, e],
        [-a, 0, 0, a, 0, 0],
        [0, -b, -c, 0, b, -c],
        [0, c, e, 0, -c, d],
    ])


def deflection_eq17(RN: np.ndarray, QN: np.ndarray, L: np.ndarray, beta: np.ndarray, EI: float) -> np.ndarray:
    """Beam deflection between segments, seed 000 eq. 17 (eta direction; see the module note on its L factor)."""
    return ((RN + QN) * beta**3 / L - 3.0 * RN * beta**2 + (2.0 * RN - QN) * L * beta) / (6.0 * EI)


def _wrap(a: np.ndarray) -> np.ndarray:
    return (a + np.pi) % (2.0 * np.pi) - np.pi


@dataclass(frozen=True)
class SegmentedRing:
    """Outer race of n rigid segments and n co-rotational beams (seed 000 sec. 3)."""

    segments: int
    mean_radius_m: float
    thickness_m: float  # radial
    width_m: float  # axial
    youngs_modulus_Pa: float
    density_kg_m3: float

    def __post_init__(self) -> None:
        if self.segments < 3:
            raise ValueError("a ring needs at least 3 segments")
        if min(self.mean_radius_m, self.thickness_m, self.width_m, self.youngs_modulus_Pa, self.density_kg_m3) <= 0:
            raise ValueError("ring dimensions and material must be positive")

    # geometry -----------------------------------------------------------
    @property
    def area_m2(self) -> float:
        return self.thickness_m * self.width_m

    @property
    def inertia_m4(self) -> float:
        return self.width_m * self.thickness_m**3 / 12.0

    @property
    def inner_radius_m(self) -> float:
        return self.mean_radius_m - 0.5 * self.thickness_m

    @property
    def outer_radius_m(self) -> float:
        return self.mean_radius_m + 0.5 * self.thickness_m

    @cached_property
    def phi(self) -> np.ndarray:
        """Angular position of each segment [rad]."""
        return 2.0 * np.pi * np.arange(self.segments) / self.segments

    @cached_property
    def ref_positions(self) -> np.ndarray:
        return self.mean_radius_m * np.column_stack([np.cos(self.phi), np.sin(self.phi)])

    @property
    def chord_m(self) -> float:
        """Free length l_0 of every beam."""
        return 2.0 * self.mean_radius_m * np.sin(np.pi / self.segments)

    @cached_property
    def ref_chord_angle(self) -> np.ndarray:
        """gamma_0 of every beam (chord from segment i to i+1)."""
        return self.phi + 0.5 * np.pi + np.pi / self.segments

    @property
    def segment_mass_kg(self) -> float:
        return self.density_kg_m3 * self.area_m2 * self.mean_radius_m * 2.0 * np.pi / self.segments

    @property
    def segment_inertia_kg_m2(self) -> float:
        s = 2.0 * np.pi * self.mean_radius_m / self.segments
        return self.segment_mass_kg * (s**2 + self.thickness_m**2) / 12.0

    @cached_property
    def local_stiffness(self) -> np.ndarray:
        return frame_stiffness(self.youngs_modulus_Pa, self.area_m2, self.inertia_m4, self.chord_m)

    def mass_diagonal(self) -> np.ndarray:
        """Diagonal mass for the DOFs [X0, Y0, T0, X1, ...]."""
        return np.tile([self.segment_mass_kg, self.segment_mass_kg, self.segment_inertia_kg_m2], self.segments)

    # beams ----------------------------------------------------------------
    def beam_state(self, q: np.ndarray) -> dict[str, np.ndarray]:
        """Co-rotational quantities of every beam for the displacement q [3n] from the reference.

        Returns e (unit chord), nrm (eta axis), l, eps [n, 6] (eqs. 9, 12, 13) and S [n, 6] (eq. 10).
        """
        n = self.segments
        Q = q.reshape(n, 3)
        P = self.ref_positions + Q[:, 0:2]
        d = np.roll(P, -1, axis=0) - P
        l = np.hypot(d[:, 0], d[:, 1])
        e = d / l[:, None]
        nrm = np.column_stack([-e[:, 1], e[:, 0]])
        dgamma = _wrap(np.arctan2(d[:, 1], d[:, 0]) - self.ref_chord_angle)
        eps = np.zeros((n, 6))
        eps[:, 2] = _wrap(Q[:, 2] - dgamma)
        eps[:, 3] = l - self.chord_m
        eps[:, 5] = _wrap(np.roll(Q[:, 2], -1) - dgamma)
        S = eps @ self.local_stiffness.T
        # shear = (end moments) / current length: eq. 11 evaluated with the current l, which makes
        # the forces the exact gradient of U (with l_0 it differs by the axial strain, ~1e-4)
        S[:, 1] = (S[:, 2] + S[:, 5]) / l
        S[:, 4] = -S[:, 1]
        return {"e": e, "nrm": nrm, "l": l, "eps": eps, "S": S}

    def internal_force(self, q: np.ndarray) -> np.ndarray:
        """Generalised beam forces on the segments [3n] (= -dU/dq), from eqs. 10-13."""
        n = self.segments
        b = self.beam_state(q)
        e, nrm, S = b["e"], b["nrm"], b["S"]
        # the beam pulls on its end segments with -S, rotated from (xi, eta) to (X, Y)
        f_i = -(S[:, 0:1] * e + S[:, 1:2] * nrm)
        f_j = -(S[:, 3:4] * e + S[:, 4:5] * nrm)
        F = np.zeros((n, 3))
        F[:, 0:2] += f_i
        F[:, 2] += -S[:, 2]
        F[:, 0:2] += np.roll(f_j, 1, axis=0)
        F[:, 2] += np.roll(-S[:, 5], 1)
        return F.ravel()

    def strain_energy_J(self, q: np.ndarray) -> float:
        b = self.beam_state(q)
        return float(0.5 * np.sum(b["eps"] * b["S"]))

    def tangent_stiffness(self, q: np.ndarray | None = None, h: float = 1e-9) -> np.ndarray:
        """Numerical -dF/dq at q (central differences); for modal checks."""
        q0 = np.zeros(3 * self.segments) if q is None else np.asarray(q, float)
        K = np.empty((q0.size, q0.size))
        scale = np.tile([self.mean_radius_m, self.mean_radius_m, 1.0], self.segments) * h
        for k in range(q0.size):
            dq = np.zeros_like(q0)
            dq[k] = scale[k]
            K[:, k] = -(self.internal_force(q0 + dq) - self.internal_force(q0 - dq)) / (2 * scale[k])
        return 0.5 * (K + K.T)

    def free_frequencies_hz(self) -> np.ndarray:
        """Free-free natural frequencies [Hz] of the segmented ring, ascending (rigid modes ~0)."""
        K = self.tangent_stiffness()
        m = self.mass_diagonal()
        A = K / np.sqrt(np.outer(m, m))
        w2 = np.linalg.eigvalsh(A)
        return np.sqrt(np.clip(w2, 0.0, None)) / (2.0 * np.pi)

    def analytic_ring_frequency_hz(self, n: int) -> float:
        """Thin free ring in-plane bending mode n (inextensional), Hz."""
        EI, rA, R = self.youngs_modulus_Pa * self.inertia_m4, self.density_kg_m3 * self.area_m2, self.mean_radius_m
        return float(np.sqrt(EI / (rA * R**4)) * n * (n**2 - 1) / np.sqrt(n**2 + 1) / (2.0 * np.pi))

    # interface to the contact search -------------------------------------
    def locate(self, psi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Beam index and chord fraction x in [0, 1) where the ray at angle psi meets the reference polygon."""
        n = self.segments
        a = (np.asarray(psi) % (2.0 * np.pi)) / (2.0 * np.pi / n)
        i = np.minimum(np.floor(a).astype(int), n - 1)
        # ray / chord intersection in the reference configuration
        alpha = (a - i) * (2.0 * np.pi / n)  # angle from segment i
        h = np.pi / n
        x = 0.5 * (1.0 + np.tan(alpha - h) / np.tan(h))
        return i, x

    def surface_operator(self, psi: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Linear map from segment displacements to the outward radial displacement of the race on the ray psi.

        Small-displacement interface of seed 000 eqs. 17 and 25 (race deflections
        are nanometres on a 14 mm radius):

            u(psi) = (1-x) e_i . dP_i + x e_j . dP_j + v(x) (eta . f)

        the radial displacements of the two segments interpolated along the
        beam, plus the eq. 17 deflection v = L [phi1 N1(x) + phi2 N2(x)] of the end
        rotations relative to the chord (eqs. 12-13 linearised, d gamma =
        eta . (dP_j - dP_i) / L) projected on the ray.  Interpolating the radial
        components (rather than the polygon chord) makes u continuous where a
        roller passes from one beam to the next, exact for a uniform expansion and
        zero for a rigid rotation of the ring, as for the real circular race.
        Returns (i, j, G) with u = G[:, :3] . q_i + G[:, 3:] . q_j (G is [k, 6]).
        """
        i, x = self.locate(psi)
        j = (i + 1) % self.segments
        gam = self.ref_chord_angle[i]
        eta = np.column_stack([-np.sin(gam), np.cos(gam)])
        f = np.column_stack([np.cos(psi), np.sin(psi)])
        ei = np.column_stack([np.cos(self.phi[i]), np.sin(self.phi[i])])
        ej = np.column_stack([np.cos(self.phi[j]), np.sin(self.phi[j])])
        L = self.chord_m
        N1 = x - 2 * x**2 + x**3
        N2 = x**3 - x**2
        proj = np.sum(eta * f, axis=1)  # about -1: eta points inwards
        # v = L N1 dTheta_i + L N2 dTheta_j - (N1 + N2) eta . (dP_j - dP_i)
        G = np.zeros((np.size(psi), 6))
        G[:, 0:2] = (1.0 - x)[:, None] * ei + ((N1 + N2) * proj)[:, None] * eta
        G[:, 3:5] = x[:, None] * ej - ((N1 + N2) * proj)[:, None] * eta
        G[:, 2] = L * N1 * proj
        G[:, 5] = L * N2 * proj
        return i, j, G
