"""Deck generators and the oracle of the property tests.

Two sources of decks:

* :func:`mutated_deck`: an example deck (decks/*.yaml, decks/validation/*.yaml, spindlesim/decks/*.yaml)
  with one to three mutations of its data (a key deleted or misspelt, a value of the wrong type, an
  extreme number, a long list, deep nesting, a unit mistake) and optionally one of its text (a YAML
  tag, an anchor and alias, a merge key, an alias bomb, deep brackets, a tab, binary garbage, a cut);
* :func:`schema_deck`: a deck drawn from the deck schema itself (every section, key, type and bound
  of ``spindlesim.deck.document.deck_model``).

The oracle (:func:`check_load`, :func:`check_run`) holds what every deck must satisfy: it loads, or
fails with :class:`DeckError` issues that are all located (``file:line:col: ...`` with a message);
an analysis of a loaded deck ends with files (exit 0), a located deck error (exit 2) or one of the
errors the command reports as a message (exit 1); never another exception, and within a time limit.
"""

from __future__ import annotations

import copy
import re
import resource
import signal
import typing
from contextlib import contextmanager
from pathlib import Path
from types import UnionType

import annotated_types as at
import numpy as np
import yaml
from hypothesis import event as _event
from hypothesis.control import currently_in_test_context
from hypothesis import strategies as st
from pydantic import BaseModel

from spindlesim.deck import DeckError, LoadedDeck, parse_deck
from spindlesim.deck.document import deck_model
from spindlesim.deck.limits import MAX_TEXT_CHARS
from spindlesim.deck.yamlmarks import DeckLoader
from spindlesim.fields import unit_range

ROOT = Path(__file__).resolve().parents[2]
DECK_FILES = sorted([*ROOT.glob("decks/*.yaml"), *ROOT.glob("decks/validation/*.yaml"),
                     *ROOT.glob("spindlesim/decks/*.yaml")])
TEXTS = {p.relative_to(ROOT).as_posix(): p.read_text(encoding="utf-8") for p in DECK_FILES}
DATA = {name: yaml.load(text, Loader=DeckLoader) for name, text in TEXTS.items()}

#: seconds for reading one deck ("within seconds") and for one cheap analysis of a loaded deck
PARSE_SECONDS = 10.0
RUN_SECONDS = 120.0
#: the test process may not grow beyond this resident size [MB] ("bounded memory")
MAX_RSS_MB = 3000

#: ``file:line:col: `` then a message (a key path and a message, or a message)
LOCATED = re.compile(r"^(?P<file>.+?):(?P<line>[1-9]\d*):(?P<col>[1-9]\d*): (?P<rest>\S.*)$", re.S)


def event(name: str) -> None:
    """Count an outcome in the Hypothesis statistics (outside a Hypothesis test: nothing)."""
    if currently_in_test_context():
        _event(name)


class Hang(Exception):
    """An example ran past its time limit."""


@contextmanager
def time_limit(seconds: float, what: str):
    """Raise Hang when the code inside uses more than ``seconds`` of this process's CPU time: a loop that does not
    end is caught, a process the machine starves (a loaded CI runner, a niced fuzz run) is not (the wall clock
    made the long fuzz runs fail on a busy machine where the same decks take 0.5 s)."""
    def _alarm(signum, frame):
        raise Hang(f"{what} took more than {seconds:g} s of CPU time")

    old = signal.signal(signal.SIGVTALRM, _alarm)
    signal.setitimer(signal.ITIMER_VIRTUAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_VIRTUAL, 0)
        signal.signal(signal.SIGVTALRM, old)


def rss_mb() -> float:
    """The process's peak resident size [MB]: since the last :func:`reset_peak` where Linux allows resetting it
    (/proc/self/clear_refs, VmHWM), else since it started."""
    try:
        for line in Path("/proc/self/status").read_text().splitlines():
            if line.startswith("VmHWM:"):
                return float(line.split()[1]) / 1024.0
    except (OSError, ValueError, IndexError):
        pass
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


def reset_peak() -> None:
    """Start the peak resident size afresh, so that what is measured is the loader's own (a large deck the
    strategies built before it, in the test's process, is not charged to it)."""
    try:
        Path("/proc/self/clear_refs").write_text("5")
    except OSError:
        pass


