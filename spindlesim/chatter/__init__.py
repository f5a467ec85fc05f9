"""Chatter stability of turning, boring, grinding and milling from the tool-point FRF.

Pure physics on FRFs and state-space models (no deck loading, no output): the rotor model, the
deck loader and the ``spindlesim chatter`` command build on it.

* inputs: :class:`Mode`, :class:`ToolPointFrf`, :class:`ToolPointModel` (A, B, C), both tool points of
  one protocol, and :class:`ToolSeries`, the tool point at each speed (:mod:`spindlesim.chatter.tool`);
  :func:`read_frf` (CSV, UFF 58), :func:`fit_tool_point_model`;
* processes: :class:`TurningProcess`, :class:`MillingProcess`;
* methods: :func:`stability_lobes` (driver) over :func:`turning_lobes` (Tlusty, oriented FRF),
  :func:`zero_order_lobes` (Altintas-Budak) and :func:`semi_discretization_lobes`
  (Insperger-Stepan, with the stability map); :func:`simulate` (time domain);
* results: :class:`LobeDiagram`, :class:`LobeCurve`, :class:`StabilityMap`, :class:`SimulationResult`;
  :func:`stability_pockets` and :func:`best_pocket` (the speed to recommend);
* deck: :class:`ChatterSection`, :func:`build_chatter`, :func:`run_chatter`;
* figures: :mod:`spindlesim.chatter.plots`.
"""

from spindlesim.lazy import lazy_exports

#: what the package exports and the module defining it: imported on first use (PEP 562), so that a
#: deck loader reading only a section does not pay for the solvers' imports (scipy.signal, numba ...)
_EXPORTS = {
    "Mode": "frf",
    "ToolPointFrf": "frf",
    "ModalFit": "modal_fit",
    "fit_tool_point_model": "modal_fit",
    "MillingProcess": "process",
    "TurningProcess": "process",
    "FrfFileError": "readers",
    "combine_frfs": "readers",
    "read_frf": "readers",
    "read_frf_csv": "readers",
    "read_frf_uff": "readers",
    "write_frf_csv": "readers",
    "LobeCurve": "results",
    "LobeDiagram": "results",
    "SimulationResult": "results",
    "StabilityMap": "results",
    "semi_discretization_lobes": "sd_lobes",
    "Pocket": "pockets",
    "stability_pockets": "pockets",
    "best_pocket": "pockets",
    "ChatterSection": "section",
    "ChatterSpec": "section",
    "build_chatter": "section",
    "simulate": "simulation",
    "ChatterResult": "stability",
    "run_chatter": "stability",
    "stability_lobes": "stability",
    "ToolPointModel": "state_space",
    "ToolPoint": "tool",
    "ToolSeries": "tool",
    "tool_series": "tool",
    "oriented_frf": "turning",
    "turning_lobes": "turning",
    "turning_parametric_lobes": "turning",
    "zero_order_lobes": "zero_order",
}


__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS)



__all__ = [
    "Mode", "ToolPointFrf", "ToolPointModel", "ToolPoint", "ToolSeries", "tool_series", "ModalFit", "fit_tool_point_model",
    "MillingProcess", "TurningProcess",
    "FrfFileError", "read_frf", "read_frf_csv", "read_frf_uff", "write_frf_csv", "combine_frfs",
    "LobeCurve", "LobeDiagram", "SimulationResult", "StabilityMap",
    "stability_lobes", "turning_lobes", "turning_parametric_lobes", "oriented_frf", "zero_order_lobes",
    "semi_discretization_lobes", "simulate", "Pocket", "stability_pockets", "best_pocket",
    "ChatterSection", "ChatterSpec", "build_chatter", "ChatterResult", "run_chatter",
]
