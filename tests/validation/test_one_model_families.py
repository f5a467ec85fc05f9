"""One spindle model, every bearing family (issue "One spindle model"): the linear analyses and the
transient use one model of each bearing.

For every family, on a rotor deck:

(a) ``linearized()`` is the tangent of the nonlinear reaction at the static state: equal to central
    differences of ``force()`` to 1e-5 of the largest entry.  For a rolling bearing the reaction
    varies as the elements roll and ``linearized()`` is the tangent of the reaction averaged over one
    element pitch (bearings/base.py), at the displacement where that average carries the static load;
    the reference is then differences of the pitch-averaged force there.  Fluid films: the exact
    (Reynolds) force, which ``static``/``modal`` freeze with (the tabulated force of a transient is
    checked apart, ``test_tabulated_film_tangent``).
(b) the static equilibrium of ``static`` is where ``transient`` starts, to 1e-9 of the deflection.
(c) a small free decay shows the damped natural frequencies of ``modal`` at the static state within
    one FFT bin; with fluid films the first forward modes' frequency and decay rate (fitted to the
    response, matrix pencil of Hua and Sarkar, IEEE Trans. ASSP 38, 1990) within 2 %.

Decks: the embedded seed 003 spindle on its linear bearings; decks/validation/jeffcott_plain.yaml (and
the same rotor on 3-lobe bearings, L/D = 1, mp = 0.5: the land shape of seed 003's bearings);
decks/validation/roller_rotor.yaml (rigid and flexible race); decks/seed001_dtrb_rotor.yaml (the DTRB
and the ball-bearing pair of the seed 001 rotor).  Measured values are quoted at each assertion.
"""

from __future__ import annotations

import functools
import math
from pathlib import Path

import numpy as np
import pytest

from spindlesim.analysis.modal import solve_modal
from spindlesim.analysis.operating import operating_state
from spindlesim.analysis.static import solve_static
from spindlesim.analysis.transient.engine import Perturbation, TransientSettings, simulate
from spindlesim.bearings.roller import bearing as roller
from spindlesim.bearings.statics import equilibrium_under_load
from spindlesim.deck import default_deck, parse_deck
from spindlesim.model.build import build_rotor

ROOT = Path(__file__).parents[2]


# ---- decks ------------------------------------------------------------------------------------------
def _text(source: str) -> str:
    return default_deck(source).text if "/" not in source else (ROOT / source).read_text()


def deck_text(source: str, **replace: str) -> str:
    """The deck ``source`` (embedded name or path from the repository root) with text replaced."""
    text = _text(source)
    for old, new in replace.items():
        assert old in text, old
        text = text.replace(old, new)
    return text


def three_lobe_jeffcott(text: str) -> str:
    """The Jeffcott rotor of decks/validation/jeffcott_plain.yaml on 3-lobe bearings: L/D = 1,
    mp = 0.5, three 100 deg lobes with 20 deg grooves, load on a lobe (seed 003's land shape, so the
    film table of seed 003 serves), radial clearance 50 um, the same isoviscous oil."""
    return (text.replace("type: plain", "type: three_lobe\n    preload: 0.5")
            .replace("width_mm: 25.0", "width_mm: 50.0").replace("clearance_mm: 0.075", "clearance_mm: 0.05"))


DECKS = {
    # name: (source, replacements)
    "spindle_linear": ("spindle_linear", {}),
    # 8000 rpm: 0.9 x the oil-whirl threshold (test_one_model_oil_whirl.py), e/Cb 0.21, the cylindrical
    # whirl mode lightly damped (log dec 0.29), a clear line in the spectrum
    "jeffcott_plain": ("decks/validation/jeffcott_plain.yaml", {"speed_rpm: 3000": "speed_rpm: 8000"}),
    "jeffcott_three_lobe": ("decks/validation/jeffcott_plain.yaml", {"three_lobe": True}),
    "roller_rigid": ("decks/validation/roller_rotor.yaml", {}),
    "roller_flexible": ("decks/validation/roller_rotor.yaml", {"model: rigid_race": "model: flexible_race"}),
    "seed001": ("decks/seed001_dtrb_rotor.yaml", {}),
}