def assert_located(text: str) -> None:
    """One printed issue: ``file:line:col: key.path: message`` (or without the key path), never an empty key."""
    m = LOCATED.match(text)
    assert m, f"issue without file:line:col: {text!r}"
    rest = m["rest"]
    assert not rest.startswith(":"), f"issue with an empty key path: {text!r}"
    assert rest.strip(": "), f"issue without a message: {text!r}"


def check_load(text: str, filename: str = "fuzz.yaml") -> LoadedDeck | None:
    """Load ``text``; None when it is refused (after checking every issue is located)."""
    reset_peak()
    with time_limit(PARSE_SECONDS, "reading the deck"):
        try:
            loaded = parse_deck(text, filename)
        except DeckError as exc:
            assert exc.issues, "a DeckError without issues"
            for issue in exc.issues:
                assert issue.file == filename
                assert_located(str(issue))
            event("deck refused")
            return None
    event("deck loaded" + (" with warnings" if loaded.warnings else ""))
    for w in loaded.warnings:
        assert w.severity == "warning"
        assert_located(str(w))
    assert rss_mb() < MAX_RSS_MB, f"resident memory {rss_mb():.0f} MB after reading the deck"
    return loaded


#: what ``commands.common.run_and_report`` turns into a one-line message and exit code 1
REPORTED = (ValueError, ArithmeticError, RuntimeError, np.linalg.LinAlgError)


def check_run(name: str, loaded: LoadedDeck, outdir: Path) -> int:
    """Run analysis ``name`` without plots; the exit code the command would give (0, 1 or 2)."""
    from spindlesim.runs import run_analysis
    from spindlesim.runs.status import IncompleteRun
    from spindlesim.commands.exits import exit_code_of

    with time_limit(RUN_SECONDS, f"the {name} analysis"):
        try:
            run_analysis(name, loaded, outdir, {"plots": False})
            code = 0
        except DeckError as exc:
            assert exc.issues
            for issue in exc.issues:
                assert_located(str(issue))
            code = 2
        except IncompleteRun as exc:
            assert str(exc).strip()
            code = exit_code_of(exc)
        except RecursionError:
            raise
        except REPORTED as exc:
            assert str(exc).strip(), f"{type(exc).__name__} without a message"
            code = 1
    assert rss_mb() < MAX_RSS_MB, f"resident memory {rss_mb():.0f} MB after {name}"
    event(f"{name}: exit code {code}")
    return code


# -- mutations of the example decks -------------------------------------------------------------

EXTREMES = [0, -1, 1, 0.0, -0.0, 1e-300, -1e-300, 1e-9, 1e30, -1e30, 1e308, -1e308, 9.2e18, 9223372036854775807,
            10**30, -(10**30), float("inf"), float("-inf"), float("nan"), 2**53 + 1, 1e15, 1e16, 123456789]


def _paths(data, prefix=()):
    """Every path into ``data`` (tuples of keys and indices), the root excluded."""
    out = []
    stack = [(prefix, data)]
    while stack:
        path, node = stack.pop()
        if isinstance(node, dict):
            items = list(node.items())
        elif isinstance(node, list):
            items = list(enumerate(node[:50]))  # a long list: its first items are enough
        else:
            continue
        for k, v in items:
            out.append(path + (k,))
            stack.append((path + (k,), v))
    return sorted(out, key=lambda p: (len(p), repr(p)))


def _get(data, path):
    for k in path:
        data = data[k]
    return data


def _set(data, path, value):
    _get(data, path[:-1])[path[-1]] = value


def _typo(draw, key: str) -> str:
    if not key:
        return "x"
    i = draw(st.integers(0, len(key) - 1))
    kind = draw(st.sampled_from(["drop", "double", "swap", "upper", "suffix", "other", "empty"]))
    if kind == "drop":
        return key[:i] + key[i + 1:] or "k"
    if kind == "double":
        return key[:i] + key[i] + key[i:]
    if kind == "swap" and len(key) > 1:
        j = min(i + 1, len(key) - 1)
        return key[:i] + key[j] + key[i] + key[j + 1:]
    if kind == "upper":
        return key.upper()
    if kind == "suffix":
        return key + draw(st.sampled_from(["_mm", "_m", "s", "_N_m", "2"]))
    if kind == "empty":
        return ""
    return draw(st.text(min_size=1, max_size=8))


