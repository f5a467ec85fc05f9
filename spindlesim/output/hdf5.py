"""Atomic HDF5 writer: provenance root attributes, units on every dataset, netCDF-4 dimension scales.

Usage::

    write_h5(path, run_info, {
        "/frf/frequency_hz": (f, "Hz", ("frequency_hz",)),           # a coordinate: its own dimension
        "/frf/receptance_m_N": (H, "m/N", ("frequency_hz",)),
        "/campbell/frequency_hz": Data(F, "Hz", ("speed_rpm", "mode"), fill_nan=True),
    }, group_attrs={"/frf": {"speed_rpm": 2170.0}})

An entry is ``(value, units)``, ``(value, units, dims)`` or a :class:`Data`.  ``dims`` names the
dimensions of the dataset, one per axis.  A dimension named like a 1-D dataset of the same group is
that dataset (it becomes an HDF5 dimension scale, i.e. a netCDF coordinate variable); any other
dimension gets an integer index coordinate 1..n (``mode``, ``node``, ``row``...), so that
``xarray.open_dataset(path, group=..., engine="h5netcdf")`` opens every group with coordinates.
:func:`labels` makes a string coordinate for a dimension whose entries have names (x, y, ...).

Non-finite numbers: a file whose run is complete never holds Inf, nor NaN except in datasets
declared ``fill_nan`` (NaN marks an absent value: a Campbell mode not tracked at a speed, a lobe
with no boundary point); those carry ``_FillValue = NaN``.  Anything else raises ValueError naming
the dataset, before a byte is written.  Group attributes must be finite too (an attribute that
does not apply is left out).

The file is written to a temporary name in the same directory, given the mode a plain ``open``
would give it (0o666 less the umask), and renamed, so a reader never sees a half-written file.
"""

from __future__ import annotations

import dataclasses
import datetime
import logging
import os
import platform
import sys
import secrets
import threading
from dataclasses import dataclass, field
from fnmatch import fnmatchcase
from pathlib import Path
from contextlib import contextmanager
from typing import Any, Iterator, Mapping, Sequence

import numpy as np

log = logging.getLogger(__name__)

__all__ = ["RunInfo", "Data", "labels", "five_dof", "write_h5", "provenance", "file_mode", "publish",
           "write_text_atomic"]

#: Datasets written by modules that do not declare their NaN fill themselves (the sweep summary):
#: NaN there marks a case without that value.  Patterns match the full dataset path.
NAN_FILL_PATTERNS: tuple[str, ...] = ("/sweep/scalars/*", "/sweep/elapsed_s")


@dataclass(frozen=True)
class RunInfo:
    """Provenance written as root attributes of every output file."""

    deck_text: str
    deck_source: str
    deck_sha256: str
    command_line: str = field(default_factory=lambda: " ".join(sys.argv))
    complete: bool = True
    incomplete_reason: str = ""


@dataclass(frozen=True)
class Data:
    """One dataset: value, UDUNITS units ("1" dimensionless) and the names of its dimensions.

    ``description`` is a note on the quantity (definition, clearance base, sign convention).
    ``fill_nan``: NaN marks an absent value (written as ``_FillValue`` NaN); otherwise NaN is refused.
    ``component_units``: for a dataset whose entries differ in units along its trailing axes (DOF
    vectors, 5 x 5 stiffness matrices), the units of each entry, shaped like those axes; ``units``
    is then "" (UDUNITS: unknown) and ``component_units`` is written as an attribute.
    """

    value: Any
    units: str
    dims: tuple[str, ...] | None = None
    description: str = ""
    fill_nan: bool = False
    component_units: Any = None
    attrs: Mapping[str, Any] = field(default_factory=dict)


def labels(group: str, dim: str, names: Sequence[str], description: str = "") -> dict[str, Data]:
    """A string coordinate ``group/dim`` naming the entries of dimension ``dim`` (e.g. x, y)."""
    return {f"{group}/{dim}": Data(np.array([str(n) for n in names], dtype=object), "1", (dim,), description)}