@functools.lru_cache(maxsize=None)
def rotor_of(name: str):
    source, rep = DECKS[name]
    rep = dict(rep)
    lobe = rep.pop("three_lobe", False)
    text = deck_text(source, **rep)
    if lobe:
        text = three_lobe_jeffcott(text)
    return build_rotor(parse_deck(text, f"{name}.yaml").deck)


@functools.lru_cache(maxsize=None)
def state_of(name: str):
    return operating_state(rotor_of(name))


# ---- (a) the tangent ----------------------------------------------------------------------------------
# family: (deck, bearing name, reference, difference step relative to the journal's displacement);
# reference "static": differences at the static state; "pitch": differences of the pitch-averaged
# reaction at its static state.  Steps: 1e-5 where the force is smooth; the DTRB's reaction has
# slice contact edges (first-order truncation error: 2.9e-5 at 1e-5, 4.2e-6 at 1e-6); the ball set's
# force carries the round-off of its ball equilibria (7.5e-5 at 1e-5, 6e-8 at 1e-4).
FAMILY_BEARINGS = {
    "linear": ("spindle_linear", "front", "static", 1e-5),
    "plain": ("jeffcott_plain", "left", "static", 1e-5),
    "three_lobe": ("jeffcott_three_lobe", "left", "static", 1e-5),
    "rigid_race": ("roller_rigid", "left", "pitch", 1e-5),
    "flexible_race": ("roller_flexible", "left", "pitch", 1e-5),
    # the DTRB's linearized() is documented as the tangent at its load equilibrium at cage angle 0
    # (bearings/dtrb/bearing.py), not pitch-averaged: compared there (see test_dtrb_pitch_variation)
    "dtrb": ("seed001", "dtrb", "static", 1e-6),
    "ball": ("seed001", "acbb", "pitch", 1e-4),
}


def differences(force, q: np.ndarray, h: np.ndarray) -> np.ndarray:
    """-d force / dq by central differences with steps h (one per DOF)."""
    n = q.size
    K = np.empty((force(q).size, n))
    for k in range(n):
        e = np.zeros(n)
        e[k] = h[k]
        K[:, k] = -(force(q + e) - force(q - e)) / (2.0 * h[k])
    return K


def pitch_points(b, speed: float) -> np.ndarray:
    """Shaft angles of the cage positions over one element pitch that the family's linearized()
    averages (rigid race 24, flexible race 4, ball set ``pitch_samples``)."""
    if isinstance(b, roller.RigidRaceBearing):
        z, cage, n = b.rollers, b.kinematics.cage_ratio, roller.RIGID_RACE_PITCH_POINTS
    elif isinstance(b, roller.FlexibleRaceBearing):
        z, cage, n = b.rollers, b.kinematics.cage_ratio, roller.FLEXIBLE_RACE_PITCH_POINTS
    else:  # ball set
        z, cage, n = b.geometry.balls, b.geometry.cage_ratio(), b.pitch_samples
    return 2.0 * math.pi / z / cage * np.arange(n) / n


def node_reaction(b, speed: float, angle: float, internal0: list):
    """q_node -> reaction on the node DOFs with the bearing's internal DOFs (if any) in equilibrium
    (the rollers and race of a flexible race are quasi-static for the rotor modes)."""
    n = len(b.dof_names)
    m = b.internal_mass.size

    def reaction(q: np.ndarray) -> np.ndarray:
        if m == 0:
            return b.force(q, np.zeros(n), 0.0, speed, angle)

        def ft(z):
            x = np.concatenate([q, z])
            f, K, _ = b.force_and_tangent(x, np.zeros(n + m), 0.0, speed, angle)
            return f[n:] / 50.0, K[n:, n:] / 50.0  # internal forces balanced to 1e-10 of ~50 N

        scale = np.concatenate([np.full(b.rollers, 1e-7), np.tile([1e-7, 1e-7, 1e-5], b.ring.segments)])
        z = equilibrium_under_load(ft, np.zeros(1), internal0[0], scale, "test", tol=1e-10)
        internal0[0] = z
        return b.force(np.concatenate([q, z]), np.zeros(n + m), 0.0, speed, angle)[:n]

    return reaction


def steps(b, q: np.ndarray, rel: float) -> np.ndarray:
    """Difference steps: ``rel`` of the journal's displacement, x 1e-3 for rotations [rad]."""
    scale = np.where(np.array([d.startswith("theta") for d in b.dof_names]), 1e-3, 1.0)
    return rel * np.max(np.abs(q[:2])) * scale


