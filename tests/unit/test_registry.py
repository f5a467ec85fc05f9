"""One registry of analyses and commands (issue 24, item 4): spindlesim/registry.py is the single source of
every table the layers use, so adding an analysis touches one entry (and the code it names)."""

import ast
import importlib
import re
from pathlib import Path

import pytest

import spindlesim
from spindlesim import registry
from spindlesim.cli import COMMANDS
from spindlesim.deck.loader import ANALYSES, SUPPORTED_ANALYSES
from spindlesim.decks import DEFAULT_DECKS
from spindlesim.output.summary import SUMMARIES, summary_of
from spindlesim.runs import DEFAULT_RUN, RUNS
from spindlesim.sweep.summary import DERIVED_UNITS, KEY_SCALARS, OVERLAYS

ROOT = Path(spindlesim.__file__).parent
NAMES = [n for a in registry.ANALYSIS_REGISTRY for n in (a.name, *a.aliases)]
COMMAND_NAMES = [a.name for a in registry.ANALYSIS_REGISTRY if a.help] + [c.name for c in registry.TOOL_COMMANDS]


def test_every_name_is_registered_once():
    assert len(NAMES) == len(set(NAMES)), NAMES
    assert len(COMMAND_NAMES) == len(set(COMMAND_NAMES)), COMMAND_NAMES


def test_the_derived_tables_agree_with_the_registry():
    assert list(ANALYSES) == NAMES and list(RUNS) == NAMES
    assert set(SUPPORTED_ANALYSES) == {a.name for a in registry.ANALYSIS_REGISTRY if a.supported}
    assert list(COMMANDS) == COMMAND_NAMES
    assert set(DEFAULT_DECKS) == set(COMMANDS) - {"decks", "schema"} - set(registry.file_commands())
    assert [n for names, _ in DEFAULT_RUN for n in names] == [a.name for a in registry.ANALYSIS_REGISTRY if a.needs]
    assert set(SUMMARIES) == ({a.name for a in registry.ANALYSIS_REGISTRY if a.summary}
                              | {c.file or c.name for c in registry.TOOL_COMMANDS if c.summary})
    assert set(OVERLAYS) <= set(NAMES)
    for a in registry.ANALYSIS_REGISTRY:  # an analysis's key results and derived scalars are of its own file
        for key in (*a.key_scalars, *(k for k, _ in a.derived_units)):
            assert re.split(r"[/@]", key)[0] == a.name, (a.name, key)
    assert len(KEY_SCALARS) == len(set(KEY_SCALARS))
    assert len(DERIVED_UNITS) == sum(len(a.derived_units) for a in registry.ANALYSIS_REGISTRY)


def test_every_entry_names_code_that_exists():
    for name, (module, function) in RUNS.items():
        assert callable(getattr(importlib.import_module(f"spindlesim.runs.{module}"), function)), name
    for stem in SUMMARIES:
        assert callable(summary_of(stem)), stem
    for name in COMMANDS:
        assert importlib.import_module(f"spindlesim.commands.{name}").command.name == name
    # and no command module the registry does not list
    defined = {p.stem for p in (ROOT / "commands").glob("*.py") if "\ncommand = " in p.read_text()
               or re.search(r"^def command\(", p.read_text(), re.M)}
    assert defined == set(COMMANDS)


def _literal_tables(tree: ast.AST):
    """(line, names) of each literal tuple, list, set or dict (keys) holding three or more analysis names
    as plain strings, whose other members are plain data too (strings, numbers, names of functions, tuples
    of them), not the code of a rule."""
    names = set(NAMES)

    def constant(node) -> bool:
        return isinstance(node, (ast.Constant, ast.Name)) or (isinstance(node, (ast.Tuple, ast.List))
                                                              and all(constant(e) for e in node.elts))

    for node in ast.walk(tree):
        if isinstance(node, (ast.Tuple, ast.List, ast.Set)):
            members, data = node.elts, node.elts
        elif isinstance(node, ast.Dict):
            members, data = [k for k in node.keys if k is not None], node.keys + node.values
        else:
            continue
        found = [m.value for m in members if isinstance(m, ast.Constant) and m.value in names]
        if len(found) >= 3 and all(d is not None and constant(d) for d in data):
            yield node.lineno, found


#: the deck's own table of top-level sections (a section's model), some named as the analysis that reads them:
#: the second (and last) table an analysis with a section of its own is added to
SECTION_TABLE = ("deck/document.py", "SECTIONS: ")


def test_no_table_of_analyses_outside_the_registry():
    bad = []
    for path in sorted(ROOT.rglob("*.py")):
        if path == ROOT / "registry.py":
            continue
        text = path.read_text(encoding="utf-8")
        for line, found in _literal_tables(ast.parse(text)):
            rel = path.relative_to(ROOT).as_posix()
            if (rel, text.splitlines()[line - 1][:len(SECTION_TABLE[1])]) == SECTION_TABLE:
                continue
            bad.append(f"{rel}:{line}: {', '.join(found)}")
    assert not bad, "tables of analyses outside spindlesim/registry.py:\n" + "\n".join(bad)


@pytest.mark.parametrize("text", [
    'RUNS = {"static": ("rotor", "run_static"), "modal": ("rotor", "run_modal"), "frf": ("rotor", "run_frf")}',
    'ANALYSES = ("static", "modal", "campbell", "frf")',
    'Name = Literal["static", "modal", "campbell"]',
    'SUMMARIES = {"static": _static, "modal": _modal, "frf": _frf}',
])
def test_the_check_sees_a_planted_table(text):
    assert list(_literal_tables(ast.parse(text)))


def test_the_registry_imports_nothing_of_spindlesim():
    tree = ast.parse((ROOT / "registry.py").read_text(encoding="utf-8"))
    imported = [n for node in ast.walk(tree) if isinstance(node, (ast.Import, ast.ImportFrom))
                for n in ([node.module or ""] if isinstance(node, ast.ImportFrom) else [a.name for a in node.names])]
    assert set(imported) <= {"__future__", "dataclasses"}, imported


def test_what_runs_by_default_is_stated_and_ruled_together():
    """An analysis that `spindlesim run` runs by default says what it needs (help) and on which sections (rule)."""
    from spindlesim.deck.document import deck_model

    sections = set(deck_model().model_fields) | {"rotor", "fluid_film"}
    for a in registry.ANALYSIS_REGISTRY:
        assert bool(a.needs) == bool(a.runs_on), a.name
        assert {s for alt in a.runs_on for s in alt} <= sections, a.name


def test_the_spindles_thermal_model_is_an_analysis_of_its_own():
    """spindle_thermal has its own run, summary and key results, and writes the thermal command's file (issue 34,
    item 3); the summary of thermal.h5 is the one of the analysis that ran (issue 34, item 1: of its result)."""
    from spindlesim.registry import file_writers

    a = registry.analysis("spindle_thermal")
    assert a.run == "spindle_thermal:run" and a.stem == "thermal" and a.key_scalars and a.runs_on
    assert registry.analysis("thermal").run == "fluidfilm:run_thermal"
    assert ("spindle_thermal", "operating") not in registry.analysis("thermal").runs_on
    assert file_writers()["thermal"] == ("spindle_thermal", "thermal") and file_writers()["chatter"] == ("chatter",)
    assert summary_of("spindle_thermal") is not summary_of("thermal")
    assert not (ROOT / "runs" / "thermal.py").exists()  # no run that picks between the two