#: the five DOFs of a bearing (inner ring or shaft) and the matching loads, with their units
DOF5 = ("x", "y", "z", "theta_x", "theta_y")
LOAD5 = ("Fx", "Fy", "Fz", "Mx", "My")
DOF5_UNITS = ("m", "m", "m", "rad", "rad")
LOAD5_UNITS = ("N", "N", "N", "N m", "N m")
#: units of K[i, j] = dF_i / dq_j over (LOAD5, DOF5): N/m, N/rad, N m/m, N m/rad
STIFFNESS5_UNITS = tuple(tuple(f"{f}/{q}" for q in DOF5_UNITS) for f in LOAD5_UNITS)


def five_dof(group: str) -> dict[str, Data]:
    """The string coordinates ``load`` (Fx..My) and ``dof`` (x..theta_y) of ``group``."""
    return {**labels(group, "load", LOAD5), **labels(group, "dof", DOF5)}


# ----------------------------------------------------------------------------------------------
# file mode and atomic rename

_UMASK_LOCK = threading.Lock()


def _umask() -> int:
    """The process umask without changing it (Linux: /proc/self/status); else set-and-restore."""
    try:
        with open("/proc/self/status", encoding="ascii") as fh:
            for line in fh:
                if line.startswith("Umask:"):
                    return int(line.split()[1], 8)
    except (OSError, ValueError, IndexError):
        pass
    with _UMASK_LOCK:
        mask = os.umask(0o022)
        os.umask(mask)
    return mask


def file_mode() -> int:
    """The permission bits ``open(path, "w")`` would give a new file: 0o666 less the umask."""
    return 0o666 & ~_umask()


def publish(tmp: str | Path, path: str | Path) -> None:
    """Give ``tmp`` (a mkstemp file, mode 0600) the umask's mode and rename it to ``path``."""
    os.chmod(tmp, file_mode())
    os.replace(tmp, path)


@contextmanager
def atomic(path: str | Path, suffix: str = ".tmp") -> Iterator[str]:
    """A temporary file next to ``path`` (``<name>.<random><suffix>``) to write; on success it is published
    (:func:`publish`) as ``path``, on any failure removed: a reader never sees a half-written file."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    while True:  # the name first, then the file (as mkstemp, exclusive, 0600): a Ctrl-C at any point after
        # the name is chosen finds it in the handler below (with mkstemp the file existed before its name was
        # returned, and one interrupted in between was left behind)
        tmp = str(path.parent / f"{path.name}.{secrets.token_hex(4)}{suffix}")
        try:
            os.close(os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600))
            break
        except FileExistsError:
            continue
        except BaseException:
            _unlink(tmp)
            raise
    try:
        yield tmp
        publish(tmp, path)
    except BaseException:
        _unlink(tmp)
        raise


def _unlink(tmp: str) -> None:
    try:
        os.unlink(tmp)
    except FileNotFoundError:
        pass


def write_text_atomic(path: str | Path, text: str) -> Path:
    """``text`` as UTF-8 to ``path`` through a temporary file renamed into place (:func:`atomic`)."""
    with atomic(path) as tmp:
        Path(tmp).write_text(text, encoding="utf-8")
    return Path(path)


# ----------------------------------------------------------------------------------------------
# provenance


def _version(dist: str) -> str:
    from importlib import metadata

    try:
        return metadata.version(dist)
    except metadata.PackageNotFoundError:
        return "not installed"


def provenance() -> dict[str, str]:
    """Root attributes besides the deck's: time (UTC, ISO 8601), platform, Python and library versions."""
    from .. import __version__

    return {
        "spindlesim_version": __version__,
        "created_utc": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
        "platform": platform.platform(),
        "python_version": platform.python_version(),
        "numpy_version": np.__version__,
        "scipy_version": _version("scipy"),
        "h5py_version": _version("h5py"),
        "numba_version": _version("numba"),
    }


