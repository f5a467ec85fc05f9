"""Heat of a ball bearing from its quasi-static state: a local model of every ball-raceway contact.

Input: a :class:`~spindlesim.bearings.ball.results.BallState` (per ball and contact the load Q, the
contact angle, the Hertz semi-axes a (across rolling) and b (along rolling)), its geometry, the
lubricant and its temperature.  Outer ring fixed, inner ring at w.  Per contact (Harris and Kotzalas
2007, *Advanced Concepts*, the friction chapters; docs/theory.md):

- Kinematics.  Ball absolute angular velocity (w_z, w_r) in the meridional plane and cage speed w_c
  from no slip at both contact centres and the race-control hypothesis of the state's model
  (outer race control: no spin at the outer contact, w_b . n_o = 0, Jones 1960; ``full``: the ball's
  angular velocity relative to the cage normal to the bisector of the two contact normals).  Spin of a
  contact = (w_ball - w_race) . n; rolling (entrainment) speed u = the race's surface speed at the
  contact relative to the cage.  The cage speed agrees with the state's centrifugal force (test).
- Spin friction: Coulomb shear mu p over the Hertz ellipse spinning about its centre,
  M_s = (3/8) mu Q a E(k), k^2 = 1 - (b/a)^2 (Harris and Kotzalas); heat M_s |w_s|.  mu is the sliding
  friction coefficient of the SKF model (SKF general catalogue, "The SKF model for calculating the
  frictional moment"): mu = f_bl mu_bl + (1 - f_bl) mu_EHL, f_bl = exp(-2.6e-8 (n nu)^1.4 d_m)
  (n rpm, nu mm^2/s, d_m mm), mu_bl = 0.15, mu_EHL = 0.05 (mineral oil) or 0.04 (synthetic).
- Rolling, EHL: the hydrodynamic rolling force of an elliptical EHL contact
  F_R = 2.86 E' R_x^2 k^0.348 G^0.022 U^0.66 W^0.47 (k = a/b, U = eta0 u / (E' R_x), W = Q / (E' R_x^2),
  G = alpha_pv E', E' = 2 E*; Harris and Kotzalas after Houpert), times SKF's inlet shear heating
  reduction phi_ish = 1 / (1 + 1.84e-9 (n d_m)^1.28 nu^0.64); heat F_R u.  Starvation (SKF's phi_rs) is
  not included.
- Rolling, elastic hysteresis (Tabor; Johnson 1985, section 9.2): a fraction alpha_h of the elastic work
  of the leading half of the Hertz pressure is lost, F_h = alpha_h (3/16) Q b / R_x; heat F_h u
  (alpha_h = 0.007 for bearing steel).
- Drag of each ball in the oil-air mixture of the cavity: F_D = (pi/8) C_D rho_eff D^2 v^2 at the orbital
  speed v = w_c d_m / 2, C_D of a sphere (Clift and Gauvin 1970: 24/Re (1 + 0.15 Re^0.687) +
  0.42 / (1 + 42500 Re^-1.16)), rho_eff = X rho_oil + (1 - X) rho_air with X the oil volume fraction of the
  free space (an input: it depends on the lubrication method and flow); heat F_D v into the lubricant.

The heat of a contact goes half to the ball and half to the ring (equal partition); the drag heat goes
to the lubricant.  Not modelled: cage (pocket and land) friction, seals, gyroscopic pivoting.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.special import ellipe

from ...thermal.friction import RPM, Lubricant
from ..rolling import RING_PROPORTION, pitch_ratio

AIR_DENSITY_KG_M3 = 1.2
AIR_VISCOSITY_PA_S = 1.8e-5
#: SKF model: boundary sliding friction coefficient and the full-film ones
MU_BOUNDARY = 0.15
MU_EHL_MINERAL = 0.05
MU_EHL_SYNTHETIC = 0.04
#: elastic hysteresis loss factor of bearing steel
HYSTERESIS_STEEL = 0.007


@dataclass(frozen=True)
class ContactFrictionOptions:
    """Choices of the local model (defaults: docs/theory.md)."""

    oil_volume_fraction: float = 0.0          # X of the free space (oil-air / mist: ~0; jet or bath: more)
    traction_coefficient: float | None = None  # None: SKF's mu_sl from the lubrication condition
    hysteresis_loss_factor: float = HYSTERESIS_STEEL
    inlet_shear_heating: bool = True           # SKF's phi_ish on the EHL rolling force
    contact_heat_to_ring: float = 0.5          # fraction of a contact's heat that goes into the ring
    starvation_K_rs: float = 0.0               # SKF's replenishment constant K_rs (0: fully flooded contacts)
    geometry_K_Z: float = 4.4                  # SKF's bearing-type constant K_Z (4.4: angular contact ball)

    def __post_init__(self) -> None:
        if not 0.0 <= self.oil_volume_fraction <= 1.0:
            raise ValueError("oil_volume_fraction must lie in [0, 1]")
        if self.traction_coefficient is not None and not 0.0 <= self.traction_coefficient < 1.0:
            raise ValueError("traction_coefficient must lie in [0, 1)")
        if not 0.0 <= self.hysteresis_loss_factor < 1.0 or not 0.0 <= self.contact_heat_to_ring <= 1.0:
            raise ValueError("hysteresis loss factor and heat partition must lie in [0, 1]")


@dataclass(frozen=True)
class BallKinematics:
    """Per ball [rows, Z]: cage speed, spins and rolling speeds of the two contacts (rad/s, m/s)."""

    cage_rad_s: np.ndarray
    spin_inner_rad_s: np.ndarray
    spin_outer_rad_s: np.ndarray
    rolling_inner_m_s: np.ndarray
    rolling_outer_m_s: np.ndarray


@dataclass(frozen=True)
class BearingHeat:
    """Heat of one bearing (set) [W], by source and by the part it goes into."""

    spin_W: float
    rolling_ehl_W: float
    hysteresis_W: float
    drag_W: float
    inner_ring_W: float
    outer_ring_W: float
    balls_W: float
    lubricant_W: float
    traction_coefficient: float
    per_contact_inner_W: np.ndarray   # (rows, Z)
    per_contact_outer_W: np.ndarray
    kinematics: BallKinematics

    @property
    def total_W(self) -> float:
        return self.inner_ring_W + self.outer_ring_W + self.balls_W + self.lubricant_W

    def parts_W(self, drag_to_balls: bool = True) -> dict[str, float]:
        """{inner_ring, outer_ring, balls} for a network without a lubricant node (drag heat to the balls)."""
        extra = self.lubricant_W if drag_to_balls else 0.0
        return {"inner_ring": self.inner_ring_W, "outer_ring": self.outer_ring_W, "balls": self.balls_W + extra}


def ball_kinematics(state, geometry, model: str = "outer_race_control") -> BallKinematics:
    """Cage speed, contact spins and rolling speeds of every ball of ``state`` (see the module docstring)."""
    w = float(state.speed_rad_s)
    D, dm = geometry.ball_diameter_m, geometry.pitch_diameter_m
    Rc, h = 0.5 * dm, 0.5 * D
    ai, ao = np.radians(state.contact_angle_inner_deg), np.radians(state.contact_angle_outer_deg)
    si, ci, so, co = np.sin(ai), np.cos(ai), np.sin(ao), np.cos(ao)
    n = ai.shape
    A = np.zeros(n + (3, 3))
    rhs = np.zeros(n + (3,))
    # unknowns (w_c, w_z, w_r): no slip at the outer and inner contact centres, race control
    A[..., 0, :] = np.stack([np.full(n, Rc), h * co, -h * so], axis=-1)
    A[..., 1, :] = np.stack([np.full(n, Rc), -h * ci, h * si], axis=-1)
    rhs[..., 1] = w * (Rc - h * ci)
    if model == "outer_race_control":
        A[..., 2, :] = np.stack([np.zeros(n), so, co], axis=-1)
    elif model == "inner_race_control":  # no spin at the inner contact: (w_z - w) sin a_i + w_r cos a_i = 0
        A[..., 2, :] = np.stack([np.zeros(n), si, ci], axis=-1)
        rhs[..., 2] = w * si
    elif model == "full":
        beta = 0.5 * (ai + ao)
        A[..., 2, :] = np.stack([-np.sin(beta), np.sin(beta), np.cos(beta)], axis=-1)
    else:
        raise ValueError(f"model must be outer_race_control, inner_race_control or full, not {model!r}")
    x = np.linalg.solve(A, rhs[..., None])[..., 0]
    wc, wz, wr = x[..., 0], x[..., 1], x[..., 2]
    spin_o = wz * so + wr * co
    spin_i = (wz - w) * si + wr * ci
    return BallKinematics(cage_rad_s=wc, spin_inner_rad_s=spin_i, spin_outer_rad_s=spin_o,
                          rolling_inner_m_s=np.abs(w - wc) * (Rc - h * ci), rolling_outer_m_s=np.abs(wc) * (Rc + h * co))


def skf_sliding_coefficient(speed_rad_s: float, viscosity_m2_s: float, pitch_diameter_m: float,
                            synthetic: bool = False) -> float:
    """SKF's mu_sl = f_bl mu_bl + (1 - f_bl) mu_EHL, f_bl = exp(-2.6e-8 (n nu)^1.4 d_m)."""
    n, nu, dm = abs(speed_rad_s) / RPM, viscosity_m2_s * 1e6, pitch_diameter_m * 1e3
    f_bl = math.exp(-2.6e-8 * (n * nu) ** 1.4 * dm)
    return f_bl * MU_BOUNDARY + (1.0 - f_bl) * (MU_EHL_SYNTHETIC if synthetic else MU_EHL_MINERAL)


