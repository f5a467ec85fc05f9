"""The transient analysis's deck: ``rotor_transient:`` (any rotor) and the rig section ``transient:``.

``rotor_transient:`` sets the time integration of a rotor deck (``spindlesim transient DECK``).  The rig
section ``transient:`` is seed 000's 2-DOF test rig (issue 4): a rigid journal of ``shaft.mass_kg`` in a
cylindrical roller bearing (the keys of ``type: roller``, ``bearings/roller/section.py``) under
``shaft.radial_load_N``, with its own integrator settings; ``spindlesim.model.rig`` turns it into a rotor
(journal + ``type: roller`` bearing) for the one transient engine.  Every key carries its unit.  Defaults
are seed 000's bearing (Table 1) with the shaft mass of Harsha and Kankar (2004); see
``spindlesim/decks/transient.yaml`` for the source of every number.
"""

from __future__ import annotations

from typing import Annotated, Literal, Optional

from pydantic import Field, model_validator

from ..bearings.roller.section import (RollerContact, RollerGeometry, RollerHousing, RollerOuterRace, Rollers,
                                       RollerWaviness, check_geometry)
from ..fields import ANY_NUMBER, DeckModel, Dof, NodeNumber, NonNegFloat, PositiveFloat


class Perturbation(DeckModel):
    """A static force held until t = 0 and then released (free vibration from a smooth shape)."""

    node: NodeNumber
    """Node number (1-based) where the force is applied."""
    dof: Dof = "x"
    """Direction of the force (a rotation DOF gives a moment, in N m)."""
    force_N: float = 100.0
    """Static force held until t = 0 and then released: the run starts from the deflected shape, at rest."""


class SpeedRamp(DeckModel):
    """A linear speed ramp over the whole run (a run-up or run-down)."""

    start: Annotated[float, Field(ge=0, le=ANY_NUMBER)]
    """Shaft speed at t = 0 (in rpm, the unit of `speed_rpm`)."""
    stop: Annotated[float, Field(ge=0, le=ANY_NUMBER)]
    """Shaft speed at the end of the run (rpm); the speed changes linearly in between and the bearings'
    forces and the shaft's gyroscopic terms follow it, while what the operating point at `operating.speed_rpm`
    sets (a fluid film's thermal-equilibrium viscosity) stays fixed."""


class TimeLoad(DeckModel):
    """A force in time at a node: ``harmonic`` amplitude sin(2 pi f t + phase), f given in Hz or as
    an ``order`` of the shaft speed; a ``step`` switched on at ``time_s``; or a ``ramp`` that grows
    linearly to its amplitude at ``time_s``."""

    node: NodeNumber
    """Node number (1-based) the load acts on."""
    dof: Dof = "x"
    """Direction of the load (a rotation DOF gives a moment, in N m)."""
    kind: Literal["harmonic", "step", "ramp"] = "harmonic"
    """harmonic: amplitude sin(2 pi f t + phase) or sin(order x shaft angle + phase); step: the full amplitude
    from `time_s` on; ramp: grows linearly from 0 at t = 0 to the full amplitude at `time_s`, then stays."""
    amplitude_N: float
    """Amplitude of the force (of the moment in N m for a rotation DOF); the sign sets its direction."""
    frequency_hz: Optional[PositiveFloat] = None
    """Frequency of a harmonic load; give this or `order`, not both."""
    order: Optional[Annotated[float, Field(gt=0, le=1000.0)]] = None
    """Frequency of a harmonic load as a multiple of the shaft speed (its phase follows the shaft angle, also
    during a speed ramp); give this or `frequency_hz`."""
    phase_deg: float = 0.0
    """Phase of a harmonic load at t = 0."""
    time_s: NonNegFloat = 0.0
    """Switch-on time of a step; time at which a ramp reaches its amplitude (0: the full amplitude from the
    start)."""

    @model_validator(mode="after")
    def _frequency(self) -> "TimeLoad":
        if self.kind == "harmonic" and (self.frequency_hz is None) == (self.order is None):
            raise ValueError("a harmonic load needs exactly one of frequency_hz and order")
        return self


