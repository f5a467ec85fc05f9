"""Steady synchronous response to a rotating unbalance over speed, the grid refined at every resonance.

The unbalance force m e W^2 (cos(W t + a), sin(W t + a)) is the real part of F e^{j W t} with
F_x = m e W^2 e^{j a}, F_y = -j m e W^2 e^{j a}; at every speed the matrices (gyroscopics, bearings
linearised at that speed's static state) are rebuilt and (-W^2 M + j W C(W) + K(W)) q = F is solved.
The response is a phasor, q(t) = Re(q e^{j W t}): |q| is a DOF's 0-peak (single) amplitude and
2 |q| its peak-to-peak amplitude.

With ``refine`` (what ``spindlesim unbalance`` does) no resonance falls between two speeds:

1. the modes at every speed of the user's grid, tracked by MAC as in a Campbell diagram (the
   reduced model when it passes its check), up to 1.25 times the highest 1x frequency;
2. each sign change of g_k(N) = f_k(N) - N/60 (f_k the damped frequency) is located by a bracketed
   secant search (Illinois) on the full model (the bracket's ends re-evaluated on it), the static state
   at each trial speed warm-started and the mode picked by MAC with the tracked one, until g is below
   1e-3 of the mode's half-power half-width zeta f_k;
3. around each crossing N_c the speeds N_c + w BAND_STEPS are added (:mod:`.resonance`), with
   w = zeta f_k / |d f_k/dN - 1/60| the half-width of the resonance in speed (zeta N_c when f_k
   does not change with speed);
4. the response peak near each crossing and its API 684 amplification factor from the half-power
   speeds, AF = N_peak / (N_2 - N_1).
"""

from __future__ import annotations

import logging

import numpy as np
import scipy.linalg as sla

from ..model.rotor import Rotor
from .campbell import _modal_at_speeds, mac, track_modes
from .modal import modal_from_matrices
from .operating import EquilibriumError
from .points import OperatingPoints
from .resonance import MIN_HALF_WIDTH, UNDAMPED_ZETA, crossings_from, find_crossings, half_power_af, refine_grid
from .results import UnbalanceResonances, UnbalanceResult

log = logging.getLogger(__name__)
#: modes tracked up to this multiple of the highest 1x frequency of the sweep
MODE_REACH = 1.25
#: a crossing is located when |f_k - N/60| is below this share of the half-power half-width zeta f_k
CROSSING_TOL = 1e-3


def solve_unbalance(rotor: "Rotor | OperatingPoints", speeds_rpm: np.ndarray, node: int, unbalance_kg_m: float,
                    phase_deg: float, output_node: int, output_dof: str, refine: bool = False,
                    operating: tuple[float, float] | None = None) -> UnbalanceResult:
    """Response to the unbalance m e (``unbalance_kg_m``) at (1-based) ``node`` over ``speeds_rpm``; with
    ``refine`` the speeds are sorted and refined at every 1x crossing in range (module note), the
    crossings judged against the ``operating`` range (minimum operating, maximum continuous speed)."""
    points = OperatingPoints.of(rotor)
    rotor = points.rotor
    speeds = np.asarray(speeds_rpm, float)
    ix, iy = rotor.dofs.index(node - 1, "x"), rotor.dofs.index(node - 1, "y")
    force = unbalance_kg_m * np.exp(1j * np.deg2rad(phase_deg))
    out = rotor.dofs.index(output_node - 1, output_dof)

    def response(st):
        W = st.speed_rad_s
        sysm = points.system(st)
        F = np.zeros(sysm.size, complex)
        F[ix], F[iy] = force * W**2, -1j * force * W**2
        return sla.solve(-(W**2) * sysm.M + 1j * W * sysm.C + sysm.K, F, check_finite=False)

    added = resonances = None
    if not refine:
        q = [response(points.state(s)) for s in speeds]
    else:
        speeds = np.unique(speeds)
        sweep = points.along(speeds, what="unbalance response")
        if sweep.interrupted:
            raise KeyboardInterrupt
        if sweep.stopped:
            raise EquilibriumError(f"unbalance response {sweep.stopped}")
        speeds, states = sweep.speeds_rpm, sweep.states
        found, at_crossings = _crossings(points, speeds, states, operating)
        speeds_all, added = refine_grid(speeds, found.speed_rpm, _half_widths(found), ())
        keep = ~(added & np.isin(speeds_all, found.speed_rpm[np.abs(found.damping_ratio) < UNDAMPED_ZETA]))
        speeds_all, added = speeds_all[keep], added[keep]  # an undamped crossing: its band, not the singular centre
        by_speed = dict(zip(speeds.tolist(), states))
        known = np.concatenate([speeds, found.speed_rpm])
        starts = list(states) + at_crossings  # an added speed starts from the nearest state known
        all_states = []
        for s in speeds_all:
            if s in by_speed:
                all_states.append(by_speed[s])
            else:
                near = starts[int(np.argmin(np.abs(known - s)))]
                all_states.append(points.state(s, start=near))
        speeds = speeds_all
        q = [response(st) for st in all_states]
        log.info("unbalance: %d speeds added around %d 1x crossings", int(added.sum()), len(found))
    q = np.asarray(q).reshape(len(speeds), -1)
    resp = np.stack([q[:, rotor.dofs.component("x")], q[:, rotor.dofs.component("y")]], axis=2)
    if refine:
        resonances = _peaks(found, speeds, np.abs(q[:, out]))
    return UnbalanceResult(speed_rpm=speeds, response_m=resp, unbalance_kg_m=unbalance_kg_m,
                           unbalance_node=node, output_node=output_node, output_dof=output_dof,
                           node_z_m=rotor.node_z_m, added=added, resonances=resonances)


