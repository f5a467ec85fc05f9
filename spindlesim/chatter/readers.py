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

      frequency_hz,real_m_N,imag_m_N[,coherence]

  A measured file may give the ordinary coherence of each term (0 to 1): ``coherence`` in the
  single-direction layout, ``xx_coherence``, ``yy_coherence``, ``xy_coherence``, ``yx_coherence`` in the
  other (``spindlesim impact`` writes it; the modal identification reports it at each mode).  A comment
  line ``# exponential_window_decay_1_s: D`` says the measurement was windowed by e^(-D t): every damping
  ratio in the file is higher by D / w_n than the structure's (``spindlesim fitmodes`` takes it off).

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
import re
from pathlib import Path
from typing import Iterator

import numpy as np

from .frf import DIRECTIONS, ToolPointFrf

__all__ = ["FrfFileError", "read_frf_csv", "write_frf_csv", "frf_csv_text", "read_frf_uff", "read_frf", "combine_frfs",
           "csv_rows", "numeric_row", "uff_dataset_lines", "uff58_sets", "WINDOW_DECAY_KEY"]

log = logging.getLogger(__name__)
_PAIRS = {"xx": (0, 0), "yy": (1, 1), "xy": (0, 1), "yx": (1, 0)}
#: the comment key of an exponential window's decay [1/s]
WINDOW_DECAY_KEY = "exponential_window_decay_1_s"
_DECAY = re.compile(r"#\s*" + WINDOW_DECAY_KEY + r"\s*[:=]\s*(\S+)\s*$", re.IGNORECASE)


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
    allowed = {"frequency_hz"} | ({"real_m_n", "imag_m_n", "coherence"} if single else
                                  {f"{p}_{c}_m_n" for p in _PAIRS for c in ("real", "imag")}
                                  | {f"{p}_coherence" for p in _PAIRS})
    unknown = [n for n in names if n not in allowed]
    if unknown:
        raise FrfFileError(path, lineno, f"unknown column(s) {', '.join(unknown)}; expected "
                           "frequency_hz with real_m_N, imag_m_N[, coherence] (one direction) or "
                           "xx_real_m_N, xx_imag_m_N[, xx_coherence], yy_..., xy_..., yx_...")
    cols = {n: i for i, n in enumerate(names)}
    if single:
        if not {"real_m_n", "imag_m_n"} <= seen:
            raise FrfFileError(path, lineno, "a single-direction file needs both real_m_N and imag_m_N")
        if direction not in DIRECTIONS:
            raise FrfFileError(path, lineno, "a single-direction file (real_m_N, imag_m_N) needs its "
                               "direction: x or y")
        d = direction * 2
        out = {"frequency_hz": cols["frequency_hz"], f"{d}_real_m_n": cols["real_m_n"],
               f"{d}_imag_m_n": cols["imag_m_n"]}
        if "coherence" in cols:
            out[f"{d}_coherence"] = cols["coherence"]
        return out
    pairs = [p for p in _PAIRS if f"{p}_real_m_n" in cols or f"{p}_imag_m_n" in cols]
    lonely = [p for p in _PAIRS if f"{p}_coherence" in cols and p not in pairs]
    if lonely:
        raise FrfFileError(path, lineno, f"column {lonely[0]}_coherence without {lonely[0]}_real_m_N, "
                           f"{lonely[0]}_imag_m_N")
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
    cols, rows, lines, header, decays = None, [], [], None, []
    for lineno, fields in csv_rows(path, decays):
        if cols is None:
            cols = _columns(path, lineno, fields, direction)
            width, header = len(fields), lineno
            continue
        vals = numeric_row(path, lineno, fields, cols, width)
        for name, v in vals.items():
            if name.endswith("coherence") and not 0.0 <= v <= 1.0 + 1e-9:
                raise FrfFileError(path, lineno, f"{name}: {v:g} is outside [0, 1]")
        rows.append(vals)
        lines.append(lineno)
    if cols is None:
        raise FrfFileError(path, None, "empty file (no header)")
    if len(rows) < 2:
        raise FrfFileError(path, lines[-1] if rows else header, f"{len(rows)} data row(s); at least two are needed"
                           + ("" if rows else " (a header but no rows)"))
    decay = _decay(path, *decays[-1]) if decays else 0.0
    f = np.array([r["frequency_hz"] for r in rows])
    if f[0] < 0:
        raise FrfFileError(path, lines[0], "negative frequency")
    bad = np.flatnonzero(np.diff(f) <= 0)
    if len(bad):
        k = bad[0] + 1
        raise FrfFileError(path, lines[k], f"frequency {f[k]:g} Hz does not increase (previous {f[k - 1]:g} Hz)")
    H = np.zeros((len(f), 2, 2), complex)
    C = np.full((len(f), 2, 2), np.nan)
    for p, (i, j) in _PAIRS.items():
        if f"{p}_real_m_n" in cols:
            H[:, i, j] = [r[f"{p}_real_m_n"] + 1j * r[f"{p}_imag_m_n"] for r in rows]
        if f"{p}_coherence" in cols:
            C[:, i, j] = [r[f"{p}_coherence"] for r in rows]
    measured = [bool(np.any(H[:, i, :] != 0) or np.any(H[:, :, i] != 0)) for i in range(2)]
    if decay:
        log.warning("%s: measured with an exponential window (decay %g 1/s): its damping ratios are higher than "
                    "the structure's by %g / w_n; spindlesim fitmodes takes it off, a sampled FRF used as it is "
                    "does not", path, decay, decay)
    return ToolPointFrf(f, H, f"csv:{path.name}" + (f" ({direction})" if direction else ""),
                        C if np.isfinite(C).any() else None, tuple(decay if m else 0.0 for m in measured))


