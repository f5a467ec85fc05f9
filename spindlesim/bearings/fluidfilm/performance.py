"""Operating point of a bearing at a given viscosity: equilibrium plus all outputs.

Dimensional results from the dimensionless film solution (see :mod:`reynolds`;
``R`` journal radius, ``Cb`` assembled clearance, ``omega`` shaft speed)::

    F      = mu omega R^4 / Cb^2 * f                          film force on the journal
    T_f    = mu omega R^4 / Cb * I_f                          friction torque on the journal
    Q      = omega R^2 Cb * I_q                               flows (inlet, side)
    h_min  = Cb * H_min
    S      = mu N D L / (psi^2 W),  psi = 2 Cp / D            seed 003 eq. 3
    Re     = rho omega R Cb / mu

with ``I_f = int int (1/H + H/2 dP/dtheta) dtheta dzeta`` over the lands (shear of a full
film over the whole land, as Raimondi & Boyd 1958 assume for the cavitated zone; grooves
carry no shear) and ``I_q = int (H/2 - H^3/12 dP/dtheta) dzeta``.
"""

from __future__ import annotations

import math

import numpy as np

from spindlesim.bearings.fluidfilm import coefficients as coef
from spindlesim.bearings.fluidfilm.equilibrium import Equilibrium, solve_axisymmetric, solve_newton
from spindlesim.bearings.fluidfilm.geometry import BearingGeometry
from spindlesim.bearings.fluidfilm.reynolds import ReynoldsSolver
from spindlesim.bearings.fluidfilm.results import FilmResult


def film_force_scale(geometry: BearingGeometry, viscosity_Pa_s: float, speed_rad_s: float) -> float:
    """mu omega R^4 / Cb^2 [N]: film force per unit dimensionless force."""
    R = geometry.radius_m
    return viscosity_Pa_s * speed_rad_s * R**4 / geometry.clearance_m**2


def friction_torque(geometry: BearingGeometry, viscosity_Pa_s: float, speed_rad_s: float, film) -> float:
    """mu omega R^4 / Cb * I_f [N m] of a dimensionless film solution."""
    return viscosity_Pa_s * speed_rad_s * geometry.radius_m**4 / geometry.clearance_m * film.friction


def flow(geometry: BearingGeometry, speed_rad_s: float, dimensionless: float) -> float:
    """omega R^2 Cb * I_q [m^3/s] of a dimensionless flow."""
    return speed_rad_s * geometry.radius_m**2 * geometry.clearance_m * dimensionless


def equilibrium(solver: ReynoldsSolver, viscosity_Pa_s: float, speed_rad_s: float,
                load_N: np.ndarray, initial=None, full_film_guess=None, initial_solution=None) -> Equilibrium:
    """Journal equilibrium under the load ``load_N`` (force of the shaft on the bearing).

    ``initial`` (X, Y) and ``full_film_guess`` warm-start the iteration from a nearby state.
    """
    geo = solver.geometry
    if speed_rad_s <= 0:
        raise ValueError("a hydrodynamic bearing needs a positive speed")
    target = -np.asarray(load_N, dtype=float) / film_force_scale(geo, viscosity_Pa_s, speed_rad_s)
    if geo.axisymmetric:
        eps0 = None if initial is None else float(np.hypot(*initial))
        return solve_axisymmetric(solver, target, initial_eps=eps0,
                                  full_film_guess=full_film_guess)
    return solve_newton(solver, target, initial=(0.0, 0.0) if initial is None else initial,
                        full_film_guess=full_film_guess, initial_solution=initial_solution)


