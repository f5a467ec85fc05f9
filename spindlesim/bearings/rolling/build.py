"""Build a transient system (rigid_race or flexible_race) from the deck's ``transient:`` section.

All unit conversion to SI happens here.  Sources of the default numbers are
in ``spindlesim/decks/transient.yaml``.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ...analysis.transient import TransientSettings
from .contact_force import CompliantContact
from .flexible_race import FlexibleRaceModel, HousingSupport
from .hertz import EXPONENT_BALL, EXPONENT_ROLLER, palmgren_roller_stiffness, per_contact_stiffness
from .kinematics import CageKinematics
from .outer_race import SegmentedRing
from .rigid_race import RigidRaceBearing, RigidRaceRotor, Waviness


def system_from_section(sec: Any, rollers: int | None = None, model: str | None = None,
                        duration_s: float | None = None):
    """(system, settings) for a validated ``TransientSection``; CLI options override the deck."""
    b = sec.bearing
    n_roll = rollers if rollers is not None else sec.rollers
    which = model if model is not None else sec.model
    T = duration_s if duration_s is not None else sec.duration_s
    kin = CageKinematics(b.inner_raceway_diameter_mm * 1e-3, b.outer_raceway_diameter_mm * 1e-3,
                         b.roller_diameter_mm * 1e-3, b.slip_inner, b.slip_outer)
    if b.element == "ball":
        K, n = float(b.contact_stiffness_N_per_m_n), EXPONENT_BALL
    else:
        K = float(b.contact_stiffness_N_per_m_n or palmgren_roller_stiffness(b.width_mm * 1e-3))
        n = EXPONENT_ROLLER
    omega = sec.speed_rpm * np.pi / 30.0
    load = (0.0, -sec.shaft.radial_load_N)
    damping = sec.shaft.damping_Ns_mm * 1e3
    if which == "rigid_race":
        wav = tuple(Waviness(w.surface, w.waves, w.amplitude_um * 1e-6, np.radians(w.phase_deg))
                    for w in sec.waviness)
        brg = RigidRaceBearing("transient", 0, n_roll, K, n, kin, omega, b.radial_clearance_mm * 1e-3, wav)
        system = RigidRaceRotor(brg, sec.shaft.mass_kg, damping, load)
    elif which == "flexible_race":
        if sec.waviness:
            raise ValueError("waviness is modelled in the rigid_race model only")
        r_out = 0.5 * b.outer_raceway_diameter_mm * 1e-3
        r_h = b.housing_radius_mm * 1e-3
        # radial clearance enlarges the outer raceway
        r_out += b.radial_clearance_mm * 1e-3
        thickness = r_h - r_out
        ring = SegmentedRing(sec.outer_race.segments, 0.5 * (r_out + r_h), thickness, b.width_mm * 1e-3,
                             b.E_GPa * 1e9, b.density_kg_m3)
        kin_f = CageKinematics(b.inner_raceway_diameter_mm * 1e-3, 2 * r_out, b.roller_diameter_mm * 1e-3,
                               b.slip_inner, b.slip_outer)
        c = sec.contact
        rc = CompliantContact(per_contact_stiffness(K, n), n, c.damping_Ns_m2, c.velocity_exponent,
                              c.indentation_exponent, c.friction, c.slip_regularisation_m_s)
        h = sec.housing
        arc = 2.0 * np.pi * r_h / ring.segments  # each segment's share of the bore
        hc = CompliantContact(h.stiffness_N_m2 * arc, 1.0, h.damping_Ns_m2 * arc, 1.0, 0.0, h.friction,
                              c.slip_regularisation_m_s)
        support = HousingSupport(hc, 0.0, h.tangential_stiffness_N_m2 * arc,
                                 rocking_arc_m=arc if h.surface_contact else 0.0)
        system = FlexibleRaceModel(kin_f, n_roll, ring, rc, support,
                                   omega, sec.shaft.mass_kg, damping, load, b.width_mm * 1e-3, b.density_kg_m3)
    else:
        raise ValueError(f"unknown transient model {which!r}")
    it = sec.integrator
    rtol = it.rtol or (1e-5 if which == "flexible_race" else 1e-7)
    settings = TransientSettings(T, settle_s=sec.settle_s if sec.settle_s is not None and sec.settle_s < T else None,
                                 sample_rate_hz=it.sample_rate_hz, method=it.method,
                                 step_s=it.step_us * 1e-6 if it.step_us else None, rtol=rtol, chunks=it.chunks)
    return system, settings