def numeric_row(path, lineno: int, fields: list[str], cols: dict[str, int], width: int,
                error: type = FrfFileError) -> dict[str, float]:
    """column -> value of one CSV row: as many fields as the header's ``width``, each column a finite number;
    ``error`` (a :class:`FrfFileError`) names the file and line otherwise."""
    if len(fields) != width:
        raise error(path, lineno, f"{len(fields)} fields, the header has {width}")
    vals = {}
    for name, i in cols.items():
        try:
            v = float(fields[i])
        except ValueError:
            raise error(path, lineno, f"{name}: {fields[i].strip()!r} is not a number") from None
        if not np.isfinite(v):
            raise error(path, lineno, f"{name}: {fields[i].strip()} is not finite")
        vals[name] = v
    return vals


def _decay(path, lineno: int, text: str) -> float:
    try:
        v = float(text)
    except ValueError:
        raise FrfFileError(path, lineno, f"{WINDOW_DECAY_KEY}: {text!r} is not a number") from None
    if not (np.isfinite(v) and v >= 0):
        raise FrfFileError(path, lineno, f"{WINDOW_DECAY_KEY}: {text} must be finite and >= 0 [1/s]")
    return v


def csv_rows(path, comments: list | None = None, error: type = FrfFileError) -> Iterator[tuple[int, list[str]]]:
    """(line number, fields) of every line of a CSV file that is neither blank nor a ``#`` comment; each
    ``# exponential_window_decay_1_s: D`` comment is appended to ``comments`` as (line, "D").  A file that
    cannot be read raises ``error`` (a :class:`FrfFileError`)."""
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8-sig")
    except FileNotFoundError:
        raise error(path, None, "no such file") from None
    except OSError as exc:
        raise error(path, None, f"cannot read: {exc.strerror or exc}") from exc
    except UnicodeDecodeError as exc:
        raise error(path, None, "not a UTF-8 text file") from exc
    for lineno, line in enumerate(text.splitlines(), start=1):
        s = line.strip()
        if not s:
            continue
        if s.startswith("#"):
            m = _DECAY.match(s)
            if m and comments is not None:
                comments.append((lineno, m.group(1)))
            continue
        yield lineno, next(csv.reader([line]))


def write_frf_csv(path, frf: ToolPointFrf, direction: str | None = None) -> None:
    """Write all four terms, or one direct term (``direction``) in the single-direction layout (with the
    coherence and the window decay the FRF carries)."""
    Path(path).write_text(frf_csv_text(frf, direction), encoding="utf-8")


