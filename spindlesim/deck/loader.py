"""Load a YAML deck: parse with line marks, validate with pydantic, check physics, collect all errors.

Errors (:class:`DeckError`) and plausibility warnings (``LoadedDeck.warnings``) are
:class:`DeckIssue` objects located as ``file:line:col: key.path: message``.  The loader never
prints; the commands print (``commands/common.py``).
"""

from __future__ import annotations

import difflib
import hashlib
import logging
from dataclasses import dataclass, field, replace
from importlib import resources
from pathlib import Path
from typing import Any

from pydantic import BaseModel, ValidationError

from ..bearings.ball import section as ball_section
from ..bearings.types import acts_radially_only, holds_axially, located_checks, network_bearings, network_types
from ..fields import unit_range, unit_text
from ..registry import ANALYSIS_REGISTRY, analysis_names
from .document import bearing_types, deck_model, keys_at
from .errors import DeckError, DeckIssue
from .limits import MAX_ISSUES, MAX_TEXT_CHARS, work_checks
from .plausibility import MIN_DIMENSION_MM, plausibility_warnings
from .yamlmarks import load_with_marks, locate, path_str

log = logging.getLogger(__name__)

#: every analysis a deck may list under ``analyses:`` (spindlesim/registry.py; ``spindlesim.runs.RUNS`` runs them)
ANALYSES = analysis_names()
#: analyses of the rotor on its bearings: without a support the stiffness matrix is singular
SUPPORTED_ANALYSES = tuple(a.name for a in ANALYSIS_REGISTRY if a.supported)
#: the smallest outer diameter and length of a beam element [mm] (1 um: below it the element's matrices lose
#: every digit; a micro tool's flutes are some 10 um)
MIN_ELEMENT_MM = 1e-3
#: columns of a shaft, holder or tool row
ROW_KEYS = ("outer_dia_mm", "inner_dia_mm", "length_mm", "density_kg_m3", "E_GPa", "G_GPa", "poisson",
            "axial_force_N")

#: top-level keys with this prefix are not sections: they hold parts shared with anchors (``<<: *name``)
SHARED_PREFIX = "x-"

Marks = dict[tuple[Any, ...], tuple[int, int]]


@dataclass(frozen=True)
class LoadedDeck:
    """A validated deck with its source text (written into every output file)."""

    deck: BaseModel
    text: str
    source: str  # file path, or "<default:name>"
    #: plausibility warnings (likely unit mistakes); ``--strict`` makes them errors
    warnings: tuple[DeckIssue, ...] = ()
    #: key path -> (line, col) of the deck text, to locate later checks
    marks: Marks = field(default_factory=dict, compare=False, repr=False)

    @property
    def sha256(self) -> str:
        return hashlib.sha256(self.text.encode()).hexdigest()

    @property
    def stem(self) -> str:
        if self.source.startswith("<default:"):
            return "default_" + self.source[len("<default:"):-1]
        return Path(self.source).stem

    def issue(self, path: tuple[Any, ...], message: str) -> DeckIssue:
        """A DeckIssue at the deck line of ``path`` (its deepest written prefix)."""
        line, col = locate(self.marks, path)
        return DeckIssue(self.source, line, col, path_str(path), message)


def _data_path(data: Any, loc: tuple[Any, ...]) -> tuple[Any, ...]:
    """Turn pydantic's error location into a path through the data.

    Union tags (a bearing type name, ``FrequencyRange``, ``list[...]``) that
    pydantic inserts are skipped; a missing or unknown key ends the path.
    """
    path: list[Any] = []
    cur = data
    for item in loc:
        if isinstance(cur, dict) and item in cur:
            path.append(item)
            cur = cur[item]
        elif isinstance(cur, list) and isinstance(item, int) and 0 <= item < len(cur):
            path.append(item)
            cur = cur[item]
        elif isinstance(item, str) and (item in bearing_types() or "[" in item or item[:1].isupper()
                                        or item.startswith(("function-", "constrained-"))):
            continue
        else:
            path.append(item)
            break
    return tuple(path)


def _did_you_mean(word: str, choices: list[str]) -> str:
    close = difflib.get_close_matches(word, choices, n=1, cutoff=0.6)
    if not close:
        lowered = {c.lower(): c for c in choices}
        close = difflib.get_close_matches(word.lower(), list(lowered), n=1, cutoff=0.6)
        close = [lowered[c] for c in close]
    return f"; did you mean '{close[0]}'?" if close else ""


