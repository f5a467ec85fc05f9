"""Cutting processes in SI: the regenerative force model each stability method works from.

Every process gives, in the tool-point frame of :mod:`spindlesim.chatter.frf`:

* ``tooth_period_s(speed)``: the regenerative delay tau (one tooth period; one revolution in
  turning, boring and grinding);
* ``mean_directional()``: the time-averaged cutting-force matrix per unit depth K0 [N/m^2] of
  the linearised dynamic force F = a K(t) (r(t) - r(t - tau)), r the tool-tip displacement;
* ``directional_steps(steps, depth)``: K(t) (depth included, [N/m]) averaged over each of
  ``steps`` equal intervals of one tooth period (semi-discretization);
* ``cutting_tables(steps, depth)``: per time step and cutting-edge slot the chip-thickness
  direction, the force per unit chip area, the static chip and the engagement weight
  (time-domain simulation, with the tool leaving the cut).

Turning, boring, grinding (one edge, full overlap): the tool feeds along the unit vector
``f = (cos t, sin t)``, t = ``feed_direction_rad``, so a tool-tip displacement along ``f``
thickens the chip: h = h0 + f . (r(t) - r(t - tau)).  The cutting force on the workpiece acts
along ``g``, ``f`` rotated by the force angle beta (counter-clockwise from +x towards +y); the
tool is pushed along ``-g`` with magnitude Ks b h.  Hence K = -Ks g f^T and the oriented FRF is
f^T H g = sum over modes of cos(alpha) cos(beta - alpha) / ... (Schmitz and Smith, Machining
Dynamics, ch. 4, directional orientation factors).  In grinding the delay is the workpiece
revolution: give the workpiece speed.

Milling (Altintas and Budak 1995): x is the feed direction and y the normal direction of their
frame, rotated by ``feed_direction_rad`` in the tool-point frame; the cutter turns from +y
towards +x and the immersion angle phi of each tooth is measured from +y in that sense.  Up
milling cuts from phi = 0 to arccos(1 - 2 ae/D), down milling from arccos(2 ae/D - 1) to pi.
Chip h_j = (fz sin phi_j + sin phi_j dx + cos phi_j dy) g(phi_j); tangential force Kt a h,
radial Kr Kt a h; F_x = -Ft cos phi - Fr sin phi, F_y = Ft sin phi - Fr cos phi on the tool.
A helix (lag angle 2 z tan(helix) / D at height z) is taken by axial slices in the
semi-discretization and the simulation; the zero-order average does not depend on it.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass, replace
from typing import Literal

import numpy as np

__all__ = ["TurningProcess", "MillingProcess", "CuttingTables", "Process", "METHOD_NAMES", "ZERO_ORDER_FLUCTUATION"]

METHOD_NAMES = ("oriented_frf", "zero_order", "semi_discretization")
#: how the methods are named in text
METHOD_TITLES = {"oriented_frf": "oriented FRF (Tlusty)", "zero_order": "zero order (Altintas-Budak)",
                 "semi_discretization": "semi-discretization (Insperger-Stepan)"}

#: ``auto`` trusts the zero-order average only where the directional matrix is constant over the tooth
#: period to this fraction of its mean (docs/theory.md, "Which method: auto"; docs/validation.md)
ZERO_ORDER_FLUCTUATION = 0.01


def _rotation(theta: float) -> np.ndarray:
    c, s = np.cos(theta), np.sin(theta)
    return np.array([[c, -s], [s, c]])


@dataclass(frozen=True, eq=False)
class CuttingTables:
    """Force model sampled at ``steps`` instants of one tooth period for every edge slot ``s``.

    F(t_k) = a sum_s w[k, s] max(0, h0[k, s] + e[k, s] . r(t_k) - surface) force[k, s],
    the surface being the one left by the previous pass over bin ``bin[k, s]``.
    """

    e: np.ndarray  # [steps, S, 2] chip-thickness direction (tool frame)
    force: np.ndarray  # [steps, S, 2] force on the tool per unit chip area [N/m^2]
    h0: np.ndarray  # [steps, S] static chip thickness [m]
    w: np.ndarray  # [steps, S] engagement weight (fraction of the depth, 0 = out of cut)
    bin: np.ndarray  # [steps, S] surface bin (angle x axial slice)
    nbins: int


class _Base:
    operation: str
    feed_direction_rad: float
    default_method: str
    methods: tuple[str, ...]
    periods_per_rev: int

    def tooth_period_s(self, speed_rpm):
        return 60.0 / (self.periods_per_rev * np.asarray(speed_rpm, float))

    def speed_rpm(self, tooth_period_s):
        return 60.0 / (self.periods_per_rev * np.asarray(tooth_period_s, float))

    def method_for(self, requested: str = "auto") -> str:
        """The stability method to run: ``auto`` resolves to the process's choice."""
        if requested == "auto":
            return self.auto_method()
        if requested not in self.methods:
            raise ValueError(f"method {requested!r} does not apply to {self.operation}; "
                             f"choose from {', '.join(self.methods)} or auto")
        return requested

    def auto_method(self) -> str:
        return self.default_method

    @property
    def cut_fraction(self) -> float:
        """Share of the tooth period during which some edge cuts (1: a continuous cut)."""
        return 1.0

    def method_note(self, requested: str = "auto") -> str:
        """Which method runs and why, in words (the summary and chatter.h5 say it)."""
        m = METHOD_TITLES[self.method_for(requested)]
        if requested != "auto":
            return f"{m}, as requested" + self._requested_caveat(requested)
        return f"auto: {m}; {self._auto_reason()}"

    def _requested_caveat(self, requested: str) -> str:
        return ""

    def _auto_reason(self) -> str:
        return "one edge in a continuous cut, where Tlusty's oriented-FRF solution is exact"


