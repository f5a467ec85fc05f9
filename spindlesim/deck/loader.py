"""Load a YAML deck: parse with line marks, validate with pydantic, check physics, collect all errors."""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Any

from pydantic import BaseModel, ValidationError

from .errors import DeckError, DeckIssue
from .document import bearing_types, deck_model
from .yamlmarks import load_with_marks, locate

#: every analysis a deck may list under ``analyses:`` (``spindlesim.runs.RUNS`` runs them)
ANALYSES = ("static", "modal", "campbell", "frf", "unbalance", "transient", "rotor_transient", "thermal",
            "coefficients", "dtrb", "contact")


@dataclass(frozen=True)
class LoadedDeck:
    """A validated deck with its source text (written into every output file)."""

    deck: BaseModel
    text: str
    source: str  # file path, or "<default:name>"

    @property
    def sha256(self) -> str:
        return hashlib.sha256(self.text.encode()).hexdigest()

    @property
    def stem(self) -> str:
        if self.source.startswith("<default:"):
            return "default_" + self.source[len("<default:"):-1]
        return Path(self.source).stem


def _path_str(path: tuple[Any, ...]) -> str:
    out = ""
    for p in path:
        out += f"[{p}]" if isinstance(p, int) else (f".{p}" if out else str(p))
    return out


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


def _message(err: dict[str, Any]) -> str:
    kind = err["type"]
    if kind == "extra_forbidden":
        return "unknown key"
    if kind == "missing":
        return "required key is missing"
    if kind == "union_tag_invalid":
        return f"unknown type; expected one of {', '.join(sorted(bearing_types()))}"
    msg = err["msg"]
    if "input" in err and kind.endswith("_type"):
        msg += f" (got {type(err['input']).__name__} {err['input']!r})"
    return msg


def _physics_checks(d: BaseModel) -> list[tuple[tuple[Any, ...], str]]:
    """Checks pydantic cannot express: element rows, node ranges, analysis names."""
    bad: list[tuple[tuple[Any, ...], str]] = []
    names = ["outer_dia_mm", "inner_dia_mm", "length_mm", "density_kg_m3", "E_GPa", "G_GPa", "poisson"]
    rows = d.shaft.elements if d.shaft is not None else []
    for i, row in enumerate(rows):
        do, di, length, rho, e, g, nu, _ = row
        for j, val in enumerate(row[:7]):
            if names[j] == "inner_dia_mm":
                if val < 0:
                    bad.append((("shaft", "elements", i, j), f"{names[j]} must be >= 0, got {val}"))
            elif names[j] == "poisson":
                if not (-1.0 < val < 0.5):
                    bad.append((("shaft", "elements", i, j), f"poisson must be in (-1, 0.5), got {val}"))
            elif not val > 0:
                bad.append((("shaft", "elements", i, j), f"{names[j]} must be > 0, got {val}"))
        if di >= do and do > 0:
            bad.append((("shaft", "elements", i, 1), f"inner_dia_mm {di} must be smaller than outer_dia_mm {do}"))
    n_nodes = len(rows) + 1 if d.shaft is not None else 1
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
    for i, load in enumerate(d.loads):
        node_ok(("loads", i, "node"), load.node)
    for sec, keys in (("static", ("stiffness_at",)), ("frf", ("input", "output"))):
        for key in keys:
            node_ok((sec, key, "node"), getattr(getattr(d, sec), key).node)
    if d.unbalance is not None:
        node_ok(("unbalance", "node"), d.unbalance.node)
        node_ok(("unbalance", "output", "node"), d.unbalance.output.node)
    fr = d.frf.frequencies_hz
    if not isinstance(fr, list) and fr.stop <= fr.start:
        bad.append((("frf", "frequencies_hz", "stop"), "stop must be greater than start"))
    sp = d.campbell.speeds_rpm
    if sp.stop <= sp.start:
        bad.append((("campbell", "speeds_rpm", "stop"), "stop must be greater than start"))
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
    if d.analyses is not None:
        for i, name in enumerate(d.analyses):
            if name not in ANALYSES:
                bad.append((("analyses", i), f"unknown analysis {name!r}; known: {', '.join(ANALYSES)}"))
    return bad


def require_rotor(loaded: LoadedDeck, analysis: str) -> None:
    """Rotor analyses need a rotor (``shaft`` or ``journal``) and ``operating``; raise a located
    DeckError otherwise."""
    d = loaded.deck
    missing = [] if d.shaft is not None or d.journal is not None else ["shaft"]
    missing += [] if d.operating is not None else ["operating"]
    if missing:
        raise DeckError([DeckIssue(loaded.source, 1, 1, k, f"required for the {analysis} analysis") for k in missing])


def available_analyses() -> tuple[str, ...]:
    return ANALYSES


def parse_deck(text: str, filename: str = "<deck>") -> LoadedDeck:
    """Validate deck ``text``; raise DeckError listing every problem found."""
    data, marks, issues = load_with_marks(text, filename)
    if data is not None and not isinstance(data, dict):
        issues.append(DeckIssue(filename, 1, 1, "", "the deck must be a mapping of sections (title, shaft, ...)"))
    if data is None or not isinstance(data, dict):
        raise DeckError(issues)
    try:
        deck = deck_model().model_validate(data)
    except ValidationError as exc:
        for err in exc.errors():
            path = _data_path(data, tuple(err["loc"]))
            line, col = locate(marks, path)
            issues.append(DeckIssue(filename, line, col, _path_str(path), _message(err)))
        # one message per location and text
        uniq = list(dict.fromkeys(issues))
        raise DeckError(uniq) from None
    for path, msg in _physics_checks(deck):
        line, col = locate(marks, path)
        issues.append(DeckIssue(filename, line, col, _path_str(path), msg))
    if issues:
        raise DeckError(issues)
    return LoadedDeck(deck=deck, text=text, source=filename)


def load_deck(path: str | Path) -> LoadedDeck:
    """Read and validate the deck at ``path``."""
    p = Path(path)
    try:
        text = p.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise DeckError([DeckIssue(str(p), 1, 1, "", f"cannot read deck: {exc}")]) from None
    return parse_deck(text, str(p))


def default_deck(name: str = "spindle") -> LoadedDeck:
    """An embedded default deck shipped in ``spindlesim/decks/<name>.yaml``."""
    text = resources.files("spindlesim.decks").joinpath(f"{name}.yaml").read_text(encoding="utf-8")
    return parse_deck(text, f"<default:{name}>")