def _unknown_key(data: Any, path: tuple[Any, ...]) -> str:
    keys = keys_at(data, path[:-1])
    key = str(path[-1]) if path else ""
    if not keys:
        return "unknown key"
    hint = _did_you_mean(key, keys)
    if hint:
        return "unknown key" + hint
    shown = ", ".join(keys) if len(keys) <= 16 else ", ".join(keys[:16]) + ", ..."
    return f"unknown key; the keys here are {shown}"


def _message(err: dict[str, Any], data: Any, path: tuple[Any, ...]) -> str:
    kind = err["type"]
    if kind == "extra_forbidden":
        return _unknown_key(data, path)
    if kind == "missing":
        return "required key is missing"
    if kind == "union_tag_invalid":
        names = sorted(bearing_types())
        hint = _did_you_mean(str((err.get("ctx") or {}).get("tag", "")), names)
        return f"unknown type; expected one of {', '.join(names)}" + (f" ({hint[2:]})" if hint else "")
    if kind == "union_tag_not_found":
        return f"a bearing needs a type: one of {', '.join(sorted(bearing_types()))}"
    bounds = {"less_than_equal": ("le", "<="), "less_than": ("lt", "<"), "greater_than_equal": ("ge", ">="),
              "greater_than": ("gt", ">")}
    ctx = err.get("ctx") or {}
    if kind in bounds and isinstance(ctx.get(bounds[kind][0]), (int, float)) and \
            isinstance(err.get("input"), (int, float)) and not isinstance(err.get("input"), bool):
        got = err["input"]
        big = isinstance(got, int) and abs(got) >= 10**300  # beyond a float
        shown = f"an integer of {len(str(abs(got)))} digits" if big else f"{float(got):g}"
        return f"must be {bounds[kind][1]} {ctx[bounds[kind][0]]:g}, got {shown}"
    msg = str(err["msg"])
    if msg.startswith("Value error, "):
        msg = msg[len("Value error, "):]
    if "input" in err and kind.endswith("_type"):
        shown = repr(err["input"])
        shown = shown if len(shown) <= 60 else shown[:57] + "..."
        msg += f" (got {type(err['input']).__name__} {shown})"
    return msg


def _row_checks(rows: list[list[float]], where: tuple[Any, ...], bad: list) -> None:
    """Element rows [outer_dia_mm, inner_dia_mm, length_mm, density_kg_m3, E_GPa, G_GPa, poisson, axial_force_N]."""
    for i, row in enumerate(rows):
        do, di = row[0], row[1]
        for j, val in enumerate(row):
            name, at = ROW_KEYS[j], where + (i, j)
            if name == "inner_dia_mm":
                if val < 0:
                    bad.append((at, f"{name} must be >= 0, got {val}"))
                    continue
            elif name == "poisson":
                if not (-1.0 < val < 0.5):
                    bad.append((at, f"poisson must be in (-1, 0.5), got {val}"))
                continue
            elif name != "axial_force_N" and not val > 0:
                bad.append((at, f"{name} must be > 0, got {val}"))
                continue
            elif name in ("outer_dia_mm", "length_mm") and val < MIN_ELEMENT_MM:
                bad.append((at, f"{name} {val:g} is below {MIN_ELEMENT_MM:g} mm, the smallest a beam element may be"))
                continue
            suffix, (lo, hi) = unit_range(name)  # type: ignore[misc]
            if not lo <= val <= hi:
                bad.append((at, f"{name} {val:g} is outside the physical range of a value in {unit_text(suffix)} "
                                f"({lo:g} .. {hi:g})"))
        if di >= do and do > 0:
            bad.append((where + (i, 1), f"inner_dia_mm {di} must be smaller than outer_dia_mm {do}"))


def _tool_library_checks(d: BaseModel, bad: list) -> None:
    """The ``tools:`` entries: a shaft to sit on, unique names, rows as the shaft's, every part given where the
    deck has no ``tool:`` section to take it from."""
    if not d.tools:
        return
    if d.shaft is None:
        bad.append((("tools",), "a tool library needs a shaft to sit on (shaft: elements: ...)"))
    seen: dict[str, int] = {}
    for i, entry in enumerate(d.tools):
        if entry.name in seen:
            bad.append((("tools", i, "name"), f"duplicate tool name {entry.name!r} (also tools[{seen[entry.name]}])"))
        seen[entry.name] = i
        for key in ("holder", "tool"):
            part = getattr(entry, key)
            if part is not None:
                _row_checks(part.elements, ("tools", i, key, "elements"), bad)
        if d.tool is None:
            missing = [k for k in ("holder", "joint", "tool") if getattr(entry, k) is None]
            if missing:
                bad.append((("tools", i), f"tool {entry.name!r} needs {', '.join(missing)}: the deck has no tool: "
                                          "section to take them from"))
        holder = entry.holder if entry.holder is not None else getattr(d.tool, "holder", None)
        tool = entry.tool if entry.tool is not None else getattr(d.tool, "tool", None)
        if entry.holder is not None or entry.tool is not None:
            _shank_fits(holder, tool, ("tools", i, "tool" if entry.tool is not None else "holder"),
                        entry.tool is not None, bad)