@dataclass(frozen=True)
class TurningProcess(_Base):
    """Turning, boring or grinding: Ks [N/m^2], force angle beta [rad] from the feed direction."""

    Ks_N_m2: float
    force_angle_rad: float
    feed_direction_rad: float = 0.0
    operation: Literal["turning", "boring", "grinding"] = "turning"
    feed_per_rev_m: float = 1e-4

    periods_per_rev = 1
    default_method = "oriented_frf"
    methods = ("oriented_frf", "semi_discretization")

    def __post_init__(self) -> None:
        if not self.Ks_N_m2 > 0:
            raise ValueError("Ks must be positive")
        if not abs(self.force_angle_rad) < np.pi / 2:
            raise ValueError("the force angle must be within (-90, 90) degrees of the feed direction")

    @property
    def feed_vector(self) -> np.ndarray:
        return np.array([np.cos(self.feed_direction_rad), np.sin(self.feed_direction_rad)])

    @property
    def force_vector(self) -> np.ndarray:
        """Direction of the cutting force on the workpiece (the tool is pushed along minus this)."""
        t = self.feed_direction_rad + self.force_angle_rad
        return np.array([np.cos(t), np.sin(t)])

    def mean_directional(self) -> np.ndarray:
        return -self.Ks_N_m2 * np.outer(self.force_vector, self.feed_vector)

    def directional_steps(self, steps: int, depth_m: float) -> np.ndarray:
        return np.broadcast_to(depth_m * self.mean_directional(), (steps, 2, 2)).copy()

    def cutting_tables(self, steps: int, depth_m: float) -> CuttingTables:
        e = np.broadcast_to(self.feed_vector, (steps, 1, 2)).copy()
        f = np.broadcast_to(-self.Ks_N_m2 * self.force_vector, (steps, 1, 2)).copy()
        return CuttingTables(e, f, np.full((steps, 1), self.feed_per_rev_m), np.ones((steps, 1)),
                             np.arange(steps).reshape(steps, 1), steps)

    def describe(self) -> str:
        return (f"{self.operation}: Ks = {self.Ks_N_m2 / 1e6:g} N/mm2, force angle "
                f"{np.rad2deg(self.force_angle_rad):g} deg, feed direction "
                f"{np.rad2deg(self.feed_direction_rad):g} deg")


def _antiderivative(phi: np.ndarray, Kr: float) -> np.ndarray:
    """Integral of the directional matrix M(phi) = f(phi) e(phi)^T (per unit Kt) [..., 2, 2]."""
    s2, c2 = np.sin(2 * phi), np.cos(2 * phi)
    out = np.empty(np.shape(phi) + (2, 2))
    out[..., 0, 0] = c2 / 4 - Kr * phi / 2 + Kr * s2 / 4
    out[..., 0, 1] = -phi / 2 - s2 / 4 + Kr * c2 / 4
    out[..., 1, 0] = phi / 2 - s2 / 4 + Kr * c2 / 4
    out[..., 1, 1] = -c2 / 4 - Kr * phi / 2 - Kr * s2 / 4
    return out


