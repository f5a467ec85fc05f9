"""Frozen results of the chatter analyses (SI: m, Hz, rpm for spindle speeds)."""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

__all__ = ["LobeCurve", "StabilityMap", "LobeDiagram", "SimulationResult", "lobe_diagram_from_lobes",
           "STABLE_GROWTH", "DECAYED", "DIED_OUT", "speed_runs"]

#: Poincare criterion of the time-domain simulation: stable when the fitted growth per tooth period is
#: below STABLE_GROWTH and the last distance below DECAYED of the largest, or below DIED_OUT of it
STABLE_GROWTH, DECAYED, DIED_OUT = 0.999, 0.1, 1e-6


#: limit depths this close to the smallest are a tie for :attr:`LobeDiagram.minimum`: the semi-discretization's
#: depth search (``rtol``) knows them to 1e-4, so which of two such speeds is lower is not known
MINIMUM_TIE_RTOL = 1e-4

@dataclass(frozen=True, eq=False)
class LobeCurve:
    """One stability lobe: ``lobe`` = number of whole chatter waves per tooth period.

    ``kind`` is ``hopf`` (secondary Hopf, complex critical multiplier) or ``flip`` (period
    doubling, multiplier -1).  NaN where the lobe has no boundary point at that speed.
    """

    lobe: int
    speed_rpm: np.ndarray
    limit_depth_m: np.ndarray
    chatter_frequency_hz: np.ndarray
    kind: str = "hopf"


@dataclass(frozen=True, eq=False)
class StabilityMap:
    """Spectral radius of the monodromy matrix over a speed x depth grid (< 1 stable)."""

    speed_rpm: np.ndarray  # [s]
    depth_m: np.ndarray  # [d]
    spectral_radius: np.ndarray  # [s, d]
    steps_per_period: np.ndarray  # [s] semi-discretization steps per tooth period
    order: int


