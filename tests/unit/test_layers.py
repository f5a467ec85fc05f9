"""The package layers import one way (issue "One spindle model", item: layers that flow one way).

Data flows deck -> model -> fe -> bearings -> analysis -> output (files, plots) -> runs -> sweep ->
commands -> CLI.  As imports that is the ranking below: a package may import only packages of a lower
rank, so no cycle can form and the physics (fe, bearings, analysis) never depends on how a deck is
written or on files and plots.
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
    "measured": 2.5,  # measured data: modal identification (sdypy-EMA), FRFs from impacts (pyFRF); reads chatter's files
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
    package_parts = _package_parts(path, module)
    return [(node.lineno, n) for node in _import_nodes(path) for n in _targets(node, package_parts)
            if n.split(".")[0] == "spindlesim"]


def _package_parts(path: Path, module: str | None) -> list[str]:
    """The dotted parts of the package ``path`` is in (``module``: its dotted name, by default from its place)."""
    if module is None:
        module = ".".join(path.relative_to(ROOT.parent).with_suffix("").parts)
    return module.split(".")[:-1]  # a package's __init__ is "<package>.__init__"


def _import_nodes(path: Path) -> list[ast.Import | ast.ImportFrom]:
    return [n for n in ast.walk(ast.parse(path.read_text(encoding="utf-8"))) if isinstance(n, (ast.Import, ast.ImportFrom))]


def _targets(node: ast.Import | ast.ImportFrom, package_parts: list[str]) -> list[str]:
    """The modules an import statement imports, relative ones resolved against ``package_parts``."""
    if isinstance(node, ast.Import):
        return [a.name for a in node.names]
    if not node.level:
        return [node.module] if node.module else []
    base = package_parts[:len(package_parts) - (node.level - 1)]
    return [".".join(base + [node.module])] if node.module else [_member(base, a.name) for a in node.names]


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


#: what a run may take from output/hdf5.py: the provenance record it is given; the layout of its files (datasets,
#: units, dimensions, attributes) is a writer's of output/ (output/*_writer.py, output/rotor_writers.py)
RUN_MAY_IMPORT_FROM_HDF5 = {"RunInfo"}


def _writes_hdf5(path: Path, module: str | None = None) -> list[str]:
    """The lines of ``path`` that import h5py, or from spindlesim/output/hdf5.py more than the provenance record."""
    bad = []
    parts = _package_parts(path, module)
    for node in _import_nodes(path):
        names = {a.name for a in node.names}
        for target in _targets(node, parts):
            if target.split(".")[0] == "h5py":
                bad.append(f"{path.name}:{node.lineno}: imports {target}")
            elif target == "spindlesim.output.hdf5" and (isinstance(node, ast.Import) or names - RUN_MAY_IMPORT_FROM_HDF5):
                bad.append(f"{path.name}:{node.lineno}: writes HDF5 with {', '.join(sorted(names))}")
            elif target == "spindlesim.output" and "hdf5" in names:  # from ..output import hdf5
                bad.append(f"{path.name}:{node.lineno}: writes HDF5 with hdf5")
    return bad


def test_no_run_or_command_writes_hdf5_itself():
    """runs/ computes and hands its results to the writers of output/ (and commands/ calls the runs): no run or
    command imports h5py or lays out a file."""
    bad = [b for layer in ("runs", "commands") for path in sorted((ROOT / layer).rglob("*.py")) for b in _writes_hdf5(path)]
    assert not bad, "HDF5 written outside the writers of output/:\n" + "\n".join(bad)


def test_the_hdf5_check_sees_a_run_writing_a_file(tmp_path):
    planted = tmp_path / "planted.py"
    planted.write_text("import h5py\nfrom ..output.hdf5 import RunInfo\nfrom ..output.hdf5 import Data, write_h5\n"
                       "from ..output import hdf5\nfrom ..output.contact_writer import write_contact\n"
                       "import spindlesim.output.hdf5\n")
    assert _writes_hdf5(planted, "spindlesim.runs.planted") == [
        "planted.py:1: imports h5py", "planted.py:3: writes HDF5 with Data, write_h5",
        "planted.py:4: writes HDF5 with hdf5", "planted.py:6: writes HDF5 with spindlesim.output.hdf5"]


def test_runs_only_write_and_draw():
    """Issue 34: a run calls the analysis's public function, then writes and draws; the computing lives in the
    analysis (each run function fits on a screen: 50 lines)."""
    import ast

    long = []
    for path in sorted((ROOT / "runs").glob("*.py")):
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.FunctionDef) and node.end_lineno - node.lineno + 1 > 50:
                long.append(f"{path.name}:{node.name} ({node.end_lineno - node.lineno + 1} lines)")
    assert not long, long
