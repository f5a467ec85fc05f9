"""Key scalars of one case's output files, for the sweep summary.

Every 0-d numeric dataset and every numeric group attribute becomes a scalar
named by its path; a few analyses add derived ones (first natural frequencies,
FRF peak, dominant spectral line).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np


def _generic(f) -> dict[str, float]:
    import h5py

    out: dict[str, float] = {}

    def visit(name, obj):
        if isinstance(obj, h5py.Dataset) and obj.dtype.kind in "iuf":
            if obj.shape == ():
                out[name] = float(obj[()])
            elif obj.size <= 4:  # 2x2 coefficient matrices, (x, y) pairs
                for idx, v in np.ndenumerate(obj[()]):
                    out[name + "[" + ",".join(map(str, idx)) + "]"] = float(v)
        if isinstance(obj, h5py.Group):
            for k, v in obj.attrs.items():
                if isinstance(v, (int, float, np.integer, np.floating)) and not isinstance(v, bool):
                    out[f"{name}@{k}"] = float(v)

    f.visititems(visit)
    return out


def _derived(f) -> dict[str, float]:
    out: dict[str, float] = {}
    if "modal/frequency_hz" in f:
        fr = f["modal/frequency_hz"][()]
        zr = f["modal/damping_ratio"][()]
        for k in range(min(4, len(fr))):
            out[f"modal/f{k + 1}_hz"] = float(fr[k])
            out[f"modal/zeta{k + 1}"] = float(zr[k])
    if "frf/receptance_m_N" in f:
        h = np.abs(f["frf/receptance_m_N"][()])
        i = int(np.argmax(h))
        out["frf/peak_m_N"] = float(h[i])
        out["frf/peak_frequency_hz"] = float(f["frf/frequency_hz"][i])
    if "campbell/critical_speed_rpm" in f:
        cs = f["campbell/critical_speed_rpm"][()]
        out["campbell/first_critical_rpm"] = float(cs[0]) if len(cs) else float("nan")
    if "static/displacement_m" in f:
        out["static/max_displacement_m"] = float(np.max(np.hypot(*f["static/displacement_m"][()].T)))
    if "transient/spectrum/amplitude_m" in f:
        freq = f["transient/spectrum/frequency_hz"][()]
        amp = f["transient/spectrum/amplitude_m"][()]
        amp = amp if amp.ndim == 1 else np.hypot(amp[:, 0], amp[:, 1])
        sel = freq > 0
        if sel.any():
            i = int(np.argmax(np.where(sel, amp, -1)))
            out["transient/dominant_frequency_hz"] = float(freq[i])
            out["transient/dominant_amplitude_m"] = float(amp[i])
    if "contact" in f and "max_pressure_Pa" in f["contact"].attrs:
        g = f["contact"].attrs
        singular = bool(g.get("edge_singular", False))
        out["contact/edge_singular"] = float(singular)
        # a sharp-edge peak is a grid value, not a stress: only converged maxima are reported as such
        out["contact/converged_max_pressure_Pa"] = float("nan") if singular else float(g["max_pressure_Pa"])
    if "unbalance/response_m" in f:
        out["unbalance/max_amplitude_m"] = float(np.max(np.abs(f["unbalance/response_m"][()])))
    return out


def case_scalars(paths: list[Path]) -> dict[str, float]:
    import h5py

    out: dict[str, float] = {}
    for p in paths:
        if Path(p).suffix != ".h5":
            continue
        with h5py.File(p, "r") as f:
            out.update(_generic(f))
            out.update(_derived(f))
    return out


# curves drawn side by side for the cases of a sweep: analysis -> (file, x dataset, y dataset, x label, y label)
OVERLAYS = {
    "rotor_transient": ("transient.h5", "transient/spectrum/frequency_hz", "transient/spectrum/amplitude_m",
                        "frequency [Hz]", "spectrum amplitude [m]"),
    "transient": ("transient.h5", "transient/spectrum/frequency_hz", "transient/spectrum/amplitude_m",
                  "frequency [Hz]", "spectrum amplitude [m]"),
    "frf": ("frf.h5", "frf/frequency_hz", "frf/receptance_m_N", "frequency [Hz]", "|receptance| [m/N]"),
}
