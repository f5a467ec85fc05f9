"""Deck section ``chatter:``: the process, the speeds, the method and where the tool-point FRF comes from.

Keys carry their units; :func:`build_chatter` converts to the SI dataclasses of the package.

    chatter:
      operation: milling             # turning | boring | grinding | milling
      speeds_rpm: {start: 5000, stop: 25000, count: 200}
      method: auto                   # auto | zero_order | semi_discretization (milling)
                                     # auto | oriented_frf | semi_discretization (turning ...)
      Kt_N_mm2: 600.0                # milling: Kt with Kn_N_mm2 or Kr (= Kn / Kt)
      Kn_N_mm2: 200.0
      teeth: 2
      tool_diameter_mm: 20.0
      radial_depth_mm: 1.0
      mode: down                     # up | down
      helix_deg: 0.0                 # optional
      feed_direction_deg: 0.0        # feed direction in the tool-point x-y frame
      frf: rotor                     # rotor | {modes: [...]} | {file: {...}} | {files: [...]}
      frf_at_each_speed: true        # recompute the rotor's tool-point FRF at every speed

    chatter:
      operation: turning
      Ks_N_mm2: 2000.0
      force_angle_deg: 70.0          # force on the workpiece from the feed (chip-thickness) direction
      feed_direction_deg: 0.0
      speeds_rpm: {start: 500, stop: 5000, count: 200}
      frf:
        modes:
          - {direction: x, frequency_hz: 180.0, damping_ratio: 0.05, stiffness_N_m: 2.0e7}
        # file: {path: tap_x.csv, format: csv, direction: x}
        # files: [{path: tap_x.csv, direction: x}, {path: tap_y.csv, direction: y}]

Optional: ``semi_discretization: {order, steps_per_period, points_per_wave, depth_points,
depth_max_mm}`` (``depth_max_mm``: the largest depth searched, the cap; default 20 x the smallest
zero-order limit) and ``simulate: {points: [{speed_rpm, depth_mm}], tooth_periods,
steps_per_period}`` (time-domain checks), ``feed_per_tooth_mm`` / ``feed_per_rev_mm`` (static
chip of the simulation).  Relative FRF file paths are taken from the deck's directory.  ``auto``:
oriented FRF for turning, boring and grinding; zero order for milling only where the directional
matrix is constant (a full slot with 4, 6, ... teeth), the semi-discretization otherwise.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from types import MappingProxyType
from typing import TYPE_CHECKING, Annotated, Literal, Mapping, Optional, Union

import numpy as np
from pydantic import Discriminator, Field, Tag, model_validator

from ..fields import DeckModel, PositiveFloat, Range
from .frf import Mode, ToolPointFrf
from .process import MillingProcess, TurningProcess
from .readers import combine_frfs, read_frf

if TYPE_CHECKING:  # the deck layer imports this module: scipy.linalg only where a model is built
    from .state_space import ToolPointModel

__all__ = ["ChatterSection", "ChatterSpec", "build_chatter"]

Angle90 = Annotated[float, Field(gt=-90.0, lt=90.0)]
_TURNING_KEYS = ("Ks_N_mm2", "force_angle_deg", "feed_per_rev_mm")
_MILLING_KEYS = ("Kt_N_mm2", "Kn_N_mm2", "Kr", "teeth", "tool_diameter_mm", "radial_depth_mm", "mode",
                 "helix_deg", "feed_per_tooth_mm")


class ChatterModeEntry(DeckModel):
    """One tap-test mode: H_dd = 1 / (k (1 - r^2 + 2 j zeta r))."""

    direction: Literal["x", "y"]
    """Direction of the mode at the tool point: x or y."""
    frequency_hz: PositiveFloat
    """Natural frequency f_n."""
    damping_ratio: Annotated[float, Field(gt=0.0, lt=1.0)]
    """Modal damping ratio zeta (dimensionless)."""
    stiffness_N_m: PositiveFloat
    """Modal stiffness k: H = 1 / (k (1 - r^2 + 2 j zeta r)), r = f / f_n."""


class FrfModes(DeckModel):
    modes: Annotated[list[ChatterModeEntry], Field(min_length=1, max_length=100)]
    """Tap-test modes of the tool point; the modes of a direction add up in its FRF, x and y uncoupled."""


class FrfFileEntry(DeckModel):
    path: Annotated[str, Field(min_length=1)]
    """File with a measured tool-point FRF; a relative path is taken from the deck's directory."""
    format: Literal["csv", "uff"] = "csv"
    """csv: frequency_hz and real/imag receptance columns (xx, yy, xy, yx or one direction per file); uff:
    universal file dataset 58 (receptance, mobility or accelerance)."""
    direction: Optional[Literal["x", "y"]] = None  # single-direction CSV, or one direction of a UFF
    """x or y: the direction of a single-direction CSV file, or the one direction kept from a UFF file. None:
    every direction in the file."""


