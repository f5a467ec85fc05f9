"""Convection coefficients from published correlations (SI; fluid properties from ``properties``).

Every function returns a Nusselt number or h [W/(m^2 K)]; the validity range is in its docstring
and in docs/theory.md ("Spindle thermal model: heat transfer").  Outside the range a correlation
is still evaluated (a spindle passes through many regimes during a run-up), and
:func:`validity_warning` logs it once per correlation.

Sources:

- Rotating cylinder in still air: Nu_D = 0.133 Re^(2/3) Pr^(1/3), Re = Omega D^2 / nu, Re < 4.3e5,
  0.7 < Pr < 670 (Kendoush, Int. J. Heat Fluid Flow 17 (1996) 439-441; the form given with
  Incropera's rotating-shaft problem).  Combined with free convection as
  Nu = (Nu_rot^3 + Nu_free^3)^(1/3) (Churchill's rule for assisting mixed convection).
- Free convection, horizontal cylinder: Churchill and Chu, Int. J. Heat Mass Transfer 18 (1975)
  1049-1053: Nu = {0.60 + 0.387 Ra^(1/6) / [1 + (0.559/Pr)^(9/16)]^(8/27)}^2, Ra <= 1e12
  (Incropera eq. 9.34); properties at the film temperature, beta = 1/T_film (ideal gas).
- Rotor-stator gap, inner cylinder rotating, no axial flow: Becker and Kaye, J. Heat Transfer 84
  (1962) 97-105, in the form reviewed by Howey, Childs and Holmes, IEEE Trans. Ind. Electron. 59
  (2012) 1367-1375: Ta = Omega^2 r_m delta^3 / nu^2, Ta_m = Ta / F_g with the geometric factor
  F_g = pi^4 / (1697 P) (2 r_m - 2.304 delta) / (2 r_m - delta),
  P = 0.0571 (1 - 0.652 x) + 0.00056 / (1 - 0.652 x), x = (delta/r_m) / (1 - delta/r_m);
  Nu = h (2 delta) / k = 2 (Ta_m < 1700, conduction), 0.128 Ta_m^0.367 (1700-1e4),
  0.409 Ta_m^0.241 (1e4-1e7).  With an axial flow through the gap we take the larger of that and
  the channel-flow Nusselt number below on D_h = 2 delta (our simplification; it neglects the
  enhancement of the combined flow).
- Channel flow (cooling jacket): laminar fully developed Nu = 3.66 (uniform wall temperature) or
  4.36 (uniform heat flux); turbulent Gnielinski, Int. Chem. Eng. 16 (1976) 359-368:
  Nu = (f/8)(Re - 1000) Pr / (1 + 12.7 sqrt(f/8) (Pr^(2/3) - 1)), f = (0.790 ln Re - 1.64)^-2
  (Petukhov), 3000 <= Re <= 5e6, 0.5 <= Pr <= 2000; between Re 2300 and 4000 the linear blend
  of Gnielinski, Int. J. Heat Mass Transfer 63 (2013) 134-140,
  Nu = (1 - g) Nu_lam + g Nu_turb(4000), g = (Re - 2300) / 1700.  Option: Dittus-Boelter,
  Nu = 0.023 Re^0.8 Pr^n (n = 0.4 heating the fluid, 0.3 cooling), Re >= 1e4, 0.6 <= Pr <= 160.
- Sphere in a flow (balls in the bearing's oil-air): Whitaker, AIChE J. 18 (1972) 361-371:
  Nu = 2 + (0.4 Re^(1/2) + 0.06 Re^(2/3)) Pr^0.4 (mu/mu_s)^(1/4), 3.5 < Re < 7.6e4,
  0.71 < Pr < 380 (Incropera eq. 7.56; the viscosity ratio is taken as 1 here).
- Radiation, linearised: h_r = eps sigma (T_s + T_inf)(T_s^2 + T_inf^2) (kelvin).
"""

from __future__ import annotations

import logging
import math

from .properties import KELVIN, FluidProperties, air

log = logging.getLogger(__name__)

STEFAN_BOLTZMANN = 5.670374419e-8
GRAVITY = 9.80665
_warned: set[str] = set()


def validity_warning(name: str, message: str) -> None:
    """Log (once per correlation) that it is used outside its published range."""
    if name not in _warned:
        _warned.add(name)
        log.info("%s used outside its range: %s", name, message)


# ---------------------------------------------------------------------- rotating shaft, free convection
def rotating_cylinder_nusselt(reynolds: float, prandtl: float) -> float:
    """Kendoush (1996): Nu = 0.133 Re^(2/3) Pr^(1/3), Re = Omega D^2 / nu."""
    if reynolds > 4.3e5:
        validity_warning("rotating cylinder", f"Re = {reynolds:.3g} > 4.3e5")
    return 0.133 * max(reynolds, 0.0) ** (2.0 / 3.0) * prandtl ** (1.0 / 3.0)


