"""Angular-contact / deep-groove ball bearing, single row or matched set (DB, DF, DT), 5 DOF.

Quasi-static model after Jones (1960) and Harris and Kotzalas (2007, *Advanced Concepts of
Bearing Technology*, ch. 3): per ball, the inner and outer contact angles and loads from the
ball's equilibrium with centrifugal force and gyroscopic moment (outer-race control, or the
friction couple shared between the races); Hertz point contacts with exact elliptic integrals
(:mod:`spindlesim.contact.hertz`); the set reaction for a 5-DOF inner-ring displacement and its
exact 5x5 tangent; ISO 281 and ISO/TS 16281 lives.

- ``section``, ``section_thermal``: deck keys (:class:`BallBearingEntry`, :class:`BallSection`, the keys of
  the bearing at temperature) and :func:`build`.
- ``geometry``: :class:`BallGeometry` (rows, grooves, Hertz constants) and :func:`ball_geometry`.
- ``kernel``: compiled ball equilibria (Newton, fallback, closed form at rest; outer-, inner-race control
  or the shared couple), row reactions, tangents.
- ``bearing``: :class:`BallBearing` (the bearing contract; states: ``solve(load)`` under a load, ``at(q)`` at a
  displacement); ``equilibrium``: the set equilibrium with DOFs free under the load or held at a displacement
  (:class:`Held`).
- ``kinematics``, ``checks``: the balls' rolling kinematics (spin, roll), Jones' race-control criterion
  and the truncation of the contact ellipses at the shoulders.
- ``rating``: ISO 281 load rating and life, ISO/TS 16281 reference rating life.
- ``results``, ``sweeps``, ``plots``: records, sweeps over preload, load and speed (and the run's
  checks), figures.
- docs/theory.md, "Ball bearings": the equations, sign conventions and choices, with sources.

The embedded default deck of ``spindlesim bearing`` (a 7014C-size DB pair) is
``spindlesim/decks/bearing.yaml``.
"""

from importlib import resources

from .section import BallBearingEntry, BallSection, build, geometry_from, preload_from

__all__ = ["BallBearingEntry", "BallSection", "build", "default_deck_text", "geometry_from", "preload_from"]


def default_deck_text() -> str:
    """Text of the embedded default deck of ``spindlesim bearing`` (``spindlesim/decks/bearing.yaml``)."""
    return resources.files("spindlesim.decks").joinpath("bearing.yaml").read_text(encoding="utf-8")