class FrfFile(DeckModel):
    file: FrfFileEntry
    """One measured FRF file."""


class FrfFiles(DeckModel):
    files: Annotated[list[FrfFileEntry], Field(min_length=1, max_length=8)]
    """Several single-direction FRF files (e.g. tap tests in x and in y), summed on the first file's frequencies
    within the common band."""


def _frf_kind(v) -> str | None:
    """Union tag of an ``frf:`` value (capitalised: the deck loader skips such tags in error paths)."""
    if isinstance(v, str):
        return "Rotor"
    if isinstance(v, dict):
        keys = [k for k in ("modes", "file", "files") if k in v]
        return keys[0].capitalize() if len(keys) == 1 else None
    return {FrfModes: "Modes", FrfFile: "File", FrfFiles: "Files"}.get(type(v))


FrfSource = Annotated[
    Union[Annotated[Literal["rotor"], Tag("Rotor")], Annotated[FrfModes, Tag("Modes")],
          Annotated[FrfFile, Tag("File")], Annotated[FrfFiles, Tag("Files")]],
    Discriminator(_frf_kind, custom_error_type="frf_source",
                  custom_error_message="frf is 'rotor', {modes: [...]}, {file: {...}} or {files: [...]}"),
]


class SdOptions(DeckModel):
    order: Literal[0, 1] = 1
    """Order of the semi-discretization: 0 (zeroth order) or 1 (first order, the delayed term interpolated
    linearly)."""
    steps_per_period: Optional[Annotated[int, Field(ge=4, le=2000)]] = None  # None: from points_per_wave
    """Time steps per tooth period. None: `points_per_wave` points on a wave at 1.2 times the highest
    significant mode's frequency, between 30 and 400, rounded up to a multiple of 10."""
    points_per_wave: Annotated[float, Field(ge=4.0, le=200.0)] = 12.0
    """Points per vibration period at 1.2 times the highest significant mode's frequency, when
    `steps_per_period` is not given (the limits are then extrapolated from this and half the steps)."""
    depth_points: Annotated[int, Field(ge=4, le=2000)] = 40
    """Number of axial depths of the stability map at each speed."""
    depth_max_mm: Optional[PositiveFloat] = None
    """Largest axial depth searched (the cap) and of the stability map. None: the cap is 20 times the smallest
    zero-order limit, the map goes to 1.25 times the zero-order estimate (the smaller of its largest limit and 3
    times its smallest) and further where a speed is still stable there."""
    stability_map: bool = False
    """Also the spectral radius over a depth grid at every speed (chatter_stability_map.png; `spindlesim chatter
    --map`). false: the limits alone, by brackets continued from the neighbouring speeds (the same limits,
    about a quarter of the evaluations)."""


class SimulationPoint(DeckModel):
    speed_rpm: PositiveFloat
    """Spindle speed of the simulated cut."""
    depth_mm: PositiveFloat
    """Axial depth of cut of the simulated cut."""


class SimulationOptions(DeckModel):
    points: Annotated[list[SimulationPoint], Field(min_length=1, max_length=100)]
    """Cuts integrated in time (nonlinear, the tool may leave the cut) as a check of the lobes; `spindlesim
    chatter --simulate RPM DEPTH_MM` adds more."""
    tooth_periods: Annotated[int, Field(ge=20, le=1_000_000)] = 400
    """Tooth periods integrated for each cut."""
    steps_per_period: Optional[Annotated[int, Field(ge=8, le=100_000)]] = None
    """Time steps per tooth period. None: an even number, at least 100 and 40 steps per period of the highest
    significant mode."""


