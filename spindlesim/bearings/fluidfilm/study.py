"""What the ``thermal`` and ``coefficients`` analyses compute for a deck's fluid-film bearings, as one frozen
result (:class:`~.results.FilmBearings`): each bearing's thermal equilibrium at one speed under its load."""

from __future__ import annotations

import logging
import math
from typing import Callable, Mapping, Sequence

import numpy as np

from .results import FilmBearings

log = logging.getLogger(__name__)


def film_bearings(bearings: Sequence, speed_rad_s: float, loads: Mapping[str, np.ndarray | None],
                  progress: Callable[[int, int], None] | None = None) -> FilmBearings:
    """Each of ``bearings`` (:class:`~.bearing.FluidFilmBearing`) at its thermal equilibrium at ``speed_rad_s``
    under ``loads[name]`` (None: its own ``load_N``); a mean film temperature beyond a mineral oil's range is
    warned of."""
    from .viscosity import OIL_MAX_C

    results = []
    for i, b in enumerate(bearings):
        res = b.analyze(speed_rad_s, loads[b.name])
        f = res.film
        log.info("%s: mean film %.2f degC, mu %.4g Pa s, S %.4g, e/Cb %.4f, attitude %.1f deg",
                 b.name, res.temperature_mean_C, f.viscosity_Pa_s, f.sommerfeld,
                 f.eccentricity_ratio, f.attitude_angle_deg)
        if res.temperature_mean_C > OIL_MAX_C:
            log.warning("bearing %r: mean film temperature %.0f C at %.0f rpm is above %.0f C, beyond a mineral "
                        "oil's usable range: more oil flow, a lighter grade or more cooling",
                        b.name, res.temperature_mean_C, speed_rad_s * 30 / math.pi, OIL_MAX_C)
        results.append(res)
        if progress is not None:
            progress(i + 1, len(bearings))
    return FilmBearings(float(speed_rad_s), tuple(b.name for b in bearings), tuple(results))
