"""Milling: zero-order (average) solution of Altintas and Budak (CIRP Annals 44/1, 1995).

The dynamic milling force F(t) = a K(t) (r(t) - r(t - tau)) is replaced by its average over
one tooth period, K0 = (N Kt / 4 pi) [alpha] with Altintas' average directional factors
(:meth:`MillingProcess.mean_directional`).  At the limit, r = H(j w_c) F gives

    det(I - a (1 - exp(-j w_c tau)) K0 H(j w_c)) = 0.

With mu the eigenvalues of K0 H, lambda = -mu and 1 + a (1 - exp(-j w tau)) lambda = 0, the
form solved in :mod:`spindlesim.chatter.regenerative`:

    a_lim = -1 / (2 Re lambda) = -(2 pi / (N Kt)) Lambda_R (1 + kappa^2)   (Altintas' form,
    Lambda = -1 / mu_alpha with mu_alpha the eigenvalues of [alpha] H, kappa = Lambda_I / Lambda_R),
    w_c tau = eps + 2 pi k,  eps = pi - 2 arctan(kappa) = (2 arg(lambda) - pi) mod 2 pi.

Both eigenvalue branches are followed continuously in frequency; the envelope is the smallest
positive limit over branches, crossings and lobes.  Speed-independent FRFs are solved for all
speeds at once (vectorised); a tool per speed is solved speed by speed.
"""

from __future__ import annotations

import numpy as np

from .process import MillingProcess, TurningProcess
from .regenerative import eigen_branches, frequency_domain_diagram
from .results import LobeDiagram
from .tool import ToolSource

__all__ = ["zero_order_lobes"]

METHOD = "zero_order"


def zero_order_lobes(process: MillingProcess | TurningProcess, tool: ToolSource, speeds_rpm: np.ndarray, *,
                     max_lobes: int | None = None, frequency_hz: np.ndarray | None = None,
                     **_ignored) -> LobeDiagram:
    """Zero-order lobes: per-lobe limits a_lim [m], envelope and chatter frequencies."""
    K0 = process.mean_directional()
    notes = ()
    if isinstance(process, MillingProcess) and process.helix_rad:
        notes = ("zero-order average does not depend on the helix angle",)
    return frequency_domain_diagram(process, tool, speeds_rpm,
                                    lambda H: eigen_branches(-np.einsum("ij,fjk->fik", K0, H)),
                                    METHOD, max_lobes, frequency_hz, notes)