class ChatterSection(DeckModel):
    """What `spindlesim chatter` computes: the stability lobes of a cutting process from the tool-point FRF
    (the deck rotor's, tap-test modes or measured files), with optional time-domain checks."""

    operation: Literal["turning", "boring", "grinding", "milling"]
    """Cutting process: milling (teeth, immersion, Altintas and Budak) or turning, boring, grinding (one edge;
    in grinding give the workpiece speed: the delay is its revolution)."""
    speeds_rpm: Range
    """Spindle speeds of the stability lobes (0 < start < stop)."""
    method: Literal["auto", "oriented_frf", "zero_order", "semi_discretization"] = "auto"
    """Stability method: auto (milling: semi_discretization below 30 % radial immersion, zero_order above;
    turning, boring, grinding: oriented_frf), zero_order (milling), oriented_frf (turning, boring, grinding:
    Tlusty) or semi_discretization (any)."""
    frf: FrfSource = "rotor"
    """Where the tool-point FRF comes from: rotor (the deck's rotor, at the tool tip when it has a `tool`
    section, else node 1), {modes: [...]} (tap-test modes), {file: {...}} or {files: [...]} (measured FRFs)."""
    frf_at_each_speed: Optional[bool] = None  # default decided by the rotor coupling
    """With frf: rotor, true: the rotor's tool-point FRF is computed again at every speed of the diagram
    (speed-dependent bearings); false: once at `operating.speed_rpm`. None: true when a bearing's stiffness or
    damping changes over the speed range."""
    feed_direction_deg: Annotated[float, Field(ge=-360.0, le=360.0)] = 0.0
    """Feed direction in the tool-point x-y frame, from +x towards +y."""
    # turning, boring, grinding
    Ks_N_mm2: Optional[PositiveFloat] = None
    """Specific cutting force Ks of turning, boring or grinding (force per chip area); required there."""
    force_angle_deg: Optional[Angle90] = None
    """Angle beta of the cutting force on the workpiece from the feed (chip-thickness) direction, towards +y;
    required for turning, boring, grinding."""
    feed_per_rev_mm: Optional[PositiveFloat] = None
    """Feed per revolution (the static chip of the time-domain simulation; turning, boring, grinding). None: 0.1
    mm."""
    # milling
    Kt_N_mm2: Optional[PositiveFloat] = None
    """Tangential cutting-force coefficient Kt of milling; required there."""
    Kn_N_mm2: Optional[Annotated[float, Field(ge=0.0)]] = None
    """Normal (radial) cutting-force coefficient Kn of milling; give it or `Kr` (Kr = Kn / Kt)."""
    Kr: Optional[Annotated[float, Field(ge=0.0, le=10.0)]] = None
    """Ratio Kr = Kn / Kt of the radial to the tangential cutting force (dimensionless); give it or `Kn_N_mm2`.
    """
    teeth: Optional[Annotated[int, Field(ge=1, le=200)]] = None
    """Number of teeth (flutes) of the milling cutter; required for milling."""
    tool_diameter_mm: Optional[PositiveFloat] = None
    """Diameter of the milling cutter; required for milling."""
    radial_depth_mm: Optional[PositiveFloat] = None
    """Radial depth of cut (width of engagement) ae; at most the tool diameter; required for milling."""
    mode: Optional[Literal["up", "down"]] = None
    """up or down milling; required for milling."""
    helix_deg: Optional[Annotated[float, Field(ge=0.0, lt=80.0)]] = None
    """Helix angle of the cutter, taken into account by semi-discretization and the simulation (axial slices);
    the zero-order average does not depend on it. None: 0 (straight teeth)."""
    feed_per_tooth_mm: Optional[PositiveFloat] = None
    """Feed per tooth (the static chip of the time-domain simulation; milling). None: 0.1 mm."""
    semi_discretization: SdOptions = SdOptions()
    """Settings of the semi-discretization method."""
    simulate: Optional[SimulationOptions] = None
    """Time-domain simulation of chosen cuts. None: none (unless `--simulate` asks for some)."""

    @model_validator(mode="after")
    def _consistent(self) -> "ChatterSection":
        milling = self.operation == "milling"
        need, other = (("Kt_N_mm2", "teeth", "tool_diameter_mm", "radial_depth_mm", "mode"), _TURNING_KEYS) \
            if milling else (("Ks_N_mm2", "force_angle_deg"), _MILLING_KEYS)
        missing = [k for k in need if getattr(self, k) is None]
        if missing:
            raise ValueError(f"operation '{self.operation}' needs {', '.join(missing)}")
        wrong = [k for k in other if getattr(self, k) is not None]
        if wrong:
            raise ValueError(f"{', '.join(wrong)} do(es) not apply to operation '{self.operation}'")
        if milling:
            if (self.Kn_N_mm2 is None) == (self.Kr is None):
                raise ValueError("give exactly one of Kn_N_mm2 and Kr")
            if self.radial_depth_mm > self.tool_diameter_mm:
                raise ValueError("radial_depth_mm exceeds tool_diameter_mm")
            if self.method == "oriented_frf":
                raise ValueError("method 'oriented_frf' is for turning, boring and grinding; "
                                 "milling: auto, zero_order or semi_discretization")
        elif self.method == "zero_order":
            raise ValueError(f"method 'zero_order' is for milling; {self.operation}: auto, oriented_frf "
                             "(Tlusty) or semi_discretization")
        if self.speeds_rpm.start <= 0 or self.speeds_rpm.stop <= self.speeds_rpm.start:
            raise ValueError("speeds_rpm needs 0 < start < stop")
        return self