def inlet_shear_heating_factor(speed_rad_s: float, viscosity_m2_s: float, pitch_diameter_m: float) -> float:
    """SKF's phi_ish = 1 / (1 + 1.84e-9 (n d_m)^1.28 nu^0.64)."""
    n, nu, dm = abs(speed_rad_s) / RPM, viscosity_m2_s * 1e6, pitch_diameter_m * 1e3
    return 1.0 / (1.0 + 1.84e-9 * (n * dm) ** 1.28 * nu ** 0.64)


#: SKF's kinematic replenishment constant K_rs by lubrication method (SKF General Catalogue 6000 EN, 2005,
#: "Frictional moment": 3e-8 for a low oil level bath and oil jet, 6e-8 for grease and oil-air / oil-mist)
STARVATION_K_RS = {"grease": 6e-8, "oil_air": 6e-8, "oil_mist": 6e-8, "oil_jet": 3e-8, "oil_bath": 3e-8}


def replenishment_factor(speed_rad_s: float, viscosity_m2_s: float, bore_m: float, outside_m: float,
                         K_rs: float, K_Z: float = 4.4) -> float:
    """SKF's kinematic replenishment/starvation reduction factor of the rolling friction,
    phi_rs = exp(-K_rs nu n (d + D) sqrt(K_Z / (2 (D - d)))) (nu mm^2/s, n rpm, d and D mm); 1 with K_rs 0.
    At high speed the balls push the oil aside faster than it flows back: the contacts run starved, the
    film and its rolling resistance shrink."""
    if K_rs <= 0.0:
        return 1.0
    n, nu = abs(speed_rad_s) / RPM, viscosity_m2_s * 1e6
    d, D = bore_m * 1e3, outside_m * 1e3
    return float(math.exp(-K_rs * nu * n * (d + D) * math.sqrt(K_Z / (2.0 * (D - d)))))


