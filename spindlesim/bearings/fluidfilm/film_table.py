"""Reduced fluid-film force: per-land tables of the exact discrete LCP solution.

Reduction (exact for the discrete model, verified in tests/unit/test_fluidfilm_film_force.py)
-----------------------------------------------------------------------------------------
Lands are independent (P = 0 at the grooves).  In the frame of land k (rotated by its
preload direction ``theta_k``; the arc centre for a plain land), with ``phi = theta - theta_k``
and the journal at ``(xi, eta)`` (``X`` rotated by ``-theta_k``), the film is
``H = a - xi' cos(phi) - eta sin(phi)`` with ``xi' = xi + (a - 1)``, ``a = 1/(1 - mp)``: the
journal relative to the lobe's centre of curvature.  The finite-volume right-hand side of
:mod:`film_force` (Couette flux differences plus the node-point squeeze term) is, node by
node, exactly::

    b_i = 12 w_j sin(D/2) [ -alpha sin(phi_i) + beta cos(phi_i) ],   D = land's dtheta
    alpha = omega xi' - 2 kappa eta_r,   beta = omega eta + 2 kappa xi_r,   kappa = (D/2)/sin(D/2)

(``xi_r = xi'/Cb`` rates in 1/s): the pressure is that of a *static* journal at the film
position (xi', eta) loaded by the right-hand side of the "apparent" position (alpha, beta)/omega
(for omega > 0; the classical squeeze-film shift, e.g. Childs 1993 sec. 2.6, here with the
discrete factor kappa = 1 + D^2/24).  The LCP solution is positively homogeneous of degree 1
in b (P(s b) = s P(b), s >= 0), so with ``(alpha, beta) = rho (cos psi, sin psi)``::

    F_land = rho g(xi', eta, psi)

a function of three variables per land *shape* (all lobes of an n-lobe bearing share it).
A 360 deg bore (``geometry.axisymmetric``) is invariant under rotation, so g depends on the
eccentricity and ``psi - gamma`` only: a 2-D table in the line-of-centres frame.

Table layout
------------
Position in polar coordinates about the lobe's centre of curvature, ``(r, phi)``, with the
radial coordinate ``u = ln((a - r_lo)/(a - r)) / L_u`` in [0, 1] (geometric grading towards
the bore, where the force grows like (a - r)^-2.5; ``a - r`` is the minimum film when phi lies
in the arc).  The journal disk ``|X| <= eps_t`` (``TableResolution.eccentricity_max``) is
covered by ``r in [c0 - eps_t, c0 + eps_t]``, ``|phi| <= asin(eps_t/c0)`` when the centre of
curvature lies outside it (``c0 = a - 1``; seed 003's mp = 0.5 gives c0 = 1), else by
``r in [0, c0 + eps_t]`` and a periodic phi with twice the angular nodes.  The third axis is
the direction of the right-hand side, ``chi = psi - phi``, periodic.  The stored quantity is
the land force in the journal's radial frame, ``T = R(-phi) g`` (the pressure field turns with
the journal, so T varies slowly; storing lobe-frame components against psi was 3 times less
accurate).  Where the table contains the centre of curvature (plain grooved bearings,
multilobes with mp < ~0.49) the polar pole would make T multi-valued at r = 0; there
``g = g0(psi) + R(phi) T`` with g0 the force at the centre (a 1-D periodic spline) and T = 0
at r = 0, so g is single-valued and its gradient bounded at the pole.  A 360 deg bore needs
no phi axis.  Symmetric lobes (preload centre mid-arc) satisfy
``g(r, -phi, pi - psi) = diag(1, -1) g(r, phi, psi)`` exactly (the mirror image; the reversed
rotation is absorbed in psi), which halves the build.

Interpolation: tensor-product cubic splines (:mod:`film_spline`), tangent = derivative of the
interpolant.  Outside the table (``|X| > eps_t``) the exact solve is used.  Tables are cached on
disk (``$SPINDLESIM_CACHE`` or ``~/.cache/spindlesim``, sub-folder ``film_tables``) under a
hash of the land shape, grid and resolution; written to a temporary file and renamed, so
concurrent writers are safe.  Error study: benchmarks/bench_film_force.py.
"""

