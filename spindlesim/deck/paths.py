"""Deck values by key path: ``tool.joint.translational_N_m``, ``bearings.front.K_N_m.0.0``, ``shaft.elements.3.2``
(mapping keys by name, list items by 0-based index or by the ``name`` of a named item), in the deck's data
(``get_path``, ``set_path``: what ``sweep``, ``calibrate`` and ``optimize`` change) and in its text
(``replace_in_text``: new values written in place, the rest of the text, its comments and layout as written, so a
calibrated deck diffs against the original).  The text is composed by PyYAML (node positions), each scalar
replaced where it stands.
"""

from __future__ import annotations

from typing import Any

import yaml

from .yamlmarks import DeckLoader


def list_index(items: list, part: str, where: str) -> int:
    """The index of path part ``part`` in a list: an integer (negative from the end) or the ``name`` of an item."""
    if part.lstrip("-").isdigit():
        idx = int(part)
        if not -len(items) <= idx < len(items):
            raise KeyError(f"{where}: index out of range (list has {len(items)} items)")
        return idx
    named = [i for i, it in enumerate(items) if isinstance(it, dict) and it.get("name") == part]
    if not named:
        raise KeyError(f"{where}: no item named {part!r}")
    return named[0]


def set_path(data: Any, path: str, value: Any) -> None:
    """Set ``value`` at dotted ``path`` in the YAML data (in place); raise KeyError naming the bad part.

    A mapping the path passes through that the deck leaves out (a key with a default, e.g. a bearing's
    ``damping``) is created empty: the deck is validated before it is used, so a misspelt key is still
    reported there."""
    parts = path.split(".")
    cur = data
    for i, part in enumerate(parts):
        last = i == len(parts) - 1
        where = ".".join(parts[: i + 1])
        if isinstance(cur, dict):
            if last:
                cur[part] = value
                return
            if part not in cur or cur[part] is None:
                cur[part] = {}
            cur = cur[part]
        elif isinstance(cur, list):
            idx = list_index(cur, part, where)
            if last:
                cur[idx] = value
                return
            cur = cur[idx]
        else:
            raise KeyError(f"{where}: cannot descend into a {type(cur).__name__}")


def get_path(data: Any, path: str) -> Any:
    """The value at dotted ``path`` of the deck data; KeyError naming the part that is not there."""
    cur = data
    parts = path.split(".")
    for i, part in enumerate(parts):
        where = ".".join(parts[: i + 1])
        if isinstance(cur, dict):
            if part not in cur:
                raise KeyError(f"{where}: no such key in the deck")
            cur = cur[part]
        elif isinstance(cur, list):
            cur = cur[list_index(cur, part, where)]
        else:
            raise KeyError(f"{where}: cannot descend into a {type(cur).__name__}")
    return cur


def _node_at(root: yaml.Node, path: str) -> yaml.ScalarNode:
    cur = root
    parts = path.split(".")
    for i, part in enumerate(parts):
        where = ".".join(parts[: i + 1])
        if isinstance(cur, yaml.MappingNode):
            hit = [v for k, v in cur.value if isinstance(k, yaml.ScalarNode) and k.value == part]
            if not hit:
                raise KeyError(f"{where}: not written in the deck text (a merged or default value cannot be edited "
                               "in place)")
            cur = hit[0]
        elif isinstance(cur, yaml.SequenceNode):
            names = [next((v.value for k, v in it.value if isinstance(k, yaml.ScalarNode) and k.value == "name"), None)
                     if isinstance(it, yaml.MappingNode) else None for it in cur.value]
            items = [{"name": n} if n is not None else None for n in names]
            cur = cur.value[list_index(items, part, where)]
        else:
            raise KeyError(f"{where}: cannot descend into a scalar")
    if not isinstance(cur, yaml.ScalarNode):
        raise KeyError(f"{path}: not a single value")
    return cur


def number_text(value: float, digits: int = 6) -> str:
    """A float as the deck writes numbers: ``digits`` significant digits (17: exact), an exponent YAML 1.2 reads
    (4.12e+08)."""
    v = float(value)
    text = f"{v:.{digits}g}"
    if "e" not in text and "." not in text:
        text += ".0"
    return text


def _scalar_text(value, digits: int) -> str:
    if isinstance(value, str):
        return '"' + value.replace("\\", "\\\\").replace('"', '\\"') + '"'
    return number_text(value, digits)


def replace_in_text(text: str, values: dict[str, float | str], digits: int = 6) -> str:
    """``text`` with the scalar at each path replaced by its new value (a number as ``number_text`` with
    ``digits`` significant digits, a string double-quoted), nothing else changed.

    KeyError: a path that is not written in the text, or whose value is shared through an anchor (editing it
    would change every alias)."""
    root = yaml.compose(text, Loader=DeckLoader)
    seen: dict[int, int] = {}
    stack = [root]
    while stack:  # how often each node object appears: an alias is the anchored node itself
        n = stack.pop()
        seen[id(n)] = seen.get(id(n), 0) + 1
        if seen[id(n)] == 1:
            if isinstance(n, yaml.MappingNode):
                stack.extend(v for kv in n.value for v in kv)
            elif isinstance(n, yaml.SequenceNode):
                stack.extend(n.value)
    spans = []
    for path, value in values.items():
        node = _node_at(root, path)
        if seen.get(id(node), 0) > 1:
            raise KeyError(f"{path}: the value is shared through an anchor (editing it would change every alias)")
        spans.append((node.start_mark.index, node.end_mark.index, _scalar_text(value, digits)))
    out = text
    for start, end, new in sorted(spans, reverse=True):
        out = out[:start] + new + out[end:]
    return out
