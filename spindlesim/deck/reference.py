"""The deck key reference, docs/deck-reference.md, written from the deck's JSON schema.

One table per section: every key with its type, unit, default, range and description.  The
descriptions are the docstrings written under the keys in the deck models
(:class:`spindlesim.fields.DeckJsonSchema`); the unit is the one the key's name ends with and the
range joins the key's own bounds with the physical range of that unit
(:data:`spindlesim.fields.UNIT_RANGES`).  Nothing here is written by hand, so the reference cannot
drift from the code: ``tests/unit/test_deck_reference.py`` compares the file with
:func:`deck_reference`.  Regenerate it with::

    spindlesim schema --markdown -o docs/deck-reference.md
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from typing import Any

from ..fields import unit_range, unit_text

#: the command that writes docs/deck-reference.md (named by the test when the file is stale)
REGENERATE = "spindlesim schema --markdown -o docs/deck-reference.md"
#: the shared {start, stop, count} model, documented once instead of under every key that uses it
RANGE = "Range"

Schema = dict[str, Any]


@dataclass(frozen=True)
class Row:
    key: str
    type: str
    unit: str
    default: str
    range: str
    description: str


def deck_schema() -> Schema:
    """The deck's JSON schema, as ``spindlesim schema`` writes it."""
    from .document import deck_model

    schema = deck_model().model_json_schema()
    schema.setdefault("title", "spindlesim deck")
    return schema


def _number(v: float) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int) or (isinstance(v, float) and v.is_integer() and abs(v) < 1e6):
        return str(int(v))
    text = f"{v:.6g}"
    return text.replace("e+0", "e").replace("e+", "e").replace("e-0", "e-")


