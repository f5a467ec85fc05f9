"""chatter.h5: the lobe diagram, the tool-point FRF it used, the simulations (docs/output-format.md).

Dimensions: ``speed_rpm`` (a copy in every group that has it), ``mode`` (1-based), ``depth_m``,
``frequency_hz``, ``time_s``, ``tooth_period``; string coordinates ``dof`` (x, y) and ``load``
(Fx, Fy).  NaN marks an absent value (``_FillValue``) in the lobe limits and chatter frequencies (no
boundary point at that speed) and in ``frf_per_speed`` (speeds with fewer significant modes).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from ..analysis.chatter_study import NO_LOBES
from ..chatter.pockets import MIN_TOLERANCE, POCKET_LEVEL
from ..chatter.results import speed_runs
from .hdf5 import Data, RunInfo, labels, write_h5
from .rotor_writers import tool_point_frf

NO_BOUNDARY = "NaN where there is no stability boundary at that speed"


def _frf(tool) -> tuple[np.ndarray, np.ndarray]:
    frf = tool.frf()
    return frf.frequency_hz, frf.H


def _limits(g: str, speed_rpm, limit_depth_m, chatter_frequency_hz) -> dict[str, Any]:
    s = ("speed_rpm",)
    return {f"{g}/speed_rpm": (np.asarray(speed_rpm, float), "rpm", s),
            f"{g}/limit_depth_m": Data(limit_depth_m, "m", s, NO_BOUNDARY, fill_nan=True),
            f"{g}/chatter_frequency_hz": Data(chatter_frequency_hz, "Hz", s, NO_BOUNDARY, fill_nan=True)}


def _frf_per_speed(series, speed_rpm: np.ndarray) -> dict[str, Any]:
    """The dominant modes of the tool series' state-space models at every speed (NaN pads speeds with fewer
    modes)."""
    models = [t.state_space for t in series.tools]
    modes = [[(m.frequency_hz, m.damping_ratio, m.peak_compliance_m_N) for m in ss.significant_modes(rel=0.1)]
             for ss in models if ss is not None]
    if not modes:
        return {}
    width = max(len(m) for m in modes)
    arr = np.full((len(modes), width, 3), np.nan)
    for i, m in enumerate(modes):
        arr[i, :len(m)] = m
    g = "/chatter/frf_per_speed"
    pad = "NaN where the speed has fewer significant modes"
    data = {f"{g}/frequency_hz": Data(arr[:, :, 0], "Hz", ("speed_rpm", "mode"), pad, fill_nan=True),
            f"{g}/damping_ratio": Data(arr[:, :, 1], "1", ("speed_rpm", "mode"), pad, fill_nan=True),
            f"{g}/peak_compliance_m_N": Data(arr[:, :, 2], "m/N", ("speed_rpm", "mode"), pad, fill_nan=True)}
    if len(modes) == len(speed_rpm):
        data[f"{g}/speed_rpm"] = (np.asarray(speed_rpm, float), "rpm", ("speed_rpm",))
    return data


def _simulation(g: str, s) -> dict[str, Any]:
    t, f = ("time_s",), ("spectrum_frequency_hz",)
    return {f"{g}/time_s": (s.time_s, "s", t),
            f"{g}/displacement_m": (s.displacement_m, "m", ("time_s", "dof")),
            f"{g}/force_N": (s.force_N, "N", ("time_s", "load")),
            f"{g}/poincare_m": Data(s.poincare_m, "m", ("tooth_period", "dof"), "displacement once per tooth period"),
            f"{g}/spectrum_frequency_hz": (s.spectrum_frequency_hz, "Hz", f),
            f"{g}/spectrum_amplitude_m": Data(s.spectrum_amplitude_m, "m", f, "amplitude of |(x, y)|"),
            **labels(g, "dof", ("x", "y")), **labels(g, "load", ("Fx", "Fy"))}


def _methods(g: str, dg) -> dict[str, Any]:
    return {f"{g}/method": Data(np.asarray(dg.method_per_speed, dtype=object), "1", ("speed_rpm",),
                                "the method that produced the limit at each speed"),
            f"{g}/capped": Data(np.asarray(dg.capped, np.int8), "1", ("speed_rpm",),
                                "1: stable up to the depth cap (the largest depth searched); the limit is NaN "
                                "and at least the cap")}


def _pockets(result) -> tuple[dict[str, Any], dict[str, Any]]:
    """Datasets of every pocket and the attributes of the recommended one (the summary reads them)."""
    pk = result.pockets
    if not pk:
        return {}, {"recommendation": result.recommendation_text}
    g, d = "/chatter/pockets", ("pocket",)
    data = {f"{g}/peak_speed_rpm": (np.array([p.peak_speed_rpm for p in pk]), "rpm", d),
            f"{g}/peak_depth_m": Data(np.array([p.peak_depth_m for p in pk]), "m", d,
                                      "largest limit depth of the pocket (at least this where capped)"),
            f"{g}/depth_m": Data(np.array([p.depth_m for p in pk]), "m", d,
                                 f"the depth the speed interval keeps: {POCKET_LEVEL:.0%} of the peak, less where "
                                 f"needed for the interval to span +-{MIN_TOLERANCE:.0%} of the speed"),
            f"{g}/speed_min_rpm": (np.array([p.speed_min_rpm for p in pk]), "rpm", d),
            f"{g}/speed_max_rpm": (np.array([p.speed_max_rpm for p in pk]), "rpm", d),
            f"{g}/grid_speeds": (np.array([p.grid_speeds for p in pk]), "1", d),
            f"{g}/capped": (np.array([p.capped for p in pk], np.int8), "1", d)}
    r = result.recommendation
    if r is None:  # every pocket runs above the spindle's thermal speed limit
        return data, {"recommendation": result.recommendation_text}
    attrs = {"recommended_speed_rpm": r.speed_rpm, "recommended_depth_m": r.depth_m,
             "recommended_speed_tolerance_rpm": r.tolerance_rpm, "pocket_speed_min_rpm": r.speed_min_rpm,
             "pocket_speed_max_rpm": r.speed_max_rpm, "pocket_peak_depth_m": r.peak_depth_m,
             "pocket_peak_speed_rpm": r.peak_speed_rpm, "pocket_level": r.level, "pocket_capped": r.capped,
             "pocket_grid_speeds": r.grid_speeds, "recommendation": result.recommendation_text}
    return data, attrs


#: the attribute ``stability_map`` of a semi-discretization run that did not ask for the map
MAP_NOT_ASKED = "not computed (ask with spindlesim chatter --map, or semi_discretization: {stability_map: true})"


def write_chatter(path: Path, run: RunInfo, spec, result, at_deck, shown, info: dict[str, Any]) -> Path:
    """chatter.h5 of ``result`` (its tool series: the modes per speed when it changes with the speed); ``shown``
    the tool point whose FRF the file holds (:attr:`~spindlesim.analysis.chatter_study.ChatterStudy.shown_tool`)."""
    dg = result.diagram
    data: dict[str, Any] = _limits("/chatter", dg.speed_rpm, dg.limit_depth_m, dg.chatter_frequency_hz)
    data["/chatter/boundary_kind"] = Data(np.asarray(dg.boundary_kind, dtype=object), "1", ("speed_rpm",),
                                          "kind of the critical lobe (hopf, flip; empty: none)")
    data.update(_methods("/chatter", dg))
    pocket_data, pocket_attrs = _pockets(result)
    data.update(pocket_data)
    for c in dg.lobes:
        data.update(_limits(f"/chatter/lobes/{c.kind}_{c.lobe}", c.speed_rpm, c.limit_depth_m, c.chatter_frequency_hz))
    data.update(tool_point_frf("/chatter/frf", *_frf(shown)))
    if result.tool.speed_dependent:
        data.update(_frf_per_speed(result.tool, dg.speed_rpm))
    if at_deck is not None:
        data.update(_limits("/chatter/at_deck_speed", at_deck.speed_rpm, at_deck.limit_depth_m,
                            at_deck.chatter_frequency_hz))
        data.update(_methods("/chatter/at_deck_speed", at_deck))
    if np.any(np.asarray(dg.steps_per_period) > 0):
        data["/chatter/steps_per_period"] = Data(np.asarray(dg.steps_per_period), "1", ("speed_rpm",),
                                                 "semi-discretization steps per tooth period (0: another method)")
    sm = dg.stability_map
    if sm is not None:
        g = "/chatter/stability_map"
        data.update({f"{g}/speed_rpm": (sm.speed_rpm, "rpm", ("speed_rpm",)),
                     f"{g}/depth_m": (sm.depth_m, "m", ("depth_m",)),
                     f"{g}/spectral_radius": Data(sm.spectral_radius, "1", ("speed_rpm", "depth_m"),
                                                  "of the monodromy matrix (< 1 stable); NaN where not evaluated "
                                                  "(above the depth following the first crossing)", fill_nan=True),
                     f"{g}/steps_per_period": (sm.steps_per_period, "1", ("speed_rpm",))})
    for k, s in enumerate(result.simulations):
        data.update(_simulation(f"/chatter/simulation/{k + 1}", s))
    attrs: dict[str, dict[str, Any]] = {"/chatter": {
        "operation": spec.process.operation if hasattr(spec.process, "operation") else dg.process,
        "process": dg.process, "method": dg.method, "method_selection": dg.selection,
        "frf_source": info["frf_source"], "frf_at_each_speed": bool(info.get("frf_at_each_speed", False)),
        "capped_speeds": int(np.count_nonzero(dg.capped)), "notes": "; ".join(dg.notes), **pocket_attrs}}
    if dg.method == "semi_discretization":
        attrs["/chatter"]["stability_map"] = "written" if sm is not None else MAP_NOT_ASKED
    if np.isfinite(dg.depth_cap_m):
        attrs["/chatter"]["depth_cap_m"] = dg.depth_cap_m
    if np.any(dg.capped):
        attrs["/chatter"]["capped_speeds_rpm"] = speed_runs(dg.speed_rpm[np.asarray(dg.capped, bool)])
    for key in ("node", "model", "deck_speed_rpm", "frf_at_each_speed_reason"):
        if key in info:
            attrs["/chatter"][{"node": "tool_point_node"}.get(key, key)] = info[key]
    if result.minimum is not None:
        s_min, a_min = result.minimum
        attrs["/chatter"].update(minimum_limit_depth_m=a_min, minimum_at_speed_rpm=s_min)
    if result.speed_limit_rpm is not None:
        attrs["/chatter"]["thermal_speed_limit_rpm"] = float(result.speed_limit_rpm)
    if at_deck is not None:
        attrs["/chatter/at_deck_speed"] = {"method": at_deck.method, "method_selection": at_deck.selection}
    attrs["/chatter/frf"] = {"layout": "[frequency, output (x, y), input (x, y)]"}
    if info.get("deck_speed_rpm") is not None:
        attrs["/chatter/frf"]["speed_rpm"] = info["deck_speed_rpm"]
    for k, s in enumerate(result.simulations):
        a = {"speed_rpm": s.speed_rpm, "depth_m": s.depth_m, "stable": s.stable,
             "tooth_frequency_hz": s.tooth_frequency_hz, "growth_per_period": s.growth_per_period,
             "fft_bin_hz": s.fft_bin_hz, "decay_ratio": s.decay_ratio, "verdict": s.verdict}
        if np.isfinite(s.chatter_frequency_hz):  # NaN when stable: the attribute is left out
            a["chatter_frequency_hz"] = s.chatter_frequency_hz
        attrs[f"/chatter/simulation/{k + 1}"] = a
    return write_h5(path, run, data, attrs)


def write_chatter_tool_point(path: Path, run: RunInfo, spec, series, shown, info: dict[str, Any]) -> Path:
    """chatter.h5 of a run interrupted in the lobes: what was computed before them, the FRF of the tool point
    ``shown`` (and the dominant modes at every speed where the tool series changes with the speed); ``run`` says
    why it is incomplete."""
    data: dict[str, Any] = dict(tool_point_frf("/chatter/frf", *_frf(shown)))
    if series.speed_dependent:
        data.update(_frf_per_speed(series, np.asarray(spec.speeds_rpm, float)))
    attrs: dict[str, dict[str, Any]] = {"/chatter": {
        "process": spec.process.describe(), "lobes": NO_LOBES,
        "frf_source": info["frf_source"], "frf_at_each_speed": bool(info.get("frf_at_each_speed", False))}}
    for key in ("node", "model", "deck_speed_rpm", "frf_at_each_speed_reason"):
        if key in info:
            attrs["/chatter"][{"node": "tool_point_node"}.get(key, key)] = info[key]
    attrs["/chatter/frf"] = {"layout": "[frequency, output (x, y), input (x, y)]"}
    if info.get("deck_speed_rpm") is not None:
        attrs["/chatter/frf"]["speed_rpm"] = info["deck_speed_rpm"]
    return write_h5(path, run, data, attrs)
