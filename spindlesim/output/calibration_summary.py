"""Terminal summary of calibration.h5: per parameter its start, calibrated value and 95 % interval; the fit error
of each measurement before and after; the warnings."""

from __future__ import annotations

import numpy as np


def calibration(f):
    g = f["calibration"]
    names = [str(n) for n in g["parameter"][:].astype(str)]
    units = [str(u) for u in g["value"].attrs.get("component_units", [""] * len(names))]
    lines, params = [], {}
    for k, name in enumerate(names):
        ini, val = float(g["initial"][k]), float(g["value"][k])
        lo, hi = float(g["lower_95"][k]), float(g["upper_95"][k])
        u = f" {units[k]}" if units[k] not in ("", "1") else ""
        ci = f"95 %: {lo:.4g} .. {hi:.4g}" if np.isfinite(lo) else "not determined"
        flags = (" AT A BOUND" if g["at_bound"][k] else "") + (" NOT DETERMINED" if g["undetermined"][k] else "")
        lines.append(f"{name}: {ini:.4g} -> {val:.4g}{u} ({ci}){flags}")
        params[name] = {"initial": ini, "value": val, "lower_95": lo, "upper_95": hi}
    fits = {}
    for k in sorted(g.get("measurements", {}), key=int):
        a = g["measurements"][k].attrs
        if "final_error" in a:
            lines.append(f"  {a['file']} (node {int(a['node'])} {a['direction']}, {float(a['speed_rpm']):g} rpm): rms "
                         f"error {100 * float(a['initial_error']):.1f} % -> {100 * float(a['final_error']):.1f} %")
            fits[str(a["file"])] = [float(a["initial_error"]), float(a["final_error"])]
    lines.append(f"  {int(g.attrs['evaluations'])} model evaluations: {g.attrs['message']}")
    warnings = str(g.attrs.get("warnings", "none"))
    if warnings != "none":
        lines += [f"  WARNING: {w}" for w in warnings.split("; ")]
    return lines, {"parameters": params, "rms_error": fits, "warnings": [] if warnings == "none" else
                   warnings.split("; ")}