def _half_widths(c) -> np.ndarray:
    """Half-power half-width of each crossing in speed [rpm]: zeta f / |df/dN - n/60|, at most a
    quarter of the crossing speed (a mode running along the line), at least 1e-6 of it."""
    rel = np.abs(c.slope_hz_per_rpm - c.order / 60.0)
    with np.errstate(divide="ignore"):
        w = np.abs(c.damping_ratio) * c.frequency_hz / rel
    return np.clip(np.nan_to_num(w, nan=np.inf), MIN_HALF_WIDTH * c.speed_rpm, 0.25 * c.speed_rpm)


def _crossings(points, speeds: np.ndarray, states, operating):
    """(the 1x crossings of the modes tracked over ``speeds``, the static state at each) (module note,
    steps 1 and 2)."""
    rotor = points.rotor
    if len(speeds) < 2:
        return crossings_from([], operating), []
    top = modal_from_matrices(points.system(states[-1]), rotor.dofs, rotor.node_z_m, 2 * rotor.dofs.size, speeds[-1])
    low = modal_from_matrices(points.system(states[0]), rotor.dofs, rotor.node_z_m, 2 * rotor.dofs.size, speeds[0])
    reach = MODE_REACH * speeds[-1] / 60.0
    n = max(int(np.sum(top.frequency_hz <= reach)), int(np.sum(low.frequency_hz <= reach))) + 2
    _, modal = _modal_at_speeds(points, speeds, n + max(4, n // 2), states, n_check=n,
                                key=("unbalance", float(speeds[0]), float(speeds[-1])))
    tr = track_modes(modal, len(speeds), n, keep_shapes=True)
    rough = find_crossings(speeds, tr.frequency_hz, tr.damping_ratio, tr.whirl, (1.0,))
    rows = []
    for j in range(len(rough)):
        k = int(rough.mode[j])
        i = int(np.searchsorted(speeds, rough.speed_rpm[j], side="right") - 1)
        i = min(max(i, 0), len(speeds) - 2)
        sc, fc, zc, wc, st = _locate(points, speeds, states, tr, i, k)
        rows.append((sc, 1.0, k, fc, zc, wc, float(rough.slope_hz_per_rpm[j]), st))
    rows.sort(key=lambda r: r[0])
    return crossings_from([r[:7] for r in rows], operating), [r[7] for r in rows]


def _locate(points, speeds, states, tr, i: int, k: int):
    """(speed, frequency, damping ratio, whirl, static state) where tracked mode ``k`` crosses the 1x
    line between speeds i and i + 1: Illinois (regula falsi with halving) on the full model."""
    rotor = points.rotor
    ref = tr.shapes[i, k] if np.all(np.isfinite(tr.shapes[i, k])) else tr.shapes[i + 1, k]
    n_modes = tr.frequency_hz.shape[1] + 4
    near = [states[i]]

    def g(s):
        st = points.state(s, start=near[0])
        near[0] = st
        m = modal_from_matrices(points.system(st), rotor.dofs, rotor.node_z_m, n_modes, s)
        shapes = m.mode_shape.reshape(len(m.frequency_hz), -1)
        f_ref = np.interp(s, speeds[i:i + 2], tr.frequency_hz[i:i + 2, k])
        rel = np.abs(m.frequency_hz - f_ref) / max(f_ref, 1e-12)
        c = int(np.argmax(mac(ref[None, :], shapes)[0] - 0.5 * np.minimum(rel, 1.0)))
        return m.frequency_hz[c] - s / 60.0, (m.frequency_hz[c], m.damping_ratio[c], m.whirl[c])

    # the bracket on the full model (the tracked frequencies may come from the reduced one, whose error can
    # exceed a lightly damped mode's half-width); without a sign change there, plain secant steps
    a, b = speeds[i], speeds[i + 1]
    (ga, info), (gb, _) = g(a), g(b)
    bracketed = ga * gb <= 0
    c = a
    for _ in range(40):
        if gb == ga:
            break
        c = b - gb * (b - a) / (gb - ga)
        gc, info = g(c)
        tol = CROSSING_TOL * max(abs(info[1]), MIN_HALF_WIDTH) * info[0]
        if abs(gc) <= tol or abs(b - a) <= 1e-12 * abs(c):
            break
        if not bracketed or gc * gb < 0:
            a, ga = b, gb
        else:
            ga *= 0.5
        b, gb = c, gc
    else:
        log.warning("1x crossing of mode %d near %.6g rpm: located to |f - N/60| = %.3g Hz only", k + 1, c, gc)
    return float(c), float(info[0]), float(info[1]), str(info[2]), near[0]


def _peaks(c, speeds: np.ndarray, amp: np.ndarray) -> UnbalanceResonances:
    """The response peak within each crossing's band (three half-widths) and its half-power AF; NaN
    where the output shows no local maximum there (a mode the unbalance does not drive)."""
    w = _half_widths(c) if len(c) else np.zeros(0)
    pk_s, pk_a, af = (np.full(len(c), np.nan) for _ in range(3))
    for j, (sc, wj) in enumerate(zip(c.speed_rpm, w)):
        idx = np.flatnonzero(np.abs(speeds - sc) <= 3.0 * wj)
        if not len(idx):
            continue
        p = int(idx[np.argmax(amp[idx])])
        if 0 < p < len(speeds) - 1 and amp[p] >= amp[p - 1] and amp[p] >= amp[p + 1] and amp[p] > 0:
            pk_s[j], pk_a[j] = speeds[p], amp[p]
            af[j] = half_power_af(speeds, amp, p)[0]
    return UnbalanceResonances(crossings=c, peak_speed_rpm=pk_s, peak_amplitude_m=pk_a, half_power_af=af)

