"""Modal parameters from a measured FRF: ``identify_modes(frf) -> ModalIdentification``.

Method (docs/theory.md, "Modal identification"): sdypy-EMA's LSCF estimator gives the poles of every model
order 2, 4, ..., 2 ``max_order``; sdypy-EMA's LSFD gives each order's residues over the band; the rule of
:mod:`~spindlesim.measured.stabilisation` picks the stable poles (frequency, damping and residue stable
through the orders); LSFD gives the chosen poles' residues with the upper and lower residuals.  Each mode
is then put in the chatter section's modal form H = 1 / (k (1 - r^2 + 2 j zeta r)) with f_n = |lambda| /
2 pi, zeta = -Re lambda / |lambda| and 1 / m = -2 w_d Im A (k = w_n^2 m): the real mode with the same pole
whose residue is the measured one's component along -j (a real mode's residue is -j / (2 m w_d)).  Modes of no
physical meaning are left out and said so: negative damping, a
residue of the wrong sign for a direct (driving-point) FRF (negative k), a peak 1 / (2 zeta k) under
``min_peak_share`` of the largest |H| in the band (a tiny residue).

An exponential window of the measurement (``frf.window_decay_1_s``, from the file) moved every pole by
-decay: it is added back to every pole's real part (the residues are unchanged).

The FRF's coherence, where the file gives it, is reported at each mode, not used as a weight: LSCF and
LSFD of sdypy-EMA fit every sample of the band alike.  LSCF needs equally spaced frequencies on multiples of
their step; other samples are interpolated (linearly, real and imaginary parts) onto such a grid first.

The band picks the modes reported, their residues (LSFD) and the fit errors.  LSCF is fitted from the band's low
edge (with a coherence: from the coherent band's, when that is lower) to the end of the usable data (the file's,
or with a coherence the coherent band's, when that is higher than the band's): its discrete-time
model takes the last frequency for its Nyquist frequency, and a band's upper edge inside the data is a
discontinuity there, whose poles scatter through the band; a fit starting high in the spectrum fares no better
(docs/decisions.md, measured on the packaged tap test).
"""

from __future__ import annotations

import logging

import numpy as np

from . import ema
from .errors import IdentificationError, MeasurementInputError
from .bands import COHERENCE_LEVEL, COHERENCE_WINDOW, coherent_band
from .results import DirectionIdentification, DiscardedMode, IdentifiedMode, ModalIdentification, \
    StabilisationDiagram
from .stabilisation import StabilityCriteria, candidates, classify, modes_from_tracks, tracks

__all__ = ["identify_modes", "modal_receptance", "MIN_SAMPLES", "MAX_SAMPLES"]

log = logging.getLogger(__name__)

DIRECTIONS = ("x", "y")
#: fewest samples in the band: the highest model order has 2 max_order poles to fit
MIN_SAMPLES = 16
#: most samples of a grid made uniform by interpolation
MAX_SAMPLES = 16384


def identify_modes(frf, band_hz: tuple[float, float] | None = None, *, direction: str | None = None,
                   max_order: int = 40, criteria: StabilityCriteria = StabilityCriteria(),
                   min_peak_share: float = 0.01) -> ModalIdentification:
    """Modes of the direct receptance(s) of ``frf`` (a :class:`~spindlesim.chatter.frf.ToolPointFrf`: its
    ``frequency_hz``, ``H`` [f, 2, 2] and, when read from a file that has them, ``coherence`` and
    ``window_decay_1_s``).

    ``band_hz``: (low, high) [Hz], by default where the coherence is good (:func:`~.bands.coherent_band`), or
    without a coherence every frequency above 0; ``direction``: "x" or "y", by
    default every direction whose direct term is not zero; ``max_order``: the LSCF model orders are 2, 4,
    ..., 2 max_order.  Raises :class:`IdentificationError` when a direction has no stable mode."""
    if max_order < criteria.min_stable + 1:
        raise MeasurementInputError(f"max_order must be at least {criteria.min_stable + 1} ({criteria.min_stable} "
                                    f"stable orders make a mode), got {max_order}")
    H = np.asarray(frf.H)
    wanted = [direction] if direction is not None else [d for i, d in enumerate(DIRECTIONS) if np.any(H[:, i, i] != 0)]
    if direction is not None and direction not in DIRECTIONS:
        raise MeasurementInputError(f"direction must be x or y, not {direction!r}")
    if not wanted:
        raise MeasurementInputError(f"{frf.source or 'the FRF'}: no direct term (xx or yy) to identify")
    coherence = getattr(frf, "coherence", None)
    decay = getattr(frf, "window_decay_1_s", (0.0, 0.0))
    out = []
    for d in wanted:
        i = DIRECTIONS.index(d)
        h = H[:, i, i]
        if not np.any(h != 0):
            raise MeasurementInputError(f"{frf.source or 'the FRF'}: the direct term {d}{d} is zero")
        coh = None if coherence is None else np.asarray(coherence)[:, i, i]
        if coh is not None and not np.any(np.isfinite(coh)):
            coh = None
        f = np.asarray(frf.frequency_hz, float)
        usable = _band(f, None, d) if coh is None else coherent_band(f, coh)
        if usable is None:
            raise MeasurementInputError(f"direction {d}: the coherence never reaches {COHERENCE_LEVEL} (a running "
                                        f"median over {COHERENCE_WINDOW} samples): no usable band")
        band = _band(f, usable if band_hz is None else band_hz, d)
        notes = [f"band {band[0]:g}-{band[1]:g} Hz: where the coherence (running median over {COHERENCE_WINDOW} "
                 f"samples) is at least {COHERENCE_LEVEL}"] if band_hz is None and coh is not None else []
        # LSCF sees the usable data (the coherent band, else the file) from the band's low edge, or lower down to
        # the usable band's with a coherence, to the usable band's end
        fit = (min(band[0], usable[0]) if coh is not None else band[0], max(band[1], usable[1]))
        out.append(_direction(f, h, coh, d, band, fit, max_order, criteria, min_peak_share, float(decay[i]), notes))
    return ModalIdentification(tuple(out), frf.source, criteria, max_order, min_peak_share,
                               f"sdypy-EMA {ema.ema_version()}")


