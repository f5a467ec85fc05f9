"""Quasi-static double-row tapered roller bearing (DTRB), back-to-back (issue 6).

After seed 001 section 2-1 (Kim, Suh, Kim and Yu 2023, following Bercea, Cretu and
Nelias 2003): inner ring with 5 DOF (dX, dY, dZ, phiX, phiY) plus the axial preload
delta0; each roller with 3 DOF found by batched Newton-Raphson (eqs. 33-35); sliced
line contacts with the crowned profile of eq. 1 (eqs. 23-27); rib contact of the
roller's large end (eqs. 28-29); centrifugal force and gyroscopic moment (31-32);
reactions (36-40) and the analytic 5x5 stiffness.

- ``geometry``: bearing and roller geometry, crowned profile (eq. 1), mass properties.
- ``contact``: line-contact law of eqs. 23-26, Hertz point contact for the rib (28-29).
- ``roller_equilibrium``: the batched Newton solve of eqs. 33-35.
- ``reactions``: eqs. 36-40 and the condensed stiffness.
- ``bearing``: :class:`DtrbBearing` (reaction, stiffness, ``solve(load)`` and ``at(displacement)``, linearized).
"""

from spindlesim.lazy import lazy_exports

#: what the package exports and the module defining it: imported on first use (PEP 562), so that a
#: deck loader reading only a section does not pay for the solvers' imports (scipy.signal, numba ...)
_EXPORTS = {
    "DtrbBearing": "bearing",
    "DtrbGeometry": "geometry",
    "dtrb_geometry": "geometry",
}


__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS)



__all__ = ["DtrbBearing", "DtrbGeometry", "dtrb_geometry"]
