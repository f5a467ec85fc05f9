"""The one place spindlesim calls sdypy-EMA (``from sdypy import EMA``): LSCF poles over the model orders,
LSFD residues for a set of poles.

sdypy-EMA's :class:`Model` is made for one FRF here (one response, one reference), in receptance form.
Its pole picking is interactive (a Qt or Tk chart) or :meth:`Model.select_closest_poles` (its own
stability test around given frequencies); spindlesim decides the stable poles itself
(:mod:`spindlesim.measured.stabilisation`) and hands the chosen ones to :meth:`Model.get_constants` through
``pole_ind`` (the attribute both of its pickers fill).  Every call runs inside :func:`~.quiet.quiet`
(sdypy-EMA draws tqdm progress bars, prints notes and warns).

A version change of sdypy-EMA touches this module only; docs/decisions.md names the versions tried.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .quiet import quiet

__all__ = ["LscfPoles", "lscf_poles", "lsfd", "ema_version"]


def _ema():
    with quiet("sdypy-EMA"):  # its import draws nothing, but may warn (a GUI toolkit missing)
        from sdypy import EMA
    return EMA


def ema_version() -> str:
    return str(getattr(_ema(), "__version__", "unknown"))


@dataclass(frozen=True, eq=False)
class LscfPoles:
    """The poles of every LSCF model order (``orders[i]`` poles at ``poles[i]``, both conjugates, every
    frequency) and the library model that computed them (for :func:`lsfd`)."""

    orders: tuple[int, ...]
    poles: tuple[np.ndarray, ...]
    model: object


def lscf_poles(frequency_hz: np.ndarray, h: np.ndarray, band_hz: tuple[float, float], max_order: int) -> LscfPoles:
    """LSCF (least-squares complex frequency) poles of the receptance ``h`` [m/N] at ``frequency_hz`` (uniform,
    on multiples of its step) for the orders 2, 4, ..., 2 ``max_order``, fitted from ``band_hz[0]`` to
    ``band_hz[1]``.

    The data above ``band_hz[1]`` are not passed (the library's z-domain spans 0 to the last frequency given, its
    Nyquist frequency); the data below ``band_hz[0]`` are left out of the fit by the library (its ``lower``)."""
    EMA = _ema()
    f = np.asarray(frequency_hz, float)
    keep = f <= band_hz[1] * (1 + 1e-12)
    f, h = f[keep], np.asarray(h, complex)[keep]
    # sdypy-EMA cuts its data below the sample nearest to ``upper`` (excluded): one sample past the band
    # keeps the band's last sample in the fit
    f = np.append(f, f[-1] + (f[-1] - f[-2]))
    h = np.append(h, h[-1])
    with quiet("sdypy-EMA"):
        model = EMA.Model(frf=h[None, :], freq=f, lower=float(band_hz[0]), upper=float(f[-1]),
                          pol_order_high=int(max_order), frf_form="receptance")
        model.get_poles(method="lscf", show_progress=False)
    poles = tuple(np.asarray(p, complex) for p in model.all_poles)
    return LscfPoles(tuple(len(p) for p in poles), poles, model)


@dataclass(frozen=True, eq=False)
class Lsfd:
    """LSFD (least-squares frequency domain) result for a set of poles: each pole's residue ``A`` (H =
    sum A / (j w - lambda) + conj), the lower (mass line, ``- lower / w^2``) and upper (``+ upper``)
    residuals [m/N (rad/s)^2, m/N], and the reconstructed receptance at the model's frequencies."""

    residues: np.ndarray
    lower_residual: complex
    upper_residual: complex
    frequency_hz: np.ndarray
    reconstructed: np.ndarray


def lsfd(lscf: LscfPoles, picked: list[tuple[int, int]], band_hz: tuple[float, float]) -> Lsfd:
    """Residues of the poles ``picked`` [(index of the model order in ``lscf.orders``, index of the pole in
    it)] by LSFD over ``band_hz``, with both residual terms."""
    model = lscf.model
    model.pole_ind = np.asarray(picked, dtype=int).reshape(-1, 2)
    with quiet("sdypy-EMA"):
        H, A = model.get_constants(method="lsfd", whose_poles="own", f_lower=float(band_hz[0]),
                                   f_upper=float(np.asarray(model.freq)[-1]), upper_r=True, lower_r=True)
    f = np.asarray(model.freq, float)
    rec = np.asarray(H)[0]
    keep = (f >= band_hz[0] * (1 - 1e-12)) & (f <= band_hz[1] * (1 + 1e-12))
    return Lsfd(np.asarray(A)[0].copy(), complex(np.asarray(model.LR)[0]), complex(np.asarray(model.UR)[0]),
                f[keep], rec[keep])