@dataclass(frozen=True, eq=False)
class LobeDiagram:
    """Limit depth of cut against spindle speed.

    ``limit_depth_m`` is the lower envelope over the lobes (NaN: no instability found, e.g.
    above the SD map's depth range), ``chatter_frequency_hz`` the frequency of the critical
    lobe, ``boundary_kind`` its kind (``hopf``/``flip``/``""``).  ``stability_map`` is set by
    the semi-discretization.  ``method_per_speed`` names the method that produced each speed's
    limit, ``capped`` marks the speeds found stable up to ``depth_cap_m`` (the largest depth
    searched; their limit is NaN and at least the cap), ``selection`` says which method ran and why.
    """

    speed_rpm: np.ndarray
    limit_depth_m: np.ndarray
    chatter_frequency_hz: np.ndarray
    lobes: tuple[LobeCurve, ...]
    method: str
    process: str
    boundary_kind: np.ndarray = field(default_factory=lambda: np.array([], dtype="<U4"))
    stability_map: StabilityMap | None = None
    frf_at_each_speed: bool = False
    notes: tuple[str, ...] = ()
    method_per_speed: np.ndarray = field(default_factory=lambda: np.array([], dtype=object))
    capped: np.ndarray = field(default_factory=lambda: np.array([], dtype=bool))
    depth_cap_m: float = float("nan")
    selection: str = ""
    #: semi-discretization steps per tooth period at each speed (0: another method)
    steps_per_period: np.ndarray = field(default_factory=lambda: np.array([], dtype=int))

    def __post_init__(self) -> None:
        S = len(self.speed_rpm)
        if len(self.method_per_speed) != S:
            object.__setattr__(self, "method_per_speed", np.full(S, self.method, dtype=object))
        if len(self.capped) != S:
            object.__setattr__(self, "capped", np.zeros(S, bool))
        if len(self.steps_per_period) != S:
            object.__setattr__(self, "steps_per_period", np.zeros(S, int))

    def limit_at(self, speed_rpm: float | np.ndarray) -> np.ndarray:
        """Limit depth interpolated linearly between the computed speeds."""
        return np.interp(speed_rpm, self.speed_rpm, self.limit_depth_m)

    def is_stable(self, speed_rpm: float, depth_m: float) -> bool:
        lim = float(self.limit_at(speed_rpm))
        return bool(np.isnan(lim) or depth_m < lim)

    def merged(self, other: "LobeDiagram", note: str = "") -> "LobeDiagram":
        """This diagram with ``other``'s speeds added (sorted by speed; the stability map stays this
        diagram's; the depth cap is the smaller of the two, so that a capped speed of either is at least
        it); ``note`` is appended to the notes."""
        speeds = np.concatenate([self.speed_rpm, other.speed_rpm])
        order = np.argsort(speeds, kind="stable")
        n_a = len(self.speed_rpm)

        def cat(a, b, fill=None, dtype=None):
            a = np.asarray(a) if a is not None else np.full(n_a, fill, dtype)
            b = np.asarray(b) if b is not None else np.full(len(other.speed_rpm), fill, dtype)
            return np.concatenate([a.astype(dtype) if dtype else a, b.astype(dtype) if dtype else b])[order]

        curves = {}
        for side, dg in ((0, self), (1, other)):
            for c in dg.lobes:
                curves.setdefault((c.kind, c.lobe), [None, None])[side] = c
        lobes = []
        for (kind, lobe), (a, b) in sorted(curves.items(), key=lambda kv: (kv[0][0], -kv[0][1])):
            lim = cat(a.limit_depth_m if a else None, b.limit_depth_m if b else None, np.nan, float)
            frq = cat(a.chatter_frequency_hz if a else None, b.chatter_frequency_hz if b else None, np.nan, float)
            lobes.append(LobeCurve(lobe, speeds[order], lim, frq, kind))
        return replace(self, speed_rpm=speeds[order],
                       limit_depth_m=cat(self.limit_depth_m, other.limit_depth_m, dtype=float),
                       chatter_frequency_hz=cat(self.chatter_frequency_hz, other.chatter_frequency_hz, dtype=float),
                       lobes=tuple(lobes),
                       boundary_kind=cat(self.boundary_kind if len(self.boundary_kind) == n_a else None,
                                         other.boundary_kind if len(other.boundary_kind) == len(other.speed_rpm)
                                         else None, "", "<U4"),
                       method_per_speed=cat(self.method_per_speed, other.method_per_speed, dtype=object),
                       capped=cat(self.capped, other.capped, dtype=bool),
                       steps_per_period=cat(self.steps_per_period, other.steps_per_period, dtype=int),
                       depth_cap_m=float(np.nanmin([self.depth_cap_m, other.depth_cap_m]))
                       if np.isfinite([self.depth_cap_m, other.depth_cap_m]).any() else float("nan"),
                       notes=self.notes + ((note,) if note else ()))

    @property
    def minimum(self) -> tuple[float, float]:
        """(speed [rpm], depth [m]) of the smallest limit depth over the speed range; limits within
        ``MINIMUM_TIE_RTOL`` of it are a tie, and the lowest of their speeds is reported (the milling deck's
        23,910 and 24,000 rpm straddle the bottom of a lobe and agree to 1e-5: which one is reported must not
        hang on the depth search's last step)."""
        d = np.asarray(self.limit_depth_m, float)
        lo = float(np.nanmin(d))
        ties = np.flatnonzero(d <= lo * (1.0 + MINIMUM_TIE_RTOL))
        k = int(ties[np.argmin(np.asarray(self.speed_rpm, float)[ties])])
        return float(self.speed_rpm[k]), float(d[k])


