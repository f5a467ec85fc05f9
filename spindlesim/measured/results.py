"""Results of the measured-data analyses: frozen dataclasses of SI values, nothing cached on models.

* :class:`ModalIdentification` (``identify_modes``): per direction the kept modes in the chatter section's
  modal form, the computational modes left out and why, the stabilisation diagram, the measured, fitted
  and modal receptances and the fit errors.
* :class:`ImpactFrf` (``frf_from_impacts``): the H1 receptance and its coherence from the accepted
  impacts, every impact's verdict, the windows used.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .stabilisation import StabilityCriteria

__all__ = ["IdentifiedMode", "DiscardedMode", "StabilisationDiagram", "DirectionIdentification",
           "ModalIdentification", "ImpactRecord", "ImpactVerdict", "ImpactFrf"]


@dataclass(frozen=True)
class IdentifiedMode:
    """One mode in the chatter section's modal form, H = 1 / (k (1 - r^2 + 2 j zeta r)), r = f / f_n."""

    direction: str
    frequency_hz: float  # undamped natural frequency |lambda| / 2 pi
    damping_ratio: float
    stiffness_N_m: float  # modal stiffness k = w_n^2 m, 1 / m = -2 w_d Im A
    residue: complex  # LSFD residue A of the pole [m/N rad/s]: H = A / (j w - lambda) + conj
    complexity_deg: float  # angle of A from -90 deg (0: a real, proportionally damped mode)
    stable_orders: int  # stable poles in its track of the stabilisation diagram
    order: int  # model order of the chosen pole
    coherence: float = float("nan")  # measured coherence at f_n (NaN: the file has none)

    @property
    def peak_m_N(self) -> float:
        """The mode's own peak compliance 1 / (2 zeta k)."""
        return 1.0 / (2.0 * self.damping_ratio * self.stiffness_N_m)

    def receptance(self, frequency_hz: np.ndarray) -> np.ndarray:
        r = np.asarray(frequency_hz, float) / self.frequency_hz
        return 1.0 / (self.stiffness_N_m * (1.0 - r**2 + 2j * self.damping_ratio * r))


@dataclass(frozen=True)
class DiscardedMode:
    """A stable pole of the diagram left out of the modes, and why (a computational mode)."""

    direction: str
    frequency_hz: float
    damping_ratio: float
    stiffness_N_m: float  # may be negative (residue of the wrong sign)
    reason: str


@dataclass(frozen=True, eq=False)
class StabilisationDiagram:
    """The candidate poles of every model order: ``orders[o]``; frequency [Hz], damping ratio and status
    (stabilisation.NEW .. STABLE) of its poles ``[o, p]``, NaN / -1 past the order's last candidate."""

    orders: np.ndarray
    frequency_hz: np.ndarray
    damping_ratio: np.ndarray
    status: np.ndarray


@dataclass(frozen=True, eq=False)
class DirectionIdentification:
    """The identification of one direct FRF (direction x or y) over its band."""

    direction: str
    band_hz: tuple[float, float]
    frequency_hz: np.ndarray  # the samples fitted (a uniform grid)
    measured_m_N: np.ndarray
    fitted_m_N: np.ndarray  # every chosen pole (computational ones too) with its residue, both residuals (LSFD)
    modal_m_N: np.ndarray  # kept modes in the modal form alone (what `chatter.frf: {modes: ...}` gets), with the
    #: measurement's exponential window when it had one (comparable with measured_m_N)
    coherence: np.ndarray | None
    modes: tuple[IdentifiedMode, ...]
    discarded: tuple[DiscardedMode, ...]
    lower_residual: complex  # - lower / w^2 [m/N (rad/s)^2]
    upper_residual: complex  # + upper [m/N]
    fit_error: float  # relative RMS of (fitted - measured) over the band
    modal_fit_error: float  # relative RMS of (modal - measured) over the band
    diagram: StabilisationDiagram
    window_decay_1_s: float = 0.0  # exponential window of the measurement, taken off every pole
    notes: tuple[str, ...] = ()