from __future__ import annotations

import functools
import hashlib
import json
import logging
import math
import os
import tempfile
import time
import zipfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy.interpolate import BSpline

from spindlesim.bearings.fluidfilm.film_force import (
    DimensionalFilmForce,
    ExactFilmForce,
    force_scale,
    lcp_active_set,
)
from spindlesim.bearings.fluidfilm.film_spline import eval_land_group, fit_tensor_spline
from spindlesim.bearings.fluidfilm.geometry import BearingGeometry, Land
from spindlesim.bearings.fluidfilm.reynolds import (
    DEFAULT_AXIAL,
    DEFAULT_CIRCUMFERENTIAL,
    ReynoldsSolver,
    _film_at,
)

log = logging.getLogger(__name__)

TABLE_VERSION = 2
_SECTOR_MARGIN = 0.02  # centre of curvature at least this far (over Cb) outside the disk


@dataclass(frozen=True)
class TableResolution:
    """Table nodes: radial (u), angular (phi, unused for 360 deg bores), rhs direction (even),
    and the eccentricity ``e/Cb`` up to which the table is used (exact solve beyond)."""

    n_radial: int = 16
    n_angle: int = 16
    n_direction: int = 48
    eccentricity_max: float = 0.95

    def __post_init__(self) -> None:
        if self.n_radial < 4 or self.n_angle < 4 or self.n_direction < 8:
            raise ValueError("table too coarse (need n_radial, n_angle >= 4, n_direction >= 8)")
        if self.n_direction % 2:
            raise ValueError("n_direction must be even")
        if not 0.0 < self.eccentricity_max < 1.0:
            raise ValueError("eccentricity_max must be in (0, 1)")


#: tables of a plain bore (no preload): an oil whirl circles the clearance there (e/Cb 0.97-0.98 at 1.4
#: times the threshold), so its table reaches e/Cb = 0.99, with 24 radial nodes (the spacing in ln(1 - e)
#: of 16 nodes to 0.95); off the table every call is a full solve, some hundred times slower
#: (benchmarks/bench_whirl.py).  A multilobe bore keeps the default (its lobes hold the journal off the wall).
PLAIN_BORE = TableResolution(n_radial=24, eccentricity_max=0.99)


def default_resolution(geometry: BearingGeometry) -> TableResolution:
    """The table resolution of ``geometry``: :data:`PLAIN_BORE` without preload, else the default."""
    return PLAIN_BORE if geometry.preload == 0 else TableResolution()


@dataclass(frozen=True)
class LandShape:
    """Dimensionless shape of a land in its own frame (start relative to the frame angle)."""

    start_rel: float
    arc: float
    periodic: bool
    preload: float
    l_over_d: float
    n_circ: int
    n_axial: int
    axisymmetric: bool

    def geometry(self) -> BearingGeometry:
        """A one-land bearing (D = 1) with the same discrete land problem."""
        land = Land(self.start_rel, self.arc, 0.0, self.periodic)
        return BearingGeometry(1.0, self.l_over_d, 1e-3, self.preload, (land,), "table")

    @property
    def symmetric(self) -> bool:
        return (not self.axisymmetric and not self.periodic
                and abs(self.start_rel + 0.5 * self.arc) < 1e-12)

    def key(self, res: TableResolution) -> str:
        f = lambda x: f"{x:.12g}"  # noqa: E731
        return "|".join([f"v{TABLE_VERSION}", f(self.start_rel), f(self.arc), str(self.periodic),
                         f(self.preload), f(self.l_over_d), str(self.n_circ), str(self.n_axial),
                         str(self.axisymmetric), str(res.n_radial), str(res.n_angle),
                         str(res.n_direction), f(res.eccentricity_max)])