# ----------------------------------------------------------------------------------------------
# one direction


def _direction(f, h, coh, d, band, fit_hz, max_order, c, min_peak_share, decay, notes) -> DirectionIdentification:
    f, h, coh, note = uniform_grid(f, h, coh, fit_hz)
    if note:
        notes.append(note)
        log.info("direction %s: %s", d, note)
    in_band = (f >= band[0]) & (f <= band[1])
    if np.count_nonzero(in_band) < max(MIN_SAMPLES, max_order):
        raise MeasurementInputError(f"direction {d}: {np.count_nonzero(in_band)} samples in the band "
                                    f"{band[0]:g}-{band[1]:g} Hz; at least {max(MIN_SAMPLES, max_order)} are needed")
    lscf = ema.lscf_poles(f, h, fit_hz, max_order)
    cands, status, match = [], [], []
    for o, poles in enumerate(lscf.poles):
        cur = candidates(lscf.orders[o], poles, band, c.max_damping)
        if len(cur.index):
            fit = ema.lsfd(lscf, [(o, int(k)) for k in cur.index], band)
            cur.residue[:] = fit.residues
        s, m = classify(cur, cands[-1] if cands else None, c)
        cands.append(cur)
        status.append(s)
        match.append(m)
    diagram = _diagram(cands, status)
    chosen = modes_from_tracks(tracks(cands, status, match), len(cands), c)
    if not chosen:
        raise IdentificationError(f"direction {d}: no pole is stable through {c.min_stable} model orders in "
                                  f"{band[0]:g}-{band[1]:g} Hz (orders 2 to {2 * max_order}); a band starting lower "
                                  "(LSCF fits from its low edge) or another --max-order may help")
    picked = [(o, int(cands[o].index[i])) for o, i in (t.representative for t in chosen)]
    peak = float(np.max(np.abs(h[in_band])))
    # one LSFD with every chosen pole: a computational one stays in the fit (it models what is in the data, so the
    # others' residues are not bent to absorb it) but is not a mode
    fit = ema.lsfd(lscf, picked, band)
    modes, discarded = [], []
    for k, ((o, p), t) in enumerate(zip(picked, chosen)):
        lam = lscf.poles[o][p] + decay
        mode = _modal_form(d, lam, fit.residues[k], t.stable, lscf.orders[o], f, coh)
        reason = _computational(mode, peak, min_peak_share)
        if reason:
            discarded.append(DiscardedMode(d, mode.frequency_hz, mode.damping_ratio, mode.stiffness_N_m, reason))
        else:
            modes.append(mode)
    if not modes:
        raise IdentificationError(f"direction {d}: every stable pole in {band[0]:g}-{band[1]:g} Hz is computational ("
                                  + "; ".join(f"{m.frequency_hz:.1f} Hz: {m.reason}" for m in discarded) + ")")
    for m in discarded:
        log.info("direction %s: %.1f Hz left out: %s", d, m.frequency_hz, m.reason)
    fb, hb = f[in_band], h[in_band]
    fitted = np.interp(fb, fit.frequency_hz, fit.reconstructed.real) + 1j * np.interp(
        fb, fit.frequency_hz, fit.reconstructed.imag)
    if decay:
        notes.append(f"exponential window of the measurement (decay {decay:.4g} 1/s) taken off every pole: the "
                     "damping ratios are the structure's; the fitted curves and errors are with the window, as "
                     "measured")
    modal = modal_receptance(modes, fb, decay)
    return DirectionIdentification(
        d, band, fb, hb, fitted, modal, None if coh is None else coh[in_band], tuple(modes), tuple(discarded),
        fit.lower_residual, fit.upper_residual, _relative_rms(fitted, hb), _relative_rms(modal, hb), diagram, decay,
        tuple(notes))


