"""Finite-volume Reynolds equation with the Reynolds (Swift-Stieber) cavitation condition.

Dimensionless incompressible, isoviscous Reynolds equation (e.g. Hamrock, Schmid &
Jacobson, Fundamentals of Fluid Film Lubrication, 2nd ed., ch. 7; Lund & Thomsen 1978)::

    d/dtheta(H^3 dP/dtheta) + d/dzeta(H^3 dP/dzeta) = 6 dH/dtheta + 12 dH/dtau

with ``H = h/Cb``, ``zeta = z/R`` (``|zeta| <= L/D``), ``tau = omega t`` and
``P = p Cb^2 / (mu omega R^2)``.  Only the half width ``0 <= zeta <= L/D`` is solved
(the film is symmetric about the mid-plane for an aligned journal): Neumann condition at
``zeta = 0``, ``P = 0`` at the bearing edge and at the grooves (land edges).

Cavitation (Reynolds / Swift-Stieber condition: ``P >= 0`` and ``dP/dn = 0`` on the free
boundary) is the obstacle problem of Cryer (1971) / Kinderlehrer & Stampacchia: with the
discrete operator ``A P = b`` (A symmetric M-matrix)::

    P >= 0,   w = A P - b >= 0,   P . w = 0

a linear complementarity problem.  It is solved exactly (up to round-off) by the
primal-dual active-set method of Hintermueller, Ito & Kunisch (SIAM J. Optim. 13, 2003),
which for M-matrices converges monotonically in a finite number of steps; each step is
one sparse LU solve on the current full-film (inactive) set.

Perturbations (coefficients and Newton Jacobian) are the exact derivatives of the
discrete solution for a fixed full-film set (Lund's first-order perturbation with the
cavitation boundary held fixed, which is exact to first order for the Reynolds condition
because P and grad P vanish there).
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from scipy.linalg.lapack import dpbtrf, dpbtrs

from spindlesim.bearings.fluidfilm.geometry import BearingGeometry

log = logging.getLogger(__name__)

#: Default grid, chosen by the grid-convergence study (docs/validation.md):
#: intervals per 360 deg of circumference and across the half width.
DEFAULT_CIRCUMFERENTIAL = 192
DEFAULT_AXIAL = 12


class ReynoldsError(RuntimeError, ArithmeticError):
    """The complementarity solve failed (should not happen for a valid film), or the journal touches the
    bore.  An ArithmeticError too: the failure the bearing contract's solvers catch (a transient's Newton
    iterate pushed through the bore ends its step's iterations, not the program)."""