def pitch_averaged_static_state(b, speed: float, load: np.ndarray, rel: float):
    """(q0, F_avg) with the pitch-averaged reaction F_avg(q0) + load = 0 (Newton with differences)."""
    angles = pitch_points(b, speed)
    n = len(b.dof_names)
    if b.internal_mass.size:  # a flexible race: each cage position's own equilibrium as the start
        starts = [b.static_displacement(speed, load, angle=a) for a in angles]
    else:
        starts = [b.static_displacement(speed, load) for _ in angles]
    reactions = [node_reaction(b, speed, a, [s[n:]]) for a, s in zip(angles, starts)]

    def F(q):
        return np.mean([r(q) for r in reactions], axis=0)

    q = starts[0][:n].copy()
    h = steps(b, q, rel)
    for _ in range(20):
        r = F(q) + load
        if np.max(np.abs(r)) <= 1e-11 * np.max(np.abs(load)):
            break
        q = q + np.linalg.solve(differences(F, q, h), r)  # differences() is K = -dF/dq
    return q, F


@pytest.mark.parametrize("family", list(FAMILY_BEARINGS))
def test_a_linearized_is_the_tangent_of_the_reaction(family):
    deck, name, ref, rel = FAMILY_BEARINGS[family]
    st = state_of(deck)
    k = [b.name for b in st.bearings].index(name)
    b, load, W = st.bearings[k], st.operating_loads[k], st.speed_rad_s
    n = len(b.dof_names)
    K_lin, C_lin = b.linearized(W, load)
    if ref == "static":
        q = np.concatenate([st.q[st.bearing_index[k]], st.internal[k]])[:n]
        reaction = node_reaction(b, W, 0.0, [st.internal[k]])
        assert np.max(np.abs(reaction(q) + st.loads[k])) <= 1e-8 * np.max(np.abs(st.loads[k]))  # a static state
    else:
        q, reaction = pitch_averaged_static_state(b, W, load, rel)
    K_d = differences(reaction, q, steps(b, q, rel))
    err_K = np.max(np.abs(K_lin - K_d)) / np.max(np.abs(K_d))
    # measured: linear 7e-12, plain 2.6e-10 (9.0 % before the film start was held at the operating
    # point), 3-lobe 1.4e-9, rigid race 3.5e-10, flexible race 4.4e-6 (7.0 % before: the tangents of each
    # cage position's own equilibrium were averaged, and symmetrised), DTRB 4.2e-6 (the step's slice-edge
    # error), ball 4.4e-8
    assert err_K <= 1e-5, f"{family}: |K_lin - K_diff| = {err_K:.3g} of max|K|"
    if b.internal_mass.size == 0 and np.any(C_lin):
        v = np.zeros(n)
        hv = 1e-5 * max(W, 1.0) * np.max(np.abs(q[:2])) * np.ones(n)
        # a rolling bearing's C (beta K, issue 30) is pitch-averaged like its K: so are the differences
        angles = [0.0] if ref == "static" else pitch_points(b, W)
        C_d = np.mean([differences(lambda vv, a=a: b.force(q, vv, 0.0, W, a), v, hv) for a in angles], axis=0)
        err_C = np.max(np.abs(C_lin - C_d)) / np.max(np.abs(C_d))
        # measured: linear and fluid films <= 6e-11 (the rolling bearings pass at the tolerance of their K)
        assert err_C <= 1e-5, f"{family}: |C_lin - C_diff| = {err_C:.3g} of max|C|"


# ---- (b) static = start of the transient ---------------------------------------------------------------
# the flexible race integrates with the compiled RK4 (its rollers and race, ~100 kHz, make Newmark's
# Newton fail at steps that resolve the rotor: "did not converge at t = 0.058 s", 26 us steps)
METHOD = {"roller_flexible": "rk4"}


