"""The package layers import one way (issue "One spindle model", item: layers that flow one way).

Data flows deck -> model -> fe -> bearings -> analysis -> runs (files, plots) -> CLI.  As imports that
is the ranking below: a package may import only packages of a lower rank, so no cycle can form and
the physics (fe, bearings, analysis) never depends on how a deck is written or on files and plots.
The test parses every module's imports (no import is executed) and names each offending line.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

import spindlesim

ROOT = Path(spindlesim.__file__).parent

#: rank of each top-level package or module; imports must go to a strictly lower rank
RANK = {
    "_cachedirs": -1,  # the package's first act: writable caches for numba and matplotlib (imports neither)
    "registry": -0.5,  # names and dotted paths of every analysis and command (imports nothing of spindlesim)
    "__init__": 0, "fields": 0, "lazy": 0,
    "contact": 1,
    "thermal": 1.5,  # heat transfer, heat generation, growth: pure physics the bearings and analyses call
    "bearings": 2, "chatter": 2,
    "deck": 3, "model": 3,
    "fe": 4,
    "analysis": 5,
    "output": 6,
    "runs": 7,
    "sweep": 8,
    "commands": 9,
    "cli": 10,
    "__main__": 11,
    "decks": 0,  # data files only
}


def _package(module: str) -> str:
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else "__init__"


def _member(base: list[str], name: str) -> str:
    """``from <base> import name``: the submodule when ``name`` is one, else the package itself."""
    folder = ROOT.parent.joinpath(*base)
    is_module = (folder / f"{name}.py").exists() or (folder / name / "__init__.py").exists()
    return ".".join(base + [name]) if is_module else ".".join(base)


def _imports(path: Path, module: str | None = None) -> list[tuple[int, str]]:
    """(line, imported spindlesim module) of every import in ``path``; ``module``: its dotted name (by
    default from its place under the package)."""
    if module is None:
        module = ".".join(path.relative_to(ROOT.parent).with_suffix("").parts)
    package_parts = module.split(".") if path.name == "__init__.py" else module.split(".")[:-1]
    if path.name == "__init__.py":
        package_parts = package_parts[:-1]
    out = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = package_parts[:len(package_parts) - (node.level - 1)]
                names = [".".join(base + [node.module])] if node.module else [_member(base, a.name) for a in node.names]
            else:
                names = [node.module] if node.module and node.module.split(".")[0] == "spindlesim" else []
        elif isinstance(node, ast.Import):
            names = [a.name for a in node.names if a.name.split(".")[0] == "spindlesim"]
        else:
            continue
        out += [(node.lineno, n) for n in names]
    return out


def _modules():
    for path in sorted(ROOT.rglob("*.py")):
        rel = path.relative_to(ROOT)
        own = rel.parts[0] if len(rel.parts) > 1 else rel.stem
        yield path, own


def test_every_package_has_a_rank():
    owners = {own for _, own in _modules()}
    assert owners <= set(RANK), f"packages without a layer: {sorted(owners - set(RANK))}"


def _against_layers(path: Path, own: str, module: str | None = None) -> list[str]:
    bad = []
    for line, target in _imports(path, module):
        dest = _package(target)
        if dest == own:
            continue
        if dest not in RANK or RANK[dest] >= RANK[own]:
            bad.append(f"{path.name}:{line}: {own} imports {target}")
    return bad


def test_imports_go_down_the_layers():
    bad = [b for path, own in _modules() for b in _against_layers(path, own)]
    assert not bad, "imports against the layers:\n" + "\n".join(bad)


def test_the_check_sees_a_planted_violation(tmp_path):
    """A module of the bearing families that imports an analysis (relatively and absolutely) and one of
    the analyses that imports the runs: the check names every line (so the test above can fail)."""
    planted = tmp_path / "probe.py"
    planted.write_text("from ...analysis import points\nimport spindlesim.runs.rotor\nfrom ...fields import Load5\n")
    bad = _against_layers(planted, "bearings", "spindlesim.bearings.ball.probe")
    assert bad == ["probe.py:1: bearings imports spindlesim.analysis",
                   "probe.py:2: bearings imports spindlesim.runs.rotor"]
    upward = tmp_path / "upward.py"
    upward.write_text("from ..runs import common\nfrom .points import OperatingPoints\n")
    assert _against_layers(upward, "analysis", "spindlesim.analysis.upward") == [
        "upward.py:1: analysis imports spindlesim.runs"]


#: what the analyses must not do: ask a bearing what it is (the contract is all they may use)
PROBES = re.compile(r"hasattr\(\s*b\w*\s*,|getattr\(\s*b\w*\s*,\s*\"(?!name)|\.type\s+(==|in)\s|isinstance\(\s*b\w*\s*,")


#: the layers above the bearings and the deck: they use the bearing contract and ask the deck layer
#: (deck/describe.py) which entries are of which type
ABOVE = ("analysis", "fe", "runs", "output", "sweep", "commands")


def _probes(paths) -> list[str]:
    bad = []
    for path in paths:
        for i, text in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            if PROBES.search(text) and "noqa: contract" not in text:
                bad.append(f"{path.name}:{i}: {text.strip()}")
    return bad


def test_no_layer_above_the_bearings_asks_a_bearing_what_it_is():
    bad = _probes(p for layer in ABOVE for p in sorted((ROOT / layer).rglob("*.py")))
    assert not bad, "type or attribute probes above the bearings:\n" + "\n".join(bad)


def test_the_probe_check_sees_a_planted_probe(tmp_path):
    planted = tmp_path / "planted.py"
    planted.write_text("ok = 1\nfluid = [b for b in deck.bearings if b.type == 'plain']\n"
                       "has_oil = hasattr(bearing, 'oil')\n")
    assert _probes([planted]) == ["planted.py:2: fluid = [b for b in deck.bearings if b.type == 'plain']",
                                  "planted.py:3: has_oil = hasattr(bearing, 'oil')"]
