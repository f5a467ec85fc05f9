"""Issue 34, item 1: the terminal summaries, the report's sections and its verdicts are built from the results the
analyses return, not read back from the files.  Each command below runs with every HDF5 read refused (h5py.File in
mode "r" raises): it must still print its summary, and ``run`` its report with the verdicts.  (That each summary
prints what it printed when it read the file: tests/unit/test_rotor_summary.py,
tests/unit/test_summaries_of_bearing_results.py and scripts/snapshot_outputs.py before and after.)"""

from __future__ import annotations

import ast
from pathlib import Path

import h5py
import pytest
from click.testing import CliRunner

from spindlesim.cli import main
from spindlesim.registry import ANALYSIS_REGISTRY

ROOT = Path(__file__).parents[2]
DECKS = ROOT / "decks"
PACKAGE = ROOT / "spindlesim"

CASES = [
    ("static", "milling_spindle.yaml"), ("modal", "seed001_dtrb_rotor.yaml"), ("frf", "milling_spindle.yaml"),
    ("campbell", "seed003_spindle_linear.yaml", "--speeds", "1000:12000:4"),
    ("unbalance", "seed003_spindle_linear.yaml"), ("thermal", "seed003_three_lobe.yaml"),
    ("bearing", "ball_single_row.yaml"), ("contact", "contact_roller.yaml"),
    ("transient", "seed000_roller_bearing.yaml", "--duration", "0.02"), ("tools", "tool_library.yaml", "--no-lobes"),
    ("chatter", "small chatter"),
]


def _deck(name: str, tmp_path: Path) -> Path:
    """An example deck; "small chatter": the milling deck on 12 speeds without its thermal section."""
    if name != "small chatter":
        return DECKS / name
    text = (DECKS / "milling_spindle.yaml").read_text().replace(
        "speeds_rpm: {start: 6000, stop: 24000, count: 200}", "speeds_rpm: {start: 8000, stop: 20000, count: 12}")
    p = tmp_path / "chatter.yaml"
    p.write_text(text[:text.index("\nspindle_thermal:")] + "\n")
    return p


def _refuse_reading(monkeypatch) -> None:
    real = h5py.File

    def file(name, mode="r", *args, **kwargs):
        if mode == "r":
            raise OSError(f"test: reading {name} back is not allowed")
        return real(name, mode, *args, **kwargs)

    monkeypatch.setattr(h5py, "File", file)


def _summary(output: str) -> list[str]:
    """The printed summary: the lines after the paths."""
    lines = output.splitlines()
    first = next((k for k, ln in enumerate(lines) if ln.endswith(".h5:")), len(lines))
    return lines[first:]


@pytest.mark.parametrize("case", CASES, ids=lambda c: " ".join(c[:2]))
def test_the_summary_is_the_results_not_the_files(case, tmp_path, monkeypatch):
    cmd, deck, *opts = case
    argv = [cmd, str(_deck(deck, tmp_path)), *opts]
    _refuse_reading(monkeypatch)
    refused = CliRunner().invoke(main, [*argv, "-o", str(tmp_path / "b")])
    assert refused.exit_code == 0, refused.output
    summary = _summary(refused.output)
    assert len(summary) >= 2 and summary[0] == f"{cmd}.h5:", refused.output
    assert (tmp_path / "b" / f"{cmd}.h5").is_file()


def test_runs_report_and_verdicts_come_from_the_results(tmp_path, monkeypatch):
    """``run`` on the milling spindle with reading refused: the report has every analysis's key results and the
    verdicts (API 684 margins, the thermal speed limit, the stable depth)."""
    _refuse_reading(monkeypatch)
    text = (DECKS / "milling_spindle.yaml").read_text()
    deck = tmp_path / "m.yaml"
    text = text.replace("  warm_up: {steps:", "  # warm_up: {steps:")  # the equilibria only
    deck.write_text(text.replace("title:", "analyses: [spindle_thermal, static, campbell]\ntitle:", 1))
    res = CliRunner().invoke(main, ["run", str(deck), "-o", str(tmp_path / "o"), "-q"])
    assert res.exit_code == 0, res.output
    page = (tmp_path / "o" / "report.html").read_text()
    assert 'id="verdicts"' in page and "Thermal speed limit" in page and "API 684 separation margins" in page
    assert page.count("summary unavailable") == 0 and page.count("no summary for this file") == 0
    assert "static stiffness at node" in page and "thermal equilibrium at" in page and "critical" in page


def _imports_h5py(path: Path) -> bool:
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import) and any(a.name == "h5py" for a in node.names):
            return True
        if isinstance(node, ast.ImportFrom) and node.module == "h5py":
            return True
    return False


def test_no_analysis_summary_module_reads_hdf5():
    """The modules holding the analyses' summaries (the registry's ``summary``) and the verdicts import no h5py."""
    modules = {a.summary.split(":")[0] for a in ANALYSIS_REGISTRY if a.summary} - {"summary"}
    bad = [m for m in sorted(modules) if _imports_h5py(PACKAGE / "output" / f"{m}.py")]
    assert not bad, bad
    assert not _imports_h5py(PACKAGE / "analysis" / "verdicts.py")