WRONG = st.one_of(
    st.text(max_size=12), st.booleans(), st.none(), st.just([]), st.just({}),
    st.lists(st.integers(-5, 5), max_size=3), st.dictionaries(st.sampled_from(["a", "type", "node"]),
                                                              st.integers(0, 3), max_size=2),
    st.sampled_from(["1e6", "12 mm", "fast", "yes", "0x1F", "1_000", "~", "2001-01-01", ".inf"]),
)


DATA_MUTATIONS = ("delete", "rename", "wrong_type", "extreme", "long_list", "nest", "unit", "copy", "negate")
#: mutations that keep the deck's shape: most such decks still load and run
NUMBER_MUTATIONS = ("extreme", "unit", "negate")


def _mutate_data(draw, data, kinds=DATA_MUTATIONS):
    paths = _paths(data)
    if not paths:
        return draw(WRONG)
    kind = draw(st.sampled_from(kinds))
    path = draw(st.sampled_from(paths))
    parent, key = _get(data, path[:-1]), path[-1]
    value = parent[key]
    if kind == "delete":
        del parent[key]
    elif kind == "rename" and isinstance(parent, dict):
        new = _typo(draw, str(key))
        del parent[key]
        parent[new] = value
    elif kind == "extreme":
        numbers = [p for p in paths if isinstance(_get(data, p), (int, float)) and not isinstance(_get(data, p), bool)]
        if numbers:
            path = draw(st.sampled_from(numbers))
        _set(data, path, draw(st.one_of(st.sampled_from(EXTREMES), st.floats(), st.integers())))
    elif kind == "unit":
        numbers = [p for p in paths if isinstance(_get(data, p), (int, float)) and not isinstance(_get(data, p), bool)]
        if numbers:
            path = draw(st.sampled_from(numbers))
            _set(data, path, _get(data, path) * draw(st.sampled_from([1e-6, 1e-3, 1e3, 1e6])))
    elif kind == "negate":
        numbers = [p for p in paths if isinstance(_get(data, p), (int, float)) and not isinstance(_get(data, p), bool)]
        if numbers:
            path = draw(st.sampled_from(numbers))
            _set(data, path, -_get(data, path))
    elif kind == "long_list":
        lists = [p for p in paths if isinstance(_get(data, p), list) and _get(data, p)]
        if lists:
            path = draw(st.sampled_from(lists))
            items = _get(data, path)
            n = draw(st.sampled_from([20, 201, 501, 1001, 10_000]))
            # bounded: mutations compound (a list of 10,000 copies of a list of 10,000), and building such a deck
            # took the test process to 24 GB before the loader saw it; texts up to twice the loader's limit remain
            per_item = len(repr(items)) / len(items)
            n = min(n, max(20, int(2 * MAX_TEXT_CHARS / max(per_item, 1.0))))
            _set(data, path, [copy.deepcopy(items[i % len(items)]) for i in range(n)])
    elif kind == "nest":
        for _ in range(draw(st.integers(1, 40))):
            value = [value] if draw(st.booleans()) else {"k": value}
        parent[key] = value
    elif kind == "copy":
        other = draw(st.sampled_from(paths))
        parent[key] = copy.deepcopy(_get(data, other))
    else:
        parent[key] = draw(WRONG)
    return data


TAGS = ["!!int", "!!float", "!!bool", "!!str", "!!null", "!!binary", "!!timestamp", "!!set", "!!omap", "!!map",
        "!!seq", "!!python/object/apply:os.getcwd", "!!python/name:os.system", "!custom", "!", "!<tag:x>"]

BOMB = ("x-lol: &l0 [lol, lol, lol, lol, lol, lol, lol, lol, lol, lol]\n"
        + "".join(f"x-lol{i}: &l{i} [" + ", ".join([f"*l{i - 1}"] * 10) + "]\n" for i in range(1, 9)))


def _lines_with_values(text):
    return [i for i, s in enumerate(text.split("\n")) if re.match(r"^\s*(- )?[A-Za-z_][\w.-]*: \S", s)]


