"""Measured tool-point FRF files: CSV and universal file format 58 (through pyuff).

CSV (comma-separated, UTF-8; blank lines and lines starting with ``#`` are ignored; the first
other line is the header; column order is free, names are case-insensitive).  Two layouts:

* all directions in one file::

      frequency_hz,xx_real_m_N,xx_imag_m_N,yy_real_m_N,yy_imag_m_N[,xy_real_m_N,xy_imag_m_N,yx_real_m_N,yx_imag_m_N]

  ``ij`` is the displacement in direction i per unit force in direction j.  A missing pair is
  zero: no xy/yx columns means uncoupled directions; a file with xx only (or yy only) describes
  a tool that is rigid in the other direction.
* one direction per file (the usual tap test), the direction given by the caller (the deck's
  ``direction:``)::

      frequency_hz,real_m_N,imag_m_N

Values are receptance in m/N, frequencies in Hz, strictly increasing.  Several single-direction
files are merged with :func:`combine_frfs` (same frequencies, or interpolated onto the first
file's frequencies within the common band).

UFF 58 (ASCII or binary 58b), read with pyuff: every function of type 4 (FRF) whose response
and reference directions are +-X or +-Y (1, 2; the sign is applied) fills H[i, j]; the ordinate
may be displacement (8, receptance), velocity (11, mobility, divided by j w) or acceleration
(12, accelerance, divided by -w^2) over force (13, or 0 = unknown, taken as force).  Units are
taken as SI unless the ordinate unit label says mm/N or um/N.

Every problem raises :class:`FrfFileError` naming the file, the line (CSV, and the first line of
the UFF dataset) and the problem.
"""

from __future__ import annotations

import csv
import logging
from pathlib import Path

import numpy as np

from .frf import DIRECTIONS, ToolPointFrf

__all__ = ["FrfFileError", "read_frf_csv", "write_frf_csv", "read_frf_uff", "read_frf", "combine_frfs"]

log = logging.getLogger(__name__)
_PAIRS = {"xx": (0, 0), "yy": (1, 1), "xy": (0, 1), "yx": (1, 0)}


class FrfFileError(ValueError):
    """A measured FRF file that cannot be used: ``path:line: message``."""

    def __init__(self, path, line: int | None, message: str):
        self.path, self.line, self.message = str(path), line, message
        where = f"{self.path}:{line}" if line is not None else self.path
        super().__init__(f"{where}: {message}")


def _columns(path, lineno: int, header: list[str], direction: str | None) -> dict[str, int]:
    names = [h.strip().lower() for h in header]
    seen = set()
    for n in names:
        if n in seen:
            raise FrfFileError(path, lineno, f"column {n!r} appears twice")
        seen.add(n)
    if "frequency_hz" not in names:
        raise FrfFileError(path, lineno, "header has no 'frequency_hz' column "
                           f"(found: {', '.join(names)})")
    single = {"real_m_n", "imag_m_n"} & seen
    allowed = {"frequency_hz"} | ({"real_m_n", "imag_m_n"} if single else
                                  {f"{p}_{c}_m_n" for p in _PAIRS for c in ("real", "imag")})
    unknown = [n for n in names if n not in allowed]
    if unknown:
        raise FrfFileError(path, lineno, f"unknown column(s) {', '.join(unknown)}; expected "
                           "frequency_hz with real_m_N, imag_m_N (one direction) or "
                           "xx_real_m_N, xx_imag_m_N, yy_..., xy_..., yx_...")
    cols = {n: i for i, n in enumerate(names)}
    if single:
        if not {"real_m_n", "imag_m_n"} <= seen:
            raise FrfFileError(path, lineno, "a single-direction file needs both real_m_N and imag_m_N")
        if direction not in DIRECTIONS:
            raise FrfFileError(path, lineno, "a single-direction file (real_m_N, imag_m_N) needs its "
                               "direction: x or y")
        d = direction * 2
        return {"frequency_hz": cols["frequency_hz"], f"{d}_real_m_n": cols["real_m_n"],
                f"{d}_imag_m_n": cols["imag_m_n"]}
    pairs = [p for p in _PAIRS if f"{p}_real_m_n" in cols or f"{p}_imag_m_n" in cols]
    for p in pairs:
        for c in ("real", "imag"):
            if f"{p}_{c}_m_n" not in cols:
                raise FrfFileError(path, lineno, f"column {p}_{c}_m_N is missing (its pair is given)")
    if not pairs:
        raise FrfFileError(path, lineno, "no FRF columns")
    return cols