#: a shank this much larger than the holder's bore [mm] does not go in (a shrink fit's interference is microns)
SHANK_OVER_BORE_MM = 0.05


def _shank_fits(holder, tool, where: tuple, at_tool: bool, bad: list) -> None:
    """The tool's first row (its shank) must go into the holder's bore (the inner diameter of the holder's last
    row), where both are given and the bore is open."""
    if holder is None or tool is None or not holder.elements or not tool.elements:
        return
    bore, shank = float(holder.elements[-1][1]), float(tool.elements[0][0])
    if bore > 0.0 and shank > bore + SHANK_OVER_BORE_MM:
        at = where + ("elements", 0, 0) if at_tool else where + ("elements", len(holder.elements) - 1, 1)
        bad.append((at, f"the tool's shank (outer_dia_mm {shank:g} of its first row) is larger than the holder's "
                        f"bore (inner_dia_mm {bore:g} of the holder's last row): it does not go in"))


def _physics_checks(d: BaseModel) -> list[tuple[tuple[Any, ...], str]]:
    """Checks pydantic cannot express: element rows, node ranges, analysis names, work limits."""
    bad: list[tuple[tuple[Any, ...], str]] = []
    rows = d.shaft.elements if d.shaft is not None else []
    _row_checks(rows, ("shaft", "elements"), bad)
    if rows and all(0 < r[0] < MIN_DIMENSION_MM and 0 < r[2] < MIN_DIMENSION_MM for r in rows):
        bad.append((("shaft", "elements", 0, 0), f"every shaft row is under {MIN_DIMENSION_MM:g} mm in diameter and "
                                                 f"length: were they given in metres? ({rows[0][0]:g} m = "
                                                 f"{rows[0][0] * 1e3:g} mm); the keys are outer_dia_mm and length_mm"))
    if d.tool is not None:
        _row_checks(d.tool.holder.elements, ("tool", "holder", "elements"), bad)
        _row_checks(d.tool.tool.elements, ("tool", "tool", "elements"), bad)
        _shank_fits(d.tool.holder, d.tool.tool, ("tool", "tool"), True, bad)
    n_nodes = len(rows) + 1 if d.shaft is not None else 1
    if d.tool is not None and d.shaft is not None:
        if d.tool.holder_node not in (1, n_nodes):
            bad.append((("tool", "holder_node"), f"the holder sits at an end of the shaft: node 1 or {n_nodes}"))
        n_nodes += len(d.tool.holder.elements) + len(d.tool.tool.elements) + 1 + (d.tool.interface is not None)
    elif d.tool is not None:
        bad.append((("tool",), "a tool needs a shaft to sit on (shaft: elements: ...)"))
    _tool_library_checks(d, bad)
    has_rotor = d.shaft is not None or d.journal is not None

    def node_ok(path: tuple[Any, ...], node: int) -> None:
        if not has_rotor:
            return  # reported by require_rotor() when a rotor analysis runs
        if node > n_nodes:
            bad.append((path, f"node {node} is out of range: the rotor has nodes 1..{n_nodes}"))

    for i, disk in enumerate(d.disks):
        node_ok(("disks", i, "node"), disk.node)
    seen: dict[str, int] = {}
    for i, b in enumerate(d.bearings):
        node_ok(("bearings", i, "node"), b.node)
        if b.name in seen:
            bad.append((("bearings", i, "name"), f"duplicate bearing name {b.name!r} (also bearings[{seen[b.name]}])"))
        seen[b.name] = i
    for i, b in enumerate(d.bearings):
        bad += [(("bearings", i) + path, msg) for path, msg in located_checks(b)]
    if getattr(d, "bearing", None) is not None:
        bad += [(("bearing",) + path, msg) for path, msg in ball_section.located_checks(d.bearing)]
    for i, load in enumerate(d.loads):
        node_ok(("loads", i, "node"), load.node)
    for sec, keys in (("static", ("stiffness_at",)), ("frf", ("input", "output"))):
        for key in keys:
            where = getattr(getattr(d, sec), key)
            if where is not None:
                node_ok((sec, key, "node"), where.node)
    if d.calibration is not None:
        for i, m in enumerate(d.calibration.measurements):
            node_ok(("calibration", "measurements", i, "node"), m.node)
    if d.unbalance is not None:
        node_ok(("unbalance", "node"), d.unbalance.node)
        node_ok(("unbalance", "output", "node"), d.unbalance.output.node)
    for sec, key in (("frf", "frequencies_hz"), ("campbell", "speeds_rpm")):
        r = getattr(getattr(d, sec), key)
        if not isinstance(r, list) and r.stop <= r.start:
            bad.append(((sec, key, "stop"), "stop must be greater than start"))
    if d.unbalance is not None and d.unbalance.speeds_rpm.stop <= d.unbalance.speeds_rpm.start:
        bad.append((("unbalance", "speeds_rpm", "stop"), "stop must be greater than start"))
    if d.shaft is not None and d.journal is not None:
        bad.append((("journal",), "give either shaft (a flexible rotor) or journal (a rigid journal), not both"))
    rt = d.rotor_transient
    if rt is not None:
        for path, node in ((("rotor_transient", "record_node"), rt.record_node),
                           (("rotor_transient", "perturbation", "node"), rt.perturbation and rt.perturbation.node)):
            if node is not None:
                node_ok(path, node)
        for i, load in enumerate(rt.loads):
            node_ok(("rotor_transient", "loads", i, "node"), load.node)
    if d.spindle_thermal is not None:
        if d.shaft is None:
            bad.append((("spindle_thermal",), "the spindle's thermal model needs a shaft (shaft: elements: ...)"))
        sets, refused = network_bearings(d.bearings)
        if not sets:
            *first, last = network_types()
            bad.append((("spindle_thermal",), f"the spindle's thermal model needs rolling-bearing entries (type: "
                                              f"{', '.join(first)} or {last})"))
        bad += [(("bearings", i, "model"), why) for i, _, why in refused]
        for i, b in sets:
            if b.temperatures_C is not None:
                bad.append((("bearings", i, "temperatures_C"), "prescribed temperatures and the spindle_thermal "
                                                               "section exclude each other: the section computes them"))
    if d.analyses is not None:
        for i, name in enumerate(d.analyses):
            if name not in ANALYSES:
                hint = _did_you_mean(name, list(ANALYSES))
                bad.append((("analyses", i), f"unknown analysis {name!r}{hint or '; known: ' + ', '.join(ANALYSES)}"))
    return bad + work_checks(d)