@dataclass(frozen=True)
class LandTable:
    """Spline table of one land shape (see the module docstring for the layout)."""

    key: str
    a: float
    c0: float
    r_lo: float
    L_u: float
    kappa: float
    has_phi: bool
    phi_periodic: bool
    has_centre: bool
    eccentricity_max: float
    knots_u: np.ndarray
    knots_phi: np.ndarray
    knots_dir: np.ndarray
    coef: np.ndarray  # (n_u, n_phi, n_dir, 2)
    knots_centre: np.ndarray  # g0(psi), periodic (unused without a centre term)
    coef_centre: np.ndarray  # (n, 2)
    build_seconds: float


def land_frames(geometry: BearingGeometry, n_circ: int, n_axial: int):
    """[(LandShape, frame angle theta_k)] for each land of the bearing."""
    if geometry.axisymmetric:
        land = geometry.lands[0]
        return [(LandShape(land.start_rad, land.arc_rad, land.periodic, 0.0, geometry.l_over_d,
                           n_circ, n_axial, True), 0.0)]
    out = []
    for land in geometry.lands:
        if land.periodic:
            raise NotImplementedError("a periodic land in a non-axisymmetric bore has no table")
        th = land.preload_centre_rad if geometry.preload > 0 else land.start_rad + 0.5 * land.arc_rad
        out.append((LandShape(round(land.start_rad - th, 12), round(land.arc_rad, 12), False,
                              geometry.preload, geometry.l_over_d, n_circ, n_axial, False), th))
    return out


def _layout(shape: LandShape, res: TableResolution):
    """Axes and flags of the table of ``shape``."""
    a = 1.0 / (1.0 - shape.preload)
    c0 = a - 1.0
    et = res.eccentricity_max
    if shape.axisymmetric:
        r_lo, phi_nodes, centre, has_phi, phi_per = 0.0, np.zeros(1), False, False, False
    elif c0 >= et + _SECTOR_MARGIN:
        r_lo = c0 - et
        pm = math.asin(et / c0)
        phi_nodes, centre, has_phi, phi_per = np.linspace(-pm, pm, res.n_angle), False, True, False
    else:  # whole circle: twice the angular nodes
        r_lo = 0.0
        phi_nodes = np.linspace(-math.pi, math.pi, 2 * res.n_angle + 1)[:-1]
        centre, has_phi, phi_per = True, True, True
    r_hi = c0 + et
    L_u = math.log((a - r_lo) / (a - r_hi))
    u_nodes = np.linspace(0.0, 1.0, res.n_radial)
    r_nodes = a - (a - r_lo) * np.exp(-L_u * u_nodes)
    dir_nodes = np.linspace(-math.pi, math.pi, res.n_direction + 1)
    return a, c0, r_lo, L_u, u_nodes, r_nodes, phi_nodes, dir_nodes, centre, has_phi, phi_per


