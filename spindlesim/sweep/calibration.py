"""Calibration of deck values to measured FRFs (``spindlesim calibrate``, deck section ``calibration:``).

The model is the deck itself: every evaluation writes the trial values into the deck's text at their key paths
(``deck.paths.replace_in_text``), validates it as any deck, builds the rotor and its operating points (the
thermal equilibrium too, where the deck has one) and takes the direct receptance at each measurement's node and
direction at its speed: the one rotor path of every analysis, nothing of its own.

Fit: bounded nonlinear least squares (``scipy.optimize.least_squares``, trust-region reflective, Jacobian by
finite differences), a parameter spanning a decade or more (min > 0, max / min >= 10) on the logarithm of its
value, started from the deck's values.  The residual of measurement k at frequency f is

    r = (H_model(f) - H_meas(f)) / sqrt(|H_meas(f)|^2 + (FLOOR max_f |H_meas|)^2) / sqrt(N_k)

(real and imaginary parts): each frequency's error relative to the measured magnitude there, so that a small
peak counts as much as the largest, floored at FLOOR of the largest so that the noise of an antiresonance does not
rule; each measurement weighs the same whatever its number of points.

Intervals: with J the Jacobian at the optimum (in the fitted coordinates), m residuals, n parameters, the
residual variance s^2 = |r|^2 / (m - n) and the covariance s^2 (J^T J)^+; the 95 % interval is the estimate
+- t_{0.975, m-n} sigma in the fitted coordinates (asymmetric in the value for a logarithmic parameter).  The
correlation matrix is the covariance scaled by its diagonal.  Warned: a parameter at a bound, two parameters
correlated above 0.95, an interval wider than the bounds (the data do not determine it).
"""

from __future__ import annotations

import logging
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable

import numpy as np

log = logging.getLogger(__name__)

#: the residual's weight is floored at this share of a measurement's largest magnitude
FLOOR = 0.05
#: fewest measured points a measurement must keep in the band
MIN_POINTS = 10
#: correlation above which two parameters are said to be confounded
CORRELATED = 0.95


class CalibrationError(ArithmeticError):
    """The fit did not converge (the message says what was tried and how far it got)."""


class _OverBudget(Exception):
    """The model evaluations allowed are spent."""


@dataclass(frozen=True)
class Measured:
    """One measurement as fitted: the direct FRF at ``node`` (1-based) in ``direction`` at ``speed_rpm``."""

    label: str
    node: int
    direction: str
    speed_rpm: float
    frequency_hz: np.ndarray
    H: np.ndarray  # complex [f]

    def weight_of(self, model: np.ndarray) -> np.ndarray:
        """1 / sqrt(|H_model|^2 + floor^2) / sqrt(N) (module note)."""
        floor = FLOOR * float(np.max(np.abs(self.H)))
        return 1.0 / np.sqrt(np.abs(model) ** 2 + floor**2) / np.sqrt(len(self.H))


@dataclass(frozen=True)
class Parameter:
    path: str
    lower: float
    upper: float
    initial: float

    @property
    def log_scale(self) -> bool:
        return self.lower > 0 and self.upper / self.lower >= 10.0

    def to_x(self, v):
        return np.log10(v) if self.log_scale else np.asarray(v, float)

    def from_x(self, x):
        return 10.0 ** np.asarray(x, float) if self.log_scale else np.asarray(x, float)


@dataclass(frozen=True)
class FittedParameter:
    path: str
    initial: float
    value: float
    lower_95: float  # NaN: not determined (singular Jacobian)
    upper_95: float
    min: float
    max: float
    log_scale: bool
    at_bound: bool
    undetermined: bool  # the interval reaches past both bounds, or the data do not move the model


@dataclass(frozen=True)
class CalibrationResult:
    """What ``spindlesim calibrate`` computes (module note)."""

    parameters: tuple[FittedParameter, ...]
    correlation: np.ndarray  # [parameter, parameter]
    measurements: tuple[Measured, ...]
    initial_H: tuple[np.ndarray, ...]
    calibrated_H: tuple[np.ndarray, ...]
    initial_error: np.ndarray  # relative rms error of each measurement, the deck's values
    final_error: np.ndarray  # the same, calibrated
    evaluations: int
    message: str
    calibrated_text: str
    warnings: tuple[str, ...] = ()
    complete: bool = True  # False: interrupted; the values are the best evaluated, without intervals