def churchill_chu_cylinder_nusselt(rayleigh: float, prandtl: float) -> float:
    """Churchill and Chu (1975), horizontal cylinder, Ra <= 1e12."""
    if rayleigh > 1e12:
        validity_warning("Churchill-Chu", f"Ra = {rayleigh:.3g} > 1e12")
    ra = max(rayleigh, 0.0)
    return (0.60 + 0.387 * ra ** (1.0 / 6.0) / (1.0 + (0.559 / prandtl) ** (9.0 / 16.0)) ** (8.0 / 27.0)) ** 2


def rayleigh_cylinder(diameter_m: float, surface_C: float, ambient_C: float, props: FluidProperties) -> float:
    """Ra_D = g beta |T_s - T_inf| D^3 / (nu alpha), beta = 1 / T_film [K] (ideal gas)."""
    t_film = 0.5 * (surface_C + ambient_C) + KELVIN
    return (GRAVITY / t_film * abs(surface_C - ambient_C) * diameter_m ** 3
            / (props.kinematic_viscosity_m2_s * props.diffusivity_m2_s))


def free_cylinder_h(diameter_m: float, surface_C: float, ambient_C: float) -> float:
    """h [W/(m^2 K)] of a horizontal cylinder in still air (Churchill-Chu, film properties)."""
    p = air(0.5 * (surface_C + ambient_C))
    nu = churchill_chu_cylinder_nusselt(rayleigh_cylinder(diameter_m, surface_C, ambient_C, p), p.prandtl)
    return nu * p.conductivity_W_mK / diameter_m


def rotating_shaft_h(diameter_m: float, speed_rad_s: float, surface_C: float, ambient_C: float) -> float:
    """h [W/(m^2 K)] of a horizontal shaft rotating in still air: rotation (Kendoush) combined with
    free convection (Churchill-Chu) as (Nu_rot^3 + Nu_free^3)^(1/3)."""
    p = air(0.5 * (surface_C + ambient_C))
    re = abs(speed_rad_s) * diameter_m ** 2 / p.kinematic_viscosity_m2_s
    nu_r = rotating_cylinder_nusselt(re, p.prandtl)
    nu_f = churchill_chu_cylinder_nusselt(rayleigh_cylinder(diameter_m, surface_C, ambient_C, p), p.prandtl)
    return (nu_r ** 3 + nu_f ** 3) ** (1.0 / 3.0) * p.conductivity_W_mK / diameter_m


# ---------------------------------------------------------------------- rotor-stator gap
def gap_geometric_factor(mean_radius_m: float, gap_m: float) -> float:
    """Becker and Kaye's F_g (close to 1 for a thin gap)."""
    d = gap_m / mean_radius_m
    x = d / (1.0 - d)
    P = 0.0571 * (1.0 - 0.652 * x) + 0.00056 / (1.0 - 0.652 * x)
    return math.pi ** 4 / (1697.0 * P) * (2.0 * mean_radius_m - 2.304 * gap_m) / (2.0 * mean_radius_m - gap_m)


def modified_taylor_number(rotor_radius_m: float, gap_m: float, speed_rad_s: float, kinematic_viscosity_m2_s: float) -> float:
    """Ta_m = Omega^2 r_m delta^3 / (nu^2 F_g), r_m = r_rotor + delta/2."""
    rm = rotor_radius_m + 0.5 * gap_m
    ta = speed_rad_s ** 2 * rm * gap_m ** 3 / kinematic_viscosity_m2_s ** 2
    return ta / gap_geometric_factor(rm, gap_m)


def taylor_couette_nusselt(ta_m: float) -> float:
    """Becker and Kaye (1962): Nu on D_h = 2 delta vs the modified Taylor number."""
    if ta_m < 1700.0:
        return 2.0
    if ta_m < 1e4:
        return 0.128 * ta_m ** 0.367
    if ta_m > 1e7:
        validity_warning("Becker-Kaye gap", f"Ta_m = {ta_m:.3g} > 1e7")
    return 0.409 * ta_m ** 0.241


def gap_h(rotor_diameter_m: float, gap_m: float, speed_rad_s: float, fluid_C: float,
          axial_velocity_m_s: float = 0.0, gap_length_m: float | None = None) -> float:
    """h [W/(m^2 K)] across an air gap, from one surface to the other (q = h (T_rotor - T_stator);
    Nu = 2 is conduction across the gap, h = k / delta): Becker-Kaye, or
    with axial flow the larger of that and the channel flow on D_h = 2 delta."""
    if not (gap_m > 0.0 and rotor_diameter_m > 0.0):
        raise ValueError("gap and rotor diameter must be > 0")
    p = air(fluid_C)
    nu_rot = taylor_couette_nusselt(modified_taylor_number(0.5 * rotor_diameter_m, gap_m, speed_rad_s,
                                                           p.kinematic_viscosity_m2_s))
    nu = nu_rot
    if axial_velocity_m_s > 0.0:
        re = axial_velocity_m_s * 2.0 * gap_m / p.kinematic_viscosity_m2_s
        nu = max(nu_rot, channel_nusselt(re, p.prandtl, wall="flux"))
    return nu * p.conductivity_W_mK / (2.0 * gap_m)