def _mutate_text(draw, text: str) -> str:
    lines = text.split("\n")
    kind = draw(st.sampled_from(["tag", "alias", "bad_alias", "merge", "bomb", "brackets", "tab", "garbage",
                                 "cut", "dup_line", "document", "flow"]))
    valued = _lines_with_values(text)
    if kind == "tag" and valued:
        i = draw(st.sampled_from(valued))
        k = lines[i].index(": ") + 2
        lines[i] = lines[i][:k] + draw(st.sampled_from(TAGS)) + " " + lines[i][k:]
    elif kind == "alias" and len(valued) > 1:
        i, j = sorted(draw(st.lists(st.sampled_from(valued), min_size=2, max_size=2, unique=True)))
        k = lines[i].index(": ") + 2
        lines[i] = lines[i][:k] + "&a " + lines[i][k:]
        lines[j] = lines[j][:lines[j].index(": ") + 2] + "*a"
    elif kind == "bad_alias" and valued:
        i = draw(st.sampled_from(valued))
        lines[i] = lines[i][:lines[i].index(": ") + 2] + "*nowhere"
    elif kind == "merge":
        maps = [i for i, s in enumerate(lines) if re.match(r"^\s*[A-Za-z_][\w-]*:\s*$", s)]
        keys = [i for i, s in enumerate(lines) if re.match(r"^\s*[A-Za-z_][\w-]*:", s)]
        if maps and keys:
            i = draw(st.sampled_from(maps))
            j = draw(st.sampled_from(keys))
            lines[i] = lines[i].rstrip() + " &m"
            indent = re.match(r"^\s*", lines[j]).group(0)
            lines.insert(j, f"{indent}<<: {draw(st.sampled_from(['*m', '[*m]', '*m2', '1', '[1, 2]']))}")
    elif kind == "bomb":
        lines.insert(0, BOMB.rstrip("\n"))
        if draw(st.booleans()):
            lines.append("x-boom: [" + ", ".join(["*l8"] * 10) + "]")
    elif kind == "brackets" and valued:
        i = draw(st.sampled_from(valued))
        n = draw(st.sampled_from([10, 33, 100, 1000, 20_000]))
        lines[i] = lines[i][:lines[i].index(": ") + 2] + "[" * n + "1" + "]" * n
    elif kind == "tab":
        indented = [i for i, s in enumerate(lines) if s.startswith("  ")]
        if indented:
            i = draw(st.sampled_from(indented))
            lines[i] = "\t" + lines[i].lstrip(" ")
    elif kind == "garbage":
        pos = draw(st.integers(0, len(text)))
        junk = draw(st.one_of(st.text(max_size=20), st.binary(max_size=20).map(lambda b: b.decode("latin-1")),
                              st.sampled_from(["\x00", "\ufeff", "\x1b[31m", "\\", "\"", "'", "{", "]", "&", "*",
                                               "%YAML 1.1\n", "? ", ": ", "- ", "|\n", ">-\n"])))
        return text[:pos] + junk + text[pos:]
    elif kind == "cut":
        return text[:draw(st.integers(0, len(text)))]
    elif kind == "dup_line" and lines:
        i = draw(st.integers(0, len(lines) - 1))
        lines.insert(i, lines[i])
    elif kind == "document":
        lines.append(draw(st.sampled_from(["---", "...", "--- !!map", "%TAG ! tag:x,2000:"])))
    elif kind == "flow" and valued:
        i = draw(st.sampled_from(valued))
        lines[i] = lines[i][:lines[i].index(": ") + 2] + draw(st.sampled_from(
            ["{a: 1, a: 2}", "[1, 2", "{? [1]: 2}", "{[1, 2]: 3}", "{1: 2}", "{null: 1}", "{true: 1}", "{: 1}",
             "{'': 1}"]))
    return "\n".join(lines)


@st.composite
def mutated_deck(draw, data_mutations=(1, 3), text_mutation: bool = True, kinds=DATA_MUTATIONS,
                 rotor_only: bool = False) -> str:
    names = [n for n in sorted(TEXTS) if not rotor_only or "shaft" in DATA[n] or "journal" in DATA[n]]
    name = draw(st.sampled_from(names))
    data = copy.deepcopy(DATA[name])
    for _ in range(draw(st.integers(*data_mutations))):
        data = _mutate_data(draw, data, kinds)
    text = yaml.safe_dump(data, sort_keys=False, allow_unicode=True, width=120)
    if text_mutation and draw(st.booleans()):
        text = _mutate_text(draw, text)
    return text


@st.composite
def text_mutated_deck(draw) -> str:
    """An example deck as written (comments and all) with one or two text mutations."""
    text = TEXTS[draw(st.sampled_from(sorted(TEXTS)))]
    for _ in range(draw(st.integers(1, 2))):
        text = _mutate_text(draw, text)
    return text


# -- decks from the schema ------------------------------------------------------------------------

