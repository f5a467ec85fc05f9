"""Impact records of a tap test: force and response time records in CSV or universal file format 58.

CSV (comma-separated, UTF-8; blank lines and ``#`` lines ignored; the first other line is the header; column
order free, names case-insensitive)::

    time_s,force_N,acceleration_m_s2[,impact]

with exactly one response column: ``acceleration_m_s2``, ``velocity_m_s`` or ``displacement_m``.  Without an
``impact`` column the file is one impact; with it, the rows of each impact (any integer label) follow each
other, each impact with its own time from its trigger.  Times strictly increase by one step within an
impact (1 % tolerance, for times printed with few digits).

UFF 58 (ASCII or binary, read with pyuff): datasets of function type 1 (time response); a force record
(ordinate type 13) and a response record (acceleration 12, velocity 11, displacement 8) make an impact, the
k-th force with the k-th response in the file's order.  The response's direction (1 = +X, 2 = +Y, negative:
reversed) and the force's give the FRF's direction and sign.  Units SI unless the ordinate label says
otherwise (g, mm/s^2, mm/s, mm, um; kN).

Every impact of every file must have the same time step and length.  Each problem raises
:class:`RecordFileError` naming the file, the line (the dataset's first line in a universal file) and the
problem.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..chatter.readers import FrfFileError, csv_rows, numeric_row, uff58_sets
from .results import ImpactRecord

__all__ = ["RecordFileError", "read_impact_records", "read_impact_csv", "read_impact_uff", "RESPONSES",
           "MIN_RECORD_SAMPLES"]

#: CSV column -> the response it holds
RESPONSES = {"acceleration_m_s2": "acceleration", "velocity_m_s": "velocity", "displacement_m": "displacement"}
#: UFF ordinate type -> response
_UFF_RESPONSES = {12: "acceleration", 11: "velocity", 8: "displacement"}
#: fewest samples of a record (the double-hit check of pyFRF needs a few hundred)
MIN_RECORD_SAMPLES = 512
_STEP_TOL = 0.01


class RecordFileError(FrfFileError):
    """An impact record file that cannot be used: ``path:line: message``."""


def read_impact_records(path, format: str | None = None) -> list[ImpactRecord]:
    """Every impact of one file; ``format`` csv or uff, by default from the suffix (.uff, .unv: uff)."""
    path = Path(path)
    fmt = format or ("uff" if path.suffix.lower() in (".uff", ".unv") else "csv")
    if fmt == "csv":
        return read_impact_csv(path)
    if fmt == "uff":
        return read_impact_uff(path)
    raise ValueError(f"unknown record format {format!r} (csv or uff)")


# ----------------------------------------------------------------------------------------------
# CSV


def _header(path: Path, lineno: int, fields: list[str]) -> tuple[dict[str, int], str]:
    names = [h.strip().lower() for h in fields]
    dup = {n for n in names if names.count(n) > 1}
    if dup:
        raise RecordFileError(path, lineno, f"column {sorted(dup)[0]!r} appears twice")
    allowed = {"time_s", "force_n", "impact", *RESPONSES}
    unknown = [n for n in names if n not in allowed]
    if unknown:
        raise RecordFileError(path, lineno, f"unknown column(s) {', '.join(unknown)}; expected time_s, force_N, one "
                              "of acceleration_m_s2, velocity_m_s, displacement_m, and optionally impact")
    missing = [n for n in ("time_s", "force_n") if n not in names]
    if missing:
        raise RecordFileError(path, lineno, f"header has no {missing[0]!r} column")
    responses = [n for n in names if n in RESPONSES]
    if len(responses) != 1:
        raise RecordFileError(path, lineno, "one response column is needed (acceleration_m_s2, velocity_m_s or "
                              f"displacement_m), found {len(responses)}")
    return {n: i for i, n in enumerate(names)}, responses[0]


def read_impact_csv(path) -> list[ImpactRecord]:
    """The impacts of a CSV record file (module docstring)."""
    path = Path(path)
    cols, groups, header = None, {}, None
    order: list[float] = []
    for lineno, fields in csv_rows(path, error=RecordFileError):
        if cols is None:
            cols, response = _header(path, lineno, fields)
            width, header = len(fields), lineno
            continue
        vals = numeric_row(path, lineno, fields, cols, width, RecordFileError)
        label = vals.get("impact", 1.0)
        if label != round(label):
            raise RecordFileError(path, lineno, f"impact: {label:g} is not a whole number")
        if label not in groups:
            groups[label] = []
            order.append(label)
        elif order[-1] != label:
            raise RecordFileError(path, lineno, f"impact {label:g} appears again after impact {order[-1]:g} (the rows "
                                  "of one impact must follow each other)")
        groups[label].append((lineno, vals["time_s"], vals["force_n"], vals[response]))
    if cols is None:
        raise RecordFileError(path, None, "empty file (no header)")
    if not groups:
        raise RecordFileError(path, header, "a header but no rows")
    records = []
    for label in order:
        rows = groups[label]
        lines = [r[0] for r in rows]
        t = np.array([r[1] for r in rows])
        name = f"{path}:{lines[0]} (impact {label:g})" if "impact" in cols else f"{path}:{lines[0]}"
        dt = _uniform_step(path, lines, t, f"impact {label:g}: " if "impact" in cols else "")
        records.append(ImpactRecord(np.array([r[2] for r in rows]), np.array([r[3] for r in rows]),
                                    RESPONSES[response], dt, name, float(t[0])))
    return records


def _uniform_step(path: Path, lines: list[int], t: np.ndarray, what: str) -> float:
    if len(t) < MIN_RECORD_SAMPLES:
        raise RecordFileError(path, lines[-1], f"{what}{len(t)} samples; a record needs at least {MIN_RECORD_SAMPLES}")
    steps = np.diff(t)
    dt = float((t[-1] - t[0]) / (len(t) - 1))
    bad = np.flatnonzero(steps <= 0)
    if len(bad):
        k = bad[0] + 1
        raise RecordFileError(path, lines[k], f"{what}time {t[k]:g} s does not increase (previous {t[k - 1]:g} s)")
    bad = np.flatnonzero(np.abs(steps - dt) > _STEP_TOL * dt)
    if len(bad):
        k = bad[0] + 1
        raise RecordFileError(path, lines[k], f"{what}time step {steps[k - 1]:.6g} s differs from the record's "
                              f"{dt:.6g} s (records are sampled at a constant rate)")
    return dt


# ----------------------------------------------------------------------------------------------
# UFF 58, function type 1


def read_impact_uff(path) -> list[ImpactRecord]:
    """The impacts of a universal file's time records (module docstring)."""
    path = Path(path)
    forces, responses = [], []
    for n, line, d in uff58_sets(path, RecordFileError):
        if int(d.get("func_type", -1)) != 1:
            continue
        abscissa = int(d.get("abscissa_spec_data_type", 17))
        if abscissa not in (0, 17):
            raise RecordFileError(path, line, f"dataset {n + 1}: abscissa type {abscissa} is not time (17)")
        x = np.asarray(d["x"], float)
        y = np.asarray(d["data"])
        if np.iscomplexobj(y):
            raise RecordFileError(path, line, f"dataset {n + 1}: a time record must be real")
        kind = int(d.get("ordinate_spec_data_type", 0))
        label = str(d.get("ordinate_axis_units_lab", "")).strip().lower().replace("µ", "u")
        sign = float(np.sign(int(d.get("rsp_dir", 0))) or 1.0)
        values = y.astype(float) * sign * _uff_scale(path, line, n, kind, label)
        item = (n, line, x, values, abs(int(d.get("rsp_dir", 0))))
        if kind == 13:
            forces.append(item)
        elif kind in _UFF_RESPONSES:
            responses.append(item + (_UFF_RESPONSES[kind],))
        else:
            raise RecordFileError(path, line, f"dataset {n + 1}: ordinate type {kind} is neither force (13) nor a "
                                  "response (acceleration 12, velocity 11, displacement 8)")
    if not forces and not responses:
        raise RecordFileError(path, None, "no dataset 58 of function type 1 (time response)")
    if len(forces) != len(responses):
        raise RecordFileError(path, None, f"{len(forces)} force record(s) and {len(responses)} response record(s): "
                              "an impact is one of each")
    records = []
    for (nf, lf, xf, f, _), (nr, lr, xr, r, dr, kind) in zip(forces, responses):
        where = f"{path}:{lf}" if lf else f"{path} (dataset {nf + 1})"
        if len(xf) != len(xr) or not np.allclose(xf, xr, rtol=1e-9, atol=1e-12):
            raise RecordFileError(path, lr, f"dataset {nr + 1}: the response's times are not those of its force "
                                  f"(dataset {nf + 1})")
        lines = [lf or 0] * len(xf)
        dt = _uniform_step(path, lines, xf, f"dataset {nf + 1}: ")
        records.append(ImpactRecord(f, r, kind, dt, where, float(xf[0]), {1: "x", 2: "y"}.get(dr)))
    return records


def _uff_scale(path, line, n, kind: int, label: str) -> float:
    if kind == 13:
        return 1e3 if label.startswith("kn") else 1.0
    if kind == 12 and (label == "g" or label.startswith("g ")):
        return 9.80665
    if label.startswith("mm"):
        return 1e-3
    if label.startswith("um"):
        return 1e-6
    return 1.0