# ---------------------------------------------------------------------- channels (cooling jacket)
NU_LAMINAR = {"temperature": 3.66, "flux": 4.36}


def gnielinski_nusselt(reynolds: float, prandtl: float) -> float:
    """Gnielinski (1976) with Petukhov's friction factor; 3000 <= Re <= 5e6, 0.5 <= Pr <= 2000."""
    if not (2300.0 <= reynolds <= 5e6 and 0.5 <= prandtl <= 2000.0):
        validity_warning("Gnielinski", f"Re = {reynolds:.3g}, Pr = {prandtl:.3g}")
    f = (0.790 * math.log(reynolds) - 1.64) ** -2
    f8 = f / 8.0
    return f8 * (reynolds - 1000.0) * prandtl / (1.0 + 12.7 * math.sqrt(f8) * (prandtl ** (2.0 / 3.0) - 1.0))


def dittus_boelter_nusselt(reynolds: float, prandtl: float, heating: bool = True) -> float:
    """Dittus-Boelter: 0.023 Re^0.8 Pr^n, n = 0.4 when the fluid is heated, 0.3 when cooled."""
    if reynolds < 1e4 or not 0.6 <= prandtl <= 160.0:
        validity_warning("Dittus-Boelter", f"Re = {reynolds:.3g}, Pr = {prandtl:.3g}")
    return 0.023 * reynolds ** 0.8 * prandtl ** (0.4 if heating else 0.3)


def channel_nusselt(reynolds: float, prandtl: float, wall: str = "flux", turbulent: str = "gnielinski") -> float:
    """Fully developed channel flow: laminar below Re 2300 (3.66 / 4.36), Gnielinski's linear blend
    to his turbulent value at Re 4000, turbulent above (``turbulent="dittus_boelter"`` for the
    Dittus-Boelter form above Re 4000, blended the same way)."""
    if wall not in NU_LAMINAR:
        raise ValueError("wall must be 'temperature' or 'flux'")
    if turbulent not in ("gnielinski", "dittus_boelter"):
        raise ValueError("turbulent must be 'gnielinski' or 'dittus_boelter'")
    turb = gnielinski_nusselt if turbulent == "gnielinski" else dittus_boelter_nusselt
    lam = NU_LAMINAR[wall]
    if reynolds <= 2300.0:
        return lam
    if reynolds < 4000.0:
        g = (reynolds - 2300.0) / 1700.0
        return (1.0 - g) * lam + g * turb(4000.0, prandtl)
    return turb(reynolds, prandtl)


def channel_h(hydraulic_diameter_m: float, velocity_m_s: float, props: FluidProperties, wall: str = "flux",
              turbulent: str = "gnielinski") -> float:
    """h [W/(m^2 K)] of fully developed flow in a channel of hydraulic diameter D_h."""
    re = velocity_m_s * hydraulic_diameter_m / props.kinematic_viscosity_m2_s
    return channel_nusselt(re, props.prandtl, wall, turbulent) * props.conductivity_W_mK / hydraulic_diameter_m


def capacity_rate_W_K(flow_m3_s: float, props: FluidProperties) -> float:
    """Heat-capacity flow m_dot c_p = rho V_dot c_p [W/K]."""
    return props.density_kg_m3 * flow_m3_s * props.specific_heat_J_kgK


# ---------------------------------------------------------------------- spheres, radiation
def whitaker_sphere_nusselt(reynolds: float, prandtl: float) -> float:
    """Whitaker (1972), mu/mu_s = 1: 2 + (0.4 Re^0.5 + 0.06 Re^(2/3)) Pr^0.4."""
    if reynolds > 7.6e4:
        validity_warning("Whitaker sphere", f"Re = {reynolds:.3g} > 7.6e4")
    re = max(reynolds, 0.0)
    return 2.0 + (0.4 * math.sqrt(re) + 0.06 * re ** (2.0 / 3.0)) * prandtl ** 0.4


def radiation_h(surface_C: float, surroundings_C: float, emissivity: float) -> float:
    """Linearised radiation coefficient eps sigma (T_s + T_sur)(T_s^2 + T_sur^2) [W/(m^2 K)]."""
    if not 0.0 <= emissivity <= 1.0:
        raise ValueError("emissivity must be in [0, 1]")
    ts, tsur = surface_C + KELVIN, surroundings_C + KELVIN
    return emissivity * STEFAN_BOLTZMANN * (ts + tsur) * (ts * ts + tsur * tsur)
