"""Atomic HDF5 writer: root attributes (version, deck sha256 and text, command line), units on every dataset.

Usage::

    write_h5(path, run_info, {"/modal/frequency_hz": (array, "Hz"), ...},
             group_attrs={"/modal": {"speed_rpm": 2170.0}})

The file is written to a temporary name in the same directory and renamed, so a
reader never sees a half-written file.
"""

from __future__ import annotations

import os
import sys
import tempfile
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Mapping

import numpy as np


@dataclass(frozen=True)
class RunInfo:
    """Provenance written as root attributes of every output file."""

    deck_text: str
    deck_source: str
    deck_sha256: str
    command_line: str = field(default_factory=lambda: " ".join(sys.argv))
    complete: bool = True
    incomplete_reason: str = ""


def _value(v: Any) -> Any:
    if isinstance(v, str):
        return v
    arr = np.asarray(v)
    if arr.dtype.kind in "OU":
        return np.asarray(arr, dtype=object).astype(str).astype(object)
    return arr


def write_h5(path: str | Path, run: RunInfo, datasets: Mapping[str, tuple[Any, str]],
             group_attrs: Mapping[str, Mapping[str, Any]] | None = None) -> Path:
    """Write ``datasets`` {"/group/name": (value, units)} atomically to ``path``."""
    import h5py

    from .. import __version__

    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=path.name + ".", suffix=".tmp", dir=path.parent)
    os.close(fd)
    try:
        with h5py.File(tmp, "w") as f:
            f.attrs["spindlesim_version"] = __version__
            f.attrs["deck_sha256"] = run.deck_sha256
            f.attrs["deck_text"] = run.deck_text
            f.attrs["deck_source"] = run.deck_source
            f.attrs["command_line"] = run.command_line
            f.attrs["complete"] = run.complete
            if run.incomplete_reason:
                f.attrs["incomplete_reason"] = run.incomplete_reason
            str_dt = h5py.string_dtype()
            for name, (value, units) in datasets.items():
                v = _value(value)
                if isinstance(v, np.ndarray) and v.dtype == object:
                    ds = f.create_dataset(name, data=v, dtype=str_dt)
                elif isinstance(v, str):
                    ds = f.create_dataset(name, data=v, dtype=str_dt)
                else:
                    ds = f.create_dataset(name, data=v)
                ds.attrs["units"] = units
            for group, attrs in (group_attrs or {}).items():
                g = f.require_group(group)
                for k, v in attrs.items():
                    g.attrs[k] = v
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise
    return path