@dataclass(frozen=True, eq=False)
class SimulationResult:
    """Time-domain simulation at one speed and depth.

    ``stable`` follows the Poincare criterion of :mod:`spindlesim.chatter.simulation`:
    ``growth_per_period`` is the fitted ratio of successive Poincare distances (comparable to the
    monodromy's spectral radius while the motion is linear), ``decay_ratio`` the last Poincare
    distance over the largest one.
    """

    speed_rpm: float
    depth_m: float
    time_s: np.ndarray  # [k]
    displacement_m: np.ndarray  # [k, 2]
    force_N: np.ndarray  # [k, 2]
    poincare_m: np.ndarray  # [p, 2] displacement once per tooth period
    poincare_velocity_m_s: np.ndarray  # [p, 2]
    spectrum_frequency_hz: np.ndarray
    spectrum_amplitude_m: np.ndarray  # [f] amplitude of |(x, y)|
    tooth_frequency_hz: float
    chatter_frequency_hz: float  # NaN when stable
    stable: bool
    growth_per_period: float
    decay_ratio: float
    out_of_cut_fraction: float  # share of engaged edge-steps (static chip >= 10 % of max) out of cut, last half
    steps_per_period: int
    fft_bin_hz: float

    @property
    def verdict(self) -> str:
        """The verdict and the numbers it rests on (the Poincare criterion), in words."""
        g, d = self.growth_per_period, self.decay_ratio
        if self.stable:
            if d < DIED_OUT:
                return f"stable: the vibration died out (last Poincare distance {d:.1e} of the largest)"
            return (f"stable: decaying by {g:.4f} per tooth period (< {STABLE_GROWTH}), last Poincare distance "
                    f"{d:.2g} of the largest (< {DECAYED})")
        if d >= DECAYED:
            why = (f"not decaying: last Poincare distance {d:.2g} of the largest (stable needs < {DECAYED}), "
                   f"fitted growth {g:.4f} per tooth period")
        else:
            why = (f"the late vibration does not decay: growth {g:.4f} per tooth period (stable needs "
                   f"< {STABLE_GROWTH}) after falling to {d:.2g} of the largest")
        if self.out_of_cut_fraction > 0.05:
            why += f"; tool out of the cut {100 * self.out_of_cut_fraction:.0f} % of the time"
        return f"chatter: {why}"


def lobe_diagram_from_lobes(speed_rpm: np.ndarray, depth: np.ndarray, freq: np.ndarray, lobe_numbers,
                            method: str, process: str, frf_at_each_speed: bool,
                            notes: tuple[str, ...] = ()) -> LobeDiagram:
    """Envelope over per-lobe limits ``depth[k, s]`` (inf/NaN where a lobe has no point)."""
    speed_rpm = np.asarray(speed_rpm, float)
    depth = np.where(np.isfinite(depth), depth, np.nan)
    lobes = tuple(LobeCurve(int(k), speed_rpm, depth[i], freq[i]) for i, k in enumerate(lobe_numbers)
                  if np.any(np.isfinite(depth[i])))
    if depth.shape[0] == 0 or np.all(np.isnan(depth)):
        env = np.full(len(speed_rpm), np.nan)
        fc = np.full(len(speed_rpm), np.nan)
    else:
        filled = np.where(np.isnan(depth), np.inf, depth)
        kmin = np.argmin(filled, axis=0)
        cols = np.arange(len(speed_rpm))
        env = filled[kmin, cols]
        fc = freq[kmin, cols]
        none = ~np.isfinite(env)
        env[none], fc[none] = np.nan, np.nan
    kind = np.where(np.isnan(env), "", "hopf")
    return LobeDiagram(speed_rpm, env, fc, lobes, method, process, kind, None, frf_at_each_speed, notes)


def speed_runs(speeds: np.ndarray) -> str:
    """Speeds as runs of neighbouring grid speeds, '5,000-6,500, 9,000 rpm' (text for notes and files)."""
    speeds = np.asarray(speeds, float)
    if not len(speeds):
        return ""
    step = float(np.min(np.diff(speeds))) if len(speeds) > 1 else 0.0
    parts, start, prev = [], speeds[0], speeds[0]
    for s in list(speeds[1:]) + [None]:
        if s is not None and step > 0 and s - prev <= 1.5 * step:
            prev = s
            continue
        parts.append(f"{start:,.0f}" if start == prev else f"{start:,.0f}-{prev:,.0f}")
        if s is not None:
            start = prev = s
    return ", ".join(parts) + " rpm"
