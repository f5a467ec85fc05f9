"""Losses of a built-in spindle motor (SI): electrical losses split stator/rotor, rotor windage.

Electrical losses at the rated point: P_loss = P (1 - eta) / eta (P the rated shaft power, eta the
rated efficiency).  They are split into a load-dependent part (copper, ~ torque^2) and a speed-
dependent part (iron, ~ f^beta with beta = 1.5-2: hysteresis ~ f, eddy currents ~ f^2):

    P_el(n, M) = P_loss [c (M / M_r)^2 + (1 - c) (min(n, n_r) / n_r)^beta]

with c = ``copper_fraction`` (share of copper losses at the rated point; default 0.6, our
assumption: take it from the motor maker when known), M_r = P / (2 pi n_r / 60) the rated torque,
n_r the rated (base) speed.  Above the base speed an induction spindle motor runs at constant
power, so the torque for a given power is P / omega; its flux is weakened as 1/n there, so the
iron losses stop growing (eddy currents ~ f^2 B^2 stay constant, hysteresis ~ f B^2 falls): they are
held at their base-speed value (our simplification).

Stator/rotor split: the iron losses heat the stator (the rotor iron sees only the slip frequency);
``stator_fraction`` of the copper losses heats the stator (default 2/3) and the rest the rotor (1/3):
the split Bossmanns and Tu (Int. J. Mach. Tools Manuf. 39 (1999) 1345-1366) used for an induction
spindle motor's losses under load.  Rotor windage (air friction in the gap) is added on top: half to
the rotor, half to the stator (it heats the gap air, which exchanges with both surfaces; our choice).

Windage: torque coefficient of a cylinder rotating inside a fixed one, Bilgen and Boulos,
J. Fluids Eng. 95 (1973) 122-126, Re = Omega R delta / nu, C_M = 2 M / (pi rho Omega^2 R^4 L):

    C_M = 10 (delta/R)^0.3 / Re          Re < 64
          2 (delta/R)^0.3 Re^-0.6         64 < Re < 500
          1.03 (delta/R)^0.3 Re^-0.5      500 < Re < 1e4
          0.065 (delta/R)^0.3 Re^-0.2     Re > 1e4

and P_w = M Omega = C_M pi rho Omega^3 R^4 L / 2.  For a thin gap in laminar Couette flow
M = 2 pi mu Omega R^3 L / delta, i.e. C_M = 4 / Re; the first branch gives 10 (delta/R)^0.3 / Re,
which is 4.07 / Re at delta/R = 0.05 (a check in the tests).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .properties import air

#: default stator share of the electrical losses (Bossmanns and Tu 1999)
STATOR_FRACTION = 2.0 / 3.0
#: default copper share of the rated losses (our assumption)
COPPER_FRACTION = 0.6
#: default exponent of the iron losses vs frequency
IRON_EXPONENT = 1.5


@dataclass(frozen=True)
class MotorLosses:
    """Heat [W] into the stator and the rotor, and its parts."""

    stator_W: float
    rotor_W: float
    electrical_W: float
    windage_W: float

    @property
    def total_W(self) -> float:
        return self.stator_W + self.rotor_W


@dataclass(frozen=True)
class MotorRating:
    """Rated point and loss model of a built-in motor (SI; speeds in rad/s)."""

    rated_power_W: float
    efficiency: float
    rated_speed_rad_s: float
    stator_fraction: float = STATOR_FRACTION
    copper_fraction: float = COPPER_FRACTION
    iron_exponent: float = IRON_EXPONENT

    def __post_init__(self):
        if not self.rated_power_W > 0 or not 0.0 < self.efficiency <= 1.0 or not self.rated_speed_rad_s > 0:
            raise ValueError("motor: need rated power > 0, 0 < efficiency <= 1, rated speed > 0")
        for name in ("stator_fraction", "copper_fraction"):
            if not 0.0 <= getattr(self, name) <= 1.0:
                raise ValueError(f"motor: {name} must be in [0, 1]")

    @property
    def rated_loss_W(self) -> float:
        """P (1 - eta) / eta."""
        return self.rated_power_W * (1.0 - self.efficiency) / self.efficiency

    @property
    def rated_torque_Nm(self) -> float:
        return self.rated_power_W / self.rated_speed_rad_s


def copper_loss_W(motor: MotorRating, torque_Nm: float) -> float:
    """P_loss c (M/M_r)^2 (module docstring)."""
    return motor.rated_loss_W * motor.copper_fraction * (torque_Nm / motor.rated_torque_Nm) ** 2


def iron_loss_W(motor: MotorRating, speed_rad_s: float) -> float:
    """P_loss (1 - c) (n/n_r)^beta up to the base speed, constant above it (module docstring)."""
    ratio = min(abs(speed_rad_s) / motor.rated_speed_rad_s, 1.0)
    return motor.rated_loss_W * (1.0 - motor.copper_fraction) * ratio ** motor.iron_exponent


def electrical_loss_W(motor: MotorRating, speed_rad_s: float, torque_Nm: float) -> float:
    """Copper plus iron losses (module docstring)."""
    return copper_loss_W(motor, torque_Nm) + iron_loss_W(motor, speed_rad_s)


def windage_torque_coefficient(reynolds: float, gap_to_radius: float) -> float:
    """Bilgen and Boulos (1973) C_M (module docstring)."""
    if reynolds <= 0.0:
        return 0.0
    g = gap_to_radius ** 0.3
    if reynolds < 64.0:
        return 10.0 * g / reynolds
    if reynolds < 500.0:
        return 2.0 * g * reynolds ** -0.6
    if reynolds < 1e4:
        return 1.03 * g * reynolds ** -0.5
    return 0.065 * g * reynolds ** -0.2


def windage_loss_W(rotor_radius_m: float, gap_m: float, length_m: float, speed_rad_s: float,
                   air_C: float = 40.0) -> float:
    """Air friction loss C_M pi rho Omega^3 R^4 L / 2 [W] of a rotor in its stator bore."""
    w = abs(speed_rad_s)
    if w == 0.0:
        return 0.0
    p = air(air_C)
    re = w * rotor_radius_m * gap_m / p.kinematic_viscosity_m2_s
    cm = windage_torque_coefficient(re, gap_m / rotor_radius_m)
    return 0.5 * cm * math.pi * p.density_kg_m3 * w ** 3 * rotor_radius_m ** 4 * length_m


def motor_losses(motor: MotorRating, speed_rad_s: float, *, power_W: float | None = None,
                 torque_Nm: float | None = None, load_fraction: float | None = None, windage_W: float = 0.0) -> MotorLosses:
    """Heat into stator and rotor at a speed and a load, given as the shaft power, the torque, or a
    fraction of the power available at that speed (rated torque below the base speed, rated power
    above it).  ``windage_W`` (e.g. :func:`windage_loss_W`) is split half and half."""
    given = [x is not None for x in (power_W, torque_Nm, load_fraction)]
    if sum(given) != 1:
        raise ValueError("give exactly one of power_W, torque_Nm, load_fraction")
    w = abs(speed_rad_s)
    if torque_Nm is None:
        if load_fraction is not None:
            available = motor.rated_power_W * min(1.0, w / motor.rated_speed_rad_s)
            power_W = load_fraction * available
        torque_Nm = power_W / w if w > 0 else (motor.rated_torque_Nm * load_fraction if load_fraction else 0.0)
    cu, fe = copper_loss_W(motor, torque_Nm), iron_loss_W(motor, w)
    s = motor.stator_fraction
    return MotorLosses(fe + s * cu + 0.5 * windage_W, (1.0 - s) * cu + 0.5 * windage_W, cu + fe, windage_W)