def require_section(loaded: LoadedDeck, section: str, analysis: str, keys: str) -> Any:
    """The deck's ``section`` (e.g. ``chatter``), or a deck error (exit 2) saying the analysis needs it and
    what it holds (``keys``); docs/deck-format.md describes every section."""
    value = getattr(loaded.deck, section, None)
    if value is None:
        raise DeckError([DeckIssue(loaded.source, 1, 1, section, f"the {analysis} analysis needs a '{section}' "
                                   f"section ({keys}); see docs/deck-format.md")])
    return value


def require_rotor(loaded: LoadedDeck, analysis: str) -> None:
    """Rotor analyses need a rotor (``shaft`` or ``journal``), ``operating`` and bearings that hold the
    rotor; raise a located DeckError otherwise (a singular stiffness matrix is a deck error)."""
    d = loaded.deck
    missing = [] if d.shaft is not None or d.journal is not None else ["shaft"]
    missing += [] if d.operating is not None else ["operating"]
    if missing:
        raise DeckError([DeckIssue(loaded.source, 1, 1, k, f"required for the {analysis} analysis") for k in missing])
    if analysis not in SUPPORTED_ANALYSES:
        return
    if not d.bearings:
        raise DeckError([loaded.issue(("bearings",), f"the {analysis} analysis needs bearings that hold the rotor "
                                                     "(a rotor without supports has a singular stiffness matrix)")])
    issues = []
    if d.shaft is not None and all(acts_radially_only(b) for b in d.bearings) and len({b.node for b in d.bearings}) == 1:
        issues.append(loaded.issue(("bearings", 0, "node"),
                                   f"the {analysis} analysis needs the shaft held at two nodes: these bearings act on "
                                   f"x and y only and all sit at node {d.bearings[0].node}, so the shaft can tilt freely"))
    axial = [b for b in d.bearings if holds_axially(b)]
    if not axial:
        for i, p in enumerate(d.loads):
            if p.fz_N:
                issues.append(loaded.issue(("loads", i, "fz_N"), "an axial load needs a bearing that holds the rotor "
                                                                 "axially (type ball, or dtrb with dofs: 5)"))
    if issues:
        raise DeckError(issues)


def available_analyses() -> tuple[str, ...]:
    return ANALYSES