class RotorTransientSection(DeckModel):
    """Time response of the rotor with its bearings' full nonlinear reactions (``spindlesim transient``)."""

    duration_s: PositiveFloat = 0.5
    """Simulated time (`spindlesim transient --duration` overrides it)."""
    # newmark: implicit average acceleration + Newton (any bearing); rk4: explicit fixed step with
    # compiled bearing forces; RK45, DOP853, Radau, BDF, LSODA: scipy's adaptive methods (a cross-check)
    method: Literal["newmark", "rk4", "RK45", "DOP853", "Radau", "BDF", "LSODA"] = "newmark"
    """Time integrator: newmark (implicit average acceleration with Newton iterations, any bearing); rk4
    (explicit, fixed step, compiled bearing forces); RK45, DOP853, Radau, BDF, LSODA (scipy's adaptive methods,
    slower: a cross-check)."""
    time_step_s: Optional[PositiveFloat] = None  # newmark default 5e-5; rk4 default: min(1 us, stability)
    """Largest time step; the step used is the largest one not above it that lands on every sample. None: 5e-5 s
    for newmark; for rk4 the smaller of 1 us and its stability limit."""
    sample_rate_hz: Optional[PositiveFloat] = None
    """Rate of the recorded samples. None: every step for newmark; otherwise 50 samples per roller pass of the
    first roller bearing (per revolution without one), at least 2 kHz."""
    rtol: Optional[Annotated[float, Field(gt=0, lt=1e-2)]] = None  # scipy methods
    """Relative tolerance of the scipy methods (ignored by newmark and rk4). None: 1e-8."""
    record_node: Optional[NodeNumber] = None  # default: the first bearing's node
    """Node whose response is recorded and plotted (orbit, spectrum). None: the node of the first bearing."""
    settle_fraction: Annotated[float, Field(ge=0.0, lt=1.0)] = 0.3  # start of the steady part for the spectrum
    """Start of the steady part used for the spectrum and the Poincare map, as a fraction of the duration."""
    unbalance: bool = True  # apply the deck's unbalance section
    """true: apply the deck's `unbalance` section (rotating with the shaft) when it has one."""
    speed_rpm: Optional[SpeedRamp] = None  # a run-up / run-down; default: operating.speed_rpm constant
    """A linear run-up or run-down over the whole run. None: constant `operating.speed_rpm`."""
    loads: Annotated[list[TimeLoad], Field(max_length=1000)] = []
    """Forces in time at nodes, added to the static loads (point loads and gravity)."""
    perturbation: Optional[Perturbation] = None
    """Start from the shape deflected by a static force that is released at t = 0. None: start from the static
    equilibrium."""


class TransientShaft(DeckModel):
    mass_kg: PositiveFloat = 0.6
    """Mass of the rigid journal (shaft) in the bearing."""
    damping_Ns_mm: NonNegFloat = 0.2
    """Viscous damping of the journal to ground in x and in y (in N s/mm: 1 N s/mm = 1000 N s/m)."""
    radial_load_N: NonNegFloat = 6.0  # along -y (gravity direction)
    """Constant radial load on the journal along -y (gravity direction)."""


class TransientIntegrator(DeckModel):
    # RK4: compiled fixed-step RK4 (default); the others are scipy's adaptive solve_ivp methods on the
    # numpy right-hand side (slow: a cross-check).  step_us bounds the RK4 step (default: 1 us for the
    # rigid race, the stability limit, at most 2 us, for the flexible race); rtol is for the adaptive methods
    # (default 1e-7 rigid race, 1e-5 flexible race).
    method: Literal["RK4", "RK45", "DOP853", "LSODA", "BDF", "Radau"] = "RK4"
    """RK4: compiled fixed-step Runge-Kutta (default); RK45, DOP853, LSODA, BDF, Radau: scipy's adaptive methods
    on the numpy right-hand side (slow: a cross-check)."""
    step_us: Optional[PositiveFloat] = None
    """Largest RK4 step. None: 1 us for the rigid race, the RK4 stability limit (at most 2 us) for the flexible
    race."""
    rtol: Optional[Annotated[float, Field(gt=0, lt=1e-2)]] = None
    """Relative tolerance of the adaptive methods. None: 1e-7 for the rigid race, 1e-5 for the flexible race."""
    sample_rate_hz: Optional[PositiveFloat] = None
    """Rate of the recorded samples. None: 50 samples per roller pass, at least 2 kHz (RK4 rounds it to a whole
    number of samples per roller pass)."""
    chunks: Annotated[int, Field(ge=1, le=100000)] = 40
    """Pieces the run is integrated in; Ctrl-C between two keeps what was computed."""


class TransientSection(DeckModel):
    """The rig section ``transient:``: seed 000's 2-DOF test rig (rigid journal in the bearing)."""

    model: Literal["flexible_race", "rigid_race"] = "flexible_race"
    """flexible_race: seed 000's segmented flexible outer race; rigid_race: rigid rings, 2 DOF (Harsha and
    Kankar, Sunnersjo). `spindlesim transient --model` overrides it."""
    rollers: Rollers = 8
    """Number of rollers (`--rollers` overrides it)."""
    duration_s: PositiveFloat = 0.3
    """Simulated time (`--duration` overrides it)."""
    settle_s: Optional[NonNegFloat] = None
    """Start of the steady part used for the spectrum and the Poincare map; shorter than `duration_s`. None: 40
    % of the run."""
    speed_rpm: NonNegFloat = 5000.0
    """Speed of the inner ring (the journal)."""
    bearing: RollerGeometry = RollerGeometry()
    """The bearing's geometry and material."""
    shaft: TransientShaft = TransientShaft()
    """The rigid journal: mass, damping and load."""
    outer_race: RollerOuterRace = RollerOuterRace()
    """The flexible outer race (flexible_race model)."""
    contact: RollerContact = RollerContact()
    """Damping and friction of the roller contacts (flexible_race model)."""
    housing: RollerHousing = RollerHousing()
    """Support of the outer race by the housing (flexible_race model)."""
    waviness: Annotated[list[RollerWaviness], Field(max_length=64)] = []
    """Surface waviness of the raceways or rollers (rigid_race model only)."""
    integrator: TransientIntegrator = TransientIntegrator()
    """Time integration settings."""

    @model_validator(mode="after")
    def _consistent(self) -> "TransientSection":
        check_geometry(self.bearing, self.model)
        if self.settle_s is not None and self.settle_s >= self.duration_s:
            raise ValueError("settle_s must be shorter than duration_s")
        if self.model == "flexible_race" and self.waviness:
            raise ValueError("waviness is modelled in the rigid_race model only")
        return self
