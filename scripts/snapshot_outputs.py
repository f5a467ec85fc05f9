"""A snapshot of what the commands print and write, to compare a refactoring against: every command on every
example deck (cut down where a command takes an option for it), each HDF5 dataset's values (floats to 10
significant digits) and attributes, and the printed summary.  Not a test: run it before and after a change and
compare the two JSON files (python scripts/snapshot_outputs.py OUT.json; then diff or --compare A B)."""

from __future__ import annotations

import json
import os
import sys
import tempfile
from pathlib import Path

import h5py
import numpy as np
from click.testing import CliRunner

ROOT = Path(__file__).parents[1]
RUNS = [
    ("static", "milling_spindle.yaml"), ("modal", "milling_spindle.yaml"), ("frf", "milling_spindle.yaml"),
    ("campbell", "milling_spindle.yaml", "--speeds", "0:24000:13"), ("unbalance", "milling_spindle.yaml"),
    ("thermal", "milling_spindle.yaml"), ("static", "seed001_dtrb_rotor.yaml"), ("modal", "seed001_dtrb_rotor.yaml"),
    ("campbell", "seed003_three_lobe.yaml", "--speeds", "1000:12000:6"), ("thermal", "seed003_three_lobe.yaml"),
    ("coefficients", "seed003_three_lobe.yaml"), ("modal", "lathe_headstock.yaml"), ("thermal", "lathe_headstock.yaml"),
    ("bearing", "ball_single_row.yaml"), ("dtrb", "dtrb_wheel_hub.yaml"), ("contact", "contact_roller.yaml"),
    ("transient", "seed000_roller_bearing.yaml", "--duration", "0.05"), ("tools", "tool_library.yaml", "--no-lobes"),
    ("chatter", "seed003_spindle_linear.yaml"), ("chatter", "milling_spindle.yaml"), ("chatter", "seed003_three_lobe.yaml"),
    ("chatter", "tool_library.yaml"),
    ("run", "milling_spindle.yaml"), ("run", "seed003_three_lobe.yaml"),
]


def _report_text(path: Path) -> str:
    """report.html without its times and folder names: the verdicts and each analysis's summary lines."""
    import re

    if not path.is_file():
        return ""
    text = path.read_text()
    text = re.sub(r"data:image/png;base64,[A-Za-z0-9+/=]+", "PNG", text)
    text = re.sub(r"\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d[^<\"]*", "TIME", text)
    text = re.sub(r"/tmp/[A-Za-z0-9_./-]+", "TMP", text)
    return text


def _value(v):
    a = np.asarray(v)
    if a.dtype.kind in "fc":
        a = a.astype(complex) if a.dtype.kind == "c" else a.astype(float)
        flat = np.ravel(a)
        if a.dtype.kind == "c":
            return [[float(f"{z.real:.10g}"), float(f"{z.imag:.10g}")] for z in flat[:2000]]
        return [None if not np.isfinite(x) else float(f"{x:.10g}") for x in flat[:2000]]
    if a.dtype.kind in "iub":
        return np.ravel(a)[:2000].tolist()
    return [x.decode() if isinstance(x, bytes) else str(x) for x in np.ravel(a)[:2000]]


def snapshot() -> dict:
    from spindlesim.cli import main

    out: dict = {}
    only = set(os.environ.get("SNAPSHOT_ONLY", "").split(",")) - {""}  # e.g. SNAPSHOT_ONLY=chatter,run
    for run in RUNS:
        if only and run[0] not in only:
            continue
        cmd, deck, *opts = run
        key = " ".join(run)
        with tempfile.TemporaryDirectory() as tmp:
            res = CliRunner().invoke(main, [cmd, str(ROOT / "decks" / deck), "-o", tmp, *opts])
            files = {}
            for p in sorted(Path(tmp).glob("*.h5")):
                d: dict = {}
                with h5py.File(p) as f:
                    def visit(name, obj):
                        if isinstance(obj, h5py.Dataset):
                            d[name] = _value(obj[()])
                        for k, v in obj.attrs.items():
                            if k not in ("created_utc", "command_line", "deck_source", "deck_text", "wall_time_s") and \
                                    not k.endswith("_version") and k != "platform":
                                d[f"{name}@{k}"] = _value(v)
                    f.visititems(visit)
                files[p.name] = d
            text = "\n".join(ln for ln in res.output.splitlines() if not ln.startswith(("/", tmp)))
            report = _report_text(Path(tmp) / "report.html")
        with tempfile.TemporaryDirectory() as tmp:
            res = CliRunner().invoke(main, [cmd, str(ROOT / "decks" / deck), "-o", tmp, "--json", *opts])
            try:
                data = json.loads(res.output.splitlines()[-1])
                data.pop("paths", None)
            except (ValueError, IndexError):
                data = res.output
            here = str(ROOT)  # the checkout's folder (a worktree's or another clone's): not a difference
            out[key] = {"exit": res.exit_code, "summary": text.replace(here, "ROOT"), "files": files,
                        "report": report.replace(here, "ROOT"),
                        "json": json.dumps(data, sort_keys=True, default=str).replace(here, "ROOT")}
        print(f"{key}: exit {res.exit_code}", file=sys.stderr)
    return out


def compare(a: dict, b: dict) -> list[str]:
    diffs = []
    for key in sorted(set(a) | set(b)):
        if key not in a or key not in b:
            diffs.append(f"{key}: only in {'second' if key not in a else 'first'}")
            continue
        x, y = a[key], b[key]
        if x["exit"] != y["exit"]:
            diffs.append(f"{key}: exit {x['exit']} -> {y['exit']}")
        for part in ("summary", "report", "json"):
            if x.get(part) != y.get(part):
                diffs.append(f"{key}: {part} differs")
        for fname in sorted(set(x["files"]) | set(y["files"])):
            fx, fy = x["files"].get(fname, {}), y["files"].get(fname, {})
            for ds in sorted(set(fx) | set(fy)):
                if fx.get(ds) != fy.get(ds):
                    diffs.append(f"{key}: {fname}:{ds} differs{_by_how_much(fx.get(ds), fy.get(ds))}")
    return diffs


def _by_how_much(x, y) -> str:
    """For two numeric values of a dataset: the largest difference relative to the largest magnitude."""
    try:
        a = np.asarray(x.get("value") if isinstance(x, dict) else x, dtype=float)
        b = np.asarray(y.get("value") if isinstance(y, dict) else y, dtype=float)
    except (TypeError, ValueError, AttributeError):
        return ""
    if a.shape != b.shape or not a.size:
        return f" (shape {a.shape} -> {b.shape})"
    scale = max(float(np.nanmax(np.abs(a))), 1e-300)
    return f" (max {float(np.nanmax(np.abs(a - b))) / scale:.1e} of its largest value)"


if __name__ == "__main__":
    if sys.argv[1] == "--compare":
        a, b = (json.loads(Path(p).read_text()) for p in sys.argv[2:4])
        d = compare(a, b)
        print("\n".join(d) if d else "identical")
        sys.exit(1 if d else 0)
    Path(sys.argv[1]).write_text(json.dumps(snapshot()))
