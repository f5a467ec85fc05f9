"""Turning, boring and grinding: Tlusty's regenerative theory with the oriented FRF.

One cutting edge, full overlap, chip thickness h = h0 + f . (r(t) - r(t - T)), T = 60 / n the
spindle (workpiece) revolution, force on the workpiece Ks b h along g (see
:mod:`spindlesim.chatter.process` for f, g and the force angle beta).  The characteristic
equation 1 + Ks b (1 - exp(-j w T)) G_or(w) = 0 holds with the oriented FRF

    G_or(w) = f^T H(w) g = sum_ij f_i H_ij(w) g_j

(Schmitz and Smith, Machining Dynamics, ch. 4: for a mode at angle alpha from the surface
normal its directional orientation factor is mu = cos(beta - alpha) cos(alpha)).  Hence

    b_lim = -1 / (2 Ks Re[G_or(w_c)])      where Re G_or < 0,

and the lobe speeds follow from the phase of G_or at the chatter frequency w_c:

    eps = 2 pi - 2 arctan(Re G_or / Im G_or)   (Im G_or < 0; in general (2 psi - pi) mod 2 pi,
    psi = atan2(Im, Re) the FRF phase; equals Altintas' 3 pi + 2 psi),
    f_c T = k + eps / (2 pi),  n = 60 / T = 60 f_c / (k + eps / 2 pi)  [rpm],  k = 0, 1, 2 ...

The phase convention: eps is the phase by which the inner modulation (present vibration)
lags the outer one (the surface left one revolution earlier), in [0, 2 pi).  For a single
direction (mode along f, beta = 0) this is exact; for a single-degree-of-freedom tool
(stiffness k, damping ratio zeta) along f with force angle beta the minimum is
b_lim,min = 2 k zeta (1 + zeta) / (Ks cos beta) at w_c = w_n (1 + zeta).
"""

from __future__ import annotations

import numpy as np

from .process import TurningProcess
from .regenerative import frequency_domain_diagram, parametric_lobes, sample_tool
from .results import LobeCurve, LobeDiagram
from .tool import ToolPoint, ToolSource

__all__ = ["oriented_frf", "turning_lobes", "turning_parametric_lobes"]

METHOD = "oriented_frf"


def oriented_frf(process: TurningProcess, H: np.ndarray) -> np.ndarray:
    """G_or = f^T H g [m/N] for receptances ``H[..., 2, 2]``."""
    return np.einsum("i,...ij,j->...", process.feed_vector, H, process.force_vector)


def _branches(process: TurningProcess):
    return lambda H: (process.Ks_N_m2 * oriented_frf(process, H))[None, :]


def turning_lobes(process: TurningProcess, tool: ToolSource, speeds_rpm: np.ndarray, *,
                  max_lobes: int | None = None, frequency_hz: np.ndarray | None = None,
                  **_ignored) -> LobeDiagram:
    """Limit depth b_lim [m] per lobe and its lower envelope at ``speeds_rpm``."""
    return frequency_domain_diagram(process, tool, speeds_rpm, _branches(process), METHOD,
                                    max_lobes, frequency_hz)


def turning_parametric_lobes(process: TurningProcess, tool: ToolPoint, lobes=range(6),
                             frequency_hz: np.ndarray | None = None) -> list[LobeCurve]:
    """The classical parametric lobes (speed, b_lim, f_c) swept over the chatter frequency."""
    omega, H = sample_tool(tool, frequency_hz)
    lam = _branches(process)(H)
    return [LobeCurve(k, n, a, f) for k, n, a, f in parametric_lobes(omega, lam, lobes, 1)]