def build_table(shape: LandShape, res: TableResolution) -> LandTable:
    """Solve the land LCP at every table node and fit the spline."""
    t0 = time.perf_counter()
    (a, c0, r_lo, L_u, u_nodes, r_nodes, phi_nodes, dir_nodes, centre, has_phi,
     phi_per) = _layout(shape, res)
    geo = shape.geometry()
    solver = ReynoldsSolver(geo, shape.n_circ, shape.n_axial)
    g = solver.grid
    # rhs basis: b_couette is affine in (X, Y) with d/dX -> alpha and d/dY -> beta
    def couette(X, Y):
        return solver._face_divergence(6.0 * _film_at(geo, g.cf_land, g.cf_theta, X, Y) * g.cf_w)
    b0 = couette(0.0, 0.0)
    b_al, b_be = couette(1.0, 0.0) - b0, couette(0.0, 1.0) - b0
    dth = g.land_dtheta[0]
    kappa = 0.5 * dth / math.sin(0.5 * dth)
    cw = 2.0 * g.node_area * np.cos(g.node_theta)
    sw = 2.0 * g.node_area * np.sin(g.node_theta)
    n_r, n_p, n_d = r_nodes.size, phi_nodes.size, res.n_direction
    n_solve = 0

    def film(X, Y):
        Hc = _film_at(geo, g.cf_land, g.cf_theta, X, Y)
        Ha = _film_at(geo, g.af_land, g.af_theta, X, Y)
        gc, ga = solver._conductances(Hc, Ha)
        return gc, ga, solver._diagonal(gc, ga)

    def land_force(op, psi, guess):
        b = math.cos(psi) * b_al + math.sin(psi) * b_be
        P, guess, _, _ = lcp_active_set(solver, *op, b, guess)
        return -(cw @ P), -(sw @ P), guess

    knots_g0, coef_g0 = np.zeros(2 * 3 + 2), np.zeros((2, 2))
    g0 = None
    if centre:  # g0(psi): journal at the centre of curvature
        op, guess, v0 = film(-c0, 0.0), None, np.zeros((n_d + 1, 2))
        for k in range(n_d):
            v0[k, 0], v0[k, 1], guess = land_force(op, dir_nodes[k], guess)
        v0[n_d] = v0[0]
        n_solve += n_d
        (knots_g0,), coef_g0 = fit_tensor_spline((dir_nodes,), (True,), v0)
        g0 = BSpline(knots_g0, coef_g0, 3, extrapolate="periodic")
    vals = np.zeros((n_r, n_p + (1 if phi_per else 0), n_d + 1, 2))
    mirror_p = np.arange(n_p)[::-1] if not phi_per else (-np.arange(n_p)) % n_p
    mirror_d = (n_d // 2 - np.arange(n_d)) % n_d
    todo = [j for j in range(n_p) if not shape.symmetric or mirror_p[j] >= j]
    for i, r in enumerate(r_nodes):
        if centre and i == 0:
            continue  # T = 0 at the centre of curvature by construction
        guess0 = None
        for j in todo:
            phi = phi_nodes[j]
            op = film(r * math.cos(phi) - c0, r * math.sin(phi))
            cp, sp = math.cos(phi), math.sin(phi)
            guess = guess0
            psis = dir_nodes[:n_d] + phi
            base = g0(psis) if centre else np.zeros((n_d, 2))
            for k in range(n_d):
                fx, fy, guess = land_force(op, psis[k], guess)
                if k == 0:
                    guess0 = guess
                n_solve += 1
                fx, fy = fx - base[k, 0], fy - base[k, 1]
                fx, fy = cp * fx + sp * fy, -sp * fx + cp * fy  # radial frame: R(-phi) f
                vals[i, j, k] = fx, fy
                if shape.symmetric:
                    vals[i, mirror_p[j], mirror_d[k]] = fx, -fy
    vals[:, :, n_d] = vals[:, :, 0]
    axes = [u_nodes, phi_nodes, dir_nodes]
    if phi_per:
        vals[:, n_p] = vals[:, 0]
        axes[1] = np.append(phi_nodes, math.pi)
    if not has_phi:
        knots, coef = fit_tensor_spline((axes[0], axes[2]), (False, True), vals[:, 0])
        knots = (knots[0], np.zeros(1), knots[1])
        coef = coef[:, None]
    else:
        knots, coef = fit_tensor_spline(tuple(axes), (False, phi_per, True), vals)
    dt = time.perf_counter() - t0
    log.info("film table %s: %d land solves in %.2f s", shape.key(res), n_solve, dt)
    return LandTable(key=shape.key(res), a=a, c0=c0, r_lo=r_lo, L_u=L_u, kappa=kappa,
                     has_phi=has_phi, phi_periodic=phi_per, has_centre=centre,
                     eccentricity_max=res.eccentricity_max, knots_u=knots[0],
                     knots_phi=knots[1], knots_dir=knots[2], coef=coef,
                     knots_centre=np.ascontiguousarray(knots_g0),
                     coef_centre=np.ascontiguousarray(coef_g0), build_seconds=dt)


def cache_dir() -> Path:
    """``$SPINDLESIM_CACHE/film_tables`` or ``~/.cache/spindlesim/film_tables``."""
    root = os.environ.get("SPINDLESIM_CACHE")
    base = Path(root) if root else Path.home() / ".cache" / "spindlesim"
    return base / "film_tables"


_SCALARS = ("a", "c0", "r_lo", "L_u", "kappa", "has_phi", "phi_periodic", "has_centre",
            "eccentricity_max", "build_seconds")
_ARRAYS = ("knots_u", "knots_phi", "knots_dir", "coef", "knots_centre", "coef_centre")


def _save(table: LandTable, path: Path) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    meta = {"key": table.key, **{k: getattr(table, k) for k in _SCALARS}}
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=path.stem, suffix=".tmp")
    try:
        with os.fdopen(fd, "wb") as fh:
            np.savez(fh, meta=np.array(json.dumps(meta)),
                     **{k: getattr(table, k) for k in _ARRAYS})
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, path)  # atomic: readers see the old file or the complete new one
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def _load(path: Path, key: str) -> LandTable | None:
    try:
        with np.load(path) as z:
            meta = json.loads(str(z["meta"]))
            if meta.get("key") != key:
                return None
            arrays = {k: np.ascontiguousarray(z[k]) for k in _ARRAYS}
    except (OSError, ValueError, KeyError, EOFError, zipfile.BadZipFile) as exc:
        log.warning("film table cache %s unreadable (%s); rebuilding", path, exc)
        return None
    return LandTable(key=key, **{k: meta[k] for k in _SCALARS}, **arrays)


