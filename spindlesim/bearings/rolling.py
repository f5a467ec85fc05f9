"""What the rolling-element families share: the pitch ratio gamma and the catalogue proportion of the rings.

- gamma = D cos(alpha) / d_m (D the rolling element's diameter, alpha the contact angle, d_m the pitch
  diameter): the cage ratio (1 - gamma) / 2, the rolling radii R_x = (D / 2)(1 -+ gamma) of the inner and
  outer contact and the element's spin (d_m / 2D) omega (1 - gamma^2) follow from it (Harris and Kotzalas,
  *Essential Concepts*, ch. 8).  One function for every family and every model that needs it.
- :data:`RING_PROPORTION`: a bearing's bore and outside diameter estimated from its pitch and rolling-element
  diameters, d_m -+ k D (a 7014 has d 70, D 110, d_m 90, D_w 12.7: k = 1.575); used where a deck does not give
  the rings (the thermal network's ring masses and seats, SKF's starvation factor).
"""

from __future__ import annotations

import math

import numpy as np

#: bore and outside diameter of a rolling bearing from its pitch and rolling-element diameters: d_m -+ k D
RING_PROPORTION = 1.575


def pitch_ratio(element_diameter_m, contact_angle_rad, pitch_diameter_m):
    """gamma = D cos(alpha) / d_m: a float for a float angle, an array for an array of angles."""
    if isinstance(contact_angle_rad, np.ndarray):
        return element_diameter_m * np.cos(contact_angle_rad) / pitch_diameter_m
    return element_diameter_m * math.cos(contact_angle_rad) / pitch_diameter_m
