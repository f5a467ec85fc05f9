"""One tool-point protocol (issue 34, item 3): which kind of tool source a caller handed over is asked in one
module only, spindlesim/chatter/tool.py (the protocol and the tool series); everywhere else a tool point is used
through the protocol (receptance, frf, state_space) and a series through its speeds and tools.

The test parses every module (no import is executed) and names each line that asks: ``isinstance`` against a
tool-point class or the series, ``isinstance`` of a tool-like name against a list, tuple or sequence,
``callable`` or ``hasattr`` of a tool-like name."""

from __future__ import annotations

import ast
import re
from pathlib import Path

import spindlesim

ROOT = Path(spindlesim.__file__).parent
PROTOCOL = ROOT / "chatter" / "tool.py"
CLASSES = {"ToolPointModel", "ToolPointFrf", "ToolSeries", "ToolPoint", "ToolPointSeries", "SdModel"}
SEQUENCES = {"list", "tuple", "Sequence"}
#: names of a tool source
TOOLISH = re.compile(r"tool|src|model", re.I)


def _names(node: ast.AST) -> set[str]:
    return {n.id for n in ast.walk(node) if isinstance(n, ast.Name)} | \
        {n.attr for n in ast.walk(node) if isinstance(n, ast.Attribute)}


def _asks(path: Path) -> list[str]:
    bad = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if not (isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.args):
            continue
        what = ast.unparse(node.args[0])
        fn = node.func.id
        if fn == "isinstance" and len(node.args) == 2:
            kinds = _names(node.args[1])
            if kinds & CLASSES or (kinds & SEQUENCES and TOOLISH.search(what)):
                bad.append(f"{path.name}:{node.lineno}: {ast.unparse(node)}")
        elif fn in ("callable", "hasattr") and TOOLISH.search(what):
            bad.append(f"{path.name}:{node.lineno}: {ast.unparse(node)}")
    return bad


def test_only_the_protocol_module_asks_what_a_tool_source_is():
    bad = [b for p in sorted(ROOT.rglob("*.py")) if p != PROTOCOL for b in _asks(p)]
    assert not bad, "tool-source type checks outside spindlesim/chatter/tool.py:\n" + "\n".join(bad)


def test_the_protocol_module_is_where_the_forms_are_told_apart():
    assert _asks(PROTOCOL), "tool_series no longer tells the forms apart: the check above would see nothing"


def test_the_check_sees_planted_type_checks(tmp_path):
    """Yesterday's checks, planted: each one is named, a deck's isinstance is not."""
    planted = tmp_path / "planted.py"
    planted.write_text(
        "frf = tool.frf() if isinstance(tool, ToolPointModel) else tool\n"
        "shown = deck_tool if deck_tool is not None else (tool[0] if isinstance(tool, list) else tool)\n"
        "if callable(tool):\n    pass\n"
        "per_speed = isinstance(src, (list, tuple))\n"
        "ok = [m for m in models if not isinstance(m, ToolPointFrf)]\n"
        "fine = isinstance(frf, FrfModes) or isinstance(value, dict)\n")
    assert sorted(int(b.split(":")[1]) for b in _asks(planted)) == [1, 2, 3, 5, 6]
