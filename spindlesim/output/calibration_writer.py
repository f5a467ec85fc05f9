"""calibration.h5 and calibrated.yaml of ``spindlesim calibrate`` (docs/output-format.md).

/calibration: attributes evaluations, message, complete; /calibration/parameters: ``path`` (strings), ``initial``,
``value``, ``lower_95``, ``upper_95`` (NaN: not determined), ``min``, ``max``, ``log_scale``, ``at_bound``,
``undetermined`` [parameter] (each value in its deck key's unit, component_units); ``correlation`` [parameter,
parameter2]; /calibration/measurements/<k>: ``frequency_hz``, ``measured_m_N``, ``initial_m_N``, ``calibrated_m_N``
(complex), attributes file, node, direction, speed_rpm, initial_error, final_error (relative rms).
"""

from __future__ import annotations

import datetime
from pathlib import Path

import numpy as np

from .hdf5 import Data, RunInfo, labels, write_h5


def _unit_of(path: str) -> str:
    """The unit of the deck key a path ends in (a row column of the shaft: its column's unit)."""
    from ..deck.loader import ROW_KEYS
    from ..fields import unit_range, unit_text

    parts = path.split(".")
    key = parts[-1]
    if key.isdigit() and len(parts) > 2 and parts[-3] == "elements" and int(key) < len(ROW_KEYS):
        key = ROW_KEYS[int(key)]
    found = unit_range(key)
    return unit_text(found[0]) if found else "1"


def write_calibration(path: Path, run: RunInfo, res) -> Path:
    g = "/calibration"
    names = [p.path for p in res.parameters]
    units = np.array([_unit_of(n) for n in names], dtype=object)
    data: dict = {**labels(g, "parameter", names, "deck key path"),
                  **labels(g, "parameter2", names, "deck key path")}
    for key, what in (("initial", "the deck's value"), ("value", "the calibrated value"),
                      ("lower_95", "lower end of the 95 % interval (NaN: not determined)"),
                      ("upper_95", "upper end of the 95 % interval (NaN: not determined)"),
                      ("min", "lower bound"), ("max", "upper bound")):
        data[f"{g}/{key}"] = Data(np.array([getattr(p, key) for p in res.parameters], float), "", ("parameter",),
                                  what + ", in the unit of its deck key", fill_nan=True, component_units=units)
    for key in ("log_scale", "at_bound", "undetermined"):
        data[f"{g}/{key}"] = Data(np.array([getattr(p, key) for p in res.parameters], np.int8), "1", ("parameter",))
    data[f"{g}/correlation"] = Data(res.correlation, "1", ("parameter", "parameter2"),
                                    "correlation of the estimates (from the Jacobian at the optimum)", fill_nan=True)
    attrs: dict = {g: {"evaluations": res.evaluations, "message": res.message,
                       "warnings": "; ".join(res.warnings) if res.warnings else "none"}}
    for k, m in enumerate(res.measurements):
        mg = f"{g}/measurements/{k}"
        data[f"{mg}/frequency_hz"] = (m.frequency_hz, "Hz", ("frequency_hz",))
        data[f"{mg}/measured_m_N"] = Data(m.H, "m/N", ("frequency_hz",), "the measured direct receptance")
        data[f"{mg}/initial_m_N"] = Data(res.initial_H[k], "m/N", ("frequency_hz",), "the deck's model")
        data[f"{mg}/calibrated_m_N"] = Data(res.calibrated_H[k], "m/N", ("frequency_hz",), "the calibrated model")
        attrs[mg] = {"file": m.label, "node": m.node, "direction": m.direction, "speed_rpm": m.speed_rpm}
        if np.isfinite(res.initial_error[k]):
            attrs[mg].update(initial_error=float(res.initial_error[k]), final_error=float(res.final_error[k]))
    if not res.complete:
        import dataclasses

        run = dataclasses.replace(run, complete=False, incomplete_reason=res.message)
    return write_h5(path, run, data, attrs)


def calibrated_deck_text(res, source: str, measurement_paths: dict[str, str] | None = None) -> str:
    """The deck with the fitted values in place and a comment at the top naming the measurements, the date and
    the values with their intervals."""
    from ..deck.paths import replace_in_text

    text = res.calibrated_text
    if measurement_paths:
        text = replace_in_text(text, measurement_paths)
    day = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    lines = [f"# Calibrated by spindlesim calibrate on {day} from {source}",
             "# to the measured FRFs " + "; ".join(f"{m.label} (node {m.node}, {m.direction}, {m.speed_rpm:g} rpm)"
                                                    for m in res.measurements) + ":"]
    for p in res.parameters:
        ci = (f" (95 %: {p.lower_95:.4g} .. {p.upper_95:.4g})" if np.isfinite(p.lower_95) else " (not determined)")
        lines.append(f"#   {p.path} = {p.value:.6g}{ci}, was {p.initial:.6g}")
    if not res.complete:
        lines.append("# INCOMPLETE: interrupted; the best values evaluated, no intervals")
    return "\n".join(lines) + "\n" + text