@pytest.mark.parametrize("deck", list(DECKS))
def test_b_static_equilibrium_is_where_the_transient_starts(deck):
    rotor = rotor_of(deck)
    q_static = solve_static(rotor).state.q
    method = METHOD.get(deck, "newmark")
    h = 1e-6 if method == "rk4" else 1e-5
    res = simulate(rotor, TransientSettings(5 * h, method=method, step_s=h, settle_s=0.0))
    trans = np.array([d in ("x", "y") for d in rotor.dofs.names] * rotor.n_nodes)
    scale = np.max(np.abs(q_static[trans]))
    for q in (res.static_displacement, res.rotor_displacement[0]):
        # measured: 0 (linear, rolling), 3e-14 (seed 001: DTRB and ball), 1e-12 plain and 6e-10 3-lobe
        # with the tabulated film, whose force error at the operating point is removed (without that:
        # 2.4e-5 and 8.2e-5, the table's error)
        assert np.max(np.abs(q - q_static)) <= 1e-9 * scale


# ---- (c) free decay at the modal frequencies -----------------------------------------------------------
def matrix_pencil(y: np.ndarray, dt: float, order: int) -> tuple[np.ndarray, np.ndarray]:
    """Poles s_k [1/s] and complex amplitudes of y_n = sum_k a_k exp(s_k n dt) (Hua and Sarkar 1990:
    SVD of the Hankel matrix of the samples, rank ``order``, pencil of the shifted right vectors)."""
    y = np.asarray(y, complex)
    N = y.size
    L = N // 3
    Y = np.array([y[i:i + L + 1] for i in range(N - L)])
    V = np.linalg.svd(Y, full_matrices=False)[2][:order].conj().T
    z = np.linalg.eigvals(np.linalg.pinv(V[:-1]) @ V[1:])
    a = np.linalg.lstsq(z[None, :] ** np.arange(N)[:, None], y, rcond=None)[0]
    return np.log(z) / dt, a


def spectral_peaks(res, fmin: float, fmax: float, rel: float) -> np.ndarray:
    """Frequencies of the local maxima in [fmin, fmax] of either channel reaching ``rel`` of that
    channel's largest maximum in the band."""
    f, A = res.spectrum.frequency_hz, res.spectrum.amplitude
    band = (f >= fmin) & (f <= fmax)
    out = []
    for ch in range(A.shape[1]):
        a = A[:, ch]
        top = a[band].max()
        out += [f[i] for i in np.flatnonzero(band)[1:-1] if a[i] >= a[i - 1] and a[i] >= a[i + 1]
                and a[i] >= rel * top]
    return np.unique(out)


def excite(rotor, settings: dict) -> TransientSettings:
    """A released static force (perturbation) and an impact (initial velocity) at the given DOFs."""
    node, dof, force = settings["perturbation"]
    vel = tuple((rotor.dofs.index(n, d), v) for n, d, v in settings.get("impact", ()))
    return TransientSettings(settings["duration_s"], method=settings.get("method", "newmark"),
                             step_s=settings.get("step_s"), settle_s=0.0, record_node=settings["record"],
                             sample_rate_hz=settings.get("sample_rate_hz"),
                             perturbation=Perturbation(rotor.dofs.index(node, dof), force), initial_velocity=vel)


# Per deck: excitation, run, and the band of the spectral check.  Amplitudes are small against the
# bearings' static deflection / clearance (the nonlinear reactions stay near their tangent):
# rollers 5 N, ~1e-8 m against the 1.2e-7 m static deflection; the free decay then dominates the
# roller-pass response (the varying compliance) by three orders in amplitude.  Steps resolve the
# checked modes with >= 40 steps a period (Newmark's period error (w h)^2/12 <= 2e-3).
C_CASES = {
    "spindle_linear": dict(record=0, perturbation=(0, "x", 50.0), impact=[(0, "y", 1e-4)], duration_s=0.25,
                           step_s=2e-5, fmax=1300.0),
    "roller_rigid": dict(record=0, perturbation=(0, "x", 5.0), impact=[(0, "y", 5e-5)], duration_s=0.1,
                         fmax=1500.0),
    "roller_flexible": dict(record=0, perturbation=(0, "x", 5.0), impact=[(0, "y", 5e-5)], duration_s=0.1,
                            method="rk4", sample_rate_hz=20000.0, fmax=1500.0),
    "seed001": dict(record=4, perturbation=(8, "x", 500.0), impact=[(8, "y", 1e-3)], duration_s=0.2,
                    step_s=1e-4, fmax=300.0),
    "jeffcott_plain": dict(record=2, perturbation=(2, "x", 20.0), duration_s=0.5, step_s=2.5e-4, fmax=150.0),
    "jeffcott_three_lobe": dict(record=2, perturbation=(2, "x", 20.0), duration_s=0.25, step_s=5e-5,
                                fmax=500.0),
}
#: modes lighter than this make spectral lines (heavier ones: a fluid film's first modes, fitted below)
LINE_DAMPING = 0.3