def ehl_rolling_force_N(Q_N, u_m_s, Rx_m, ellipticity, E_prime_Pa: float, eta0_Pa_s: float, alpha_pv_1_Pa: float):
    """Hydrodynamic rolling force of elliptical EHL contacts, 2.86 E' Rx^2 k^0.348 G^0.022 U^0.66 W^0.47."""
    Q = np.maximum(np.asarray(Q_N, float), 0.0)
    U = eta0_Pa_s * np.abs(u_m_s) / (E_prime_Pa * Rx_m)
    W = Q / (E_prime_Pa * Rx_m * Rx_m)
    G = alpha_pv_1_Pa * E_prime_Pa
    return 2.86 * E_prime_Pa * Rx_m * Rx_m * ellipticity ** 0.348 * G ** 0.022 * U ** 0.66 * W ** 0.47


def sphere_drag_coefficient(reynolds):
    """Clift and Gauvin (1970) sphere drag, valid to Re ~ 3e5."""
    Re = np.maximum(np.asarray(reynolds, float), 1e-12)
    return 24.0 / Re * (1.0 + 0.15 * Re ** 0.687) + 0.42 / (1.0 + 42500.0 * Re ** -1.16)


def _spin_moment(mu, Q, a, b):
    """(3/8) mu Q a E(k), k^2 = 1 - (b/a)^2."""
    m = 1.0 - np.minimum(b / np.where(a > 0.0, a, 1.0), 1.0) ** 2
    return 0.375 * mu * Q * a * ellipe(m)


