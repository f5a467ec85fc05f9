"""Key scalars of one case's output files, for the sweep summary, with their units.

Every 0-d numeric dataset and every numeric group attribute becomes a scalar
named by its path; a few analyses add derived ones (first natural frequencies,
FRF peak, dominant spectral line, steady vibration amplitude).  Units come from
the source: a dataset's ``units`` attribute, an attribute's ``<name>_units``
sibling or its SI suffix (``_hz``, ``_N``, ``_m`` ...), the derived ones from
their definition.  :data:`KEY_SCALARS` orders what the summary plot shows.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from ..registry import ANALYSIS_REGISTRY

#: name suffix -> unit, longest first (attribute names carry their unit: speed_rpm, load_N, area_m2)
_SUFFIX_UNITS = (("_Ns_m", "N s/m"), ("_m_s2", "m/s^2"), ("_N_m", "N/m"), ("_m_N", "m/N"), ("_m3_s", "m^3/s"), ("_W_K", "W/K"),
                 ("_Pa_s", "Pa s"), ("_m_s", "m/s"), ("_g_mm", "g mm"), ("_Nm", "N m"), ("_hz", "Hz"),
                 ("_Hz", "Hz"), ("_rpm", "rpm"), ("_m2", "m^2"), ("_Pa", "Pa"), ("_GPa", "GPa"), ("_rad", "rad"),
                 ("_deg", "deg"), ("_um", "um"), ("_mm", "mm"), ("_m", "m"), ("_N", "N"), ("_s", "s"), ("_W", "W"),
                 ("_C", "degC"), ("_kg", "kg"), ("_J", "J"))

#: the derived scalars' units (each analysis's, spindlesim/registry.py)
DERIVED_UNITS = {k: u for a in ANALYSIS_REGISTRY for k, u in a.derived_units}

#: the key results of each analysis, most important first ("*" matches one path part; spindlesim/registry.py);
#: the summary plot draws these (when finite in some case), then other scalars that vary
KEY_SCALARS = tuple(k for a in ANALYSIS_REGISTRY for k in a.key_scalars)
#: bookkeeping, never plotted
_NOT_RESULTS = re.compile(r"(iterations|wall_time|elapsed|record_node|step_s|sample_rate|settle_s|@row$|@roller$|"
                          r"@node$|@rollers$|frequency_hz\.|poincare|@operating_speed_rpm$)")


def unit_from_name(name: str) -> str:
    """The unit an attribute name's suffix states (``speed_rpm`` -> rpm), or "" when it states none."""
    leaf = re.split(r"[/@]", name.split("[")[0])[-1]
    for part in reversed(leaf.split(".")):  # frequency_hz.dtrb.cage: the unit is on the first part
        for suffix, unit in _SUFFIX_UNITS:
            if part.endswith(suffix) and len(part) > len(suffix):
                return unit
    return ""


def key_order(names) -> list[str]:
    """``names`` that are key results, in the order of :data:`KEY_SCALARS`."""
    out: list[str] = []
    for pattern in KEY_SCALARS:
        rx = re.compile("^" + re.escape(pattern).replace(r"\*", "[^/@]*") + "$")
        out += [n for n in names if rx.match(n) and n not in out]
    return out


def is_bookkeeping(name: str) -> bool:
    return bool(_NOT_RESULTS.search(name))


def _units_attr(obj) -> str:
    u = obj.attrs.get("units", "")
    return u.decode() if isinstance(u, bytes) else str(u)


def _is_series(ds) -> bool:
    """A time series or a dimension scale (a short Poincare set, its time_s): samples, not scalars."""
    cls = ds.attrs.get("CLASS", b"")
    if (cls.decode() if isinstance(cls, bytes) else str(cls)) == "DIMENSION_SCALE":
        return True
    if ds.ndim and "DIMENSION_LIST" in ds.attrs:
        return "time_s" in ds.dims[0].keys()
    return False


def _generic(f, units: dict[str, str]) -> dict[str, float]:
    import h5py

    out: dict[str, float] = {}

    def visit(name, obj):
        if isinstance(obj, h5py.Dataset) and obj.dtype.kind in "iuf" and not _is_series(obj):
            if obj.shape == ():
                out[name] = float(obj[()])
                units[name] = _units_attr(obj)
            elif obj.size <= 4:  # 2x2 coefficient matrices, (x, y) pairs
                for idx, v in np.ndenumerate(obj[()]):
                    key = name + "[" + ",".join(map(str, idx)) + "]"
                    out[key] = float(v)
                    units[key] = _units_attr(obj)
        if isinstance(obj, h5py.Group):
            for k, v in obj.attrs.items():
                if isinstance(v, (int, float, np.integer, np.floating)) and not isinstance(v, (bool, np.bool_)):
                    out[f"{name}@{k}"] = float(v)
                    stated = obj.attrs.get(f"{k}_units")
                    unit = str(stated) if stated is not None else unit_from_name(k)
                    # an integer attribute without a unit is a count or an index (iterations, rollers, row)
                    units[f"{name}@{k}"] = unit or ("1" if isinstance(v, (int, np.integer)) else "")

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
    if "transient/displacement_m" in f and "transient/time_s" in f:
        t, d = f["transient/time_s"][()], f["transient/displacement_m"][()]
        steady = t >= float(f["transient"].attrs.get("settle_s", 0.0)) - 1e-12
        if steady.sum() >= 2 and d.ndim == 2:
            out["transient/steady_amplitude_x_m"] = 0.5 * float(np.ptp(d[steady, 0]))
            out["transient/steady_amplitude_y_m"] = 0.5 * float(np.ptp(d[steady, 1]))
    if "contact" in f and "max_pressure_Pa" in f["contact"].attrs:
        g = f["contact"].attrs
        singular = bool(g.get("edge_singular", False))
        out["contact/edge_singular"] = float(singular)
        # a sharp-edge peak is a grid value, not a stress: only converged maxima are reported as such
        out["contact/converged_max_pressure_Pa"] = float("nan") if singular else float(g["max_pressure_Pa"])
    if "unbalance/response_m" in f:
        out["unbalance/max_amplitude_m"] = float(np.max(np.abs(f["unbalance/response_m"][()])))
    return out


def _derived_unit(name: str) -> str:
    generic = re.sub(r"\d+(_hz)?$", lambda m: "{k}" + (m.group(1) or ""), name)
    return DERIVED_UNITS.get(name, DERIVED_UNITS.get(generic, unit_from_name(name)))


def case_results(paths: list[Path]) -> tuple[dict[str, float], dict[str, str]]:
    """(scalars, units) of one case's HDF5 files."""
    import h5py

    out: dict[str, float] = {}
    units: dict[str, str] = {}
    for p in paths:
        if Path(p).suffix != ".h5":
            continue
        with h5py.File(p, "r") as f:
            out.update(_generic(f, units))
            derived = _derived(f)
            out.update(derived)
            units.update({k: _derived_unit(k) for k in derived})
    return out, units


def case_scalars(paths: list[Path]) -> dict[str, float]:
    return case_results(paths)[0]


# curves drawn side by side for the cases of a sweep: analysis (aliases included) -> (file, x dataset,
# y dataset, x label, y label)
OVERLAYS = {n: a.overlay for a in ANALYSIS_REGISTRY if a.overlay for n in (a.name, *a.aliases)}