@functools.lru_cache(maxsize=None)
def free_decay(deck: str):
    rotor = rotor_of(deck)
    return simulate(rotor, excite(rotor, C_CASES[deck]))


@pytest.mark.slow
@pytest.mark.parametrize("deck", list(C_CASES))
def test_c_free_decay_shows_the_modal_frequencies(deck):
    rotor, cfg = rotor_of(deck), C_CASES[deck]
    res = free_decay(deck)
    assert res.complete, res.reason
    md = solve_modal(rotor, n_modes=12)
    fmax, df = cfg["fmax"], res.spectrum.resolution_hz
    lines = md.frequency_hz[(md.damping_ratio < LINE_DAMPING) & (md.frequency_hz < fmax)]
    assert lines.size, "no lightly damped mode in the band: the check could not fail"
    peaks = spectral_peaks(res, 0.2 * lines.min(), fmax, rel=0.01)
    # measured (modal -> spectral line, bin): spindle_linear 1116.72, 1118.97 -> 1115.96 Hz (4.0 Hz);
    # roller rigid 502.70, 657.45, 664.16, 1402.63 -> 499.91, 659.89, 1399.76 (10 Hz); flexible 471.28,
    # 610.49, 655.73, 1372.01 -> 469.92, 609.89, 659.89, 1369.76 (10 Hz); seed 001 220.12, 230.24 ->
    # 219.93, 229.93 (5 Hz); Jeffcott plain 69.69 -> 69.97 (2 Hz); 3-lobe 390.80, 393.34 -> 387.92,
    # 391.92 (4 Hz).  Roller pass (2392 Hz) and its sidebands: below 1 % of the modal lines.
    # every lightly damped mode has a line within one FFT bin ...
    miss = [f for f in lines if np.min(np.abs(peaks - f)) > df]
    assert not miss, f"{deck}: modes {miss} Hz have no spectral line within {df:.3g} Hz (lines {peaks})"
    # ... and every strong line is a mode (the roller pass and its sidebands stay below 5 %)
    strong = spectral_peaks(res, 0.2 * lines.min(), fmax, rel=0.05)
    extra = [p for p in strong if np.min(np.abs(md.frequency_hz - p)) > df]
    assert not extra, f"{deck}: lines {extra} Hz are not modes ({md.frequency_hz} Hz)"


def whirl_signal(res, rotor, node: int) -> np.ndarray:
    """x + i y about the static state at ``node`` (forward whirl: positive frequencies)."""
    ix, iy = rotor.dofs.index(node, "x"), rotor.dofs.index(node, "y")
    q, q0 = res.rotor_displacement, res.static_displacement
    return (q[:, ix] - q0[ix]) + 1j * (q[:, iy] - q0[iy])