def read_frf_csv(path, direction: str | None = None) -> ToolPointFrf:
    """Read a CSV FRF file (layouts in the module docstring)."""
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8-sig")
    except OSError as exc:
        raise FrfFileError(path, None, f"cannot read: {exc.strerror or exc}") from exc
    except UnicodeDecodeError as exc:
        raise FrfFileError(path, None, "not a UTF-8 text file") from exc
    cols, rows, lines = None, [], []
    for lineno, fields in _numbered_rows(text):
        if cols is None:
            cols = _columns(path, lineno, fields, direction)
            width = len(fields)
            continue
        if len(fields) != width:
            raise FrfFileError(path, lineno, f"{len(fields)} fields, the header has {width}")
        vals = {}
        for name, i in cols.items():
            try:
                v = float(fields[i])
            except ValueError:
                raise FrfFileError(path, lineno, f"{name}: {fields[i].strip()!r} is not a number") from None
            if not np.isfinite(v):
                raise FrfFileError(path, lineno, f"{name}: {fields[i].strip()} is not finite")
            vals[name] = v
        rows.append(vals)
        lines.append(lineno)
    if cols is None:
        raise FrfFileError(path, None, "empty file (no header)")
    if len(rows) < 2:
        raise FrfFileError(path, None, f"{len(rows)} data row(s); at least two are needed")
    f = np.array([r["frequency_hz"] for r in rows])
    if f[0] < 0:
        raise FrfFileError(path, lines[0], "negative frequency")
    bad = np.flatnonzero(np.diff(f) <= 0)
    if len(bad):
        k = bad[0] + 1
        raise FrfFileError(path, lines[k], f"frequency {f[k]:g} Hz does not increase (previous {f[k - 1]:g} Hz)")
    H = np.zeros((len(f), 2, 2), complex)
    for p, (i, j) in _PAIRS.items():
        if f"{p}_real_m_n" in cols:
            H[:, i, j] = [r[f"{p}_real_m_n"] + 1j * r[f"{p}_imag_m_n"] for r in rows]
    return ToolPointFrf(f, H, f"csv:{path.name}" + (f" ({direction})" if direction else ""))


def _numbered_rows(text: str):
    for lineno, line in enumerate(text.splitlines(), start=1):
        s = line.strip()
        if not s or s.startswith("#"):
            continue
        yield lineno, next(csv.reader([line]))