# ----------------------------------------------------------------------------------------------
# entries


def _value(v: Any) -> Any:
    if isinstance(v, str):
        return v
    arr = np.asarray(v)
    if arr.dtype.kind in "OUS":
        return np.asarray(arr, dtype=object).astype(str).astype(object)
    return arr


def _entry(name: str, spec: Any) -> Data:
    if isinstance(spec, Data):
        return spec
    if not isinstance(spec, tuple) or len(spec) not in (2, 3):
        raise TypeError(f"{name}: a dataset is (value, units), (value, units, dims) or Data, not {type(spec)}")
    return Data(spec[0], spec[1], tuple(spec[2]) if len(spec) == 3 else None)


def _split(name: str) -> tuple[str, str]:
    name = "/" + name.strip("/")
    group, _, base = name.rpartition("/")
    return group or "/", base


def _join(group: str, base: str) -> str:
    return f"{group.rstrip('/')}/{base}"


def _nonfinite(name: str, v: Any, fill_nan: bool) -> str | None:
    """Why ``v`` may not be written (or None)."""
    if isinstance(v, str) or not isinstance(v, np.ndarray) or v.dtype.kind not in "fc":
        return None
    n_inf = int(np.count_nonzero(np.isinf(v)))
    n_nan = int(np.count_nonzero(np.isnan(v)))
    if n_inf:
        return f"{name} has {n_inf} infinite value(s) of {v.size}"
    if n_nan and not fill_nan:
        return f"{name} has {n_nan} NaN value(s) of {v.size} and does not declare NaN as a fill value"
    return None


def _attr_nonfinite(group: str, key: str, v: Any) -> str | None:
    if isinstance(v, (str, bytes, bool, np.bool_)):
        return None
    try:
        a = np.asarray(v)
    except Exception:  # noqa: BLE001 - an attribute h5py will judge itself
        return None
    if a.dtype.kind in "fc" and not np.all(np.isfinite(a)):
        return f"attribute {key!r} of {group} is not finite ({v!r})"
    return None


def _check(path: Path, run: RunInfo, entries: Mapping[str, tuple[Data, Any]],
           group_attrs: Mapping[str, Mapping[str, Any]]) -> None:
    problems = [p for n, (d, v) in entries.items() if (p := _nonfinite(n, v, d.fill_nan))]
    problems += [p for g, attrs in group_attrs.items() for k, v in attrs.items() if (p := _attr_nonfinite(g, k, v))]
    if not problems:
        return
    if run.complete:
        raise ValueError(f"{path.name}: refusing to write non-finite results: {problems[0]}"
                         + (f" (and {len(problems) - 1} more)" if len(problems) > 1 else ""))
    log.warning("%s (incomplete run): %s", path.name, "; ".join(problems))


# ----------------------------------------------------------------------------------------------
# dimension scales


def _dims_of(name: str, d: Data, v: Any) -> tuple[str, ...] | None:
    if d.dims is None:
        return None
    shape = () if isinstance(v, str) else np.shape(v)
    if len(d.dims) != len(shape):
        raise ValueError(f"{name}: {len(d.dims)} dimension name(s) {d.dims} for a dataset of shape {shape}")
    return tuple(d.dims)


def _index_coordinates(entries: Mapping[str, tuple[Data, Any]]) -> dict[str, tuple[Data, Any]]:
    """The integer index coordinates of dimensions that have no dataset of their own."""
    sizes: dict[str, tuple[int, str]] = {}
    for name, (d, v) in entries.items():
        dims = _dims_of(name, d, v)
        for axis, dim in enumerate(dims or ()):
            key = _join(_split(name)[0], dim)
            n = int(np.shape(v)[axis])
            if key in sizes and sizes[key][0] != n:
                raise ValueError(f"dimension {dim!r}: {sizes[key][1]} has {sizes[key][0]} entries, {name} has {n}")
            sizes.setdefault(key, (n, name))
    out = {}
    for key, (n, _) in sizes.items():
        if key in entries:
            d, v = entries[key]
            if np.ndim(v) != 1 or np.shape(v)[0] != n or _dims_of(key, d, v) not in (None, (_split(key)[1],)):
                raise ValueError(f"{key} is used as a dimension but is not its 1-D coordinate")
            continue
        out[key] = (Data(None, "1", (_split(key)[1],), "index (1-based)"), np.arange(1, n + 1, dtype=np.int64))
    return out


