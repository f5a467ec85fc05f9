"""Time-domain check: the nonlinear regenerative cutting process integrated in time.

Model.  The tool-point model x' = A x + B F, y = C x is driven by the cutting force of every
engaged edge slot s (teeth x axial slices, :class:`~spindlesim.chatter.process.CuttingTables`):

    h_s = h0_s + e_s . y(t) - u_s,     F = a sum_s w_s max(0, h_s) f_s,

u_s the surface left by the previous pass over the same angle (and slice).  When an edge cuts,
the surface becomes e_s . y(t); when it does not (h_s <= 0, the tool has left the cut) the old
surface stays and the next edge meets it with one more feed (u_s <- u_s - h0_s).  This is the
regenerative delay equation with the multiple-regeneration memory; for h_s > 0 throughout it is
the linear model of the stability methods.

Integration.  Exact exponential integration of the structure over the step dt = tau / m with a
first-order hold on the force (exponential time differencing, predictor-corrector):
x_{k+1} = P x_k + G0 F_k + G1 (F_{k+1} - F_k), P = exp(A dt), G0 = Phi0 B, G1 = Phi1 B as in the
semi-discretization, F_{k+1} from the predicted state.  Unconditionally stable for any structural
mode (FE models with high modes need no small step); second order in dt.  The delay is exactly
m steps.  The cut starts at t = 0 on a nominal surface (static chip everywhere), which excites
every mode.

Stability criterion.  The Poincare section samples the displacement once per tooth period,
p_j = y(j tau).  A stable cut converges to the forced tooth-periodic motion, so the distances
d_j = |p_{j+1} - p_j| decay like rho^j (rho the monodromy's spectral radius); chatter keeps them
finite (quasi-periodic: Hopf) or alternating (period two: flip).  ``growth_per_period`` is
exp(slope) of a least-squares line through log d_j and
``decay_ratio`` = d_last / max d (:func:`_growth` gives the fitting window).  The cut is
declared stable when growth < 0.999 and decay_ratio < 0.1, or when the perturbation has died out
by six orders of magnitude (decay_ratio < 1e-6); run more periods when 1 - rho is small (about
5 / (1 - rho) periods).

Spectrum and chatter frequency.  Amplitude spectrum of |y| over the last half (a whole number of
tooth periods, Hann window, so tooth-passing harmonics fall on bins); the chatter frequency is
the highest peak outside +-2 bins of the harmonics (NaN when stable).
"""

from __future__ import annotations

import numpy as np

from ._expm import expm_batch
from .results import DECAYED, DIED_OUT, STABLE_GROWTH, SimulationResult
from .tool import ToolPoint, as_state_space

__all__ = ["simulate"]


def _discretise(model, dt: float):
    n = model.A.shape[0]
    Z = np.zeros((3 * n, 3 * n))
    Z[:n, :n] = model.A * dt
    Z[:n, n:2 * n] = np.eye(n) * dt
    Z[n:2 * n, 2 * n:] = np.eye(n)
    X = expm_batch(Z[None])[0]
    return X[:n, :n], X[:n, n:2 * n] @ model.B, X[:n, 2 * n:] @ model.B


def _growth(d: np.ndarray) -> tuple[float, float]:
    """(growth per period, decay ratio) of the Poincare distances ``d``.

    The growth is fitted (log-linear least squares) over the later half of the decaying part
    after the largest distance, down to 1e-4 of it (far below, around 1e-6, the zero-thickness
    entry or exit of the edges, switching in and out of the cut, leaves a non-smooth residue
    that is not chatter), or over the last half of the run when there is no such part (growing
    or saturated motion).
    """
    if len(d) < 4 or d.max() <= 0:
        return 0.0, 0.0
    d_max, j_max = d.max(), int(np.argmax(d))
    idx = np.flatnonzero((np.arange(len(d)) >= j_max + 5) & (d > 1e-4 * d_max))
    if len(idx) >= 10:
        idx = idx[len(idx) // 2:]
    else:
        idx = np.arange(len(d) // 2, len(d))
        idx = idx[d[idx] > 0]
    growth = float(np.exp(np.polyfit(idx, np.log(d[idx]), 1)[0])) if len(idx) >= 3 else 0.0
    return growth, float(d[-1] / d_max)


def _default_steps(model, tau: float) -> int:
    f_top = max(md.frequency_hz for md in model.significant_modes())
    return int(2 * np.ceil(max(100, 40 * f_top * tau) / 2))


def simulate(process, tool: ToolPoint, speed_rpm: float, depth_m: float, *, tooth_periods: int = 400,
             steps_per_period: int | None = None, fit_options: dict | None = None) -> SimulationResult:
    """Integrate the cut at ``speed_rpm`` and axial depth ``depth_m`` for ``tooth_periods`` periods."""
    if not (np.isfinite(depth_m) and depth_m > 0 and np.isfinite(speed_rpm) and speed_rpm > 0):
        raise ValueError(f"simulation needs a positive speed and depth (got {speed_rpm} rpm, {depth_m} m)")
    model = as_state_space(tool, **(fit_options or {}))
    tau = float(process.tooth_period_s(speed_rpm))
    m = steps_per_period or _default_steps(model, tau)
    dt = tau / m
    P, G0, G1 = _discretise(model, dt)
    tab = process.cutting_tables(m, depth_m)
    from ._simulation_kernels import integrate  # numba: imported when a simulation runs (a tenth of a second)

    Y, F, late = integrate(P, np.ascontiguousarray(G0), np.ascontiguousarray(G1), model.C, tab.e, tab.force,
                            tab.h0, tab.w, tab.bin, tab.nbins, float(depth_m), m, int(tooth_periods),
                            0.1 * float(tab.h0.max()))
    t = np.arange(len(Y)) * dt
    poincare = Y[::m]
    xdot = np.gradient(Y, dt, axis=0)[::m]
    d = np.linalg.norm(np.diff(poincare, axis=0), axis=1)
    growth, decay = _growth(d)
    stable = bool(decay < DIED_OUT or (growth < STABLE_GROWTH and decay < DECAYED))
    # spectrum of the last half, a whole number of periods
    p_half = tooth_periods // 2
    seg = Y[-p_half * m - 1:-1]
    seg = seg - seg.mean(axis=0)
    win = np.hanning(len(seg))[:, None]
    spec = np.fft.rfft(seg * win, axis=0)
    amp = 2 * np.linalg.norm(np.abs(spec), axis=1) / win.sum()
    freq = np.fft.rfftfreq(len(seg), dt)
    bin_hz = 1.0 / (p_half * tau)
    harm = np.arange(len(freq)) % p_half  # harmonics of 1/tau sit on multiples of p_half bins
    near = (harm <= 2) | (harm >= p_half - 2)
    masked = np.where(near, 0.0, amp)
    fc = float(freq[int(np.argmax(masked))]) if not stable else float("nan")
    engaged = late.sum()
    return SimulationResult(float(speed_rpm), float(depth_m), t, Y, F, poincare, xdot, freq, amp,
                            1.0 / tau, fc, bool(stable), growth, decay,
                            float(late[1] / engaged) if engaged else 0.0, int(m), bin_hz)
