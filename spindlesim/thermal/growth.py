"""Thermal, fit and centrifugal growth of shaft, bearing rings and housing (SI, pure functions).

Sources (docs/theory.md, "Spindle thermal model: heat generation and growth"):

- Free thermal growth: a body at a uniform temperature T, free of constraint, grows in every dimension
  by the factor 1 + alpha (T - T_ref): it stays stress free, so a free ring's groove radius, raceway
  diameter and width all grow by the same strain.
- Fits (Lame's thick-walled cylinders, Timoshenko and Goodier, *Theory of Elasticity*, 3rd ed., 1970,
  art. 28; Harris and Kotzalas 2007, *Essential Concepts*, "Interference fitting and clearance"): two
  cylinders pressed together at the diameter d with the diametral interference I carry the pressure

      p = I / (d [ (1/E_o) ((c^2 + d^2)/(c^2 - d^2) + nu_o) + (1/E_i) ((d^2 + a^2)/(d^2 - a^2) - nu_i) ])

  (inner body of bore a, outer body of outer diameter c, all diameters); the outer body's free
  surface at c grows by 2 p d^2 c / (E_o (c^2 - d^2)) (diametral), the inner body's bore a shrinks by
  2 p d^2 a / (E_i (d^2 - a^2)).  A solid shaft (a = 0) of the ring's material expands a ring of
  outer diameter c by I d / c, the familiar rule.
- Rotating annular disc, plane stress, free edges a < b (Timoshenko and Goodier, art. 32):

      u(r) = rho w^2 r / (8 E) [ (3 + nu)(1 - nu)(a^2 + b^2) + (3 + nu)(1 + nu) a^2 b^2 / r^2 - (1 - nu^2) r^2 ]

  (radii here); a solid disc is a = 0.  The bore of a rotating ring grows more than the surface of the
  shaft it sits on, so a fit loosens with speed; when the interference reaches zero the fit is lost
  (:class:`FitState` reports it, :func:`inner_fit_loss_speed_rad_s` gives the speed) and the ring grows
  freely.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

ZERO_C_K = 273.15

#: through-hardened bearing steel (100Cr6 / AISI 52100), 20-100 C: handbook range 11-12.5e-6 1/K
BEARING_STEEL_EXPANSION_1_K = 11.5e-6
#: bearing-grade silicon nitride (hot isostatically pressed Si3N4): about 3.2e-6 1/K
SI3N4_EXPANSION_1_K = 3.2e-6
#: carbon or low-alloy steel shaft: 11-12e-6 1/K
STEEL_EXPANSION_1_K = 11.5e-6
#: grey cast iron housing (e.g. EN-GJL-250): 10-11e-6 1/K
CAST_IRON_EXPANSION_1_K = 10.5e-6


@dataclass(frozen=True)
class ThermoElastic:
    """Elastic, mass and thermal-expansion data of one body (SI)."""

    E_Pa: float
    poisson: float
    density_kg_m3: float
    expansion_1_K: float

    def __post_init__(self) -> None:
        if not (self.E_Pa > 0.0 and -1.0 < self.poisson < 0.5 and self.density_kg_m3 >= 0.0):
            raise ValueError("E must be positive, Poisson's ratio in (-1, 0.5), density >= 0")
        if not 0.0 <= self.expansion_1_K < 1e-3:
            raise ValueError(f"thermal expansion coefficient {self.expansion_1_K:g} 1/K must lie in [0, 1e-3)")


BEARING_STEEL = ThermoElastic(208e9, 0.3, 7850.0, BEARING_STEEL_EXPANSION_1_K)
SI3N4 = ThermoElastic(310e9, 0.26, 3200.0, SI3N4_EXPANSION_1_K)
STEEL_SHAFT = ThermoElastic(208e9, 0.3, 7850.0, STEEL_EXPANSION_1_K)
CAST_IRON = ThermoElastic(110e9, 0.26, 7200.0, CAST_IRON_EXPANSION_1_K)


def check_temperature(value_C: float, what: str = "temperature") -> float:
    """The temperature, or ValueError if it is below absolute zero or not finite."""
    t = float(value_C)
    if not math.isfinite(t) or t <= -ZERO_C_K:
        raise ValueError(f"{what} {value_C!r} C is at or below absolute zero (-273.15 C)")
    return t


def thermal_strain(expansion_1_K: float, temperature_C: float, reference_C: float = 20.0) -> float:
    """Free thermal strain alpha (T - T_ref) of a body at a uniform temperature."""
    check_temperature(temperature_C)
    check_temperature(reference_C, "reference temperature")
    if expansion_1_K < 0.0:
        raise ValueError(f"thermal expansion coefficient {expansion_1_K:g} 1/K is negative")
    return expansion_1_K * (temperature_C - reference_C)


def free_growth(length_m: float, expansion_1_K: float, temperature_C: float, reference_C: float = 20.0) -> float:
    """Change of a length of a free body at a uniform temperature [m]."""
    return length_m * thermal_strain(expansion_1_K, temperature_C, reference_C)


# ---- Lame ------------------------------------------------------------------------------------------
def _outer_term(d: float, c: float, mat: ThermoElastic) -> float:
    if math.isinf(c):  # a housing of unlimited wall thickness
        return (1.0 + mat.poisson) / mat.E_Pa
    if not c > d:
        raise ValueError(f"outer diameter {c * 1e3:g} mm must exceed the fit diameter {d * 1e3:g} mm")
    return ((c * c + d * d) / (c * c - d * d) + mat.poisson) / mat.E_Pa


def _inner_term(d: float, a: float, mat: ThermoElastic) -> float:
    if not 0.0 <= a < d:
        raise ValueError(f"bore {a * 1e3:g} mm must lie in [0, {d * 1e3:g}) mm")
    return ((d * d + a * a) / (d * d - a * a) - mat.poisson) / mat.E_Pa


def fit_pressure(interference_m: float, d_m: float, inner_bore_m: float, inner: ThermoElastic,
                 outer_diameter_m: float, outer: ThermoElastic) -> float:
    """Lame contact pressure [Pa] of a diametral interference at the diameter d (0 for I <= 0)."""
    if interference_m <= 0.0:
        return 0.0
    return interference_m / (d_m * (_outer_term(d_m, outer_diameter_m, outer) + _inner_term(d_m, inner_bore_m, inner)))


def outer_body_surface_growth(pressure_Pa: float, d_m: float, outer_diameter_m: float, outer: ThermoElastic) -> float:
    """Diametral growth of the free outer surface (diameter c) of a cylinder under internal pressure p at d."""
    c = outer_diameter_m
    if pressure_Pa == 0.0 or math.isinf(c):
        return 0.0
    return 2.0 * pressure_Pa * d_m * d_m * c / (outer.E_Pa * (c * c - d_m * d_m))


def inner_body_bore_change(pressure_Pa: float, d_m: float, inner_bore_m: float, inner: ThermoElastic) -> float:
    """Diametral change (negative: contraction) of the bore a of a cylinder under external pressure p at d."""
    a = inner_bore_m
    if pressure_Pa == 0.0 or a == 0.0:
        return 0.0
    return -2.0 * pressure_Pa * d_m * d_m * a / (inner.E_Pa * (d_m * d_m - a * a))


# ---- rotating disc -----------------------------------------------------------------------------------
def rotating_disc_radial_displacement(r_m: float, bore_m: float, outer_diameter_m: float, mat: ThermoElastic,
                                      speed_rad_s: float) -> float:
    """Radial displacement u(r) [m] of a free annular disc (bore, outer diameter) spinning at w, plane stress."""
    a, b = 0.5 * bore_m, 0.5 * outer_diameter_m
    if not 0.0 <= a < b:
        raise ValueError("disc bore must be smaller than its outer diameter")
    if not a - 1e-12 <= r_m <= b + 1e-12:
        raise ValueError(f"radius {r_m:g} m outside the disc [{a:g}, {b:g}] m")
    nu, w2 = mat.poisson, speed_rad_s * speed_rad_s
    k = mat.density_kg_m3 * w2 * r_m / (8.0 * mat.E_Pa)
    hole = (3.0 + nu) * (1.0 + nu) * a * a * b * b / (r_m * r_m) if a > 0.0 else 0.0
    return k * ((3.0 + nu) * (1.0 - nu) * (a * a + b * b) + hole - (1.0 - nu * nu) * r_m * r_m)


# ---- a ring on a shaft, a ring in a housing ------------------------------------------------------------
@dataclass(frozen=True)
class FitState:
    """One fit at the operating point.  Interferences diametral [m], positive = interference."""

    nominal_interference_m: float     # as mounted at the reference temperature, at rest
    thermal_change_m: float           # from the different growth of the two bodies
    centrifugal_change_m: float       # rotating bodies (inner ring and shaft); 0 for a housing fit
    pressure_Pa: float
    raceway_change_m: float           # diametral change of the raceway from the fit pressure alone

    @property
    def interference_m(self) -> float:
        """Effective interference at temperature and speed (<= 0: the fit is lost)."""
        return self.nominal_interference_m + self.thermal_change_m + self.centrifugal_change_m

    @property
    def lost(self) -> bool:
        """True when a fit mounted with interference has none left (the ring would creep)."""
        return self.nominal_interference_m > 0.0 and self.interference_m <= 0.0


def inner_ring_fit(interference_m: float, bore_m: float, raceway_diameter_m: float, ring: ThermoElastic,
                   shaft_bore_m: float, shaft: ThermoElastic, *, ring_strain: float = 0.0,
                   shaft_strain: float = 0.0, speed_rad_s: float = 0.0) -> FitState:
    """Inner ring (bore d, equivalent outer diameter = its raceway diameter) on a hollow shaft.

    ``ring_strain`` and ``shaft_strain``: free thermal strains alpha (T - T_ref).  The ring and the
    shaft spin at ``speed_rad_s``; their free centrifugal growths at the seat change the interference."""
    d, c = bore_m, raceway_diameter_m
    if not c > d:
        raise ValueError(f"inner raceway diameter {c * 1e3:g} mm must exceed the bore {d * 1e3:g} mm")
    thermal = d * (shaft_strain - ring_strain)
    cent = 0.0
    if speed_rad_s != 0.0:
        u_ring = rotating_disc_radial_displacement(0.5 * d, d, c, ring, speed_rad_s)
        u_shaft = rotating_disc_radial_displacement(0.5 * d, shaft_bore_m, d, shaft, speed_rad_s)
        cent = -2.0 * (u_ring - u_shaft)
    eff = interference_m + thermal + cent
    p = fit_pressure(eff, d, shaft_bore_m, shaft, c, ring)
    return FitState(interference_m, thermal, cent, p, outer_body_surface_growth(p, d, c, ring))


def inner_fit_loss_speed_rad_s(interference_m: float, bore_m: float, raceway_diameter_m: float,
                               ring: ThermoElastic, shaft_bore_m: float, shaft: ThermoElastic, *,
                               ring_strain: float = 0.0, shaft_strain: float = 0.0) -> float:
    """Speed at which the inner ring's fit on the shaft is lost (its centrifugal loosening grows as w^2):
    w = sqrt(I_T / l), l the loosening at 1 rad/s; inf if the ring does not loosen, 0 if already loose."""
    d = bore_m
    eff = interference_m + d * (shaft_strain - ring_strain)
    if eff <= 0.0:
        return 0.0
    loosen = 2.0 * (rotating_disc_radial_displacement(0.5 * d, d, raceway_diameter_m, ring, 1.0)
                    - rotating_disc_radial_displacement(0.5 * d, shaft_bore_m, d, shaft, 1.0))
    return math.sqrt(eff / loosen) if loosen > 0.0 else math.inf


def outer_ring_fit(interference_m: float, outer_diameter_m: float, raceway_diameter_m: float,
                   ring: ThermoElastic, housing_outer_diameter_m: float, housing: ThermoElastic, *,
                   ring_strain: float = 0.0, housing_strain: float = 0.0) -> FitState:
    """Outer ring (outside diameter D, equivalent bore = its raceway diameter) in a housing of outer
    diameter ``housing_outer_diameter_m`` (inf: a thick housing).  The outer ring does not rotate."""
    D, b = outer_diameter_m, raceway_diameter_m
    if not D > b:
        raise ValueError(f"outer raceway diameter {b * 1e3:g} mm must be below the outside diameter {D * 1e3:g} mm")
    thermal = D * (ring_strain - housing_strain)
    eff = interference_m + thermal
    p = fit_pressure(eff, D, b, ring, housing_outer_diameter_m, housing)
    return FitState(interference_m, thermal, 0.0, p, inner_body_bore_change(p, D, b, ring))


def inner_raceway_growth(raceway_diameter_m: float, bore_m: float, ring: ThermoElastic, ring_strain: float,
                         fit: FitState | None, speed_rad_s: float = 0.0) -> float:
    """Diametral change of a rotating inner ring's raceway: free thermal growth, its own centrifugal
    growth (free disc, bore to raceway) and the fit pressure's expansion."""
    c = raceway_diameter_m
    cent = 2.0 * rotating_disc_radial_displacement(0.5 * c, bore_m, c, ring, speed_rad_s) if speed_rad_s else 0.0
    return c * ring_strain + cent + (0.0 if fit is None else fit.raceway_change_m)


