"""Fluid-film journal bearings: plain (360 deg or grooved) and multilobe (3-lobe).

Layers (each usable on its own):

- :mod:`geometry`     film thickness of plain and multilobe bearings
- :mod:`reynolds`     finite-volume Reynolds equation with the Reynolds (Swift-Stieber)
                      cavitation condition solved as a linear complementarity problem
- :mod:`equilibrium`  Newton iteration on the journal position for a given load
- :mod:`coefficients` eight stiffness and damping coefficients
- :mod:`performance`  friction, flows, minimum film, Reynolds number
- :mod:`viscosity`    Walther (ASTM D341) viscosity-temperature relation, ISO VG table
- :mod:`thermal`      thermal equilibrium of seed 003 eqs. 4-14
- :mod:`bearing`      :class:`FluidFilmBearing` implementing the linearised bearing protocol
- :mod:`film_model`   :class:`FilmForceModel`: nonlinear film force and tangent F(q, v) for
                      transients, exact (:mod:`film_force`) or tabulated (:mod:`film_table`,
                      :mod:`film_spline`); imported on demand (numba)
"""

from spindlesim.lazy import lazy_exports

#: exports and their modules, imported on first use (PEP 562): the deck section needs none of them
_EXPORTS = {
    "FluidFilmBearing": "bearing",
    "BearingGeometry": "geometry",
    "Land": "geometry",
    "multilobe_geometry": "geometry",
    "plain_geometry": "geometry",
    "ThermalEquilibriumError": "thermal",
    "ThermalParameters": "thermal",
    "ConstantViscosity": "viscosity",
    "WaltherViscosity": "viscosity",
}


__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS)


__all__ = [
    "BearingGeometry", "ConstantViscosity", "FluidFilmBearing", "Land", "ThermalEquilibriumError",
    "ThermalParameters", "WaltherViscosity", "multilobe_geometry", "plain_geometry",
]