def _capped(issues: list[DeckIssue]) -> DeckError:
    uniq = list(dict.fromkeys(issues))
    return DeckError(uniq[:MAX_ISSUES], total=len(uniq))


def parse_deck(text: str, filename: str = "<deck>") -> LoadedDeck:
    """Validate deck ``text``; raise DeckError listing every problem found (at most MAX_ISSUES shown)."""
    data, marks, issues = load_with_marks(text, filename)
    if data is None and not issues:
        issues.append(DeckIssue(filename, 1, 1, "", "the deck is empty"))
    if data is not None and not isinstance(data, dict):
        kind = "a list" if isinstance(data, list) else f"a single value ({type(data).__name__})"
        issues.append(DeckIssue(filename, *marks.get((), (1, 1)), "",
                                f"the deck is {kind}; it must be a mapping of sections (title:, shaft:, bearings:, ...)"))
    if data is None or not isinstance(data, dict):
        raise _capped(issues)
    # top-level keys starting with "x-" hold shared parts for anchors and merge keys (``x-rows: &rows ...``)
    data = {k: v for k, v in data.items() if not (isinstance(k, str) and k.startswith(SHARED_PREFIX))}
    yaml_paths = {i.path for i in issues}
    try:
        deck = deck_model().model_validate(data)
    except ValidationError as exc:
        for err in exc.errors():
            path = _data_path(data, tuple(err["loc"]))
            if path_str(path) in yaml_paths:
                continue  # already reported by the YAML reader (a bad tag, an unreadable value)
            line, col = locate(marks, path)
            issues.append(DeckIssue(filename, line, col, path_str(path), _message(err, data, path)))
        raise _capped(issues) from None
    for path, msg in _physics_checks(deck):
        line, col = locate(marks, path)
        issues.append(DeckIssue(filename, line, col, path_str(path), msg))
    if issues:
        raise _capped(issues)
    loaded = LoadedDeck(deck=deck, text=text, source=filename, marks=marks)
    warnings = tuple(replace(loaded.issue(path, msg), severity="warning") for path, msg in plausibility_warnings(deck))
    for w in warnings:
        log.debug("%s", w)
    return LoadedDeck(deck=deck, text=text, source=filename, warnings=warnings, marks=marks)


def load_deck(path: str | Path) -> LoadedDeck:
    """Read and validate the deck at ``path``."""
    import stat

    p = Path(path)
    try:
        mode = p.stat().st_mode
        if not stat.S_ISREG(mode):  # a directory, a socket, a pipe: never read (a pipe would block)
            kind = "a directory" if stat.S_ISDIR(mode) else "not a regular file"
            raise DeckError([DeckIssue(str(p), 1, 1, "", f"the deck is {kind}: give a YAML file")])
        size = p.stat().st_size
        if size > 4 * MAX_TEXT_CHARS:  # UTF-8: at most 4 bytes a character
            raise DeckError([DeckIssue(str(p), 1, 1, "", f"the deck is {size} bytes; the limit is {MAX_TEXT_CHARS} "
                                                         "characters (see 'Limits' in docs/deck-format.md)")])
        text = p.read_text(encoding="utf-8")
    except UnicodeDecodeError as exc:
        line = exc.object[:exc.start].count(b"\n") + 1
        col = exc.start - (exc.object.rfind(b"\n", 0, exc.start) + 1) + 1
        raise DeckError([DeckIssue(str(p), line, col, "", f"the deck is not UTF-8 text (byte 0x{exc.object[exc.start]:02x} "
                                                          "cannot be decoded): is it a YAML file?")]) from None
    except OSError as exc:
        raise DeckError([DeckIssue(str(p), 1, 1, "", f"cannot read deck: {exc.strerror or exc}")]) from None
    return parse_deck(text, str(p))


def default_deck(name: str = "spindle") -> LoadedDeck:
    """An embedded default deck shipped in ``spindlesim/decks/<name>.yaml``."""
    text = resources.files("spindlesim.decks").joinpath(f"{name}.yaml").read_text(encoding="utf-8")
    return parse_deck(text, f"<default:{name}>")


def deck_folder(loaded: LoadedDeck) -> Path:
    """The folder a deck's relative file paths (measured FRFs) are taken from: the deck file's, the package's
    for an embedded deck, the working directory for a deck given as text."""
    if loaded.source.startswith("<default:"):
        return Path(str(resources.files("spindlesim.decks")))
    if loaded.source.startswith("<"):
        return Path.cwd()
    return Path(loaded.source).parent


__all__ = ["ANALYSES", "LoadedDeck", "available_analyses", "default_deck", "deck_folder", "load_deck",
           "parse_deck", "require_rotor"]
