"""Damping of the rolling bearings (ball sets, DTRBs, rigid-race roller bearings): stiffness-proportional.

A rolling bearing's damping comes from its lubricant films, the fits of its rings and the materials; none of
the quasi-static contact models here (Jones' ball set, seed 001's DTRB, the rigid-race roller bearing) has it.
The relation used instead is the one rotordynamics practice takes for rolling bearings (Kraemer, *Dynamics of
Rotors and Foundations*, Springer 1993; docs/theory.md "Damping of the rolling bearings"):

    C = beta K,       beta = (0.25 ... 2.5) x 1e-5 s,     default beta = 1.0e-5 s

applied to the bearing's whole tangent stiffness (the 5 x 5 of a ball set or a 5-DOF DTRB: x, y, z and the
tilts; the 2 x 2 of a radial bearing), so a mode that strains the bearing axially or in tilt is damped as one
that strains it radially.  A mode whose strain energy lies in the bearing gets the damping ratio
zeta = beta omega / 2 (1.0 % at 318 Hz with the default).

The contract (``bearings/base.py``): ``linearized`` returns C = beta K at the operating point (K the
pitch-averaged tangent).  ``force_and_tangent`` returns the force f_el(q) - C v with C_t = C, where C is

* for a time integration (the bearing of ``at_operating_point(..., transient=True)``): beta K at that
  operating point, held: a linear damper with the coefficients of the modal analysis.  The state's own
  beta K_t(q) is not smooth where a rolling element or a roller slice enters contact (k ~ delta^(n-1)), and
  Newton's iterations of the implicit integrator stalled on it (seed 001's preload study at 50 um:
  corrections of 8e-12 m that no longer fell);
* otherwise beta K_t(q) of the state (K_t stays the tangent of the elastic force).

Only pydantic is imported when the module loads (the deck sections import :class:`RollingDamping`, and
loading a deck stays light); :func:`damped` imports numpy.
"""

from __future__ import annotations

from typing import Annotated

from pydantic import Field

from ..fields import DeckModel

#: beta [s] of C = beta K when a deck says nothing: inside Kraemer's (0.25 ... 2.5) x 1e-5 s
DEFAULT_STIFFNESS_PROPORTIONAL_S = 1.0e-5
#: the range of beta [s] Kraemer (1993) gives for rolling bearings (docs/theory.md)
LITERATURE_RANGE_S = (0.25e-5, 2.5e-5)


class RollingDamping(DeckModel):
    """Damping of a rolling bearing, C = beta K on its whole tangent stiffness (docs/theory.md, Kraemer 1993:
    beta = 0.25e-5 ... 2.5e-5 s for rolling bearings)."""

    stiffness_proportional_s: Annotated[float, Field(ge=0.0, le=1e-3)] = DEFAULT_STIFFNESS_PROPORTIONAL_S
    """beta of C = beta K: the bearing's damping coefficients [N s/m, N m s/rad] are beta times its tangent
    stiffness at the operating point (every DOF: radial, axial, tilt). Kraemer (1993) gives 0.25e-5 to 2.5e-5 s
    for rolling bearings; 0 turns the damping off (the contact model alone). A mode whose strain energy lies in
    the bearing gets the damping ratio beta omega / 2."""


def damping_of(entry_damping: RollingDamping | None) -> float:
    """beta [s] of a deck entry's ``damping`` (None: the default)."""
    return DEFAULT_STIFFNESS_PROPORTIONAL_S if entry_damping is None else float(entry_damping.stiffness_proportional_s)


def check_beta(beta_s: float) -> float:
    """beta as a float, refused when negative or not finite (a constructor's check)."""
    b = float(beta_s)
    if not b >= 0.0 or b == float("inf"):
        raise ValueError(f"stiffness-proportional damping must be finite and >= 0 s, not {beta_s!r}")
    return b


def damped(f, K, v, beta_s: float, held=None):
    """(f - C v, C): the reaction with the damping force and its C_t (``v`` the velocity of the DOFs of K):
    C = ``held`` when given (the damping matrix held at an operating point for a time integration), else
    beta K (the state's own tangent)."""
    if held is not None:
        import numpy as np

        C = np.array(held, float).reshape(K.shape)
        return f - C @ v, C
    if beta_s == 0.0:
        return f, 0.0 * K
    C = beta_s * K
    return f - C @ v, C