@dataclass(frozen=True)
class Grid:
    """Finite-volume grid of all lands of one bearing (pattern only, no film values).

    Unknowns are the nodes with free pressure.  Circumferential faces join
    ``cf_left``/``cf_right`` (index -1: a Dirichlet node with P = 0) at angle
    ``cf_theta`` with axial width ``cf_w`` and spacing ``cf_dtheta``; axial faces join
    ``af_low``/``af_high`` at node angle ``af_theta`` with circumferential width
    ``af_dtheta`` and spacing ``af_dzeta``.
    """

    n_unknown: int
    node_theta: np.ndarray
    node_area: np.ndarray  # dtheta * w_j (half width); full-width integrals use 2x
    node_land: np.ndarray
    node_j: np.ndarray
    cf_left: np.ndarray
    cf_right: np.ndarray
    cf_theta: np.ndarray
    cf_w: np.ndarray
    cf_dtheta: np.ndarray
    cf_land: np.ndarray
    cf_entry: np.ndarray  # True on the leading-edge face of a non-periodic land
    af_low: np.ndarray
    af_high: np.ndarray
    af_theta: np.ndarray
    af_dtheta: np.ndarray
    af_dzeta: np.ndarray
    af_land: np.ndarray
    af_edge: np.ndarray  # True on the face to the bearing edge (side leakage)
    land_theta_mid: tuple  # per land: midpoints of intervals (for shear integral)
    land_dtheta: tuple
    n_circ: int
    n_axial: int
    half_width: float  # L/D, the zeta extent of the half bearing

    @classmethod
    def build(
        cls,
        geometry: BearingGeometry,
        n_circ: int = DEFAULT_CIRCUMFERENTIAL,
        n_axial: int = DEFAULT_AXIAL,
    ) -> "Grid":
        """Grid with about ``n_circ`` intervals per 360 deg and ``n_axial`` across L/2."""
        if n_circ < 8 or n_axial < 2:
            raise ValueError("grid too coarse")
        half = geometry.l_over_d
        dz = half / n_axial
        w = np.full(n_axial, dz)
        w[0] = 0.5 * dz  # half control volume on the symmetry plane
        th_nodes, areas, lands_of, js = [], [], [], []
        cf = {k: [] for k in ("l", "r", "t", "w", "d", "land", "entry")}
        af = {k: [] for k in ("lo", "hi", "t", "d", "dz", "land", "edge")}
        mids, dths = [], []
        offset = 0
        for li, land in enumerate(geometry.lands):
            n = max(8, int(round(n_circ * land.arc_rad / (2 * math.pi))))
            dth = land.arc_rad / n
            theta = land.start_rad + dth * np.arange(n + 1)
            mids.append(land.start_rad + dth * (np.arange(n) + 0.5))
            dths.append(dth)
            if land.periodic:
                free_i = np.arange(n)  # node n is node 0
            else:
                free_i = np.arange(1, n)
            ni = free_i.size
            index = np.full((n + 1, n_axial + 1), -1, dtype=np.int64)
            index[free_i[:, None], np.arange(n_axial)[None, :]] = (
                offset + np.arange(ni * n_axial).reshape(ni, n_axial)
            )
            if land.periodic:
                index[n, :] = index[0, :]
            offset += ni * n_axial
            ii, jj = np.meshgrid(free_i, np.arange(n_axial), indexing="ij")
            th_nodes.append(theta[ii].ravel())
            areas.append((dth * w[jj]).ravel())
            lands_of.append(np.full(ii.size, li))
            js.append(jj.ravel())
            # circumferential faces between node i and i+1, i = 0..n-1
            fi, fj = np.meshgrid(np.arange(n), np.arange(n_axial), indexing="ij")
            cf["l"].append(index[fi, fj].ravel())
            cf["r"].append(index[fi + 1, fj].ravel())
            cf["t"].append((land.start_rad + dth * (fi + 0.5)).ravel())
            cf["w"].append(w[fj].ravel())
            cf["d"].append(np.full(fi.size, dth))
            cf["land"].append(np.full(fi.size, li))
            cf["entry"].append(((fi == 0) & (not land.periodic)).ravel())
            # axial faces between j and j+1 at free nodes
            ai, aj = np.meshgrid(free_i, np.arange(n_axial), indexing="ij")
            af["lo"].append(index[ai, aj].ravel())
            af["hi"].append(index[ai, aj + 1].ravel())
            af["t"].append(theta[ai].ravel())
            af["d"].append(np.full(ai.size, dth))
            af["dz"].append(np.full(ai.size, dz))
            af["land"].append(np.full(ai.size, li))
            af["edge"].append((aj == n_axial - 1).ravel())
        cat = np.concatenate
        return cls(
            n_unknown=offset,
            node_theta=cat(th_nodes),
            node_area=cat(areas),
            node_land=cat(lands_of),
            node_j=cat(js),
            cf_left=cat(cf["l"]),
            cf_right=cat(cf["r"]),
            cf_theta=cat(cf["t"]),
            cf_w=cat(cf["w"]),
            cf_dtheta=cat(cf["d"]),
            cf_land=cat(cf["land"]),
            cf_entry=cat(cf["entry"]),
            af_low=cat(af["lo"]),
            af_high=cat(af["hi"]),
            af_theta=cat(af["t"]),
            af_dtheta=cat(af["d"]),
            af_dzeta=cat(af["dz"]),
            af_land=cat(af["land"]),
            af_edge=cat(af["edge"]),
            land_theta_mid=tuple(mids),
            land_dtheta=tuple(dths),
            n_circ=n_circ,
            n_axial=n_axial,
            half_width=half,
        )


def _film_at(geometry: BearingGeometry, land_idx: np.ndarray, theta: np.ndarray,
             X: float, Y: float) -> np.ndarray:
    """H at angles ``theta`` belonging to lands ``land_idx`` (vectorised over lands)."""
    a = 1.0 / (1.0 - geometry.preload)
    centres = np.array([ld.preload_centre_rad for ld in geometry.lands])[land_idx]
    return a - (a - 1.0) * np.cos(theta - centres) - X * np.cos(theta) - Y * np.sin(theta)