@functools.lru_cache(maxsize=64)
def land_table(shape: LandShape, res: TableResolution, directory: str | None = None) -> LandTable:
    """The table of ``shape`` from memory, the disk cache, or built (and cached)."""
    key = shape.key(res)
    path = Path(directory) if directory else cache_dir()
    path = path / f"film_table_{hashlib.sha256(key.encode()).hexdigest()[:24]}.npz"
    if path.exists():
        table = _load(path, key)
        if table is not None:
            log.debug("film table %s loaded from %s", key, path)
            return table
    table = build_table(shape, res)
    try:
        _save(table, path)
    except OSError as exc:
        log.warning("film table not cached (%s)", exc)
    return table


class TableFilmForce(DimensionalFilmForce):
    """Film force and tangent of a bearing from its land tables (exact solve off the table)."""

    def __init__(self, geometry: BearingGeometry, n_circ: int = DEFAULT_CIRCUMFERENTIAL,
                 n_axial: int = DEFAULT_AXIAL, resolution: TableResolution | None = None,
                 directory: str | os.PathLike | None = None) -> None:
        self.geometry = geometry
        self.resolution = resolution or default_resolution(geometry)
        self.n_circ, self.n_axial = n_circ, n_axial
        groups: dict[LandShape, list[float]] = {}
        for shape, th in land_frames(geometry, n_circ, n_axial):
            groups.setdefault(shape, []).append(th)
        d = str(directory) if directory is not None else None
        self.groups = tuple((land_table(s, self.resolution, d), np.array(ths))
                            for s, ths in groups.items())
        self._eps_max = self.resolution.eccentricity_max
        self._exact: ExactFilmForce | None = None
        self._warned = False

    @property
    def exact(self) -> ExactFilmForce:
        if self._exact is None:
            self._exact = ExactFilmForce(self.geometry, self.n_circ, self.n_axial)
        return self._exact

    def dimensionless(self, X: np.ndarray, Xr: np.ndarray, omega: float):
        """(f, df/dX, df/dX_r), x-y frame; X = q/Cb, X_r = v/Cb [1/s], omega [rad/s]."""
        X = np.ascontiguousarray(X, dtype=float)
        Xr = np.ascontiguousarray(Xr, dtype=float)
        if math.hypot(X[0], X[1]) > self._eps_max:
            if not self._warned:
                log.warning("journal at e/Cb = %.3f beyond the film table (%.3f): exact "
                            "Reynolds solves there", math.hypot(X[0], X[1]), self._eps_max)
                self._warned = True
            return self.exact.dimensionless(X, Xr, omega)
        f = np.zeros(2)
        Jp = np.zeros((2, 2))
        Jr = np.zeros((2, 2))
        for t, thetas in self.groups:
            eval_land_group(X, Xr, float(omega), thetas, t.c0, t.a, t.r_lo, t.L_u, t.kappa,
                            t.has_phi, t.phi_periodic, t.knots_u, t.knots_phi, t.knots_dir,
                            t.coef, t.has_centre, t.knots_centre, t.coef_centre, f, Jp, Jr)
        return f, Jp, Jr

