"""Chatter stability of turning, boring, grinding and milling from the tool-point FRF.

Pure physics on FRFs and state-space models (no deck loading, no output): the rotor model, the
deck loader and the ``spindlesim chatter`` command build on it.

* inputs: :class:`Mode`, :class:`ToolPointFrf`, :class:`ToolPointModel` (A, B, C),
  :func:`read_frf` (CSV, UFF 58), :func:`fit_tool_point_model`;
* processes: :class:`TurningProcess`, :class:`MillingProcess`;
* methods: :func:`stability_lobes` (driver) over :func:`turning_lobes` (Tlusty, oriented FRF),
  :func:`zero_order_lobes` (Altintas-Budak) and :func:`semi_discretization_lobes`
  (Insperger-Stepan, with the stability map); :func:`simulate` (time domain);
* results: :class:`LobeDiagram`, :class:`LobeCurve`, :class:`StabilityMap`, :class:`SimulationResult`;
* deck: :class:`ChatterSection`, :func:`build_chatter`, :func:`run_chatter`;
* figures: :mod:`spindlesim.chatter.plots`.
"""

from .frf import Mode, ToolPointFrf
from .modal_fit import ModalFit, fit_tool_point_model
from .process import MillingProcess, TurningProcess
from .readers import FrfFileError, combine_frfs, read_frf, read_frf_csv, read_frf_uff, write_frf_csv
from .results import LobeCurve, LobeDiagram, SimulationResult, StabilityMap
from .sd_lobes import semi_discretization_lobes
from .section import ChatterSection, ChatterSpec, build_chatter
from .simulation import simulate
from .stability import ChatterResult, run_chatter, stability_lobes
from .state_space import ToolPointModel
from .turning import oriented_frf, turning_lobes, turning_parametric_lobes
from .zero_order import zero_order_lobes

__all__ = [
    "Mode", "ToolPointFrf", "ToolPointModel", "ModalFit", "fit_tool_point_model",
    "MillingProcess", "TurningProcess",
    "FrfFileError", "read_frf", "read_frf_csv", "read_frf_uff", "write_frf_csv", "combine_frfs",
    "LobeCurve", "LobeDiagram", "SimulationResult", "StabilityMap",
    "stability_lobes", "turning_lobes", "turning_parametric_lobes", "oriented_frf", "zero_order_lobes",
    "semi_discretization_lobes", "simulate",
    "ChatterSection", "ChatterSpec", "build_chatter", "ChatterResult", "run_chatter",
]