def relative_error(model: np.ndarray, measured: np.ndarray) -> float:
    """rms |H_model - H_meas| / rms |H_meas|."""
    return float(np.sqrt(np.mean(np.abs(model - measured) ** 2) / np.mean(np.abs(measured) ** 2)))


class _Model:
    """The deck's direct receptances at the measurements for trial values (module note); remembers the best."""

    def __init__(self, loaded: Any, params: list[Parameter], measured: list[Measured]):
        self.loaded, self.params, self.measured = loaded, params, measured
        self.evaluations = 0
        self.best: tuple[float, np.ndarray] | None = None

    def text(self, values, digits: int = 17) -> str:
        """The deck's text with ``values`` in place (17 digits: the evaluated model exactly; 6 for the reader)."""
        from ..deck.paths import replace_in_text

        return replace_in_text(self.loaded.text, {p.path: float(v) for p, v in zip(self.params, values)}, digits)

    def frfs(self, values) -> list[np.ndarray]:
        from ..analysis.frf import receptance
        from ..analysis.points import OperatingPoints
        from ..deck import parse_deck
        from ..model.build import build_rotor
        from ..model.thermal import build_spindle_thermal

        deck = parse_deck(self.text(values), self.loaded.source).deck
        rotor = build_rotor(deck)
        thermal = build_spindle_thermal(deck, rotor)
        points = OperatingPoints(rotor, thermal if thermal is not None and thermal.analyses != "none" else None)
        out = []
        for m in self.measured:
            i = rotor.dofs.index(m.node - 1, m.direction)
            out.append(receptance(points.system(points.state(m.speed_rpm)), i, i, 2 * np.pi * m.frequency_hz))
        self.evaluations += 1
        return out

    def residual(self, x) -> np.ndarray:
        values = [p.from_x(v) for p, v in zip(self.params, x)]
        r = np.concatenate([(h - m.H) * m.weight_of(h) for h, m in zip(self.frfs(values), self.measured)])
        out = np.concatenate([r.real, r.imag])
        cost = float(out @ out)
        if self.best is None or cost < self.best[0]:
            self.best = (cost, np.array(values, float))
        return out


def _intervals(params, x, jac, res_vec, lo, hi):
    m, n = len(res_vec), len(x)
    dof = max(m - n, 1)
    bread = np.linalg.pinv(jac.T @ jac)
    leverage = np.clip(np.sum((jac @ bread) * jac, axis=1), 0.0, 0.99)
    meat = (jac * (res_vec / (1.0 - leverage)) [:, None] ** 2).T @ jac
    cov = bread @ meat @ bread
    sig = np.sqrt(np.clip(np.diag(cov), 0.0, None))
    from scipy.stats import t as student

    t = float(student.ppf(0.975, dof))
    with np.errstate(invalid="ignore", divide="ignore"):
        corr = cov / np.outer(sig, sig)
    corr[~np.isfinite(corr)] = 0.0
    np.fill_diagonal(corr, 1.0)
    dead = np.linalg.norm(jac, axis=0) <= 1e-12 * max(float(np.linalg.norm(jac)), 1e-300)
    rows = []
    for k, p in enumerate(params):
        a, b = x[k] - t * sig[k], x[k] + t * sig[k]
        undetermined = bool(dead[k] or (a <= lo[k] and b >= hi[k]))
        a, b = max(a, lo[k]), min(b, hi[k])  # the value cannot leave its bounds: the interval ends there
        lower, upper = (float("nan"), float("nan")) if dead[k] else (float(p.from_x(a)), float(p.from_x(b)))
        rows.append((lower, upper, undetermined))
    return rows, corr