def modal_receptance(modes, frequency_hz: np.ndarray, decay_1_s: float = 0.0) -> np.ndarray:
    """The sum of ``modes`` in the modal form at ``frequency_hz``; with ``decay_1_s``, as an exponential window of
    that decay shows them (every pole moved by -decay, the residues kept): comparable with the measurement."""
    f = np.asarray(frequency_hz, float)
    jw = 2j * np.pi * f
    out = np.zeros(len(f), complex)
    for m in modes:
        wn = 2 * np.pi * m.frequency_hz
        lam = complex(-m.damping_ratio * wn, wn * np.sqrt(1 - m.damping_ratio**2)) - decay_1_s
        out += (wn**2 / m.stiffness_N_m) / ((jw - lam) * (jw - lam.conjugate()))
    return out


def _band(f: np.ndarray, band_hz, d: str) -> tuple[float, float]:
    positive = f[f > 0]
    if len(positive) < 2:
        raise MeasurementInputError(f"direction {d}: fewer than two frequencies above 0 Hz")
    lo, hi = float(positive[0]), float(positive[-1])
    if band_hz is None:
        return lo, hi
    b0, b1 = float(band_hz[0]), float(band_hz[1])
    if not (0 <= b0 < b1):
        raise MeasurementInputError(f"band {b0:g}:{b1:g} Hz: needs 0 <= low < high")
    if b1 <= lo or b0 >= hi:
        raise MeasurementInputError(f"band {b0:g}:{b1:g} Hz is outside the measured {lo:g}-{hi:g} Hz")
    return max(b0, lo), min(b1, hi)


def uniform_grid(f, h, coh, band) -> tuple[np.ndarray, np.ndarray, np.ndarray | None, str]:
    """The samples up to ``band``'s end on a grid k df (what LSCF needs), interpolated when they are not on
    one already; the note says so."""
    keep = (f > 0) & (f <= band[1])
    f, h = f[keep], h[keep]
    coh = None if coh is None else coh[keep]
    steps = np.diff(f)
    df = float(np.median(steps))
    on_grid = np.allclose(steps, df, rtol=1e-6, atol=0) and abs(f[0] / df - round(f[0] / df)) < 1e-6
    if on_grid:
        return f, h, coh, ""
    sel = f >= band[0]
    df = float(np.median(np.diff(f[sel]))) if np.count_nonzero(sel) > 2 else df
    df = max(df, (band[1] - band[0]) / MAX_SAMPLES)
    g = np.arange(np.ceil(f[0] / df), np.floor(band[1] / df) + 1) * df
    g = g[(g >= f[0]) & (g <= f[-1])]
    hi = np.interp(g, f, h.real) + 1j * np.interp(g, f, h.imag)
    ci = None if coh is None else np.interp(g, f, coh)
    return g, hi, ci, (f"the frequencies are not equally spaced on multiples of their step: interpolated onto "
                       f"{len(g)} samples every {df:.4g} Hz (LSCF needs such a grid)")


def _modal_form(d, lam, A, stable, order, f, coh) -> IdentifiedMode:
    wn = abs(lam)
    zeta = -lam.real / wn
    wd = abs(lam.imag)
    one_over_m = 2.0 * wd * (-A.imag)  # the residue's component along -j, the direction of a real mode's
    k = wn**2 / one_over_m if one_over_m else np.inf
    fn = wn / (2 * np.pi)
    c = float("nan") if coh is None else float(np.interp(fn, f, coh))
    return IdentifiedMode(d, float(fn), float(zeta), float(k), complex(A), float(np.degrees(np.angle(A * 1j))),
                          int(stable), int(order), c)


def _computational(m: IdentifiedMode, peak: float, share: float) -> str:
    if m.damping_ratio <= 0:
        return f"negative damping (zeta {m.damping_ratio:.3g}): an unstable pole, not a structural mode"
    if not np.isfinite(m.stiffness_N_m) or m.stiffness_N_m <= 0:
        return ("residue of the wrong sign for a direct FRF (negative modal stiffness "
                f"{m.stiffness_N_m:.3g} N/m, residue phase {m.complexity_deg:+.0f} deg from -90)")
    if m.peak_m_N < share * peak:
        return (f"tiny residue: its peak 1/(2 zeta k) = {m.peak_m_N:.3g} m/N is {100 * m.peak_m_N / peak:.2g} % of the "
                f"largest |H| in the band (under {100 * share:g} %)")
    return ""


def _diagram(cands, status) -> StabilisationDiagram:
    width = max((len(c.index) for c in cands), default=0)
    n = len(cands)
    F = np.full((n, width), np.nan)
    Z = np.full((n, width), np.nan)
    S = np.full((n, width), -1, dtype=np.int8)
    for o, (c, s) in enumerate(zip(cands, status)):
        F[o, :len(c.index)] = c.frequency_hz
        Z[o, :len(c.index)] = c.damping_ratio
        S[o, :len(c.index)] = s
    return StabilisationDiagram(np.array([c.order for c in cands]), F, Z, S)


def _relative_rms(model: np.ndarray, measured: np.ndarray) -> float:
    return float(np.sqrt(np.sum(np.abs(model - measured) ** 2) / np.sum(np.abs(measured) ** 2)))