@dataclass(frozen=True)
class MillingProcess(_Base):
    """Milling with a uniform-pitch cutter (no runout); Kt [N/m^2], Kr = Kn / Kt."""

    teeth: int
    tool_diameter_m: float
    radial_depth_m: float
    mode: Literal["up", "down"]
    Kt_N_m2: float
    Kr: float
    helix_rad: float = 0.0
    feed_per_tooth_m: float = 1e-4
    feed_direction_rad: float = 0.0
    axial_slices: int = 16

    operation = "milling"
    periods_per_rev = property(lambda self: self.teeth)
    default_method = "zero_order"
    methods = ("zero_order", "semi_discretization")

    def __post_init__(self) -> None:
        if self.teeth < 1:
            raise ValueError("a cutter needs at least one tooth")
        if not 0 < self.radial_depth_m <= self.tool_diameter_m:
            raise ValueError("the radial depth must be in (0, tool diameter]")
        if self.mode not in ("up", "down"):
            raise ValueError("mode must be 'up' or 'down'")
        if not self.Kt_N_m2 > 0 or self.Kr < 0:
            raise ValueError("Kt must be positive and Kr non-negative")
        if not 0 <= abs(self.helix_rad) < np.pi / 2:
            raise ValueError("the helix angle must be below 90 degrees")

    @property
    def immersion(self) -> float:
        return self.radial_depth_m / self.tool_diameter_m

    @property
    def entry_exit_rad(self) -> tuple[float, float]:
        r = self.immersion
        if self.mode == "up":
            return 0.0, float(np.arccos(1.0 - 2.0 * r))
        return float(np.arccos(2.0 * r - 1.0)), float(np.pi)

    @property
    def teeth_in_cut(self) -> float:
        """Mean number of teeth in the cut, N (exit - entry) / 2 pi."""
        st, ex = self.entry_exit_rad
        return self.teeth * (ex - st) / (2 * np.pi)

    @property
    def cut_fraction(self) -> float:
        """Share of the tooth period during which a tooth cuts: min(1, teeth in the cut)."""
        return min(1.0, self.teeth_in_cut)

    def directional_fluctuation(self, samples: int = 720) -> float:
        """max over the tooth period of |K(t) - K0| / |K0| (spectral norms; helix left out).

        Zero for a full slot with an even number of teeth of at least four (the teeth in the cut
        then cancel each other's harmonics, and entries coincide with exits), where the zero-order
        average is exact."""
        plain = replace(self, helix_rad=0.0) if self.helix_rad else self
        K = plain.directional_steps(samples, 1.0)
        K0 = plain.mean_directional()
        n0 = np.linalg.norm(K0, 2)
        if not n0 > 0:
            return float("inf")
        return float(np.max(np.linalg.norm(K - K0, 2, axis=(1, 2))) / n0)

    def auto_method(self) -> str:
        """Zero order only where it is exact: the directional matrix constant over the tooth period
        (to ZERO_ORDER_FLUCTUATION); semi-discretization everywhere else.  Measured against an
        independent semi-discretization (docs/validation.md, "Which method"): in down milling with a
        fluctuating matrix, down to 30 % of its mean (8 teeth, half immersion), the zero-order limit
        came out 8 % to 21 times too high at some speed; one tooth always in the cut (4 teeth, half
        immersion) +92 %."""
        return "zero_order" if self.directional_fluctuation() <= ZERO_ORDER_FLUCTUATION else "semi_discretization"

    def _requested_caveat(self, requested: str) -> str:
        if requested != "zero_order" or self.auto_method() == "zero_order":
            return ""
        return (f"; CAUTION: the directional matrix fluctuates by {100 * self.directional_fluctuation():.0f} % of its "
                "mean, and the zero-order limit can be far too high (docs/validation.md: up to +92 % with one tooth "
                "always in the cut); method auto runs the semi-discretization")

    def _auto_reason(self) -> str:
        fl = self.directional_fluctuation()
        n = self.teeth_in_cut
        where = (f"{n:.2g} {'tooth' if abs(n - 1) < 5e-3 else 'teeth'} in the cut on average, the directional "
                 f"matrix fluctuates by {100 * fl:.0f} % of its mean over the tooth period")
        if fl <= ZERO_ORDER_FLUCTUATION:
            return f"{where}: it is constant, and the zero-order average exact"
        return (f"{where}; the zero-order average is exact only for a constant matrix (a full slot with "
                "4, 6, ... teeth) and can be too high elsewhere")

    def _to_tool(self, K: np.ndarray) -> np.ndarray:
        R = _rotation(self.feed_direction_rad)
        return R @ K @ R.T

    def mean_directional(self) -> np.ndarray:
        """K0 = (N Kt / 2 pi) [int M dphi over the cut] = (N Kt / 4 pi) [alpha] of Altintas-Budak."""
        st, ex = self.entry_exit_rad
        I = _antiderivative(np.array([st, ex]), self.Kr)
        return self._to_tool(self.teeth * self.Kt_N_m2 / (2 * np.pi) * (I[1] - I[0]))

    def _slices(self, depth_m: float) -> np.ndarray:
        """Lag angle of each axial slice (one slice without helix)."""
        if self.helix_rad == 0.0:
            return np.zeros(1)
        L = self.axial_slices
        z = (np.arange(L) + 0.5) * depth_m / L
        return 2.0 * z * np.tan(self.helix_rad) / self.tool_diameter_m

    def directional_steps(self, steps: int, depth_m: float) -> np.ndarray:
        """K(t) averaged exactly over each step (integral of M over the engaged part of the arc)."""
        engaged, dphi = _engaged_arc(self, int(steps), float(depth_m) if self.helix_rad else 0.0)
        K = self.Kt_N_m2 * depth_m * engaged / dphi  # [steps, 2, 2]
        return self._to_tool(K)

    def cutting_tables(self, steps: int, depth_m: float) -> CuttingTables:
        N, st, ex = self.teeth, *self.entry_exit_rad
        dphi = 2 * np.pi / (N * steps)
        lag = self._slices(depth_m)
        L = len(lag)
        k = np.arange(steps)[:, None, None]
        j = np.arange(N)[None, :, None]
        phi = (k * dphi + 2 * np.pi * j / N - lag[None, None, :]) % (2 * np.pi)  # [steps, N, L]
        engaged = (phi >= st) & (phi <= ex)
        s, c = np.sin(phi), np.cos(phi)
        R = _rotation(self.feed_direction_rad)
        e = np.stack([s, c], axis=-1) @ R.T
        f = self.Kt_N_m2 * np.stack([-c - self.Kr * s, s - self.Kr * c], axis=-1) @ R.T
        h0 = self.feed_per_tooth_m * s
        w = np.where(engaged, 1.0 / L, 0.0)
        bins = (np.arange(L)[None, None, :] * N * steps + (k + j * steps) % (N * steps))
        S = N * L
        return CuttingTables(e.reshape(steps, S, 2), f.reshape(steps, S, 2), h0.reshape(steps, S),
                             w.reshape(steps, S), bins.reshape(steps, S).astype(np.int64), L * N * steps)

    def describe(self) -> str:
        return (f"{self.mode} milling, {self.teeth} teeth, D = {self.tool_diameter_m * 1e3:g} mm, "
                f"ae = {self.radial_depth_m * 1e3:g} mm ({100 * self.immersion:.3g} %), "
                f"Kt = {self.Kt_N_m2 / 1e6:g} N/mm2, Kr = {self.Kr:.3g}"
                + (f", helix {np.rad2deg(self.helix_rad):g} deg" if self.helix_rad else ""))


