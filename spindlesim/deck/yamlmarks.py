"""YAML to plain Python objects while recording where every key path sits in the file.

PyYAML's composer gives nodes with start marks; we build the objects ourselves so
that duplicate keys are caught (PyYAML silently keeps the last one) and so that
pydantic's error locations can be mapped back to ``line:col``.
"""

from __future__ import annotations

from typing import Any

import re

import yaml

from .errors import DeckIssue

Path = tuple[Any, ...]


class DeckLoader(yaml.SafeLoader):
    """SafeLoader that also reads YAML 1.2 floats such as ``412.62e6`` (YAML 1.1 needs ``e+6``)."""


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


def _construct(node: yaml.ScalarNode) -> Any:
    loader = DeckLoader("")
    try:
        return loader.construct_object(node, deep=True)
    finally:
        loader.dispose()


def load_with_marks(text: str, filename: str) -> tuple[Any, dict[Path, tuple[int, int]], list[DeckIssue]]:
    """Parse ``text``; return (data, marks, issues).

    ``marks`` maps a key path (tuple of str keys and int indices) to the 1-based
    (line, col) of that key (for mapping entries) or item (for sequences).
    """
    issues: list[DeckIssue] = []
    marks: dict[Path, tuple[int, int]] = {}
    try:
        root = yaml.compose(text, Loader=DeckLoader)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None) or getattr(exc, "context_mark", None)
        line, col = (mark.line + 1, mark.column + 1) if mark is not None else (1, 1)
        problem = getattr(exc, "problem", None) or str(exc)
        issues.append(DeckIssue(filename, line, col, "", f"invalid YAML: {problem}"))
        return None, marks, issues
    if root is None:
        issues.append(DeckIssue(filename, 1, 1, "", "the deck is empty"))
        return None, marks, issues

    def pos(node: yaml.Node) -> tuple[int, int]:
        return node.start_mark.line + 1, node.start_mark.column + 1

    def build(node: yaml.Node, path: Path) -> Any:
        if isinstance(node, yaml.MappingNode):
            out: dict[Any, Any] = {}
            for key_node, value_node in node.value:
                key = _construct(key_node) if isinstance(key_node, yaml.ScalarNode) else str(key_node.value)
                child = path + (key,)
                if key in out:
                    first = marks.get(child, (0, 0))
                    issues.append(
                        DeckIssue(filename, *pos(key_node), ".".join(map(str, child)),
                                  f"duplicate key (first defined on line {first[0]})")
                    )
                    continue
                marks[child] = pos(key_node)
                out[key] = build(value_node, child)
            return out
        if isinstance(node, yaml.SequenceNode):
            items = []
            for i, item in enumerate(node.value):
                marks[path + (i,)] = pos(item)
                items.append(build(item, path + (i,)))
            return items
        return _construct(node)

    marks[()] = pos(root)
    return build(root, ()), marks, issues


def locate(marks: dict[Path, tuple[int, int]], path: Path) -> tuple[int, int]:
    """Line and column of the deepest recorded prefix of ``path``."""
    for n in range(len(path), -1, -1):
        if tuple(path[:n]) in marks:
            return marks[tuple(path[:n])]
    return 1, 1