def frf_csv_text(frf: ToolPointFrf, direction: str | None = None, header: tuple[str, ...] = ()) -> str:
    """The text of :func:`write_frf_csv`; ``header``: the comment lines put first (without their ``#``)."""
    import io

    fh = io.StringIO()
    w = csv.writer(fh, lineterminator="\n")
    for line in header or (f"tool-point receptance [m/N]; source: {frf.source or 'unnamed'}",):
        fh.write(f"# {line}\n")
    C = frf.coherence
    if direction is not None:
        i = DIRECTIONS.index(direction)
        if frf.window_decay_1_s[i]:
            fh.write(f"# {WINDOW_DECAY_KEY}: {frf.window_decay_1_s[i]!r}\n")
        coh = C is not None and bool(np.isfinite(C[:, i, i]).all())
        w.writerow(["frequency_hz", "real_m_N", "imag_m_N"] + (["coherence"] if coh else []))
        for k, (f, h) in enumerate(zip(frf.frequency_hz, frf.H[:, i, i])):
            w.writerow([repr(float(f)), repr(float(h.real)), repr(float(h.imag))]
                       + ([repr(float(C[k, i, i]))] if coh else []))
        return fh.getvalue()
    if any(frf.window_decay_1_s):
        if frf.window_decay_1_s[0] != frf.window_decay_1_s[1]:
            raise ValueError("the all-directions layout holds one window decay: write each direction on its own")
        fh.write(f"# {WINDOW_DECAY_KEY}: {frf.window_decay_1_s[0]!r}\n")
    with_coh = [p for p, (i, j) in _PAIRS.items() if C is not None and np.isfinite(C[:, i, j]).all()]
    w.writerow(["frequency_hz"] + [f"{p}_{c}_m_N" for p in _PAIRS for c in ("real", "imag")]
               + [f"{p}_coherence" for p in with_coh])
    for k, (f, H) in enumerate(zip(frf.frequency_hz, frf.H)):
        row = [repr(float(f))]
        for i, j in _PAIRS.values():
            row += [repr(float(H[i, j].real)), repr(float(H[i, j].imag))]
        row += [repr(float(C[k][_PAIRS[p]])) for p in with_coh]
        w.writerow(row)
    return fh.getvalue()


def uff_dataset_lines(path: Path) -> list[int]:
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


def uff58_sets(path, error: type = FrfFileError) -> Iterator[tuple[int, int | None, dict]]:
    """(index, first line or None, the dataset read by pyuff) of every dataset 58 of a universal file; a file or
    dataset that cannot be read raises ``error`` (a :class:`FrfFileError`) naming the file and line."""
    import pyuff

    path = Path(path)
    if not path.is_file():
        raise error(path, None, "no such file")
    starts = uff_dataset_lines(path)
    try:
        uff = pyuff.UFF(str(path))
        types = list(uff.get_set_types())
    except Exception as exc:  # pyuff raises bare Exception
        raise error(path, None, f"not a readable universal file: {exc}") from exc
    if len(starts) != len(types):
        starts = []  # binary blocks: no reliable line numbers
    for n, t in enumerate(types):
        line = starts[n] if n < len(starts) else None
        if int(t) != 58:
            continue
        try:
            d = uff.read_sets(n)
        except Exception as exc:
            raise error(path, line, f"dataset {n + 1} (58): {exc}") from exc
        yield n, line, d


def read_frf_uff(path) -> ToolPointFrf:
    """Read the X/Y FRFs of a universal file (dataset 58/58b) with pyuff."""
    path = Path(path)
    terms: dict[tuple[int, int], tuple[np.ndarray, np.ndarray]] = {}
    for n, line, d in uff58_sets(path):
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
        return ToolPointFrf(frf.frequency_hz, H, f"{frf.source} ({direction})", frf.coherence, frf.window_decay_1_s)
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
    C = np.full((len(fq), 2, 2), np.nan)
    decay = [0.0, 0.0]
    for f in frfs:
        same = len(f.frequency_hz) == len(fq) and np.allclose(f.frequency_hz, fq, rtol=1e-9)
        if not same:
            log.info("interpolating %s onto the frequencies of %s", f.source, base.source)
        g = f if same else f.interpolated(fq)
        H += g.H
        if g.coherence is not None:  # each term's coherence from the file that measured it
            C = np.where(np.isfinite(g.coherence), g.coherence, C)
        decay = [max(a, b) for a, b in zip(decay, f.window_decay_1_s)]
    return ToolPointFrf(fq, H, " + ".join(f.source for f in frfs), C if np.isfinite(C).any() else None,
                        tuple(decay))