@functools.lru_cache(maxsize=256)
def _engaged_arc(process: MillingProcess, steps: int, depth_m: float) -> tuple[np.ndarray, float]:
    """(integral of M over the engaged part of each step's arc, summed over the teeth and averaged over the axial
    slices [steps, 2, 2] (read-only), the step's angle).  Depends on the depth only through a helix's slices (0.0
    without one): a depth search evaluates many depths at one step count, and this is the costly part of each."""
    N, st, ex = process.teeth, *process.entry_exit_rad
    dphi = 2 * np.pi / (N * steps)
    lag = process._slices(depth_m)
    u = (np.arange(steps)[:, None, None] * dphi + 2 * np.pi * np.arange(N)[None, :, None] / N
         - lag[None, None, :]) % (2 * np.pi)  # [steps, N, L]
    total = np.zeros(u.shape + (2, 2))
    for shift in (0.0, 2 * np.pi):
        lo = np.maximum(u, st + shift)
        hi = np.minimum(u + dphi, ex + shift)
        cut = hi > lo
        val = _antiderivative(np.where(cut, hi, 0.0), process.Kr) - _antiderivative(np.where(cut, lo, 0.0), process.Kr)
        total += np.where(cut[..., None, None], val, 0.0)
    engaged = total.sum(axis=1).mean(axis=1)
    engaged.setflags(write=False)
    return engaged, dphi


Process = TurningProcess | MillingProcess
