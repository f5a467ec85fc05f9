"""Normal contact of rollers and balls on raceways: elastic half-space solver.

Seed 001 eqs. 42-46: gap equation, Boussinesq/Love influence coefficients, load
balance; solved with DC-FFT deflections and the Polonsky-Keer constrained CGM.

Library entry points (SI): :func:`solve_roller_contact`, :func:`solve_point_contact`,
:func:`solve_line_contact_2d`; closed forms in :mod:`spindlesim.contact.hertz`.
"""

from spindlesim.lazy import lazy_exports

#: what the package exports and the module defining it: imported on first use (PEP 562), so that a
#: deck loader reading only a section does not pay for the solvers' imports (scipy.signal, numba ...)
_EXPORTS = {
    "RollerProfile": "geometry",
    "equivalent_radius": "geometry",
    "combined_modulus": "hertz",
    "line_contact": "hertz",
    "point_contact_circular": "hertz",
    "stribeck_max_roller_load": "hertz",
    "LineContact2D": "line2d",
    "solve_line_contact_2d": "line2d",
    "STEEL": "problems",
    "solve_point_contact": "problems",
    "solve_roller_contact": "problems",
    "ContactResult": "result",
    "ContactNotConverged": "solver",
}


__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS)



__all__ = [
    "ContactResult", "ContactNotConverged", "LineContact2D", "RollerProfile", "STEEL",
    "combined_modulus", "equivalent_radius", "line_contact", "point_contact_circular",
    "solve_line_contact_2d", "solve_point_contact", "solve_roller_contact",
    "stribeck_max_roller_load",
]