@dataclass(frozen=True, eq=False)
class ModalIdentification:
    """Modes identified from a measured FRF, direction by direction (``identify_modes``)."""

    directions: tuple[DirectionIdentification, ...]
    source: str
    criteria: StabilityCriteria
    max_order: int
    min_peak_share: float
    library: str  # e.g. "sdypy-EMA 0.31.0"

    @property
    def modes(self) -> tuple[IdentifiedMode, ...]:
        return tuple(m for d in self.directions for m in d.modes)

    @property
    def discarded(self) -> tuple[DiscardedMode, ...]:
        return tuple(m for d in self.directions for m in d.discarded)

    def direction(self, name: str) -> DirectionIdentification:
        for d in self.directions:
            if d.direction == name:
                return d
        raise KeyError(name)


@dataclass(frozen=True, eq=False)
class ImpactRecord:
    """One impact: force [N] and response (``kind``: acceleration [m/s^2], velocity [m/s] or displacement
    [m]) sampled every ``dt_s`` from ``start_s``; ``where``: its file and line, for messages."""

    force_N: np.ndarray
    response: np.ndarray
    kind: str
    dt_s: float
    where: str
    start_s: float = 0.0
    direction: str | None = None  # from the file (UFF response direction), None: not stated

    @property
    def time_s(self) -> np.ndarray:
        return self.start_s + self.dt_s * np.arange(len(self.force_N))


@dataclass(frozen=True)
class ImpactVerdict:
    """Whether an impact was averaged, and why not: double hit, force or response overload."""

    where: str
    used: bool
    reasons: tuple[str, ...] = ()
    peak_force_N: float = float("nan")


@dataclass(frozen=True, eq=False)
class ImpactFrf:
    """The receptance of a tap test from its impacts (H1 over the accepted ones) and its coherence."""

    direction: str
    frequency_hz: np.ndarray
    receptance_m_N: np.ndarray
    coherence: np.ndarray
    verdicts: tuple[ImpactVerdict, ...]
    kind: str  # the response measured: acceleration, velocity or displacement
    dt_s: float
    samples: int
    force_window_s: float  # the force is kept from the record's start to this time (then a cosine taper)
    window_decay_1_s: float  # exponential window e^(-decay t) on both channels (0: none)
    tail_share: float  # response level over the records' last 5 % against its peak (leakage), before windows
    records: tuple[ImpactRecord, ...] = field(default=(), repr=False)
    library: str = ""
    notes: tuple[str, ...] = ()

    @property
    def used(self) -> int:
        return sum(v.used for v in self.verdicts)

    @property
    def rejected(self) -> tuple[ImpactVerdict, ...]:
        return tuple(v for v in self.verdicts if not v.used)

    def coherence_at(self, frequency_hz: float) -> float:
        k = int(np.argmin(np.abs(self.frequency_hz - frequency_hz)))
        return float(self.coherence[k])

    def peaks_hz(self, count: int = 6, prominence: float = 0.05) -> np.ndarray:
        """The resonances: the frequencies of the ``count`` most prominent peaks of |H| (averaged over 5 samples,
        so that noise makes none; prominence at least ``prominence`` of the largest) within the coherent band
        (:func:`~.bands.coherent_band`), ascending."""
        from scipy.signal import find_peaks

        from .bands import coherent_band

        band = coherent_band(self.frequency_hz, self.coherence) or (self.frequency_hz[0], self.frequency_hz[-1])
        inside = np.flatnonzero((self.frequency_hz >= band[0]) & (self.frequency_hz <= band[1]))
        if len(inside) < 5:
            return np.zeros(0)
        mag = np.convolve(np.abs(self.receptance_m_N[inside]), np.ones(5) / 5, mode="same")
        peaks, props = find_peaks(mag, prominence=prominence * mag.max())
        top = peaks[np.argsort(props["prominences"])[::-1][:count]]
        return np.sort(self.frequency_hz[inside][top])
