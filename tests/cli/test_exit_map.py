"""One map from how a command ended to its exit code (issue 24, item 4): spindlesim/commands/exits.py."""

import ast
from pathlib import Path

import pytest

import spindlesim
from spindlesim.analysis.operating import BearingSolveError, SingularRotorError
from spindlesim.bearings.base import SpeedRequiredError
from spindlesim.commands.exits import exit_code_of, outcome_code
from spindlesim.deck import DeckError
from spindlesim.runs.status import IncompleteRun

ROOT = Path(spindlesim.__file__).parent


def _wrapped(inner: BaseException) -> BaseException:
    try:
        try:
            raise inner
        except BaseException as exc:
            raise BearingSolveError("the front bearing failed at 1000 rpm") from exc
    except BearingSolveError as outer:
        return outer


@pytest.mark.parametrize("exc,code", [
    (KeyboardInterrupt(), 130),
    (IncompleteRun("stopped by the user", interrupted=True), 130),
    (IncompleteRun("the integration stopped at 0.1 s"), 3),
    (DeckError([]), 2),
    (SingularRotorError("not held axially"), 2),
    (SpeedRequiredError("a fluid film at rest"), 2),
    (_wrapped(SpeedRequiredError("a fluid film at rest")), 2),  # the input error met by the solver
    (_wrapped(ValueError("no convergence")), 1),
    (ValueError("no convergence"), 1),
    (ArithmeticError("overflow"), 1),
    (OSError(28, "No space left on device"), 1),
], ids=lambda v: type(v).__name__ if isinstance(v, BaseException) else str(v))
def test_exit_code_of_each_ending(exc, code):
    assert exit_code_of(exc) == code


@pytest.mark.parametrize("kw,code", [
    ({}, 0), ({"incomplete": True}, 3), ({"failed": True}, 1), ({"failed": True, "incomplete": True}, 1),
    ({"interrupted": True, "failed": True, "incomplete": True}, 130),
])
def test_outcome_of_several_runs(kw, code):
    assert outcome_code(**kw) == code


def _exit_calls(tree: ast.AST):
    for node in ast.walk(tree):
        if isinstance(node, ast.Call):
            f = node.func
            name = f.attr if isinstance(f, ast.Attribute) else getattr(f, "id", "")
            if name in ("exit", "SystemExit", "Exit") and node.args:
                yield node


def test_no_module_but_the_map_decides_an_exit_code():
    """No number given to sys.exit / SystemExit and no EXIT_* constant anywhere but commands/exits.py."""
    bad = []
    for path in sorted(ROOT.rglob("*.py")):
        if path.relative_to(ROOT).as_posix() == "commands/exits.py":
            continue
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for call in _exit_calls(tree):
            if isinstance(call.args[0], ast.Constant) and isinstance(call.args[0].value, int):
                bad.append(f"{path.relative_to(ROOT)}:{call.lineno}: exit code {call.args[0].value}")
        for node in ast.walk(tree):
            if isinstance(node, ast.Assign):
                for t in node.targets:
                    if isinstance(t, ast.Name) and t.id.startswith("EXIT_"):
                        bad.append(f"{path.relative_to(ROOT)}:{node.lineno}: {t.id} defined")
    assert not bad, "exit codes decided outside spindlesim/commands/exits.py:\n" + "\n".join(bad)


def test_the_check_sees_a_planted_exit_code(tmp_path):
    planted = ast.parse("import sys\ndef f():\n    sys.exit(2)\n")
    assert [c.lineno for c in _exit_calls(planted)] == [3]
