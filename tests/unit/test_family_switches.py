"""Each bearing family answers for itself (issue 34, item 2): no switch on the family outside bearings/.

What a layer needs of a bearing entry -- whether it acts on x and y only, whether it holds the rotor axially,
its plausibility checks, whether and how it enters the spindle's thermal network -- is in the family's row of
``BEARING_TYPES`` (``spindlesim/bearings/types.py``), and the network's questions to a bearing set (its rolling
elements, their mass, its conductances) in the set's contact paths (``thermal.layout.ContactPaths``).  So the
generic thermal network (``thermal/``), the model builders (``model/``), the deck loader and its plausibility
checks never branch on a family: no ``.type ==`` / ``.type in``, no ``getattr(b, "type")``, no ``.element ==``,
no comparison with a family's name, no table keyed by it.  A new family gets its network, its plausibility and
its axial check from its own row, or none, visibly.

The test reads the sources (nothing is imported or executed) and names each offending line.
"""

from __future__ import annotations

import re
from pathlib import Path

import spindlesim
from spindlesim.bearings.types import BEARING_TYPES

ROOT = Path(spindlesim.__file__).parent

#: where a switch on the family must not be: the generic thermal package, the model builders, the deck loader
#: and its plausibility checks
WATCHED = ("thermal", "model", "deck/loader.py", "deck/plausibility.py")

_NAMES = "|".join(sorted(BEARING_TYPES))
#: the forms of a switch on the family: its tag compared or tested, its rolling element compared, a family's
#: name compared or used as a table key, the old table of the thermal sets
SWITCH = re.compile(
    r"\.type\s*(==|!=|\bin\b|\bnot\s+in\b)"
    r"|getattr\(\s*\w+\s*,\s*[\"']type[\"']"
    r"|\.element\s*(==|!=|\bin\b|\bnot\s+in\b)"
    rf"|(==|!=)\s*[\"']({_NAMES}|balls?|rollers?)[\"']"
    rf"|[\"']({_NAMES}|balls?|rollers?)[\"']\s*(==|!=)"
    rf"|\bin\s*[\(\[\{{]\s*[\"']({_NAMES})[\"']"
    rf"|[\{{,]\s*[\"']({_NAMES})[\"']\s*:"
    r"|\b_SETS\b"
)


def _files() -> list[Path]:
    out: list[Path] = []
    for where in WATCHED:
        p = ROOT / where
        out += sorted(p.rglob("*.py")) if p.is_dir() else [p]
    return out


def _switches(paths) -> list[str]:
    bad = []
    for path in paths:
        for i, text in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            code = text.split("#", 1)[0]
            if SWITCH.search(code):
                bad.append(f"{path.name}:{i}: {text.strip()}")
    return bad


def test_the_watched_places_exist():
    assert all((ROOT / w).exists() for w in WATCHED)
    assert len(_files()) > 10


def test_no_family_switch_outside_the_bearings():
    bad = _switches(_files())
    assert not bad, ("switches on the bearing family outside bearings/ (ask the family's row of BEARING_TYPES or the "
                     "set's contact paths):\n" + "\n".join(bad))


def test_the_check_sees_planted_switches(tmp_path):
    """Each form of a switch, planted, is named (so the test above can fail); the lawful forms are not."""
    planted = tmp_path / "planted.py"
    planted.write_text(
        "ok = family(entry).holds_axially(entry)\n"
        "axial = [b for b in d.bearings if b.type == 'ball' or (b.type == \"dtrb\" and b.dofs == 5)]\n"
        "radial = all(b.type in RADIAL_ONLY for b in d.bearings)\n"
        "if getattr(b, \"type\", None) == 'ball':\n"
        "    pass\n"
        "if b.element == \"roller\":\n"
        "    pass\n"
        "sets = tuple(_SETS[e.type](e, z) for e in entries)\n"
        "table = {\"ball\": _bearing_set, \"dtrb\": _dtrb_set}\n"
        "kind = 'balls' if s.element_kind == 'ball' else 'rollers'\n"
        "if kind in ('three_lobe', 'plain'):\n"
        "    pass\n"
        "paths = s.contact_paths.conductances(s, w, qi, qo, 0.0, 0.0, t)  # no switch: b.type == 'ball' in a comment\n")
    assert _switches([planted]) == [
        "planted.py:2: axial = [b for b in d.bearings if b.type == 'ball' or (b.type == \"dtrb\" and b.dofs == 5)]",
        "planted.py:3: radial = all(b.type in RADIAL_ONLY for b in d.bearings)",
        "planted.py:4: if getattr(b, \"type\", None) == 'ball':",
        "planted.py:6: if b.element == \"roller\":",
        "planted.py:8: sets = tuple(_SETS[e.type](e, z) for e in entries)",
        "planted.py:9: table = {\"ball\": _bearing_set, \"dtrb\": _dtrb_set}",
        "planted.py:10: kind = 'balls' if s.element_kind == 'ball' else 'rollers'",
        "planted.py:11: if kind in ('three_lobe', 'plain'):",
    ]


def test_every_family_answers_the_layers_questions():
    """Each row of BEARING_TYPES says what the loader, the plausibility checks and the thermal model ask; a
    family in the thermal network builds its set there."""
    for name, t in BEARING_TYPES.items():
        assert callable(t.holds_axially) and callable(t.plausibility) and callable(t.located_checks), name
        assert isinstance(t.radial_only, bool), name
        assert t.thermal_set is None or callable(t.thermal_set), name
    assert {n for n, t in BEARING_TYPES.items() if t.thermal_set is not None} == {"ball", "dtrb", "roller"}
