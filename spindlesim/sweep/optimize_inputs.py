"""The ``optimize:`` section checked before anything is computed: every variable's path, bounds or values (the
deck must accept each bound and each value), every tied path, every objective's and constraint's name and the
sections it needs; each problem a located deck issue naming the entry (``DeckError``, exit 2)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import yaml

SECTION = "optimize"


@dataclass(frozen=True)
class Variable:
    """A deck value chosen: continuous in [lower, upper], or one of ``choices``; ``initial`` the deck's value;
    ``tied``: (path, factor, deck value) moved with it."""

    path: str
    lower: float
    upper: float
    initial: Any
    choices: tuple | None = None
    tied: tuple[tuple[str, float, float], ...] = ()

    @property
    def discrete(self) -> bool:
        return self.choices is not None

    def deck_values(self, value) -> dict[str, Any]:
        """Every deck path this variable sets, at ``value``."""
        out = {self.path: value}
        for path, factor, base in self.tied:
            out[path] = base + factor * (float(value) - float(self.initial))
        return out


@dataclass(frozen=True)
class Goal:
    """An objective: a named result, +1 to maximize, -1 to minimize."""

    name: str
    sense: int

    @property
    def label(self) -> str:
        return f"{'maximize' if self.sense > 0 else 'minimize'} {self.name}"


@dataclass(frozen=True)
class Bound:
    """A constraint: lower <= named result <= upper (None: no such side)."""

    name: str
    lower: float | None
    upper: float | None

    @property
    def label(self) -> str:
        lo = "" if self.lower is None else f"{self.lower:g} <= "
        hi = "" if self.upper is None else f" <= {self.upper:g}"
        return f"{lo}{self.name}{hi}"


@dataclass(frozen=True)
class Problem:
    variables: tuple[Variable, ...]
    objectives: tuple[Goal, ...]
    constraints: tuple[Bound, ...]
    budget: int
    seed: int

    @property
    def names(self) -> tuple[str, ...]:
        """Every named result an evaluation computes, objectives first."""
        seen: dict[str, None] = {}
        for n in [g.name for g in self.objectives] + [c.name for c in self.constraints]:
            seen.setdefault(n, None)
        return tuple(seen)

    @property
    def discrete(self) -> bool:
        return any(v.discrete for v in self.variables)


def _refused(loaded, path: str, value) -> str:
    """The deck's first objection to ``path`` = ``value`` ("" : accepted)."""
    from ..deck import DeckError, parse_deck
    from ..deck.paths import replace_in_text

    try:
        parse_deck(replace_in_text(loaded.text, {path: value}), loaded.source)
    except KeyError as exc:
        return str(exc.args[0])
    except DeckError as exc:
        return exc.issues[0].message
    return ""


def _number(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def _check_path(loaded, data, at, path: str, issues: list, what: str):
    """The deck's value at ``path``, or None with an issue."""
    from ..deck.paths import get_path

    if path.split(".")[0] in (SECTION, "sweep", "calibration"):
        issues.append(loaded.issue(at, f"{path}: a study's own settings are not a model value"))
        return None
    try:
        return get_path(data, path)
    except KeyError as exc:
        issues.append(loaded.issue(at, f"{exc.args[0]} ({what} {path})"))
        return None


def _variable(loaded, data, i, v, issues: list) -> Variable | None:
    at = (SECTION, "variables", i)
    value = _check_path(loaded, data, at + ("path",), v.path, issues, "optimize variable")
    if value is None:
        return None
    if v.values is not None:
        for k, choice in enumerate(v.values):
            why = _refused(loaded, v.path, choice)
            if why:
                issues.append(loaded.issue(at + ("values", k), f"the deck refuses {v.path} = {choice}: {why}"))
                return None
        return Variable(v.path, 0.0, float(len(v.values) - 1), value, tuple(v.values))
    if not _number(value):
        issues.append(loaded.issue(at + ("path",), f"{v.path} holds {value!r}, not a number"))
        return None
    if not v.min < v.max:
        issues.append(loaded.issue(at + ("max",), f"max {v.max:g} must be greater than min {v.min:g}"))
        return None
    tied = []
    for k, t in enumerate(v.tied):
        base = _check_path(loaded, data, at + ("tied", k, "path"), t.path, issues, "tied value")
        if base is None:
            return None
        if not _number(base):
            issues.append(loaded.issue(at + ("tied", k, "path"), f"{t.path} holds {base!r}, not a number"))
            return None
        tied.append((t.path, float(t.factor), float(base)))
    var = Variable(v.path, float(v.min), float(v.max), float(value), None, tuple(tied))
    for bound, key in ((v.min, "min"), (v.max, "max")):  # the deck must accept each bound, tied values included
        from ..deck import DeckError, parse_deck
        from ..deck.paths import replace_in_text

        try:
            parse_deck(replace_in_text(loaded.text, var.deck_values(float(bound))), loaded.source)
        except KeyError as exc:
            issues.append(loaded.issue(at + ("path",), str(exc.args[0])))
            return None
        except DeckError as exc:
            issues.append(loaded.issue(at + (key,), f"the deck refuses {v.path} = {bound:g}: "
                                                    f"{exc.issues[0].message}"))
            return None
    return var


def _name_issue(loaded, at, name: str) -> str:
    from .named_results import NAMED_RESULTS, missing_sections

    if name not in NAMED_RESULTS:
        return f"{name!r} is not a named result; one of {', '.join(NAMED_RESULTS)}"
    lacks = missing_sections(loaded, name)
    return f"{name} needs {lacks}; the deck has none" if lacks else ""


def check_problem(loaded: Any) -> Problem:
    """The section as a :class:`Problem`; DeckError listing every problem."""
    from ..deck import DeckError
    from ..deck.yamlmarks import DeckLoader

    sec = loaded.deck.optimize
    data = yaml.load(loaded.text, Loader=DeckLoader)
    issues: list = []
    variables, seen = [], {}
    for i, v in enumerate(sec.variables):
        for p in (v.path, *(t.path for t in v.tied)):
            if p in seen:
                issues.append(loaded.issue((SECTION, "variables", i, "path"),
                                           f"{p} is set twice (also by variables[{seen[p]}])"))
            seen[p] = i
        var = _variable(loaded, data, i, v, issues)
        if var is not None:
            variables.append(var)
    goals = []
    for i, o in enumerate(sec.objectives):
        key, name = ("maximize", o.maximize) if o.maximize is not None else ("minimize", o.minimize)
        why = _name_issue(loaded, (SECTION, "objectives", i, key), name)
        if why:
            issues.append(loaded.issue((SECTION, "objectives", i, key), why))
        goals.append(Goal(name, 1 if key == "maximize" else -1))
    if len({g.name for g in goals}) < len(goals):
        issues.append(loaded.issue((SECTION, "objectives"), "an objective is given twice"))
    bounds = []
    for i, c in enumerate(sec.constraints):
        why = _name_issue(loaded, (SECTION, "constraints", i, "name"), c.name)
        if why:
            issues.append(loaded.issue((SECTION, "constraints", i, "name"), why))
        bounds.append(Bound(c.name, None if c.min is None else float(c.min), None if c.max is None else float(c.max)))
    if issues:
        raise DeckError(issues)
    return Problem(tuple(variables), tuple(goals), tuple(bounds), int(sec.budget), int(sec.seed))
