"""The rotor analyses' terminal summaries read their results, not their files (issue 34, item 1): static, modal,
campbell, frf and unbalance are summarised from the frozen result the run hands back, so a library user gets the
lines and numbers the CLI prints without any file."""

import ast
import inspect
import shutil
from pathlib import Path

import pytest

from spindlesim.output import rotor_summary
from spindlesim.output.summary import summary_of
from tests.rotor_helpers import cli_with_result, printed_summary

DECKS = Path(__file__).parents[2] / "decks"
MILLING = DECKS / "milling_spindle.yaml"


@pytest.mark.parametrize("name,extra", [
    ("static", []), ("modal", ["--modes", "4"]), ("frf", []), ("unbalance", []),
    ("campbell", ["--speeds", "0:24000:5", "--modes", "6"]),
])
def test_summary_of_the_result_is_what_the_cli_prints(tmp_path, monkeypatch, name, extra):
    out = tmp_path / "out"
    printed, written = cli_with_result(monkeypatch, [name, MILLING, "-o", out, *extra])
    shutil.rmtree(out)  # the summary has no file to read
    lines, data = summary_of(name)(written.result)
    assert lines == printed_summary(printed, f"{name}.h5")
    assert lines and data


def test_a_campbell_study_stopped_partway_is_summarised_on_the_speeds_it_solved(tmp_path, monkeypatch):
    """Plain journals on the seed 003 spindle overheat between 19,000 and 20,000 rpm: the run raises IncompleteRun
    with the partial study; the CLI prints its summary after the reason its file notes."""
    text = (DECKS / "seed003_three_lobe.yaml").read_text().replace("type: three_lobe", "type: plain")
    text = "\n".join(ln for ln in text.splitlines() if "preload: 0.5" not in ln and "lobes: {count" not in ln)
    deck = tmp_path / "plain.yaml"
    deck.write_text(text + "\n")
    out = tmp_path / "out"
    printed, written = cli_with_result(monkeypatch, ["campbell", deck, "--speeds", "12000:30000:4", "-o", out],
                                       exit_code=3)
    shutil.rmtree(out)
    study = written.result
    assert list(study.hot.speed_rpm) == [12000.0, 18000.0] and "stopped at 24000 rpm" in study.incomplete_reason
    lines, _ = summary_of("campbell")(study)
    assert lines[0].startswith("2 speeds 12000-18000 rpm")
    assert printed_summary(printed, "campbell.h5") == [f"INCOMPLETE: {study.incomplete_reason}", *lines]


def test_rotor_summaries_import_no_file_reader():
    tree = ast.parse(inspect.getsource(rotor_summary))
    imported = {a.name.split(".")[0] for n in ast.walk(tree) if isinstance(n, (ast.Import, ast.ImportFrom))
                for a in n.names} | {(n.module or "").split(".")[0] for n in ast.walk(tree)
                                     if isinstance(n, ast.ImportFrom)}
    assert "h5py" not in imported