def _flow(v: Any) -> str:
    """A default value as YAML flow text."""
    if v is None:
        return "null"
    if isinstance(v, (bool, int, float)):
        return _number(v)
    if isinstance(v, str):
        return v
    if isinstance(v, list):
        return "[" + ", ".join(_flow(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{k}: {_flow(x)}" for k, x in v.items()) + "}"
    return json.dumps(v)


def _cell(text: str) -> str:
    return " ".join(str(text).split()).replace("|", "\\|")


class _Walker:
    def __init__(self, schema: Schema):
        self.defs: dict[str, Schema] = schema.get("$defs", {})

    # -- schema nodes ------------------------------------------------------------------------
    def ref_name(self, node: Schema) -> str | None:
        ref = node.get("$ref")
        return ref.rsplit("/", 1)[-1] if isinstance(ref, str) else None

    def resolve(self, node: Schema) -> Schema:
        name = self.ref_name(node)
        return self.defs[name] if name is not None else node

    def alternatives(self, node: Schema) -> list[Schema]:
        """The members of a union (``null`` left out), or the node itself."""
        for key in ("anyOf", "oneOf"):
            if key in node:
                out: list[Schema] = []
                for member in node[key]:
                    if member.get("type") != "null":
                        out += self.alternatives(member)
                return out
        return [node]

    def is_model(self, node: Schema) -> bool:
        name = self.ref_name(node)
        return name is not None and name != RANGE and "properties" in self.defs[name]

    # -- columns -----------------------------------------------------------------------------
    def type_text(self, node: Schema) -> str:
        texts = []
        for alt in self.alternatives(node):
            name = self.ref_name(alt)
            if name == RANGE:
                texts.append("range")
                continue
            alt = self.resolve(alt)
            if "const" in alt:
                texts.append(f"`{_flow(alt['const'])}`")
            elif "enum" in alt:
                texts.append(", ".join(f"`{_flow(v)}`" for v in alt["enum"]))
            elif alt.get("type") == "array":
                inner = self.type_text(alt.get("items", {}))
                n = alt.get("minItems")
                texts.append(f"[{inner} × {n}]" if n is not None and n == alt.get("maxItems") else f"list of {inner}")
            elif alt.get("type") == "object" and "properties" not in alt:
                extra = alt.get("additionalProperties")
                texts.append("mapping" + (f" of text to {self.type_text(extra)}" if isinstance(extra, dict) else ""))
            elif "properties" in alt:
                texts.append("mapping")
            else:
                texts.append({"number": "number", "integer": "integer", "string": "text", "boolean": "true or false"}
                             .get(alt.get("type", ""), "any value"))
        return " or ".join(dict.fromkeys(texts))

    def range_text(self, node: Schema, key: str) -> str:
        unit = unit_range(key)
        texts = [t for t in (self._range(self.resolve(alt), unit and unit[1], alt)
                             for alt in self.alternatives(node)) if t]
        return "; ".join(dict.fromkeys(texts))

    def _range(self, node: Schema, unit: tuple[float, float] | None, alt: Schema) -> str:
        kind = node.get("type")
        if self.ref_name(alt) == RANGE:  # start >= 0 (fields.Range), within the unit's range
            return "" if unit is None else f"ends in [{_number(max(0.0, unit[0]))}, {_number(unit[1])}]"
        if kind == "array":
            n_lo, n_hi = node.get("minItems"), node.get("maxItems")
            count = (f"{n_lo} items" if n_lo == n_hi and n_lo is not None else
                     f"{n_lo or 0} .. {n_hi} items" if n_hi is not None else
                     f"at least {n_lo} items" if n_lo else "")
            each = self._range(self.resolve(node.get("items", {})), unit, node.get("items", {}))
            return ", ".join(t for t in (count, f"each {each}" if each else "") if t)
        if kind == "string":
            n_lo, n_hi = node.get("minLength"), node.get("maxLength")
            return f"{n_lo} .. {n_hi} characters" if n_lo and n_hi else f"at least {n_lo} character" if n_lo else ""
        if kind not in ("number", "integer"):
            return ""
        bounds = [(node.get("minimum"), True), (node.get("exclusiveMinimum"), False)]
        lo, lo_in = max(((v, inc) for v, inc in bounds if v is not None), default=(-math.inf, False),
                        key=lambda b: (b[0], not b[1]))
        bounds = [(node.get("maximum"), True), (node.get("exclusiveMaximum"), False)]
        hi, hi_in = min(((v, inc) for v, inc in bounds if v is not None), default=(math.inf, False),
                        key=lambda b: (b[0], b[1]))
        if unit is not None and kind == "number":  # the physical range of the key's unit applies too
            if unit[0] > lo:
                lo, lo_in = unit[0], True
            if unit[1] < hi:
                hi, hi_in = unit[1], True
        if lo == -math.inf and hi == math.inf:
            return ""
        if hi == math.inf:
            return f"{'>=' if lo_in else '>'} {_number(lo)}"
        if lo == -math.inf:
            return f"{'<=' if hi_in else '<'} {_number(hi)}"
        return f"{'[' if lo_in else '('}{_number(lo)}, {_number(hi)}{']' if hi_in else ')'}"

    def default_text(self, prop: Schema, required: bool) -> str:
        if required:
            return "required"
        if "default" not in prop:
            return ""
        value = prop["default"]
        if isinstance(value, dict) and any(self.is_model(a) for a in self.alternatives(prop)):
            return "(keys below)"
        return "none" if value is None else f"`{_flow(value)}`"

    # -- rows --------------------------------------------------------------------------------
    def row(self, path: str, key: str, prop: Schema, required: bool, note: str = "", outer: str = "") -> Row:
        """``outer``: the key of the mapping this key is in; its unit applies to ``start`` and ``stop``
        (the unit check of a key reads the ends of the range under it: fields.DeckModel)."""
        named = key if unit_range(key) is not None or key not in ("start", "stop") else outer
        unit = unit_range(named)
        return Row(path, self.type_text(prop), unit_text(unit[0]) if unit else "—",
                   self.default_text(prop, required), self.range_text(prop, named),
                   note + prop.get("description", ""))

    def rows(self, model: Schema, prefix: str, skip: tuple[str, ...] = (), note: str = "",
             outer: str = "") -> list[Row]:
        out: list[Row] = []
        required = set(model.get("required", ()))
        for key, prop in model.get("properties", {}).items():
            if key in skip:
                continue
            path = f"{prefix}{key}"
            out.append(self.row(path, key, prop, key in required, note, outer))
            out += self.children(prop, path, note, key)
        return out

    def members(self, node: Schema) -> list[Schema]:
        """The members of a union (``null`` left out) with a tagged union kept whole, or the node itself."""
        if "discriminator" in node:
            return [node]
        for key in ("anyOf", "oneOf"):
            if key in node:
                return [m for member in node[key] if member.get("type") != "null" for m in self.members(member)]
        return [node]

    def children(self, prop: Schema, path: str, note: str = "", key: str = "") -> list[Row]:
        """Rows of the keys under ``prop``: a mapping's keys, a list's items (``[]``), a tagged union's."""
        out: list[Row] = []
        for alt in self.members(prop):
            node = self.resolve(alt)
            if node.get("type") == "array":
                out += self.children(node.get("items", {}), path + "[]", note)
            elif node.get("type") == "object" and isinstance(node.get("additionalProperties"), dict):
                out += self.children(node["additionalProperties"], path + ".PATH", note)
            elif "discriminator" in alt:
                out += self.tagged(alt, path, note)
            elif self.is_model(alt):
                form = f"(form {{{', '.join(node['properties'])}}}) " if len(self.members(prop)) > 1 else ""
                out += self.rows(node, f"{path}.", note=note + form, outer=key)
        return out

    def tagged(self, union: Schema, path: str, note: str = "") -> list[Row]:
        """A union told apart by one key (``kind``, ``type``): that key once, then each member's keys."""
        tag = union["discriminator"]["propertyName"]
        members = [self.resolve(m) for m in union.get("oneOf", union.get("anyOf", []))]
        first = members[0]["properties"][tag]
        tags = ", ".join(f"`{_flow(m['properties'][tag].get('const'))}`" for m in members)
        rows = [Row(f"{path}.{tag}", tags, "—", "required", "", note + first.get("description", ""))]
        for m in members:
            value = _flow(m["properties"][tag].get("const"))
            rows += self.rows(m, f"{path}.", skip=(tag,), note=f"{note}({tag} `{value}`) ")
        return rows


HEADER = """# Deck key reference

<!-- Generated from the deck models by `{regenerate}`; do not edit: tests/unit/test_deck_reference.py
     fails when this file and the models disagree. -->

Every key a deck can hold, section by section, generated from the deck's JSON schema (`spindlesim schema`),
whose descriptions are the docstrings written under the keys in the deck models. docs/deck-format.md is the
guide with an example of each section; this file is the complete list.

Columns: **type** (`a`, `b`: one of these words; mapping: keys below; range: `{{start, stop, count}}`, see
[Ranges](#ranges)); **unit**: the unit the key's name ends with, which applies to its values (list items and
range ends included; — : the name carries no unit: a count, a ratio, a choice; the description says when a
unit applies all the same); **default**: the value when the key is left out (required: it must be given;
none: the key is absent, and the description says what that means); **range**: the values accepted, `[a, b]`
with its ends, `(a, b)` without, joined with the physical range of the unit (docs/deck-format.md, "Values,
warnings and `--strict`"); checks between keys are in the descriptions.
"""


def _table(rows: list[Row]) -> list[str]:
    lines = ["| key | type | unit | default | range | description |", "|---|---|---|---|---|---|"]
    for r in rows:
        lines.append("| " + " | ".join(_cell(c) for c in (f"`{r.key}`", r.type, r.unit, r.default, r.range,
                                                              r.description)) + " |")
    return lines


def deck_reference(schema: Schema | None = None) -> str:
    """The Markdown reference of every deck key (docs/deck-reference.md) from the deck's JSON schema."""
    schema = deck_schema() if schema is None else schema
    w = _Walker(schema)
    out = [HEADER.format(regenerate=REGENERATE)]
    top = schema["properties"]
    required = set(schema.get("required", ()))
    out += ["## Top-level keys", ""]
    out += _table([w.row(k, k, p, k in required) for k, p in top.items()])
    for key, prop in top.items():
        items = w.resolve(prop).get("items", {})
        if "discriminator" in items:  # bearings: one table per type
            tag = items["discriminator"]["propertyName"]
            for member in items.get("oneOf", []):
                m = w.resolve(member)
                value = _flow(m["properties"][tag].get("const"))
                first = w.row(f"{key}[].{tag}", tag, m["properties"][tag], True)
                out += ["", f"## `{key}:` entry `{tag}: {value}`", "", _cell(first.description), ""]
                out += _table([first] + w.rows(m, f"{key}[].", skip=(tag,)))
            continue
        rows = w.children(prop, key, key=key)
        if rows:
            out += ["", f"## `{key}:`", "", _cell(prop.get("description", "")), ""]
            out += _table(rows)
    out += ["", "## Ranges", "", _cell(w.defs[RANGE].get("description", "")), ""]
    out += _table(w.rows(w.defs[RANGE], "range."))
    return "\n".join(out) + "\n"
