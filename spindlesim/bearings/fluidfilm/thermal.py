"""Thermal equilibrium of a fluid-film bearing (seed 003 eqs. 4-14).

Heat balance (eq. 5, with H3 = H4 = H5 = H6 = 0 as in the paper)::

    H = H1 + H2,   H = T_f omega (eq. 6),   H1 = c rho q (theta_o - theta_i) (eq. 7),
    H2 = a A (theta - theta_E) (eq. 9),     theta = lambda theta_i + (1 - lambda) theta_o (eq. 11)

which gives the mean film temperature explicitly for a given viscosity (eq. 12)::

    theta = [(1 - lambda)(H + a A theta_E) + c rho q theta_i] / [c rho q + a A (1 - lambda)]

The viscosity at ``theta`` (Walther, eq. 13-14) changes H and q, so the equilibrium is the
root of ``g(theta) = theta_12(mu(theta)) - theta``.  From a neighbouring equilibrium (the previous speed
of a sweep) the temperature and the journal position are stepped together, one film solution a step
(:func:`_joint_root`); otherwise, and where those steps do not settle, the nested search: secant steps on
g (from the neighbour, or from the inlet temperature), each trial temperature with the journal's own
equilibrium, bracketed and solved with :func:`scipy.optimize.brentq` where they do not settle
(scipy.optimize is imported then only: a fifth of a command's start-up).

Choices (documented in docs/theory.md):

- ``lambda`` = 1/3 by default: seed 003 Table 1 satisfies eq. 11 with lambda = 1/3
  exactly for both bearings (38.542 = 25/3 + 2 x 45.313/3; 38.337 = 25/3 + 2 x 45.006/3).
- ``q`` is the side leakage of the lands (the oil that leaves the bearing and is replaced
  by fresh oil at theta_i; the rest of the inlet flow recirculates through the grooves).
  ``oil_flow="inlet"`` uses the inlet flow of the lands instead (all oil renewed).
- Housing heat-transfer coefficient from the air velocity w (m/s)::

      a = max(15, 7 + 12 sqrt(w))   W/(m^2 K)

  15-20 W/(m^2 K) for still air and ``7 + 12 sqrt(w)`` for moving air are the values
  DIN 31652-2 / ISO 7902-1 give for the convection from a bearing housing (quoted from
  memory of the standards; they could not be checked against the standard text here).
- Housing area: by default the lateral surface of a cylindrical housing of outer
  diameter 2.5 D and length 2 L, ``A = 5 pi D L``; give ``housing_area_m2`` when known.
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass

import numpy as np

from spindlesim.bearings.fluidfilm.equilibrium import EquilibriumError
from spindlesim.bearings.fluidfilm.geometry import BearingGeometry
from spindlesim.bearings.fluidfilm.performance import film_force_scale, flow, friction_torque, operating_point
from spindlesim.bearings.fluidfilm.reynolds import ReynoldsError, ReynoldsSolver
from spindlesim.bearings.fluidfilm.results import FilmResult, ThermalResult
from spindlesim.bearings.fluidfilm.viscosity import ConstantViscosity

log = logging.getLogger(__name__)

#: highest mean film temperature tried when bracketing the equilibrium [degC]
MAX_TEMPERATURE_C = 250.0
#: lowest mean film temperature a search step may try [degC]
MIN_TEMPERATURE_C = -50.0
#: film solutions the secant steps may take before a bracket and Brent's method decide (from a neighbour three are
#: usual; from a far one, e.g. the first speed of a sweep's second half, or the inlet temperature, five to seven)
SECANT_EVALUATIONS = 8
#: film solutions the joint steps on temperature and journal position may take before the nested search decides
JOINT_EVALUATIONS = 8


class ThermalEquilibriumError(RuntimeError):
    """No thermal equilibrium exists in the temperature range tried."""


def heat_transfer_coefficient(air_velocity_m_s: float) -> float:
    """Housing-to-air heat-transfer coefficient a [W/(m^2 K)] (DIN 31652-2 / ISO 7902-1)."""
    if air_velocity_m_s < 0:
        raise ValueError("air velocity must be >= 0")
    return max(15.0, 7.0 + 12.0 * math.sqrt(air_velocity_m_s))


def default_housing_area(geometry: BearingGeometry) -> float:
    """A = 5 pi D L: lateral surface of a housing of diameter 2.5 D and length 2 L."""
    return 5.0 * math.pi * geometry.diameter_m * geometry.width_m


@dataclass(frozen=True)
class ThermalParameters:
    """Oil and environment data of seed 003 Table 1 (SI, temperatures in degC)."""

    inlet_C: float
    ambient_C: float
    density_kg_m3: float
    specific_heat_J_kgK: float
    air_velocity_m_s: float = 0.0
    mixing_lambda: float = 1.0 / 3.0
    housing_area_m2: float | None = None
    heat_transfer_W_m2K: float | None = None
    oil_flow: str = "side"

    def __post_init__(self) -> None:
        if not 0.0 <= self.mixing_lambda < 1.0:
            raise ValueError("lambda must be in [0, 1)")
        if self.density_kg_m3 <= 0 or self.specific_heat_J_kgK <= 0:
            raise ValueError("oil density and specific heat must be positive")
        if self.oil_flow not in ("side", "inlet"):
            raise ValueError("oil_flow must be 'side' or 'inlet'")

    def conductance(self, geometry: BearingGeometry) -> float:
        """a A [W/K] of the housing."""
        a = (self.heat_transfer_W_m2K if self.heat_transfer_W_m2K is not None
             else heat_transfer_coefficient(self.air_velocity_m_s))
        A = (self.housing_area_m2 if self.housing_area_m2 is not None
             else default_housing_area(geometry))
        return a * A


def _mean_temperature(p: ThermalParameters, aA: float, H: float, q: float) -> tuple[float, float]:
    """(mean temperature of eq. 12, c rho q) for the friction heat ``H`` [W] and the oil flow ``q`` [m^3/s]."""
    lam = p.mixing_lambda
    crq = p.specific_heat_J_kgK * p.density_kg_m3 * q
    return ((1 - lam) * (H + aA * p.ambient_C) + crq * p.inlet_C) / (crq + aA * (1 - lam)), crq


def _balance(p: ThermalParameters, aA: float, film: FilmResult):
    """Mean temperature of eq. 12 and the heat flows for one film state."""
    H = film.power_loss_W
    q = film.side_flow_m3_s if p.oil_flow == "side" else film.inlet_flow_m3_s
    theta, crq = _mean_temperature(p, aA, H, q)
    theta_out = (theta - p.mixing_lambda * p.inlet_C) / (1 - p.mixing_lambda)
    return theta, theta_out, H, crq * (theta_out - p.inlet_C), aA * (theta - p.ambient_C), q


def solve_thermal(solver: ReynoldsSolver, viscosity, speed_rad_s: float, load_N: np.ndarray,
                  params: ThermalParameters, xtol: float = 1e-6,
                  near: ThermalResult | None = None, guess_C: float | None = None) -> ThermalResult:
    """Thermal equilibrium and the operating point at it.

    ``viscosity`` is a callable temperature [degC] -> Pa s (:mod:`viscosity`); a
    :class:`ConstantViscosity` gives an isoviscous film whose temperatures follow from
    eq. 12 without feedback.  ``near`` is the equilibrium of a neighbouring state (the previous
    speed of a Campbell diagram): the search starts at its temperature (or at ``guess_C``, e.g.
    extrapolated from two neighbours), its journal position and its film, with joint steps on the
    temperature and the journal position (:func:`_joint_root`, two to four film solutions); where they
    do not settle, with secant steps from its balance slope, each trial temperature with the journal's
    equilibrium; a secant search that does not settle hands over to a bracket and Brent's method.  A search without a neighbour takes secant steps
    from the inlet temperature (at most ``SECANT_EVALUATIONS`` film solutions), then the same.  The
    root is found to ``xtol`` degC either way (1e-6 degC: the result does not depend on where the
    search started).
    """
    geo = solver.geometry
    aA = params.conductance(geo)
    load = np.asarray(load_N, dtype=float)
    rho = params.density_kg_m3
    state = {"pos": None, "set": None, "n": 0, "sol": None}
    done: dict[float, FilmResult] = {}  # brentq asks again for the ends of its bracket
    if near is not None:
        state["pos"], state["set"], state["sol"] = near.film.position_m, near.film.full_film, near.film.solution

    def film_at(theta: float) -> FilmResult:
        if theta in done:
            return done[theta]
        mu = viscosity(theta)
        init = None if state["pos"] is None else state["pos"] / geo.clearance_m
        f = operating_point(solver, mu, speed_rad_s, load, rho, initial=init,
                            full_film_guess=state["set"], initial_solution=state["sol"])
        state["pos"], state["set"], state["sol"] = f.position_m, f.full_film, f.solution
        state["n"] += 1
        done[theta] = f
        return f

    if isinstance(viscosity, ConstantViscosity):
        film = film_at(params.inlet_C)
        th, tho, H, H1, H2, q = _balance(params, aA, film)
        return ThermalResult(th, tho, params.inlet_C, params.ambient_C, H, H1, H2, q, aA,
                             True, 1, film)

    def g(theta: float) -> float:
        return _balance(params, aA, film_at(theta))[0] - theta

    if near is not None:
        theta0 = near.temperature_mean_C if guess_C is None else guess_C
        joint, spent = _joint_root(solver, viscosity, speed_rad_s, load, params, aA, near, theta0, xtol)
        if joint is not None:
            theta, x, sol, slope = joint
            state["pos"], state["set"], state["sol"] = x * geo.clearance_m, sol.full_film, sol
            try:  # the Newton iteration starts converged: no film solution
                return _result(params, aA, film_at(theta), spent, slope)
            except (EquilibriumError, ReynoldsError):  # e.g. the film thinner than the equilibrium accepts:
                # the nested search meets it too and says so as it always has
                state["pos"], state["set"], state["sol"] = (near.film.position_m, near.film.full_film,
                                                            near.film.solution)
        state["n"] = spent
        found = _secant_root(g, theta0, near.balance_slope, xtol)
        if found is not None:
            return _result(params, aA, film_at(found[0]), state["n"], found[1])
        bracket = _near_bracket(g, theta0)
        if bracket is not None:
            theta = bracket[0] if bracket[0] == bracket[1] else _brent(g, *bracket, xtol)
            return _result(params, aA, film_at(theta), state["n"])
    lo = min(params.inlet_C, params.ambient_C)
    try:
        glo = g(lo)
    except (EquilibriumError, ReynoldsError) as exc:
        raise ThermalEquilibriumError(
            f"the film cannot carry {np.hypot(*load):.4g} N even at {lo:.1f} degC "
            f"(viscosity {viscosity(lo):.4g} Pa s): {exc}") from exc
    if glo <= 0:  # cannot happen with positive friction heat; guard anyway
        raise ThermalEquilibriumError(f"no heating at {lo:.1f} degC (g = {glo:.3g})")
    # secant steps from the eq. 12 temperature at the inlet's viscosity (the root lies below it): five or six film
    # solutions where the bracket and Brent's method below take seven or more
    found = _secant_root(g, lo, -1.0, xtol)
    if found is not None:
        return _result(params, aA, film_at(found[0]), state["n"], found[1])
    hi, step, ghi = lo, 10.0, glo
    tried = [lo]
    first = True
    while ghi > 0:
        if first:
            # first trial just above the eq. 12 temperature at the current viscosity: the
            # root lies below it (the film thins as it heats), so this usually brackets
            hi = min(lo + glo + 0.5, MAX_TEMPERATURE_C)
            first = False
        else:
            hi = min(hi + step, MAX_TEMPERATURE_C)
        tried.append(hi)
        try:
            ghi = g(hi)
        except (EquilibriumError, ReynoldsError) as exc:
            raise ThermalEquilibriumError(
                f"no thermal equilibrium: the friction heat keeps the film above "
                f"{tried[-2]:.1f} degC, and at {hi:.1f} degC (viscosity "
                f"{viscosity(hi):.4g} Pa s) the film cannot carry the load ({exc}); "
                f"temperatures tried: {', '.join(f'{t:.1f}' for t in tried)} degC") from exc
        if ghi > 0 and hi >= MAX_TEMPERATURE_C:
            raise ThermalEquilibriumError(
                f"no thermal equilibrium below {MAX_TEMPERATURE_C:.0f} degC: heat generated "
                f"still exceeds the heat removed at every temperature tried "
                f"({', '.join(f'{t:.1f}' for t in tried)} degC)")
        if ghi > 0:
            lo, glo = hi, ghi
            step *= 2.0
    theta = _brent(g, lo, hi, xtol)
    return _result(params, aA, film_at(theta), state["n"])


def _joint_root(solver: ReynoldsSolver, viscosity, speed_rad_s: float, load: np.ndarray, p: ThermalParameters,
                aA: float, near: ThermalResult, theta0: float, xtol: float, tol: float = 1e-9,
                evaluations: int = JOINT_EVALUATIONS):
    """((temperature, journal position (X, Y), its film, dg/dtheta), film solutions) of the equilibrium by one
    film solution per step on the temperature and the journal position together; (None, film solutions)
    where it does not settle (then the nested search decides, from the neighbour as before).

    The nested search solves the journal's equilibrium (a Newton iteration, two or three film solutions) at
    every trial temperature.  Here each step takes the trial temperature's secant step (from the neighbour's
    slope dg/dtheta, then the secant of the steps' balance temperatures) and the journal's Newton step towards
    the load at the new temperature's viscosity from the same film, whose force Jacobian does not depend on
    the viscosity (the film force is mu omega R^4 / Cb^2 times the dimensionless one).  It stops where both
    the nested search and the journal's Newton iteration would: the force within ``tol`` of the load and the
    secant's distance to the root within ``xtol``; the film is then the operating point's at that viscosity.
    The neighbour's film starts it (no solution for the first step)."""
    geo = solver.geometry
    s = near.balance_slope
    sol = near.film.solution
    if geo.axisymmetric or sol is None or not (math.isfinite(s) and s < 0.0):
        return None, 0
    x = np.array([sol.X, sol.Y])
    theta, prev, n = theta0, None, 0
    try:
        while True:
            mu = viscosity(theta)
            target = -load / film_force_scale(geo, mu, speed_rad_s)
            res = sol.force - target
            H = friction_torque(geo, mu, speed_rad_s, sol) * speed_rad_s
            q = flow(geo, speed_rad_s, sol.side_flow if p.oil_flow == "side" else sol.inlet_flow)
            g = _mean_temperature(p, aA, H, q)[0] - theta
            if prev is not None and theta != prev[0]:
                s = (g - prev[1]) / (theta - prev[0])
                if not s < 0.0:  # not the smooth fall the steps rely on
                    return None, n
            if float(np.hypot(*res)) <= tol * float(np.hypot(*target)) and abs(g / s) <= xtol:
                return (theta, x, sol, s), n
            if n >= evaluations:
                return None, n
            prev, theta = (theta, g), theta - g / s
            if not MIN_TEMPERATURE_C <= theta <= MAX_TEMPERATURE_C:
                return None, n
            target = -load / film_force_scale(geo, viscosity(theta), speed_rad_s)
            step = -np.linalg.solve(sol.jac_position, sol.force - target)
            if float(np.hypot(*step)) > 0.25:  # far from the neighbour: the nested search's line search decides
                return None, n
            x = x + step
            sol = solver.solve(x[0], x[1], sol.full_film)
            n += 1
    except (ReynoldsError, np.linalg.LinAlgError):
        return None, n