def calibrate(loaded: Any, base_dir: Path, progress: Callable[[int, int], None] | None = None) -> CalibrationResult:
    """Fit the deck's ``calibration.parameters`` to its ``calibration.measurements`` (module note).

    DeckError: a located problem of the section (a path not in the deck, bounds, a start outside them, a value
    the key refuses at a bound, a measurement file that cannot be read or has too few points in the band).
    CalibrationError: the fit did not converge.  KeyboardInterrupt: the best values evaluated so far are in
    the exception's ``partial`` attribute (a CalibrationResult with ``complete = False``)."""
    from scipy.optimize import least_squares

    from .calibration_inputs import check_parameters, read_measurements

    sec = loaded.deck.calibration
    params = check_parameters(loaded)
    measured = read_measurements(loaded, base_dir)
    model = _Model(loaded, params, measured)
    budget = int(sec.max_evaluations)
    x0 = np.array([float(p.to_x(p.initial)) for p in params])
    lo = np.array([float(p.to_x(p.lower)) for p in params])
    hi = np.array([float(p.to_x(p.upper)) for p in params])
    initial_H = model.frfs([p.initial for p in params])
    x0 = np.clip(x0, lo, hi)

    start_cost = float(np.sum(np.concatenate([np.abs((h - m.H) * m.weight_of(h)) ** 2
                                               for h, m in zip(initial_H, measured)])))

    def fun(x):
        if model.evaluations >= budget:  # finite-difference Jacobians count too (least_squares' max_nfev does not)
            raise _OverBudget
        r = model.residual(x)
        if progress is not None:
            progress(min(model.evaluations, budget), budget)
        return r

    def unconverged(why: str):
        best = model.best[1] if model.best is not None else [p.initial for p in params]
        cost = model.best[0] if model.best is not None else float("nan")
        return CalibrationError(
            f"the fit did not converge within {model.evaluations} model evaluations (calibration.max_evaluations "
            f"{budget}; {why}): weighted misfit {start_cost:.4g} at the deck's values, {cost:.4g} at the best "
            "values evaluated, " + ", ".join(f"{p.path} = {v:.4g}" for p, v in zip(params, best))
            + ": raise max_evaluations, narrow the bounds or start nearer")

    try:
        res = least_squares(fun, x0, bounds=(lo, hi), method="trf", x_scale="jac", diff_step=1e-4,
                            max_nfev=budget)
    except KeyboardInterrupt as exc:
        exc.partial = _partial(model, params, measured, initial_H)  # type: ignore[attr-defined]
        raise
    except _OverBudget:
        raise unconverged("budget spent") from None
    if res.status <= 0:
        raise unconverged(str(res.message))
    values = [float(p.from_x(v)) for p, v in zip(params, res.x)]
    rows, corr = _intervals(params, res.x, res.jac, res.fun, lo, hi)
    fitted = tuple(FittedParameter(p.path, p.initial, v, a, b, p.lower, p.upper, p.log_scale,
                                   bool(res.active_mask[k] != 0), und)
                   for k, (p, v, (a, b, und)) in enumerate(zip(params, values, rows)))
    final_H = model.frfs(values)
    return CalibrationResult(
        fitted, corr, tuple(measured), tuple(initial_H), tuple(final_H),
        np.array([relative_error(h, m.H) for h, m in zip(initial_H, measured)]),
        np.array([relative_error(h, m.H) for h, m in zip(final_H, measured)]),
        model.evaluations, str(res.message), model.text(values, 6), _warnings(fitted, corr))


def _partial(model: _Model, params, measured, initial_H) -> CalibrationResult:
    values = model.best[1] if model.best is not None else np.array([p.initial for p in params])
    fitted = tuple(FittedParameter(p.path, p.initial, float(v), float("nan"), float("nan"), p.lower, p.upper,
                                   p.log_scale, False, True) for p, v in zip(params, values))
    nan = np.full(len(measured), np.nan)
    return CalibrationResult(fitted, np.full((len(params), len(params)), np.nan), tuple(measured),
                             tuple(initial_H), tuple(initial_H), nan, nan, model.evaluations,
                             "interrupted by the user: the best values evaluated, no intervals",
                             model.text(values, 6), (), complete=False)


def _warnings(fitted, corr) -> tuple[str, ...]:
    out = []
    for p in fitted:
        if p.at_bound:
            out.append(f"{p.path} sits at a bound ({p.value:.4g}, bounds {p.min:g} .. {p.max:g}): widen it or "
                       "question the model (its interval ends at the bound and is not a 95 % interval there)")
        if p.undetermined:
            out.append(f"{p.path} is not determined by the data (its 95 % interval is wider than its bounds): fix "
                       "it or measure what it changes")
    n = len(fitted)
    for i in range(n):
        for j in range(i + 1, n):
            if abs(corr[i, j]) > CORRELATED:
                out.append(f"{fitted[i].path} and {fitted[j].path} are correlated ({corr[i, j]:+.3f}): the data "
                           "determine a combination of them, not each")
    return tuple(out)
