"""Rolling kinematics of every ball at its contact angles: cage speed, ball angular velocity, spin and roll.

One ball in its meridional plane, x radial (outwards), z along the row's thrust direction, y the
orbit tangent; ball centre on the pitch circle R_c = d_m / 2, contact points at +(D/2) n_o (outer)
and -(D/2) n_i (inner), n = (cos a, 0, sin a) in (x, y, z); outer ring fixed, inner ring and shaft
turning at w about z (a mirror image for the rows carrying -z thrust: sizes and ratios are the same).
Unknowns: the cage (orbit) speed w_c and the ball's absolute angular velocity W = (W_x, 0, W_z).
No slip at both contact centres (the orbit tangent component of the contact point velocities):

    w_c R_c + (D/2)(W_z cos a_o - W_x sin a_o) = 0
    w_c R_c - (D/2)(W_z cos a_i - W_x sin a_i) = w (R_c - (D/2) cos a_i)

and the race control (Jones 1960; Harris and Kotzalas 2007, *Advanced Concepts*, ch. 2):

- outer: no spin at the outer contact, W . n_o = 0;
- inner: no spin at the inner contact, (W - w e_z) . n_i = 0;
- full: the ball's axis in the cage frame is normal to the bisector of the contact normals,
  (W - w_c e_z) . (cos b, 0, sin b) = 0, b = (a_i + a_o) / 2.

Spin at a contact: the ball's angular velocity relative to that race along the contact normal;
roll: its component in the meridional plane across the normal (the rolling axis).  The
gyroscopic moment is M_g = J w_c |W_x| (the rate of the ball's angular momentum as its axis turns
with the cage), which is the kernel's J w_R w_c sin(beta) for every race control.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

RACE_CONTROLS = ("outer_race_control", "inner_race_control", "full")
#: per-ball race-control codes (the kernel's ``race``, the state's ``race_used``): 1 outer, -1 inner, 0 full
RACE_CODES = {"outer_race_control": 1, "inner_race_control": -1, "full": 0}


@dataclass(frozen=True)
class BallMotion:
    """Rolling kinematics of the balls (arrays of the shape of the contact angles)."""

    cage_rad_s: np.ndarray            # orbit speed w_c
    ball_radial_rad_s: np.ndarray     # W_x, absolute
    ball_axial_rad_s: np.ndarray      # W_z, absolute
    spin_inner_rad_s: np.ndarray      # relative to the inner ring, along n_i
    spin_outer_rad_s: np.ndarray      # relative to the outer ring, along n_o
    roll_inner_rad_s: np.ndarray      # relative to the inner ring, across n_i (>= 0)
    roll_outer_rad_s: np.ndarray

    @property
    def spin_roll_inner(self) -> np.ndarray:
        """|spin| / roll at the inner contact (0 where the ball does not roll)."""
        return _ratio(self.spin_inner_rad_s, self.roll_inner_rad_s)

    @property
    def spin_roll_outer(self) -> np.ndarray:
        return _ratio(self.spin_outer_rad_s, self.roll_outer_rad_s)


def _ratio(spin, roll):
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(roll > 0.0, np.abs(spin) / np.where(roll > 0.0, roll, 1.0), 0.0)


def ball_motion(contact_angle_inner_rad, contact_angle_outer_rad, speed_rad_s: float, pitch_diameter_m: float,
                ball_diameter_m: float, race_control) -> BallMotion:
    """Kinematics of balls at the given contact angles (arrays) and shaft speed (module docstring);
    ``race_control``: one of RACE_CONTROLS, or per-ball codes (RACE_CODES) shaped like the angles."""
    if isinstance(race_control, str):
        if race_control not in RACE_CONTROLS:
            raise ValueError(f"race control must be one of {RACE_CONTROLS}, not {race_control!r}")
        race_control = RACE_CODES[race_control]
    ai = np.asarray(contact_angle_inner_rad, float)
    ao = np.asarray(contact_angle_outer_rad, float)
    w = float(speed_rad_s)
    Rc, h = 0.5 * pitch_diameter_m, 0.5 * ball_diameter_m
    si, ci, so, co = np.sin(ai), np.cos(ai), np.sin(ao), np.cos(ao)
    shape = ai.shape
    one, zero = np.ones(shape), np.zeros(shape)
    # unknowns (w_c, W_x, W_z)
    A = np.zeros(shape + (3, 3))
    rhs = np.zeros(shape + (3,))
    A[..., 0, :] = np.stack([Rc * one, -h * so, h * co], axis=-1)
    A[..., 1, :] = np.stack([Rc * one, h * si, -h * ci], axis=-1)
    rhs[..., 1] = w * (Rc - h * ci)
    code = np.broadcast_to(np.asarray(race_control), shape)
    b = 0.5 * (ai + ao)
    outer, inner = (code > 0)[..., None], (code < 0)[..., None]
    A[..., 2, :] = np.where(outer, np.stack([zero, co, so], axis=-1),
                            np.where(inner, np.stack([zero, ci, si], axis=-1),
                                     np.stack([-np.sin(b), np.cos(b), np.sin(b)], axis=-1)))
    rhs[..., 2] = np.where(code < 0, w * si, 0.0)
    x = np.linalg.solve(A, rhs[..., None])[..., 0]
    wc, Wx, Wz = x[..., 0], x[..., 1], x[..., 2]
    return BallMotion(
        cage_rad_s=wc, ball_radial_rad_s=Wx, ball_axial_rad_s=Wz,
        spin_inner_rad_s=Wx * ci + (Wz - w) * si, spin_outer_rad_s=Wx * co + Wz * so,
        roll_inner_rad_s=np.abs(-Wx * si + (Wz - w) * ci), roll_outer_rad_s=np.abs(-Wx * so + Wz * co))