def outer_raceway_growth(raceway_diameter_m: float, ring_strain: float, fit: FitState | None) -> float:
    """Diametral change of a stationary outer ring's raceway: free thermal growth and the fit's contraction."""
    return raceway_diameter_m * ring_strain + (0.0 if fit is None else fit.raceway_change_m)


# ---- shaft against housing between two bearing sets ---------------------------------------------------
AXIAL_ARRANGEMENTS = ("O", "X", "locating_floating", "spring")


@dataclass(frozen=True)
class AxialGrowth:
    """Axial growth of the shaft against the housing between two bearing (sets) a distance L apart."""

    shaft_growth_m: float
    housing_growth_m: float
    arrangement: str
    preload_offset_change_m: float    # change of the total axial preload offset (position-preloaded O / X)
    float_m: float                    # axial travel the floating bearing or spring takes up

    @property
    def relative_m(self) -> float:
        """Shaft growth minus housing growth (> 0: the shaft grows longer)."""
        return self.shaft_growth_m - self.housing_growth_m


def shaft_housing_axial_growth(distance_m: float, shaft_expansion_1_K: float, shaft_C: float,
                               housing_expansion_1_K: float, housing_C: float, arrangement: str,
                               reference_C: float = 20.0) -> AxialGrowth:
    """alpha_s (T_s - T_ref) L - alpha_h (T_h - T_ref) L, and what the arrangement makes of it.

    Two bearings (sets) a distance L apart, inner rings on the shaft, outer rings in the housing:

    - ``O``: back-to-back across the spindle, position-preloaded through the shaft and housing (each
      bearing's inner ring is pushed towards the other): a longer shaft pulls the inner rings apart,
      the preload offset falls by the relative growth.
    - ``X``: face-to-face across the spindle: a longer shaft raises the preload offset by the relative
      growth (the classic risk of the X arrangement).
    - ``locating_floating`` or ``spring``: the floating bearing (or the spring-loaded outer rings) slides;
      the preload offset does not change and ``float_m`` is the travel it needs.
    """
    if arrangement not in AXIAL_ARRANGEMENTS:
        raise ValueError(f"arrangement must be one of {AXIAL_ARRANGEMENTS}, not {arrangement!r}")
    if distance_m < 0.0:
        raise ValueError("distance between the bearings must be >= 0")
    s = free_growth(distance_m, shaft_expansion_1_K, shaft_C, reference_C)
    h = free_growth(distance_m, housing_expansion_1_K, housing_C, reference_C)
    rel = s - h
    if arrangement == "O":
        return AxialGrowth(s, h, arrangement, -rel, 0.0)
    if arrangement == "X":
        return AxialGrowth(s, h, arrangement, rel, 0.0)
    return AxialGrowth(s, h, arrangement, 0.0, rel)
