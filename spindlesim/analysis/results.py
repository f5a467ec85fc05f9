"""Result objects of every analysis: frozen dataclasses of SI arrays (nothing cached on models)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from .resonance import Crossings

if TYPE_CHECKING:
    from ..chatter.frf import ToolPointFrf


@dataclass(frozen=True)
class StaticResult:
    node_z_m: np.ndarray
    displacement_m: np.ndarray  # [node, 2] (x, y)
    slope_rad: np.ndarray  # [node, 2] (theta_x, theta_y)
    bearing_names: tuple[str, ...]
    bearing_nodes: np.ndarray  # 0-based
    bearing_force_N: np.ndarray  # [bearing, 2]: force the bearing exerts on the shaft
    applied_force_N: np.ndarray  # (2,) sum of applied loads incl. gravity
    stiffness_node: int  # 0-based
    stiffness_dof: str
    static_stiffness_N_m: float  # 1 / compliance at (stiffness_node, stiffness_dof)
    speed_rpm: float
    state: object = None  # the OperatingState (q with every DOF, bearing loads on all their DOFs)
    axial_displacement_m: np.ndarray | None = None  # [node] z, where the model has the axial DOF
    applied_axial_force_N: float = 0.0  # sum of the applied axial loads (z)
    tool_tip_node: int | None = None  # 0-based, when the deck has a tool
    tool_tip_stiffness_N_m: dict | None = None  # {"x", "y"[, "z"]}: 1 / direct compliance at the tip
    gravity_m_s2: float = 0.0  # gravity in the applied loads (along -y); 0: off
    damping_only: tuple[str, ...] = ()  # bearings with no stiffness at the state (a damper): no static reaction


@dataclass(frozen=True)
class ModalResult:
    speed_rpm: float
    eigenvalues: np.ndarray  # complex, underdamped modes (Im > 0), ascending damped frequency
    frequency_hz: np.ndarray  # damped natural frequency
    undamped_frequency_hz: np.ndarray  # |lambda| / 2 pi
    damping_ratio: np.ndarray
    log_dec: np.ndarray
    whirl: tuple[str, ...]  # forward / backward / mixed
    forward_fraction: np.ndarray  # share of nodes whirling forward, by mode
    # complex [mode, node, dof]: (x, y, theta_x, theta_y) and, where the rotor has the axial DOF, z last;
    # largest translation (x, y or z) = 1
    mode_shape: np.ndarray
    node_z_m: np.ndarray
    overdamped_roots: np.ndarray  # complex roots with zeta >= 0.999 (incl. real), 1/s
    rigid_body_roots: np.ndarray  # |lambda| below the rigid-body threshold
    unstable: np.ndarray  # bool per mode: damping ratio < 0


@dataclass(frozen=True)
class CampbellResult:
    speed_rpm: np.ndarray
    frequency_hz: np.ndarray  # [speed, mode], modes tracked by MAC
    log_dec: np.ndarray
    damping_ratio: np.ndarray
    whirl: np.ndarray  # [speed, mode] strings
    critical_speeds_rpm: np.ndarray  # 1x crossings with AF >= 2.5 of modes other than backward lateral
    critical_modes: np.ndarray  # tracked mode index of each critical speed
    model: str = "full state space"  # or "reduced: m of n coordinates" (analysis/reduced.py)
    incomplete_reason: str = ""  # set when a speed's static state failed: the speeds before it only
    crossings: Crossings | None = None  # every excitation order against every tracked mode, API 684 judged
    interrupted: bool = False  # stopped by Ctrl-C (incomplete_reason says where)

    @property
    def first_unstable(self) -> tuple[int, int] | None:
        """The stability threshold: (speed index, mode index) of the lowest speed at which a tracked mode's
        damping ratio is negative (of those modes, the first); None when every tracked mode is stable over
        the range (an untracked mode, NaN, is neither)."""
        unstable = np.argwhere(self.damping_ratio < 0)
        if not unstable.size:
            return None
        i, k = unstable[np.argmin(self.speed_rpm[unstable[:, 0]])]
        return int(i), int(k)


@dataclass(frozen=True)
class FrfResult:
    frequency_hz: np.ndarray
    receptance_m_N: np.ndarray  # complex
    input_node: int  # 1-based, as in the deck
    input_dof: str
    output_node: int
    output_dof: str
    speed_rpm: float
    added: np.ndarray | None = None  # bool per frequency: added around a mode (False: the user's grid)
    modes: "ModesInRange | None" = None  # the modes the grid was refined around
    static_compliance_m_N: float | None = None  # K^-1 [output, input] (0 Hz); None where K does not hold it
    # the tool tip's 2 x 2 receptance (xx, xy; yx, yy) on the same grid (chatter.frf.ToolPointFrf), when asked
    # for and the rotor has a tool
    tool_point: "ToolPointFrf | None" = None

    @property
    def dynamic_stiffness_N_m(self) -> np.ndarray:
        return 1.0 / self.receptance_m_N


@dataclass(frozen=True)
class UnbalanceResult:
    speed_rpm: np.ndarray
    response_m: np.ndarray  # complex [speed, node, 2] (x, y) amplitude phasors
    unbalance_kg_m: float
    unbalance_node: int  # 1-based
    output_node: int  # 1-based
    output_dof: str
    node_z_m: np.ndarray
    added: np.ndarray | None = None  # bool per speed: added around a resonance (False: the user's grid)
    resonances: "UnbalanceResonances | None" = None  # the 1x crossings the grid was refined around

    @property
    def amplitude(self) -> str:
        """What |response_m| is: the single (0-peak) amplitude of the phasor q(t) = Re(q e^{j W t})."""
        return "0-peak"


@dataclass(frozen=True)
class ModesInRange:
    """Damped modes (ascending) whose half-power band reaches into a requested frequency range."""

    frequency_hz: np.ndarray  # damped
    undamped_frequency_hz: np.ndarray
    damping_ratio: np.ndarray
    whirl: tuple[str, ...]


@dataclass(frozen=True)
class UnbalanceResonances:
    """1x crossings inside an unbalance sweep (speed found by a root search on f_k(N) - N/60) and the
    response peak near each: its speed and amplitude at the output, and the API 684 amplification
    factor N_peak / (N_2 - N_1) from its half-power speeds (NaN where they are not both in range)."""

    crossings: Crossings
    peak_speed_rpm: np.ndarray
    peak_amplitude_m: np.ndarray  # 0-peak, |response| at the output DOF
    half_power_af: np.ndarray