def _attach_scales(f: Any, entries: Mapping[str, tuple[Data, Any]]) -> None:
    used = {_join(_split(n)[0], dim) for n, (d, _) in entries.items() for dim in (d.dims or ())}
    scales = {}
    for name, (d, v) in entries.items():
        group, base = _split(name)
        if name in used:
            f[name].make_scale(base)
            scales[name] = f[name]
    for name, (d, v) in entries.items():
        group, base = _split(name)
        if not d.dims or d.dims == (base,):
            continue
        ds = f[name]
        for axis, dim in enumerate(d.dims):
            ds.dims[axis].attach_scale(scales[_join(group, dim)])


# ----------------------------------------------------------------------------------------------
# writer


def _create(f: Any, name: str, d: Data, v: Any) -> None:
    import h5py

    if isinstance(v, str) or (isinstance(v, np.ndarray) and v.dtype == object):
        ds = f.create_dataset(name, data=v, dtype=h5py.string_dtype())
    elif d.fill_nan and v.dtype.kind == "f":
        ds = f.create_dataset(name, data=v, fillvalue=np.nan)
        ds.attrs["_FillValue"] = np.array(np.nan, dtype=v.dtype)
    else:
        ds = f.create_dataset(name, data=v)
    ds.attrs["units"] = "" if d.component_units is not None else d.units
    if d.component_units is not None:
        ds.attrs["component_units"] = np.asarray(d.component_units, dtype=object).astype(str).astype(object)
    if d.description:
        ds.attrs["description"] = d.description
    for k, a in d.attrs.items():
        ds.attrs[k] = a


def write_h5(path: str | Path, run: RunInfo, datasets: Mapping[str, Any],
             group_attrs: Mapping[str, Mapping[str, Any]] | None = None) -> Path:
    """Write ``datasets`` {"/group/name": (value, units[, dims]) or Data} atomically to ``path``.

    Raises ValueError (nothing written) for non-finite values a complete run may not hold, for
    dimension names that do not match the shapes, or for one dimension with two lengths in a group.
    """
    import h5py

    path = Path(path)
    group_attrs = group_attrs or {}
    entries: dict[str, tuple[Data, Any]] = {}
    for name, spec in datasets.items():
        d, key = _entry(name, spec), "/" + name.strip("/")
        if not d.fill_nan and any(fnmatchcase(key, p) for p in NAN_FILL_PATTERNS):
            d = dataclasses.replace(d, fill_nan=True)
        entries[key] = (d, _value(d.value))
    _check(path, run, entries, group_attrs)
    entries.update(_index_coordinates(entries))

    with atomic(path) as tmp, h5py.File(tmp, "w") as f:
        for k, v in provenance().items():
            f.attrs[k] = v
        f.attrs["deck_sha256"] = run.deck_sha256
        f.attrs["deck_text"] = run.deck_text
        f.attrs["deck_source"] = run.deck_source
        f.attrs["command_line"] = run.command_line
        f.attrs["complete"] = run.complete
        if run.incomplete_reason:
            f.attrs["incomplete_reason"] = run.incomplete_reason
        for name, (d, v) in entries.items():
            _create(f, name, d, v)
        _attach_scales(f, entries)
        for group, attrs in group_attrs.items():
            g = f.require_group(group)
            for k, v in attrs.items():
                g.attrs[k] = v
    return path
