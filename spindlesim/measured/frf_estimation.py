"""The one place spindlesim calls pyFRF (through sdypy-FRF, ``from sdypy import FRF``): the averaged H1 estimator
and coherence of impacts, and pyFRF's check of an impact's channels for an overload (clipping).

pyFRF's double-hit check (the spectrum of the force's power spectrum after its main lobe against the main
lobe) is not used: its ratio depends on the rate, the record length and the force noise more than on the
second hit (measured in docs/decisions.md: 1 % force noise alone gives 0.0016, above its default limit of
0.001; a 40 % second hit 1.5 ms later sampled at 6400/s gives 0.0022); spindlesim.measured.impact looks for a
second pulse in the force record instead.

The windows are applied before (spindlesim.measured.impact): pyFRF's windows are given ``none``.  pyFRF's
own force and exponential windows would suit stationary signals, not impacts: it rescales H1 by the ratio
of the windows' amplitude normalisations (2 / sum w; for an exponential window ending at 1 % the H1 comes
out 4.65 times too large) and it cannot put the exponential window on the force as well, which the H1 of
a windowed impact needs (docs/decisions.md).  Every call runs inside :func:`~.quiet.quiet`.

A version change of sdypy-FRF or pyFRF touches this module only.
"""

from __future__ import annotations

import numpy as np

from .quiet import quiet

__all__ = ["h1_and_coherence", "overloads", "frf_version"]

#: the measured response -> pyFRF's response type and the FRF form it is measured in
_KINDS = {"acceleration": ("a", "accelerance"), "velocity": ("v", "mobility"), "displacement": ("d", "receptance")}


def _frf_class():
    with quiet("sdypy-FRF"):
        from sdypy import FRF
    return FRF.FRF


def frf_version() -> str:
    from importlib import metadata

    try:
        return f"sdypy-FRF {metadata.version('sdypy-FRF')} (pyFRF {metadata.version('pyFRF')})"
    except metadata.PackageNotFoundError:
        return "sdypy-FRF"


def _estimator(force: np.ndarray, response: np.ndarray, kind: str, rate_hz: float):
    resp_type, _ = _KINDS[kind]
    # pyFRF takes an integer rate; it only sets its frequency axis (and the a/v conversion, not used here)
    return _frf_class()(int(round(rate_hz)), exc=np.atleast_2d(force), resp=np.atleast_2d(response), exc_type="f",
                        resp_type=resp_type, window="none", frf_estimator="H1")


def h1_and_coherence(force: np.ndarray, response: np.ndarray, kind: str, dt_s: float) -> tuple[np.ndarray, ...]:
    """(frequency [Hz], H1 [m/N], coherence) of the impacts ``force`` [impact, sample] [N] and ``response``
    (``kind``: acceleration [m/s^2], velocity [m/s], displacement [m]), averaged over the impacts.

    The estimate is taken from pyFRF in the form the response was measured in (accelerance, mobility or
    receptance: the ratio of the spectra, whatever its rate) and made a receptance here with the exact
    frequencies: H = A / (j w)^2 or V / (j w).  The zero frequency is left out."""
    _, form = _KINDS[kind]
    n = np.shape(force)[-1]
    with quiet("sdypy-FRF"):
        est = _estimator(force, response, kind, 1.0 / dt_s)
        h = np.asarray(est.get_FRF(frf_estimator="H1", frf_form=form))[0, 0]
        coh = np.asarray(est.get_coherence(), float)[0]
    f = np.fft.rfftfreq(n, dt_s)
    jw = 2j * np.pi * f[1:]
    power = {"accelerance": 2, "mobility": 1, "receptance": 0}[form]
    return f[1:], h[1:] / jw**power, np.clip(coh[1:], 0.0, 1.0)


def overloads(force: np.ndarray, response: np.ndarray, kind: str, dt_s: float, samples: int = 3) -> tuple[str, ...]:
    """pyFRF's overload check of one impact on each channel: ``samples`` samples at the record's largest
    magnitude (a clipped channel); the channels found clipped, () when none is."""
    f, r = np.asarray(force, float), np.asarray(response, float)
    reasons = []
    with quiet("sdypy-FRF"):
        est = _estimator(f, r, kind, 1.0 / dt_s)
        # the double-hit check of is_data_ok is turned off (an infinite limit): spindlesim.measured.impact has its own
        if not est.is_data_ok(f, f, overflow_samples=samples, double_impact_limit=np.inf):
            reasons.append("force overload (clipped)")
        if not est.is_data_ok(r, r, overflow_samples=samples, double_impact_limit=np.inf):
            reasons.append(f"{kind} overload (clipped)")
    return tuple(reasons)