@dataclass(frozen=True, eq=False)
class ChatterSpec:
    """The chatter section in SI.  ``tool`` is None when the FRF comes from the rotor model."""

    process: TurningProcess | MillingProcess
    speeds_rpm: np.ndarray
    method: str  # as requested ("auto" included); resolve with process.method_for
    frf_source: str  # "rotor", "modes" or "file"
    tool: ToolPointModel | ToolPointFrf | None
    frf_at_each_speed: bool | None
    method_options: Mapping[str, object] = field(default_factory=lambda: MappingProxyType({}))
    simulation_points: tuple[tuple[float, float], ...] = ()  # (speed rpm, depth m)
    simulation_options: Mapping[str, object] = field(default_factory=lambda: MappingProxyType({}))

    @property
    def resolved_method(self) -> str:
        return self.process.method_for(self.method)


def _process(sec: ChatterSection):
    feed = np.deg2rad(sec.feed_direction_deg)
    if sec.operation == "milling":
        kr = sec.Kr if sec.Kr is not None else sec.Kn_N_mm2 / sec.Kt_N_mm2
        return MillingProcess(sec.teeth, sec.tool_diameter_mm * 1e-3, sec.radial_depth_mm * 1e-3, sec.mode,
                              sec.Kt_N_mm2 * 1e6, float(kr), np.deg2rad(sec.helix_deg or 0.0),
                              (sec.feed_per_tooth_mm or 0.1) * 1e-3, feed)
    return TurningProcess(sec.Ks_N_mm2 * 1e6, np.deg2rad(sec.force_angle_deg), feed, sec.operation,
                          (sec.feed_per_rev_mm or 0.1) * 1e-3)


def _tool(frf, base_dir: Path):
    if frf == "rotor":
        return "rotor", None
    if isinstance(frf, FrfModes):
        modes = [Mode(m.direction, m.frequency_hz, m.damping_ratio, m.stiffness_N_m) for m in frf.modes]
        from .state_space import ToolPointModel

        return "modes", ToolPointModel.from_modes(modes, "deck modes")
    entries = [frf.file] if isinstance(frf, FrfFile) else frf.files
    parts = []
    for e in entries:
        p = Path(e.path)
        parts.append(read_frf(p if p.is_absolute() else base_dir / p, e.format, e.direction))
    return "file", parts[0] if len(parts) == 1 else combine_frfs(parts)


def build_chatter(section: ChatterSection, base_dir: Path | str | None = None) -> ChatterSpec:
    """SI specification of the chatter analysis; reads FRF files (relative to ``base_dir``).

    Raises :class:`~spindlesim.chatter.readers.FrfFileError` for a bad FRF file.
    """
    sec = section
    process = _process(sec)
    r = sec.speeds_rpm
    speeds = np.linspace(r.start, r.stop, r.count)
    source, tool = _tool(sec.frf, Path(base_dir) if base_dir is not None else Path.cwd())
    sd = sec.semi_discretization
    opts = {"order": sd.order, "steps": sd.steps_per_period, "points_per_wave": sd.points_per_wave,
            "n_depths": sd.depth_points, "stability_map": sd.stability_map,
            "depth_max_m": sd.depth_max_mm * 1e-3 if sd.depth_max_mm is not None else None}
    sim_points, sim_opts = (), {}
    if sec.simulate is not None:
        sim_points = tuple((p.speed_rpm, p.depth_mm * 1e-3) for p in sec.simulate.points)
        sim_opts = {"tooth_periods": sec.simulate.tooth_periods, "steps_per_period": sec.simulate.steps_per_period}
    return ChatterSpec(process, speeds, sec.method, source, tool, sec.frf_at_each_speed,
                       MappingProxyType(opts), sim_points, MappingProxyType(sim_opts))