def _brent(g, lo: float, hi: float, xtol: float) -> float:
    """The root of g in the bracket [lo, hi] by Brent's method (scipy's), to ``xtol``."""
    from scipy.optimize import brentq

    return brentq(g, lo, hi, xtol=xtol, rtol=1e-12)


def _result(params: ThermalParameters, aA: float, film: FilmResult, n: int,
            slope: float = float("nan")) -> ThermalResult:
    th, tho, H, H1, H2, q = _balance(params, aA, film)
    log.debug("thermal equilibrium %.6f degC after %d film solutions", th, n)
    return ThermalResult(th, tho, params.inlet_C, params.ambient_C, H, H1, H2, q, aA, False, n, film, slope)


def _secant_root(g, theta0: float, slope: float, xtol: float, evaluations: int = SECANT_EVALUATIONS):
    """(root, slope) of g from ``theta0`` by secant steps, the first one along ``slope`` (a neighbouring
    equilibrium's dg/dtheta, else -1: the balance temperature moves less than the trial one); None when
    the steps do not settle within ``evaluations`` film solutions, leave the temperature range, or g
    stops falling (then a bracket and Brent's method decide).

    The root is accepted when the secant's estimate of its distance, |g| / |slope|, is below ``xtol``:
    from a neighbouring speed that takes three film solutions where scipy's secant method (which
    stops on the step, so its last iterate still needs its film solution) or Brent's method (which
    must shrink a bracket to ``xtol``) take four or five."""
    s = slope if math.isfinite(slope) and slope < 0.0 else -1.0
    try:
        t0, g0 = theta0, g(theta0)
        for _ in range(evaluations - 1):
            if abs(g0 / s) <= xtol:
                return t0, s
            t1 = t0 - g0 / s
            if not MIN_TEMPERATURE_C <= t1 <= MAX_TEMPERATURE_C:
                return None
            g1 = g(t1)
            if t1 == t0 or g1 == g0:
                return None
            s = (g1 - g0) / (t1 - t0)
            if not s < 0.0:  # g rises or is not finite: not the smooth fall a secant step relies on
                return None
            t0, g0 = t1, g1
        return (t0, s) if abs(g0 / s) <= xtol else None
    except (EquilibriumError, ReynoldsError):
        return None


def _near_bracket(g, theta0: float, tries: int = 4):
    """A sign change of g near ``theta0`` (a neighbour's equilibrium), or None (then the cold search
    from the inlet temperature runs).  g falls with slope about -1 (the balance temperature moves
    less than the trial one), so theta0 + g(theta0) is the first guess of the root."""
    try:
        g0 = g(theta0)
        if g0 == 0.0:
            return theta0, theta0
        step = g0 + math.copysign(0.01 + 0.1 * abs(g0), g0)
        a, ga = theta0, g0
        for _ in range(tries):
            b = min(max(a + step, MIN_TEMPERATURE_C), MAX_TEMPERATURE_C)
            gb = g(b)
            if ga * gb <= 0:
                return (a, b) if a < b else (b, a)
            a, ga, step = b, gb, 2.0 * step
    except (EquilibriumError, ReynoldsError):
        return None
    return None
