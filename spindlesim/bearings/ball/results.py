"""Frozen result records of the ball bearing model (SI unless the name says otherwise).

Arrays indexed [row, ball]: row 0 is the row at the smallest z; ball j sits at the azimuth
psi_j = phi_cage + 2 pi j / Z (from +x towards +y).  Contact angles are measured in each row's
own contact direction (positive: the ball is loaded towards the side the row carries thrust on).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .rating import Lives


@dataclass(frozen=True)
class BallState:
    """Quasi-static state of the bearing (set) at one inner-ring displacement."""

    displacement: np.ndarray            # (5,) x, y, z [m], theta_x, theta_y [rad]
    reaction: np.ndarray                # (5,) force/moment of the bearing on the shaft [N, N m]
    load: np.ndarray                    # (5,) load on the bearing: the given load plus the holding load
    holding_load: np.ndarray            # (5,) what holds the held DOFs puts on the bearing (0 at free DOFs)
    held: tuple[bool, ...]              # (5,) DOFs held at a prescribed displacement
    stiffness: np.ndarray               # (5, 5) K = -d reaction / d displacement
    speed_rad_s: float
    model: str                          # race control of the balls (outer_race_control, ...; auto: per ball)
    race_used: np.ndarray               # (rows, Z) race control of each ball: 1 outer, -1 inner, 0 full
    cage_angle_rad: float
    psi_rad: np.ndarray                 # (rows, Z) ball azimuths
    row_z_m: np.ndarray                 # (rows,) axial position of each row
    row_sign: np.ndarray                # (rows,) thrust direction each row carries
    element_load_inner_N: np.ndarray    # (rows, Z) Q_i
    element_load_outer_N: np.ndarray    # (rows, Z) Q_o
    contact_angle_inner_deg: np.ndarray  # (rows, Z)
    contact_angle_outer_deg: np.ndarray  # (rows, Z)
    max_pressure_inner_Pa: np.ndarray   # (rows, Z) Hertz p0
    max_pressure_outer_Pa: np.ndarray
    semi_axes_inner_m: np.ndarray       # (rows, Z, 2): a (across rolling), b (along rolling)
    semi_axes_outer_m: np.ndarray
    centrifugal_force_N: np.ndarray     # (rows, Z)
    gyroscopic_moment_Nm: np.ndarray    # (rows, Z)
    traction_ratio: np.ndarray          # (rows, Z) friction force / normal load needed for the gyroscopic couple
    spin_moment_inner_Nm: np.ndarray    # (rows, Z) (3/8) Q a E(k): full-slip spin moment per unit friction coeff.
    spin_moment_outer_Nm: np.ndarray
    race_control: np.ndarray            # (rows, Z) Jones' criterion: 1 outer, -1 inner, 0 either (checks)
    spin_roll_inner: np.ndarray         # (rows, Z) |spin| / roll at the inner contact (kinematics)
    spin_roll_outer: np.ndarray
    edge_angle_inner_deg: np.ndarray    # (rows, Z) angle the contact ellipse reaches on the thrust side
    edge_angle_outer_deg: np.ndarray
    shoulder_angle_inner_deg: float     # where the thrust-side shoulder ends the groove
    shoulder_angle_outer_deg: float
    truncated_inner: np.ndarray         # (rows, Z) bool: loaded contact whose ellipse runs over the shoulder
    truncated_outer: np.ndarray
    row_axial_load_N: np.ndarray        # (rows,) thrust each row carries (positive in its direction)
    floating_ring_axial_m: float        # outer-ring axial shift of the spring-preloaded rows (0: none)
    lives: Lives
    iterations: int                     # Newton iterations of the set equilibrium (0: given displacement)

    @property
    def element_load_N(self) -> np.ndarray:
        """(2, rows, Z): [0] inner contact loads, [1] outer contact loads."""
        return np.stack([self.element_load_inner_N, self.element_load_outer_N])

    @property
    def life_L10_Mrev(self) -> dict[str, float | None]:
        """{"ISO 281": basic rating life, "ISO/TS 16281": reference rating life} [10^6 revolutions]."""
        return {"ISO 281": self.lives.L10_iso281_Mrev, "ISO/TS 16281": self.lives.L10r_iso16281_Mrev}

    @property
    def life_L10_iso281_Mrev(self) -> float | None:
        return self.lives.L10_iso281_Mrev

    @property
    def life_L10r_iso16281_Mrev(self) -> float | None:
        return self.lives.L10r_iso16281_Mrev

    @property
    def speed_rpm(self) -> float:
        return self.speed_rad_s * 30.0 / math.pi

    def loaded_balls(self, threshold_N: float = 1e-6) -> np.ndarray:
        """Balls per row that carry load from the inner ring, shape (rows,)."""
        return (self.element_load_inner_N > threshold_N).sum(axis=1)

    def applied_load(self) -> np.ndarray:
        """The given load (without the holding load): Fx, Fy, Fz [N], Mx, My [N m]."""
        return self.load - self.holding_load

    @property
    def truncated_contacts(self) -> int:
        """Number of loaded contacts (inner and outer) whose ellipse runs over the shoulder."""
        return int(np.sum(self.truncated_inner) + np.sum(self.truncated_outer))


@dataclass(frozen=True)
class BallSweep:
    """The bearing over one swept parameter (preload, a load component or speed)."""

    name: str                            # e.g. "preload_axial_um", "fx_N", "speed_rpm"
    values: np.ndarray                   # (n,) swept values, in the unit of ``name``
    load: np.ndarray                     # (n, 5) load on the bearing at each point (given + holding)
    holding_load: np.ndarray             # (n, 5) holding load of the held DOFs (0 at free DOFs)
    model: tuple[str, ...]               # (n,) race control of each point (auto: per ball, race_used)
    race_used: np.ndarray                # (n, rows, Z) race control of each ball: 1 outer, -1 inner, 0 full
    speed_rad_s: np.ndarray              # (n,)
    displacement: np.ndarray             # (n, 5)
    stiffness: np.ndarray                # (n, 5, 5)
    element_load_inner_N: np.ndarray     # (n, rows, Z)
    element_load_outer_N: np.ndarray     # (n, rows, Z)
    contact_angle_inner_deg: np.ndarray  # (n, rows, Z)
    contact_angle_outer_deg: np.ndarray  # (n, rows, Z)
    max_pressure_inner_Pa: np.ndarray    # (n, rows, Z)
    max_pressure_outer_Pa: np.ndarray    # (n, rows, Z)
    centrifugal_force_N: np.ndarray      # (n, rows, Z)
    gyroscopic_moment_Nm: np.ndarray     # (n, rows, Z)
    race_control: np.ndarray             # (n, rows, Z) Jones' criterion
    edge_angle_inner_deg: np.ndarray     # (n, rows, Z)
    edge_angle_outer_deg: np.ndarray     # (n, rows, Z)
    truncated_inner: np.ndarray          # (n, rows, Z) bool
    truncated_outer: np.ndarray          # (n, rows, Z) bool
    row_axial_load_N: np.ndarray         # (n, rows)
    row_sign: np.ndarray                 # (rows,)
    life_L10_iso281_Mrev: np.ndarray     # (n,) nan where not applicable
    life_L10r_iso16281_Mrev: np.ndarray  # (n,)
    preload_label: str                   # e.g. "position preload 6 um" (the fixed operating data)


def sweep_from_states(name: str, values, states: list[BallState], preload_label: str) -> BallSweep:
    """Stack the states of a sweep."""
    def st(attr):
        return np.array([getattr(s, attr) for s in states])

    return BallSweep(
        name=name, values=np.asarray(values, float), load=st("load"), holding_load=st("holding_load"),
        model=tuple(s.model for s in states), race_used=st("race_used"),
        speed_rad_s=st("speed_rad_s"), displacement=st("displacement"), stiffness=st("stiffness"),
        element_load_inner_N=st("element_load_inner_N"), element_load_outer_N=st("element_load_outer_N"),
        contact_angle_inner_deg=st("contact_angle_inner_deg"), contact_angle_outer_deg=st("contact_angle_outer_deg"),
        max_pressure_inner_Pa=st("max_pressure_inner_Pa"), max_pressure_outer_Pa=st("max_pressure_outer_Pa"),
        centrifugal_force_N=st("centrifugal_force_N"), gyroscopic_moment_Nm=st("gyroscopic_moment_Nm"),
        race_control=st("race_control"), edge_angle_inner_deg=st("edge_angle_inner_deg"),
        edge_angle_outer_deg=st("edge_angle_outer_deg"), truncated_inner=st("truncated_inner"),
        truncated_outer=st("truncated_outer"), row_axial_load_N=st("row_axial_load_N"), row_sign=states[0].row_sign.copy(),
        life_L10_iso281_Mrev=np.array([math.nan if s.life_L10_iso281_Mrev is None else s.life_L10_iso281_Mrev
                                       for s in states]),
        life_L10r_iso16281_Mrev=np.array([math.nan if s.life_L10r_iso16281_Mrev is None else s.life_L10r_iso16281_Mrev
                                          for s in states]),
        preload_label=preload_label,
    )