def operating_point(solver: ReynoldsSolver, viscosity_Pa_s: float, speed_rad_s: float,
                    load_N: np.ndarray, density_kg_m3: float = float("nan"),
                    initial=None, full_film_guess=None, initial_solution=None) -> FilmResult:
    """Equilibrium, coefficients, friction, flows and film of one isoviscous state."""
    geo = solver.geometry
    load = np.asarray(load_N, dtype=float)
    W = float(np.hypot(*load))
    eq = equilibrium(solver, viscosity_Pa_s, speed_rad_s, load, initial, full_film_guess, initial_solution)
    film = eq.film
    R, Cb, Cp = geo.radius_m, geo.clearance_m, geo.machined_clearance_m
    mu, om = viscosity_Pa_s, speed_rad_s
    N = om / (2 * math.pi)
    K, B = coef.dimensional(film.jac_position, film.jac_velocity, mu, om, R, Cb)
    torque = friction_torque(geo, mu, om, film)
    ecc = float(np.hypot(eq.X, eq.Y))
    att = math.degrees(math.atan2(eq.Y, eq.X) - math.atan2(load[1], load[0]))
    att = (att + 180.0) % 360.0 - 180.0
    s_b = mu * N * geo.width_m * geo.diameter_m * (R / Cb) ** 2 / W
    g = solver.grid
    theta = g.node_theta + eq.rotation_rad
    return FilmResult(
        viscosity_Pa_s=mu,
        speed_rad_s=om,
        load_N=load,
        position_m=np.array([eq.X, eq.Y]) * Cb,
        eccentricity_ratio=ecc,
        attitude_angle_deg=att,
        sommerfeld=s_b * (Cb / Cp) ** 2,
        sommerfeld_b=s_b,
        min_film_m=film.min_film * Cb,
        friction_torque_Nm=torque,
        power_loss_W=torque * om,
        friction_coefficient=torque / (R * W),
        inlet_flow_m3_s=flow(geo, om, film.inlet_flow),
        side_flow_m3_s=flow(geo, om, film.side_flow),
        reynolds_number=density_kg_m3 * om * R * Cb / mu,
        K_N_m=K,
        C_Ns_m=B,
        k=K * Cp / W,
        c=B * Cp * om / W,
        k_load=coef.to_load_frame(K, load) * Cb / W,
        c_load=coef.to_load_frame(B, load) * Cb * om / W,
        pressure_Pa=film.pressure * mu * om * R**2 / Cb**2,
        node_theta_rad=np.mod(theta, 2 * math.pi),
        node_z_m=g.node_j * (geo.width_m / 2 / g.n_axial),
        full_film=eq.grid_full_film,
        solution=eq.film if not geo.axisymmetric else None,  # axisymmetric: the film is a rotated one
    )


def characteristic_curves(geometry: BearingGeometry, sommerfeld: np.ndarray,
                          n_circ: int | None = None, n_axial: int | None = None,
                          load_angle_deg: float = -90.0) -> dict:
    """Dimensionless characteristics vs the Sommerfeld number S (on Cp), seed 003 Figs. 1-4.

    Isoviscous sweep of the load (direction ``load_angle_deg``).  Returns arrays:
    ``S``, ``eccentricity_ratio`` (e/Cb), ``attitude_angle_deg``, ``friction_ratio``
    (f / psi with psi = 2 Cp / D, seed Fig. 2), ``inlet_flow``, ``side_flow``
    (Q / (R Cp N L), Raimondi-Boyd form on Cp), ``k``, ``c`` ([n, 2, 2], on Cp, x-y frame)
    and ``k_load``, ``c_load`` (on Cb, load frame).
    """
    from spindlesim.bearings.fluidfilm.reynolds import DEFAULT_AXIAL, DEFAULT_CIRCUMFERENTIAL

    solver = ReynoldsSolver(geometry, n_circ or DEFAULT_CIRCUMFERENTIAL, n_axial or DEFAULT_AXIAL)
    S = np.sort(np.asarray(sommerfeld, dtype=float))[::-1]  # light to heavy load: warm starts
    mu, om = 1.0, 2 * math.pi
    N = 1.0
    psi = geometry.clearance_ratio
    D, L, R, Cp = geometry.diameter_m, geometry.width_m, geometry.radius_m, geometry.machined_clearance_m
    a = math.radians(load_angle_deg)
    out = {k: [] for k in ("S", "eccentricity_ratio", "attitude_angle_deg", "friction_ratio",
                           "inlet_flow", "side_flow", "k", "c", "k_load", "c_load")}
    init, guess = None, None
    for s in S:
        W = mu * N * D * L / (psi**2 * s)
        r = operating_point(solver, mu, om, W * np.array([math.cos(a), math.sin(a)]),
                            initial=init, full_film_guess=guess)
        init, guess = r.position_m / geometry.clearance_m, r.full_film
        out["S"].append(r.sommerfeld)
        out["eccentricity_ratio"].append(r.eccentricity_ratio)
        out["attitude_angle_deg"].append(r.attitude_angle_deg)
        out["friction_ratio"].append(r.friction_coefficient / psi)
        out["inlet_flow"].append(r.inlet_flow_m3_s / (R * Cp * N * L))
        out["side_flow"].append(r.side_flow_m3_s / (R * Cp * N * L))
        for key in ("k", "c", "k_load", "c_load"):
            out[key].append(getattr(r, key))
    return {k: np.asarray(v) for k, v in out.items()}
