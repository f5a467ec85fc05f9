"""Normal contact of rollers and balls on raceways: elastic half-space solver.

Seed 001 eqs. 42-46: gap equation, Boussinesq/Love influence coefficients, load
balance; solved with DC-FFT deflections and the Polonsky-Keer constrained CGM.

Library entry points (SI): :func:`solve_roller_contact`, :func:`solve_point_contact`,
:func:`solve_line_contact_2d`; closed forms in :mod:`spindlesim.contact.hertz`.
"""

from .geometry import RollerProfile, equivalent_radius
from .hertz import combined_modulus, line_contact, point_contact_circular, stribeck_max_roller_load
from .line2d import LineContact2D, solve_line_contact_2d
from .problems import STEEL, solve_point_contact, solve_roller_contact
from .result import ContactResult
from .solver import ContactNotConverged

__all__ = [
    "ContactResult", "ContactNotConverged", "LineContact2D", "RollerProfile", "STEEL",
    "combined_modulus", "equivalent_radius", "line_contact", "point_contact_circular",
    "solve_line_contact_2d", "solve_point_contact", "solve_roller_contact",
    "stribeck_max_roller_load",
]