def fitted_pole(res, rotor, node: int, target: complex, order: int = 16, samples: int = 400) -> complex:
    """The pole of the response at ``node`` nearest ``target`` (matrix pencil on ~``samples`` samples of
    the decay down to 1e-4 of its start), with its share of the response.  Order 16: the film modes,
    the overdamped film roots and the shaft's; the fitted film poles move by < 0.1 % between orders 12
    and 20 (order 8 leaves 1.5 % on the plain bearing's conical mode)."""
    z = whirl_signal(res, rotor, node)
    t = res.time_s
    end = np.flatnonzero(np.abs(z) >= 1e-4 * np.abs(z).max())[-1] + 1
    every = max(1, end // samples)
    s, a = matrix_pencil(z[:end:every], (t[1] - t[0]) * every, order)
    k = int(np.argmin(np.abs(s - target)))
    return s[k], float(np.abs(a[k]) / np.abs(a).max())


# fluid films: the first forward modes (cylindrical, excited by a force at the disk, and conical, by a
# moment there), their damped frequency and decay rate from the free decay against ``modal``
FIT_CASES = {
    "jeffcott_plain": dict(record=2, duration_s=0.25, step_s=2.5e-4),
    "jeffcott_three_lobe": dict(record=2, duration_s=0.1, step_s=5e-5),
}


@pytest.mark.parametrize("deck", list(FIT_CASES))
@pytest.mark.parametrize("shape, dof, node", [("cylindrical", "x", 2), ("conical", "theta_y", 0)])
def test_c_fluid_film_first_forward_modes_frequency_and_decay(deck, shape, dof, node):
    rotor = rotor_of(deck)
    md = solve_modal(rotor, n_modes=6)
    fwd = [k for k in range(len(md.frequency_hz)) if md.whirl[k] == "forward"][:2]
    # the two film modes of the rigid rotor: cylindrical (bearings in phase) and conical (in antiphase)
    bearing = np.abs(md.mode_shape[fwd, 0, 0] + md.mode_shape[fwd, -1, 0])
    k = fwd[int(np.argmax(bearing))] if shape == "cylindrical" else fwd[int(np.argmin(bearing))]
    lam = md.eigenvalues[k]
    cfg = dict(FIT_CASES[deck], perturbation=(2, dof, 20.0 if dof == "x" else 2.0))
    res = simulate(rotor, excite(rotor, cfg))
    assert res.complete, res.reason
    s, share = fitted_pole(res, rotor, node, lam)
    assert share > 0.2  # the mode is what the response is made of
    err_f = abs(s.imag / lam.imag - 1.0)
    err_d = abs(s.real / lam.real - 1.0)
    # measured (frequency, decay rate): plain 8000 rpm cylindrical 69.69 Hz, -20.1 1/s: 7e-4, 3.4e-3;
    # conical 66.93 Hz, -214 1/s: 3e-5, 1.7e-3; 3-lobe 3000 rpm cylindrical 24.42 Hz, -95.2 1/s: 7e-4,
    # 5.1e-3; conical 23.74 Hz, -98.6 1/s: 3e-4, 4.9e-3 (the tabulated film; the full Reynolds solve
    # gives the same to 0.3 %)
    assert err_f <= 0.02 and err_d <= 0.02, (f"{deck} {shape}: modal {lam.imag / 2 / np.pi:.3f} Hz, "
                                             f"{lam.real:.2f} 1/s; transient {s.imag / 2 / np.pi:.3f} Hz, "
                                             f"{s.real:.2f} 1/s")


@pytest.mark.parametrize("deck, bound", [("jeffcott_plain", 0.006), ("jeffcott_three_lobe", 0.012)])
def test_tabulated_film_tangent(deck, bound):
    """The tabulated film force of a transient (transient_film: table, the default) against the exact
    tangent (``linearized``) at the static state: measured K 0.29 %, C 0.36 % of max (plain, fixed
    feed, e/Cb 0.21); K 0.62 %, C 0.63 % (3-lobe, e/Cb 0.15).  Its force there is exact (the table's
    error at the operating point is removed, test_b); these are what moves the fitted modes above."""
    st = operating_state(rotor_of(deck), transient=True)
    for b, i, w in zip(st.bearings, st.bearing_index, st.operating_loads):
        assert b.film_method == "table"
        K, C = b.linearized(st.speed_rad_s, w)
        _, Kt, Ct = b.force_and_tangent(st.q[i], np.zeros(2), 0.0, st.speed_rad_s, 0.0)
        assert np.max(np.abs(Kt - K)) <= bound * np.max(np.abs(K))
        assert np.max(np.abs(Ct - C)) <= bound * np.max(np.abs(C))


def test_dtrb_pitch_variation():
    """The DTRB's ``linearized`` is its tangent at cage angle 0 (bearings/dtrb/bearing.py), where the
    contract asks rolling bearings for the pitch average: on the seed 001 rotor the tangent varies by
    0.19 % of max|K| over a roller pitch and the angle-0 tangent is 0.16 % from the average (measured),
    far below what (c) resolves (one FFT bin, 2 % at 220 Hz)."""
    st = state_of("seed001")
    k = [b.name for b in st.bearings].index("dtrb")
    b, W = st.bearings[k], st.speed_rad_s
    q = st.q[st.bearing_index[k]]
    pitch = 2 * math.pi / b.geometry.rollers_per_row / b.geometry.cage_ratio
    Ks = [b.force_and_tangent(q, np.zeros(5), 0.0, W, pitch * j / 8)[1] for j in range(8)]
    K0, _ = b.linearized(W, st.operating_loads[k])
    assert np.max(np.abs(K0 - np.mean(Ks, axis=0))) <= 5e-3 * np.max(np.abs(K0))