#: deck paths a sweep may vary (keys of sweep.parameters)
SWEEP_PATHS = ["operating.speed_rpm", "bearings.0.K_N_m.0.0", "shaft.elements.0.0", "modal.modes", "nowhere.x", ""]


def _metadata(ann):
    meta = []
    while typing.get_origin(ann) is typing.Annotated:
        ann, *extra = typing.get_args(ann)
        for e in extra:
            meta += list(getattr(e, "metadata", [])) if hasattr(e, "metadata") else [e]
    return ann, meta


_BOUND_ATTR = {at.Ge: "ge", at.Gt: "gt", at.Le: "le", at.Lt: "lt", at.MinLen: "min_length", at.MaxLen: "max_length"}


def _bound(meta, kinds, default):
    for m in meta:
        for k in kinds:
            if isinstance(m, k):
                return float(getattr(m, _BOUND_ATTR[k]))
    return default


def _number(name: str, ann, meta):
    lo = _bound(meta, (at.Ge, at.Gt), None)
    hi = _bound(meta, (at.Le, at.Lt), None)
    unit = unit_range(name)
    if unit is not None:
        ulo, uhi = unit[1]
        lo = ulo if lo is None else max(lo, ulo)
        hi = uhi if hi is None else min(hi, uhi)
    if ann is int:
        lo_i = int(lo) if lo is not None else -10
        hi_i = int(hi) if hi is not None else lo_i + 100
        return st.integers(lo_i, min(hi_i, lo_i + 60))
    lo = -1e6 if lo is None else lo
    hi = 1e6 if hi is None else hi
    typical = [v for v in (0.0, 0.3, 1.0, 10.0, 50.0, 100.0, 1e3, 7850.0, 2e5, 1e8) if lo <= v <= hi]
    return st.one_of(st.floats(lo, hi, allow_nan=False), st.sampled_from(typical or [lo]))


def _strategy(name: str, ann, meta, depth: int = 0):
    ann, more = _metadata(ann)
    meta = meta + more
    origin = typing.get_origin(ann)
    if origin in (typing.Union, UnionType):
        return st.one_of([_strategy(name, a, meta, depth) for a in typing.get_args(ann)])
    if origin is typing.Literal:
        return st.sampled_from(typing.get_args(ann))
    if ann is type(None):
        return st.none()
    if ann is bool:
        return st.booleans()
    if ann is str:
        return st.sampled_from(["front", "rear", "a", "b", "static", "modal", "campbell", "frf", "x"]) \
            | st.text(max_size=6)
    if ann in (int, float):
        return _number(name, ann, meta)
    if ann is typing.Any:
        return st.one_of(st.floats(-1e6, 1e6), st.integers(-10, 10), st.text(max_size=4))
    if origin is list:
        (item,) = typing.get_args(ann)
        lo = int(_bound(meta, (at.MinLen,), 0))
        hi = min(int(_bound(meta, (at.MaxLen,), 4)), lo + 4)
        return st.lists(_strategy(name, item, [], depth + 1), min_size=lo, max_size=hi)
    if origin is dict:
        _, value = typing.get_args(ann)
        return st.dictionaries(st.sampled_from(SWEEP_PATHS), _strategy(name, value, [], depth + 1),
                               min_size=1, max_size=2)
    if isinstance(ann, type) and issubclass(ann, BaseModel):
        return model_strategy(ann, depth + 1)
    raise TypeError(f"no strategy for {name}: {ann!r}")


_MODELS: dict[type, st.SearchStrategy] = {}


def model_strategy(model: type[BaseModel], depth: int = 0) -> st.SearchStrategy:
    """Mappings of ``model``'s keys: the required ones always, each optional one maybe."""
    if model not in _MODELS:
        required, optional = {}, {}
        for key, f in model.model_fields.items():
            s = _strategy(key, f.annotation, list(f.metadata), depth)
            (required if f.is_required() else optional)[key] = s
        _MODELS[model] = st.fixed_dictionaries(required, optional=optional)
    return _MODELS[model]


@st.composite
def schema_deck(draw) -> str:
    """A deck drawn from the schema: a few of its top-level sections, each drawn from its model."""
    model = deck_model()
    names = draw(st.lists(st.sampled_from(sorted(model.model_fields)), min_size=1, max_size=6, unique=True))
    data = {}
    for key in names:
        f = model.model_fields[key]
        data[key] = draw(_strategy(key, f.annotation, list(f.metadata)))
    return yaml.safe_dump(data, sort_keys=False, allow_unicode=True, width=120)