@dataclass(frozen=True)
class FilmSolution:
    """Solution of the Reynolds equation for one journal position (dimensionless).

    Forces are on the journal, ``F = mu omega R^4 / Cb^2 * force``; the Jacobians are
    ``d force / d(X, Y)`` and ``d force / d(X', Y')`` with ``X' = dX/dtau``.
    """

    X: float
    Y: float
    pressure: np.ndarray  # P on the grid unknowns (>= 0)
    force: np.ndarray  # (2,)
    jac_position: np.ndarray  # (2, 2)
    jac_velocity: np.ndarray  # (2, 2)
    friction: float  # int int (1/H + H/2 dP/dtheta) dtheta dzeta over the lands, full width
    inlet_flow: float  # int (H/2 - H^3/12 dP/dtheta) dzeta at the land leading edges, full width
    side_flow: float  # leakage through both bearing edges
    min_film: float  # min H over the lands
    full_film: np.ndarray  # bool mask of the full-film (inactive) set
    iterations: int


class ReynoldsSolver:
    """Assemble and solve the FV Reynolds equation for a bearing geometry on a grid."""

    def __init__(self, geometry: BearingGeometry, n_circ: int = DEFAULT_CIRCUMFERENTIAL,
                 n_axial: int = DEFAULT_AXIAL) -> None:
        self.geometry = geometry
        self.grid = Grid.build(geometry, n_circ, n_axial)
        g = self.grid
        n = g.n_unknown
        # sparse pattern: for each face with both ends free, two off-diagonal entries
        cl, cr = g.cf_left, g.cf_right
        both_c = (cl >= 0) & (cr >= 0)
        lo, hi = g.af_low, g.af_high
        both_a = (lo >= 0) & (hi >= 0)
        self._both_c, self._both_a = both_c, both_a
        rows = np.concatenate([cl[both_c], cr[both_c], lo[both_a], hi[both_a], np.arange(n)])
        cols = np.concatenate([cr[both_c], cl[both_c], hi[both_a], lo[both_a], np.arange(n)])
        self._rows, self._cols = rows, cols
        self._off_l = np.concatenate([cl, lo])
        self._off_r = np.concatenate([cr, hi])
        self._cos_n, self._sin_n = np.cos(g.node_theta), np.sin(g.node_theta)
        self._cos_cf, self._sin_cf = np.cos(g.cf_theta), np.sin(g.cf_theta)
        self._cos_af, self._sin_af = np.cos(g.af_theta), np.sin(g.af_theta)
        self._mid_land = np.concatenate(
            [np.full(m.size, i) for i, m in enumerate(g.land_theta_mid)])
        self._mid_theta = np.concatenate(g.land_theta_mid)
        self._mid_dth = np.concatenate(
            [np.full(m.size, d) for m, d in zip(g.land_theta_mid, g.land_dtheta)])
        # what does not change with the journal position, computed once (a solve's hot loop):
        # H = base - X cos(theta) - Y sin(theta), base = a - (a - 1) cos(theta - land centre)
        self._base_cf = _film_at(geometry, g.cf_land, g.cf_theta, 0.0, 0.0)
        self._base_af = _film_at(geometry, g.af_land, g.af_theta, 0.0, 0.0)
        self._base_mid = _film_at(geometry, self._mid_land, self._mid_theta, 0.0, 0.0)
        self._cos_mid, self._sin_mid = np.cos(self._mid_theta), np.sin(self._mid_theta)
        # the faces' nodes that are unknowns (index -1: a Dirichlet boundary), for np.bincount
        self._free = tuple((idx >= 0, idx[idx >= 0]) for idx in (cl, cr, lo, hi))
        # what the derivatives and the flows of a solve take from the grid alone
        self._d_rhs = tuple(self._face_divergence(6.0 * -cq_c * g.cf_w) for cq_c in (self._cos_cf, self._sin_cf))
        self._squeeze_rhs = tuple(12.0 * cq_n * g.node_area for cq_n in (self._cos_n, self._sin_n))
        ent = np.flatnonzero(g.cf_entry)
        self._entry = ent
        self._entry_at = (g.cf_land[ent], g.cf_theta[ent] - 0.5 * g.cf_dtheta[ent])
        self._entry_first = np.isin(ent, ent[g.node_j[np.maximum(g.cf_right[ent], 0)] == 0])
        self._edge = np.flatnonzero(g.af_edge)
        self._last_pattern = None  # (full-film set's bytes, its pattern): ``_pattern``

    # -- assembly -------------------------------------------------------------
    def _conductances(self, Hc: np.ndarray, Ha: np.ndarray):
        g = self.grid
        gc = Hc**3 * g.cf_w / g.cf_dtheta
        ga = Ha**3 * g.af_dtheta / g.af_dzeta
        return gc, ga

    def _matrix(self, gc: np.ndarray, ga: np.ndarray) -> sp.csc_matrix:
        g = self.grid
        n = g.n_unknown
        diag = np.zeros(n)
        for idx, val in ((g.cf_left, gc), (g.cf_right, gc), (g.af_low, ga), (g.af_high, ga)):
            m = idx >= 0
            diag += np.bincount(idx[m], weights=val[m], minlength=n)
        data = np.concatenate(
            [-gc[self._both_c], -gc[self._both_c], -ga[self._both_a], -ga[self._both_a], diag])
        return sp.csc_matrix((data, (self._rows, self._cols)), shape=(n, n))

    def _face_divergence(self, flux_c: np.ndarray) -> np.ndarray:
        """Net circumferential flux into each node: + from the left face, - to the right."""
        n = self.grid.n_unknown
        (ml, il), (mr, ir) = self._free[0], self._free[1]
        return np.bincount(ir, weights=flux_c[mr], minlength=n) - np.bincount(il, weights=flux_c[ml], minlength=n)

    def _apply_face_operator(self, gc: np.ndarray, ga: np.ndarray, P: np.ndarray) -> np.ndarray:
        """(A(g) P) for arbitrary face weights g (used for dA/dq P)."""
        g = self.grid
        n = g.n_unknown
        Pf = np.concatenate([P, [0.0]])  # index -1 -> Dirichlet zero
        out = np.zeros(n)
        cl, cr, lo, hi = self._free
        for left, right, val, (m_l, i_l), (m_r, i_r) in ((g.cf_left, g.cf_right, gc, cl, cr),
                                                         (g.af_low, g.af_high, ga, lo, hi)):
            d = val * (Pf[left] - Pf[right])
            out += np.bincount(i_l, weights=d[m_l], minlength=n)
            out -= np.bincount(i_r, weights=d[m_r], minlength=n)
        return out

    def _diagonal(self, gc: np.ndarray, ga: np.ndarray) -> np.ndarray:
        n = self.grid.n_unknown
        diag = np.zeros(n)
        for (m, idx), val in zip(self._free, (gc, gc, ga, ga)):
            diag += np.bincount(idx, weights=val[m], minlength=n)
        return diag

    def _pattern(self, inactive: np.ndarray):
        """(unknowns of the full-film set, faces inside it, their lower and upper unknown, the half bandwidth, the
        faces' places in the band storage) of a full-film set: the last one's kept (a warm solve's set seldom
        changes between the solves of an equilibrium or a sweep)."""
        key = inactive.tobytes()
        last = self._last_pattern  # read once: another thread may replace it meanwhile
        if last is not None and last[0] == key:
            return last[1]
        n = self.grid.n_unknown
        idx = np.flatnonzero(inactive)
        mp = np.full(n + 1, -1, dtype=np.int64)  # mp[-1] (Dirichlet) stays -1
        mp[idx] = np.arange(idx.size)
        li, ri = mp[self._off_l], mp[self._off_r]
        ok = (li >= 0) & (ri >= 0)
        i, j = np.minimum(li, ri)[ok], np.maximum(li, ri)[ok]
        u = int((j - i).max()) if j.size else 0
        pattern = (idx, ok, i, j, u, (u + i - j, j))
        self._last_pattern = (key, pattern)
        return pattern

    def _factor(self, gc: np.ndarray, ga: np.ndarray, diag: np.ndarray, inactive: np.ndarray):
        """Factorise A restricted to the full-film set; returns a solve function.

        Unknowns are numbered circumferential-major, so the restricted matrix is banded
        (half bandwidth <= axial nodes) and a banded Cholesky factorisation is used; a
        periodic (groove-less) land couples its first and last columns and falls back to
        a sparse LU.
        """
        g = self.grid
        idx, ok, i, j, u, band = self._pattern(inactive)
        m = idx.size
        v = -np.concatenate([gc, ga])[ok]
        if u <= 4 * g.n_axial:
            ab = np.zeros((u + 1, m))
            ab[u, :] = diag[idx]
            ab[band] = v
            # LAPACK's banded Cholesky directly: what scipy.linalg.cholesky_banded and cho_solve_banded
            # call, without their per-call argument handling (a tenth of a warm Reynolds solve)
            cb, info = dpbtrf(ab, lower=0)
            if info != 0:
                raise np.linalg.LinAlgError(f"{info}-th leading minor not positive definite")
            return lambda rhs: dpbtrs(cb, rhs, lower=0)[0]
        A = sp.csc_matrix((np.concatenate([v, v, diag[idx]]),
                           (np.concatenate([i, j, np.arange(m)]),
                            np.concatenate([j, i, np.arange(m)]))), shape=(m, m))
        return spla.splu(A).solve

    def _system(self, Hc, gc, ga, Xdot, Ydot):
        g = self.grid
        A = self._matrix(gc, ga)
        b = self._face_divergence(6.0 * Hc * g.cf_w)
        if Xdot or Ydot:  # squeeze term: -12 dH/dtau * area, dH/dtau = -X' cos - Y' sin
            b = b + 12.0 * (Xdot * self._cos_n + Ydot * self._sin_n) * g.node_area
        return A, b

    def assemble(self, X: float, Y: float, Xdot: float = 0.0, Ydot: float = 0.0):
        """The discrete system (A, b) of ``A P = b`` on the full-film region (for checks)."""
        geo, g = self.geometry, self.grid
        Hc = _film_at(geo, g.cf_land, g.cf_theta, X, Y)
        Ha = _film_at(geo, g.af_land, g.af_theta, X, Y)
        return self._system(Hc, *self._conductances(Hc, Ha), Xdot, Ydot)

    # -- solve ----------------------------------------------------------------
    def film_heights(self, X: float, Y: float):
        """(H at the circumferential faces, H at the axial faces, H at the cell middles) at the journal
        position (X, Y) = e / Cb; ReynoldsError when the journal touches the bore."""
        Hc = self._base_cf - X * self._cos_cf - Y * self._sin_cf
        Ha = self._base_af - X * self._cos_af - Y * self._sin_af
        Hmid = self._base_mid - X * self._cos_mid - Y * self._sin_mid
        hmin = float(min(Hc.min(), Ha.min(), Hmid.min()))  # an axial face too: its conductance goes as H^3
        if hmin <= 0.0:
            raise ReynoldsError(f"journal position X={X:.4f}, Y={Y:.4f} (e/Cb {math.hypot(X, Y):.4f}) touches "
                                f"the bore (min H {hmin:.3g})")
        return Hc, Ha, Hmid

    def solve(self, X: float, Y: float, full_film_guess: np.ndarray | None = None,
              max_iter: int = 200, Xdot: float = 0.0, Ydot: float = 0.0) -> FilmSolution:
        """Film at the journal position (X, Y) = e / Cb.

        ``Xdot``, ``Ydot`` are the journal velocities dX/dtau (0 for the static film; used
        to verify the damping coefficients by finite differences).
        """
        geo, g = self.geometry, self.grid
        Hc, Ha, Hmid = self.film_heights(X, Y)
        gc, ga = self._conductances(Hc, Ha)
        b = self._face_divergence(6.0 * Hc * g.cf_w)
        if Xdot or Ydot:  # squeeze term: -12 dH/dtau * area, dH/dtau = -X' cos - Y' sin
            b = b + 12.0 * (Xdot * self._cos_n + Ydot * self._sin_n) * g.node_area
        n = g.n_unknown
        dA = self._diagonal(gc, ga)
        if full_film_guess is None:
            inactive = np.ones(n, dtype=bool)
        else:
            inactive = full_film_guess.copy()
        P = np.zeros(n)
        lu = None
        for it in range(1, max_iter + 1):
            P = np.zeros(n)
            if inactive.any():
                lu = self._factor(gc, ga, dA, inactive)
                P[inactive] = lu(b[inactive])
            lam = self._apply_face_operator(gc, ga, P) - b  # A P - b
            lam[inactive] = 0.0
            new_active = (lam - dA * P) > 0.0
            new_inactive = ~new_active
            if np.array_equal(new_inactive, inactive):
                break
            inactive = new_inactive
        else:
            raise ReynoldsError(f"active-set iteration did not converge in {max_iter} steps")
        P[~inactive] = 0.0
        idx = np.flatnonzero(inactive)
        # forces on the journal: F = -int p n dA  (n = (cos, sin) outward from journal centre)
        wgt = 2.0 * g.node_area
        force = -np.array([np.sum(P * self._cos_n * wgt), np.sum(P * self._sin_n * wgt)])
        # derivatives for a fixed full-film set
        jp = np.zeros((2, 2))
        jv = np.zeros((2, 2))
        if idx.size:
            rhs = []
            for cq_c, cq_a, db in ((self._cos_cf, self._cos_af, self._d_rhs[0]),
                                   (self._sin_cf, self._sin_af, self._d_rhs[1])):
                dHc, dHa = -cq_c, -cq_a  # db: the divergence of 6 dHc w (the grid's, computed once)
                dgc = 3.0 * Hc**2 * dHc * g.cf_w / g.cf_dtheta
                dga = 3.0 * Ha**2 * dHa * g.af_dtheta / g.af_dzeta
                rhs.append(db - self._apply_face_operator(dgc, dga, P))
            # b = -... - 12 dH/dtau * area with dH/dtau = -X' cos - Y' sin
            rhs.extend(self._squeeze_rhs)
            R = np.stack([r[idx] for r in rhs], axis=1)
            dP = lu(R)
            c, s = self._cos_n[idx] * wgt[idx], self._sin_n[idx] * wgt[idx]
            for k in range(4):
                col = -np.array([c @ dP[:, k], s @ dP[:, k]])
                if k < 2:
                    jp[:, k] = col
                else:
                    jv[:, k - 2] = col
        # friction: shear on the journal, full film over every land (Raimondi & Boyd)
        Pf = np.concatenate([P, [0.0]])
        dPc = Pf[g.cf_right] - Pf[g.cf_left]
        friction = float(np.sum(self._mid_dth / Hmid) * 2.0 * g.half_width
                         + np.sum(0.5 * Hc * dPc * g.cf_w) * 2.0)
        # flows (x 1/12 of the FV flux 6 H w - g dP), both halves
        qc = (6.0 * Hc * g.cf_w - gc * dPc) / 12.0
        # inlet flow at the land's leading edge (theta_0, P_0 = 0): Couette flow with
        # H(theta_0) and a second-order one-sided pressure gradient (4 P1 - P2)/(2 dth)
        ent = self._entry
        H0 = _film_at(geo, *self._entry_at, X, Y)
        p1 = Pf[g.cf_right[ent]]
        p2 = Pf[g.cf_right[ent + g.n_axial]]
        dp0 = (4.0 * p1 - p2) / (2.0 * g.cf_dtheta[ent])
        inlet = float(2.0 * np.sum((0.5 * H0 - H0**3 * dp0 / 12.0) * g.cf_w[ent]))
        # Couette flow through the edge strip zeta in [L/D - dz/2, L/D] (P = 0 there),
        # which belongs to no control volume
        dz = g.half_width / g.n_axial
        inlet += float(2.0 * np.sum(0.5 * H0[self._entry_first] * 0.5 * dz))
        # side leakage through the edges: -H^3/12 dP/dzeta at zeta = L/D with the
        # second-order one-sided gradient (P_edge = 0): (4 P_{m-1} - P_{m-2}) / (2 dz)
        edge = self._edge
        pm1 = Pf[g.af_low[edge]]
        pm2 = Pf[g.af_low[edge - 1]]
        side = float(2.0 * np.sum(Ha[edge] ** 3 * (4.0 * pm1 - pm2) / (2.0 * g.af_dzeta[edge])
                                  * g.af_dtheta[edge]) / 12.0)
        if not ent.size:
            # 360 deg film closed on itself (feed="periodic", not the default): there is
            # no leading edge; report the largest circumferential flow through any
            # section (an estimate of the flow carried round, not validated)
            per_theta = np.bincount(np.searchsorted(np.unique(g.cf_theta), g.cf_theta),
                                    weights=qc)
            inlet = float(2.0 * per_theta.max())
        log.debug("Reynolds: X=%.5f Y=%.5f active-set iterations %d, full film %d/%d",
                  X, Y, it, idx.size, n)
        return FilmSolution(X=X, Y=Y, pressure=P, force=force, jac_position=jp,
                            jac_velocity=jv, friction=friction, inlet_flow=inlet,
                            side_flow=side, min_film=float(min(Hc.min(), Hmid.min())), full_film=inactive,
                            iterations=it)

