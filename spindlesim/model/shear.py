"""Shear coefficient of circular sections (Cowper 1966)."""

import numpy as np


def cowper_hollow_circle(poisson, inner_over_outer):
    """kappa = 6 (1 + nu)(1 + m^2)^2 / ((7 + 6 nu)(1 + m^2)^2 + (20 + 12 nu) m^2), m = d_i / d_o.

    Cowper, J. Appl. Mech. 33 (1966) 335-340; m = 0 gives the solid circle
    6 (1 + nu) / (7 + 6 nu).
    """
    nu = np.asarray(poisson, dtype=float)
    m2 = np.asarray(inner_over_outer, dtype=float) ** 2
    return 6 * (1 + nu) * (1 + m2) ** 2 / ((7 + 6 * nu) * (1 + m2) ** 2 + (20 + 12 * nu) * m2)
