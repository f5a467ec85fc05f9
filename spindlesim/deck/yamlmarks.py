"""YAML to plain Python objects while recording where every key path sits in the file.

The deck is read from the parser's event stream (libyaml when available) by an iterative
builder, not by PyYAML's recursive composer and constructor, so that every hostile input ends
in a located :class:`DeckIssue` instead of a traceback, a hang or a memory blow-up:

* nesting deeper than :data:`MAX_DEPTH` collections, more than :data:`MAX_VALUES` values after
  alias expansion (billion laughs) and texts over :data:`MAX_TEXT_CHARS` characters are refused;
* scalars are typed by the YAML 1.1 resolver plus YAML 1.2 floats (``412.62e6``); the only tags
  accepted are ``!!str``, ``!!int``, ``!!float``, ``!!bool`` and ``!!null`` (``!!int abc`` is a
  located error, ``!!python/object`` never constructs anything);
* keys are always text (the key as written), duplicate keys are errors, merge keys
  (``<<: *base`` or ``<<: [*a, *b]``) work as in YAML 1.1, keys written in the mapping winning;
* a YAML syntax error on a line indented with a tab says so ("use spaces").

Aliased values keep the line marks of their anchor, so an error inside a shared part of a deck
points at the line where the value is written.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any, Optional

import yaml

from .errors import DeckIssue
from .limits import MAX_DEPTH, MAX_TEXT_CHARS, MAX_VALUES

Path = tuple[Any, ...]



class DeckLoader(yaml.SafeLoader):
    """SafeLoader that also reads YAML 1.2 floats such as ``412.62e6`` (YAML 1.1 needs ``e+6``).

    Kept for code that reads an already validated deck with ``yaml.load`` (sweep cases); the deck
    loader itself resolves scalars with the same rules in :func:`load_with_marks`.
    """


DeckLoader.add_implicit_resolver(
    "tag:yaml.org,2002:float",
    re.compile(
        r"""^(?:[-+]?(?:[0-9][0-9_]*)\.[0-9_]*(?:[eE][-+]?[0-9]+)?
        |[-+]?(?:[0-9][0-9_]*)(?:[eE][-+]?[0-9]+)
        |\.[0-9_]+(?:[eE][-+]?[0-9]+)?
        |[-+]?\.(?:inf|Inf|INF)
        |\.(?:nan|NaN|NAN))$""",
        re.X,
    ),
    list("-+0123456789."),
)

_Y = "tag:yaml.org,2002:"
_SCALAR_TAGS = {_Y + "str": "text", _Y + "int": "an integer", _Y + "float": "a number",
                _Y + "bool": "a boolean", _Y + "null": "null", _Y + "timestamp": "a date"}
_EXPLICIT_OK = {_Y + "str", _Y + "int", _Y + "float", _Y + "bool", _Y + "null", "!"}
_SEQ_TAGS = {None, "!", _Y + "seq"}
_MAP_TAGS = {None, "!", _Y + "map"}
_SKIP = object()  # key of a value that is read but not kept (empty or duplicate key)


class _Abort(Exception):
    """Stop reading: the issue that ends it is already recorded."""


def _parser(text: str):
    try:
        from yaml.cyaml import CParser
    except ImportError:  # PyYAML without libyaml: the pure-Python parser (slower, same events)
        return yaml.loader.BaseLoader(text)
    return CParser(text)


def _short(tag: str) -> str:
    return "!!" + tag[len(_Y):] if tag.startswith(_Y) else tag


@dataclass
class _Frame:
    kind: str  # "map" or "seq"
    value: Any
    path: Path
    anchor: Optional[str]
    start: int  # index into the builder's order of marks when the collection began
    count: int  # value count when it began
    key: Any = None  # map: the key waiting for its value (None: a key is expected)
    merge_values: list[tuple[Any, Path, int, int]] = field(default_factory=list)


class _Builder:
    """Python values with line marks from a YAML event stream, iteratively and within limits."""

    def __init__(self, filename: str, text: str):
        self.file = filename
        self.text = text
        self.issues: list[DeckIssue] = []
        self.marks: dict[Path, tuple[int, int]] = {}
        self.order: list[Path] = []  # paths in the order their marks were recorded
        self.stack: list[_Frame] = []
        self.anchors: dict[str, tuple[Any, Path, int, int, int]] = {}
        self.count = 0
        self.root: Any = None
        self.documents = 0
        self.resolver = DeckLoader("")
        self.constructor = yaml.constructor.SafeConstructor()

    # -- issues --------------------------------------------------------------------------
    def issue(self, mark, path: Path, message: str) -> None:
        line, col = (mark.line + 1, mark.column + 1) if mark is not None else (1, 1)
        self.issues.append(DeckIssue(self.file, line, col, path_str(path), message))

    def fatal(self, mark, path: Path, message: str) -> None:
        self.issue(mark, path, message)
        raise _Abort

    # -- values --------------------------------------------------------------------------
    def _mark(self, path: Path, mark) -> None:
        self.marks[path] = (mark.line + 1, mark.column + 1)
        self.order.append(path)

    def _tick(self, n: int, mark, path: Path) -> None:
        self.count += n
        if self.count > MAX_VALUES:
            self.fatal(mark, path, f"the deck holds more than {MAX_VALUES} values (aliases expanded); "
                                   "see 'Limits' in docs/deck-format.md")

    def _scalar(self, ev, path: Path) -> Any:
        tag = ev.tag
        if tag is None:
            tag = self.resolver.resolve(yaml.ScalarNode, ev.value, ev.implicit)
        elif tag == "!":
            tag = _Y + "str"  # the non-specific tag of a quoted scalar
        elif tag not in _EXPLICIT_OK:
            self.issue(ev.start_mark, path, f"YAML tag {_short(tag)} is not supported in a deck "
                                            "(numbers, text, true/false, null, lists and mappings only)")
            return None
        if tag not in _SCALAR_TAGS:
            tag = _Y + "str"
        if tag == _Y + "str":
            return ev.value
        node = yaml.ScalarNode(tag, ev.value, ev.start_mark, ev.end_mark, ev.style)
        c = self.constructor
        build = {_Y + "int": c.construct_yaml_int, _Y + "float": c.construct_yaml_float,
                 _Y + "bool": c.construct_yaml_bool, _Y + "null": c.construct_yaml_null,
                 _Y + "timestamp": c.construct_yaml_timestamp}[tag]
        try:
            return build(node)
        except (ValueError, TypeError, OverflowError, ArithmeticError, KeyError, IndexError,
                AttributeError, yaml.YAMLError):
            shown = ev.value if len(ev.value) <= 40 else ev.value[:37] + "..."
            self.issue(ev.start_mark, path, f"cannot read {shown!r} as {_SCALAR_TAGS[tag]} ({_short(tag)})")
            return None

    def _child_path(self, ev) -> Path:
        """Path of the node that starts with event ``ev``; reads a key when the mapping expects one."""
        if not self.stack:
            return ()
        top = self.stack[-1]
        if top.kind == "seq":
            path = top.path + (len(top.value),)
            self._mark(path, ev.start_mark)
            return path
        key = top.key
        if key is _SKIP:
            return top.path + ("<ignored>",)
        if key == "<<":
            return top.path + ("<<", len(top.merge_values))
        return top.path + (key,)

    def _attach(self, value: Any, path: Path, start: int) -> None:
        """Put a finished value into its parent (or make it the root)."""
        if not self.stack:
            self.root = value
            return
        top = self.stack[-1]
        if top.kind == "seq":
            top.value.append(value)
            return
        key, top.key = top.key, None
        if key == "<<":
            top.merge_values.append((value, path, start, len(self.order)))
        elif key is not _SKIP:
            top.value[key] = value

    def _key(self, ev, top: _Frame) -> None:
        """A scalar in key position: keys are the text as written."""
        key = ev.value
        path = top.path + (key,)
        is_merge = key == "<<" and ev.tag is None and ev.style in (None, "")
        if is_merge:
            top.key = "<<"
            self.marks[path] = (ev.start_mark.line + 1, ev.start_mark.column + 1)
            return
        if key == "":
            self.issue(ev.start_mark, top.path, "a key is missing before ':' (empty key)")
            top.key = _SKIP
        elif key in top.value:
            first = self.marks.get(path, (0, 0))
            self.issue(ev.start_mark, path, f"duplicate key (first defined on line {first[0]})")
            top.key = _SKIP
        else:
            top.key = key
            self._mark(path, ev.start_mark)

    def _expects_key(self) -> bool:
        return bool(self.stack) and self.stack[-1].kind == "map" and self.stack[-1].key is None

    # -- events --------------------------------------------------------------------------
    def event(self, ev) -> None:
        if isinstance(ev, yaml.DocumentStartEvent):
            self.documents += 1
            if self.documents > 1:
                self.fatal(ev.start_mark, (), "a deck is one YAML document; this is a second one ('---')")
            return
        if isinstance(ev, (yaml.StreamStartEvent, yaml.StreamEndEvent, yaml.DocumentEndEvent)):
            return
        if isinstance(ev, (yaml.MappingEndEvent, yaml.SequenceEndEvent)):
            self._end(ev)
            return
        if self._expects_key():
            top = self.stack[-1]
            if isinstance(ev, yaml.ScalarEvent):
                self._key(ev, top)
                return
            what = "an alias" if isinstance(ev, yaml.AliasEvent) else "a list or mapping"
            self.fatal(ev.start_mark, top.path, f"a key must be a plain name, not {what}")
        path = self._child_path(ev)
        start = len(self.order)
        if isinstance(ev, yaml.AliasEvent):
            self._alias(ev, path, start)
        elif isinstance(ev, yaml.ScalarEvent):
            self._tick(1, ev.start_mark, path)
            value = self._scalar(ev, path)
            if ev.anchor is not None:
                self.anchors[ev.anchor] = (value, path, len(self.order), len(self.order), 1)
            self._attach(value, path, start)
        elif isinstance(ev, (yaml.SequenceStartEvent, yaml.MappingStartEvent)):
            self._begin(ev, path)

    def _begin(self, ev, path: Path) -> None:
        self._tick(1, ev.start_mark, path)
        if len(self.stack) >= MAX_DEPTH:
            self.fatal(ev.start_mark, path, f"lists and mappings are nested more than {MAX_DEPTH} deep")
        seq = isinstance(ev, yaml.SequenceStartEvent)
        if ev.tag not in (_SEQ_TAGS if seq else _MAP_TAGS):
            self.issue(ev.start_mark, path, f"YAML tag {_short(ev.tag)} is not supported in a deck "
                                            "(numbers, text, true/false, null, lists and mappings only)")
        self.stack.append(_Frame("seq" if seq else "map", [] if seq else {}, path, ev.anchor,
                                 len(self.order), self.count))

    def _end(self, ev) -> None:
        frame = self.stack.pop()
        if frame.kind == "map":
            self._merge(frame)
        if frame.anchor is not None:
            self.anchors[frame.anchor] = (frame.value, frame.path, frame.start, len(self.order),
                                          self.count - frame.count + 1)
        self._attach(frame.value, frame.path, frame.start)

    def _merge(self, frame: _Frame) -> None:
        """Apply ``<<`` merge keys: keys written in the mapping win, then the sources in order."""
        for value, path, start, end in frame.merge_values:
            sources = value if isinstance(value, list) else [value]
            for i, src in enumerate(sources):
                if not isinstance(src, dict):
                    line, col = self.marks.get(frame.path + ("<<",), (1, 1))
                    self.issues.append(DeckIssue(self.file, line, col, path_str(frame.path + ("<<",)),
                                                 "a merge key (<<) takes a mapping or a list of mappings"))
                    continue
                src_path = path + (i,) if isinstance(value, list) else path
                for k, v in src.items():
                    if k in frame.value:
                        continue
                    frame.value[k] = v
                    self._copy_marks(src_path + (k,), frame.path + (k,), start, end)

    def _copy_marks(self, src: Path, dst: Path, start: int, end: int) -> None:
        n = len(src)
        for p in self.order[start:end]:
            if p[:n] == src:
                new = dst + p[n:]
                if new not in self.marks:
                    self.marks[new] = self.marks[p]
                    self.order.append(new)

    def _alias(self, ev, path: Path, start: int) -> None:
        name = ev.anchor
        if name not in self.anchors:
            self.fatal(ev.start_mark, path, f"alias *{name} refers to no anchor &{name} defined before it")
        value, apath, a_start, a_end, size = self.anchors[name]
        self._tick(size, ev.start_mark, path)
        n = len(apath)
        for p in self.order[a_start:a_end]:
            if p[:n] == apath:
                new = path + p[n:]
                self.marks[new] = self.marks[p]
                self.order.append(new)
        self._attach(value, path, start)


def shown_key(key) -> str:
    """A key as a message shows it: as written, or quoted with its escapes (``'title\\n'``) when it holds a control
    character or starts or ends with a space (a raw line break would split the one-line message)."""
    text = str(key)
    if any(ord(c) < 32 or ord(c) == 127 for c in text) or text != text.strip():
        return repr(text)
    return text


def path_str(path: Path) -> str:
    """``shaft.elements[3][1]`` from ``("shaft", "elements", 3, 1)``."""
    out = ""
    for p in path:
        out += f"[{p}]" if isinstance(p, int) else (f".{shown_key(p)}" if out else shown_key(p))
    return out


def _line_col(text: str, position: int) -> tuple[int, int]:
    before = text[:position]
    line = before.count("\n") + 1
    return line, position - (before.rfind("\n") + 1) + 1


def _syntax_issue(exc: yaml.YAMLError, text: str, filename: str) -> DeckIssue:
    """A located 'invalid YAML' issue; a tab in the indentation is named as the likely cause."""
    mark = getattr(exc, "problem_mark", None) or getattr(exc, "context_mark", None)
    if mark is not None:
        line, col = mark.line + 1, mark.column + 1
    elif getattr(exc, "position", None) is not None:
        line, col = _line_col(text, exc.position)
    else:
        line, col = 1, 1
    problem = getattr(exc, "problem", None) or getattr(exc, "reason", None) or str(exc)
    lines = text.splitlines()
    indent = re.compile(r"^[ ]*\t")
    tabbed = [i + 1 for i, s in enumerate(lines) if indent.match(s)]
    if tabbed:
        here = line if line in tabbed else tabbed[0]
        return DeckIssue(filename, here, 1, "", f"invalid YAML: line {here} is indented with a tab; "
                                                "YAML indentation must use spaces")
    return DeckIssue(filename, line, col, "", f"invalid YAML: {problem}")


def load_with_marks(text: str, filename: str) -> tuple[Any, dict[Path, tuple[int, int]], list[DeckIssue]]:
    """Parse ``text``; return (data, marks, issues).

    ``marks`` maps a key path (tuple of str keys and int indices) to the 1-based (line, col) of
    that key (for mapping entries) or item (for sequences).  ``data`` is None when the text
    cannot be read at all (syntax error, a limit exceeded); the issues say why.
    """
    if len(text) > MAX_TEXT_CHARS:
        return None, {}, [DeckIssue(filename, 1, 1, "", f"the deck is {len(text)} characters long; the limit is "
                                                        f"{MAX_TEXT_CHARS} (see 'Limits' in docs/deck-format.md)")]
    b = _Builder(filename, text)
    parser = _parser(text)
    try:
        while parser.check_event():
            b.event(parser.get_event())
    except _Abort:
        return None, b.marks, b.issues
    except yaml.YAMLError as exc:
        return None, b.marks, b.issues + [_syntax_issue(exc, text, filename)]
    finally:
        parser.dispose()
    if b.root is None and not b.issues:
        b.issues.append(DeckIssue(filename, 1, 1, "", "the deck is empty"))
    b.marks.setdefault((), (1, 1))
    return b.root, b.marks, b.issues


def locate(marks: dict[Path, tuple[int, int]], path: Path) -> tuple[int, int]:
    """Line and column of the deepest recorded prefix of ``path``."""
    for n in range(len(path), -1, -1):
        if tuple(path[:n]) in marks:
            return marks[tuple(path[:n])]
    return 1, 1