def ball_bearing_heat(state, geometry, lubricant: Lubricant, lubricant_C: float,
                      options: ContactFrictionOptions = ContactFrictionOptions(),
                      model: str = "outer_race_control") -> BearingHeat:
    """Heat generated in a ball bearing (set) at its quasi-static ``state`` (same ``geometry`` and
    race-control ``model`` as the bearing that produced it), lubricant at ``lubricant_C``."""
    w = float(state.speed_rad_s)
    g = geometry
    kin = ball_kinematics(state, g, model)
    zeros = np.zeros_like(state.element_load_inner_N)
    if w == 0.0:
        return BearingHeat(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, zeros, zeros.copy(), kin)
    D, dm = g.ball_diameter_m, g.pitch_diameter_m
    nu = lubricant.kinematic_m2_s(lubricant_C)
    eta = lubricant.dynamic_Pa_s(lubricant_C)
    mu = (skf_sliding_coefficient(w, nu, dm, lubricant.synthetic) if options.traction_coefficient is None
          else options.traction_coefficient)
    phi = inlet_shear_heating_factor(w, nu, dm) if options.inlet_shear_heating else 1.0
    # starvation: the bearing's bore and outside diameter from its pitch and ball diameters (d_m -+ 1.575 D)
    phi *= replenishment_factor(w, nu, dm - RING_PROPORTION * D, dm + RING_PROPORTION * D, options.starvation_K_rs,
                                options.geometry_K_Z)
    E_prime = 2.0 * g.E_star_Pa
    out = {}
    for side, Q, ang, ax, u, spin, sgn in (
            ("inner", state.element_load_inner_N, state.contact_angle_inner_deg, state.semi_axes_inner_m,
             kin.rolling_inner_m_s, kin.spin_inner_rad_s, -1.0),
            ("outer", state.element_load_outer_N, state.contact_angle_outer_deg, state.semi_axes_outer_m,
             kin.rolling_outer_m_s, kin.spin_outer_rad_s, 1.0)):
        Qp = np.maximum(Q, 0.0)
        a, b = ax[..., 0], ax[..., 1]
        gam = pitch_ratio(D, np.radians(ang), dm)
        Rx = 0.5 * D * (1.0 + sgn * gam)
        loaded = Qp > 0.0
        spin_W = np.where(loaded, _spin_moment(mu, Qp, a, b) * np.abs(spin), 0.0)
        k = np.where(loaded, a / np.where(b > 0.0, b, 1.0), 1.0)
        ehl_W = np.where(loaded, phi * ehl_rolling_force_N(Qp, u, Rx, k, E_prime, eta,
                                                           lubricant.pressure_viscosity_1_Pa) * u, 0.0)
        hyst_W = np.where(loaded, options.hysteresis_loss_factor * 0.1875 * Qp * b / Rx * u, 0.0)
        out[side] = (spin_W, ehl_W, hyst_W)
    # drag of the balls in the oil-air mixture
    X = options.oil_volume_fraction
    rho = X * lubricant.density_kg_m3 + (1.0 - X) * AIR_DENSITY_KG_M3
    mu_mix = X * eta + (1.0 - X) * AIR_VISCOSITY_PA_S
    v = np.abs(kin.cage_rad_s) * 0.5 * dm
    cd = sphere_drag_coefficient(rho * v * D / mu_mix)
    drag_W = float(np.sum(math.pi / 8.0 * cd * rho * D * D * v ** 3))
    c_in = sum(out["inner"])
    c_out = sum(out["outer"])
    fr = options.contact_heat_to_ring
    return BearingHeat(
        spin_W=float(np.sum(out["inner"][0] + out["outer"][0])),
        rolling_ehl_W=float(np.sum(out["inner"][1] + out["outer"][1])),
        hysteresis_W=float(np.sum(out["inner"][2] + out["outer"][2])),
        drag_W=drag_W, inner_ring_W=float(fr * np.sum(c_in)), outer_ring_W=float(fr * np.sum(c_out)),
        balls_W=float((1.0 - fr) * (np.sum(c_in) + np.sum(c_out))), lubricant_W=drag_W,
        traction_coefficient=float(mu), per_contact_inner_W=c_in, per_contact_outer_W=c_out, kinematics=kin)