def write_frf_csv(path, frf: ToolPointFrf, direction: str | None = None) -> None:
    """Write all four terms, or one direct term (``direction``) in the single-direction layout."""
    path = Path(path)
    with path.open("w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        fh.write(f"# tool-point receptance [m/N]; source: {frf.source or 'unnamed'}\n")
        if direction is not None:
            i = DIRECTIONS.index(direction)
            w.writerow(["frequency_hz", "real_m_N", "imag_m_N"])
            for f, h in zip(frf.frequency_hz, frf.H[:, i, i]):
                w.writerow([repr(float(f)), repr(float(h.real)), repr(float(h.imag))])
            return
        w.writerow(["frequency_hz"] + [f"{p}_{c}_m_N" for p in _PAIRS for c in ("real", "imag")])
        for f, H in zip(frf.frequency_hz, frf.H):
            row = [repr(float(f))]
            for i, j in _PAIRS.values():
                row += [repr(float(H[i, j].real)), repr(float(H[i, j].imag))]
            w.writerow(row)


def _uff_dataset_lines(path: Path) -> list[int]:
    """First line of every dataset (ASCII scan; empty when the file is not readable as text)."""
    starts = []
    try:
        with path.open("rb") as fh:
            inside = False
            for lineno, raw in enumerate(fh, start=1):
                if raw.strip() == b"-1":
                    inside = not inside
                    if inside:
                        starts.append(lineno)
    except OSError:
        return []
    return starts


def read_frf_uff(path) -> ToolPointFrf:
    """Read the X/Y FRFs of a universal file (dataset 58/58b) with pyuff."""
    import pyuff

    path = Path(path)
    if not path.is_file():
        raise FrfFileError(path, None, "no such file")
    starts = _uff_dataset_lines(path)
    try:
        uff = pyuff.UFF(str(path))
        types = list(uff.get_set_types())
    except Exception as exc:  # pyuff raises bare Exception
        raise FrfFileError(path, None, f"not a readable universal file: {exc}") from exc
    if len(starts) != len(types):
        starts = []  # binary blocks: no reliable line numbers
    terms: dict[tuple[int, int], tuple[np.ndarray, np.ndarray]] = {}
    for n, t in enumerate(types):
        line = starts[n] if n < len(starts) else None
        if int(t) != 58:
            continue
        try:
            d = uff.read_sets(n)
        except Exception as exc:
            raise FrfFileError(path, line, f"dataset {n + 1} (58): {exc}") from exc
        if int(d.get("func_type", -1)) != 4:
            log.info("%s: dataset %d is not an FRF (function type %s), skipped", path, n + 1, d.get("func_type"))
            continue
        rd, fd = int(d.get("rsp_dir", 0)), int(d.get("ref_dir", 0))
        if abs(rd) not in (1, 2) or abs(fd) not in (1, 2):
            log.info("%s: dataset %d directions %d/%d are not X/Y translations, skipped", path, n + 1, rd, fd)
            continue
        x = np.asarray(d["x"], float)
        h = np.asarray(d["data"]).astype(complex) * np.sign(rd) * np.sign(fd)
        if not np.iscomplexobj(d["data"]):
            raise FrfFileError(path, line, f"dataset {n + 1}: FRF ordinate is real, complex data expected")
        h = h * _uff_ordinate_factor(path, line, n, d, x)
        key = (abs(rd) - 1, abs(fd) - 1)
        if key in terms:
            raise FrfFileError(path, line, f"dataset {n + 1}: a second FRF for response "
                               f"{DIRECTIONS[key[0]]}, reference {DIRECTIONS[key[1]]}")
        terms[key] = (x, h)
    if not terms:
        raise FrfFileError(path, None, "no dataset 58 FRF with X/Y response and reference directions")
    f0 = next(iter(terms.values()))[0]
    H = np.zeros((len(f0), 2, 2), complex)
    for (i, j), (x, h) in terms.items():
        if len(x) != len(f0) or not np.allclose(x, f0, rtol=1e-9, atol=0):
            raise FrfFileError(path, None,
                               f"FRF {DIRECTIONS[i]}{DIRECTIONS[j]} has other frequencies than the first one")
        H[:, i, j] = h
    keep = f0 >= 0
    try:
        return ToolPointFrf(f0[keep], H[keep], f"uff:{path.name}")
    except ValueError as exc:
        raise FrfFileError(path, None, str(exc)) from exc


def _uff_ordinate_factor(path, line, n, d, x) -> np.ndarray:
    abscissa = int(d.get("abscissa_spec_data_type", 18))
    if abscissa not in (0, 18):
        raise FrfFileError(path, line, f"dataset {n + 1}: abscissa type {abscissa} is not frequency (18)")
    denom = int(d.get("orddenom_spec_data_type", 13))
    if denom not in (0, 13):
        raise FrfFileError(path, line, f"dataset {n + 1}: ordinate denominator type {denom} is not force (13)")
    kind = int(d.get("ordinate_spec_data_type", 8))
    w = 2 * np.pi * x
    with np.errstate(divide="ignore", invalid="ignore"):
        factor = {8: np.ones_like(w), 0: np.ones_like(w), 1: np.ones_like(w),
                  11: 1.0 / (1j * w), 12: -1.0 / w**2}.get(kind)
    if factor is None:
        raise FrfFileError(path, line, f"dataset {n + 1}: ordinate type {kind} is not displacement (8), "
                           "velocity (11) or acceleration (12)")
    label = str(d.get("ordinate_axis_units_lab", "")).strip().lower().replace("µ", "u")
    scale = 1e-3 if label.startswith("mm") else 1e-6 if label.startswith("um") else 1.0
    return np.where(np.isfinite(factor), factor, 0.0) * scale


def read_frf(path, format: str = "csv", direction: str | None = None) -> ToolPointFrf:
    """Read one FRF file: ``format`` csv or uff; ``direction`` only for single-direction CSV or
    to keep one direction of a UFF file."""
    if format == "csv":
        return read_frf_csv(path, direction)
    if format == "uff":
        frf = read_frf_uff(path)
        if direction is None:
            return frf
        i = DIRECTIONS.index(direction)
        H = np.zeros_like(frf.H)
        H[:, i, i] = frf.H[:, i, i]
        return ToolPointFrf(frf.frequency_hz, H, f"{frf.source} ({direction})")
    raise ValueError(f"unknown FRF file format {format!r} (csv or uff)")


def combine_frfs(frfs: list[ToolPointFrf]) -> ToolPointFrf:
    """Sum of FRFs measured separately (e.g. x and y tap tests) on the first one's frequencies."""
    if not frfs:
        raise ValueError("no FRF to combine")
    base = frfs[0]
    lo = max(f.frequency_hz[0] for f in frfs)
    hi = min(f.frequency_hz[-1] for f in frfs)
    fq = base.frequency_hz[(base.frequency_hz >= lo) & (base.frequency_hz <= hi)]
    if len(fq) < 2:
        raise ValueError("the FRFs have no common frequency band")
    H = np.zeros((len(fq), 2, 2), complex)
    for f in frfs:
        same = len(f.frequency_hz) == len(fq) and np.allclose(f.frequency_hz, fq, rtol=1e-9)
        if not same:
            log.info("interpolating %s onto the frequencies of %s", f.source, base.source)
        H += f.H if same else f.interpolated(fq).H
    return ToolPointFrf(fq, H, " + ".join(f.source for f in frfs))
