"""The vocabulary of deck keys: the pydantic base model and the number types every deck section uses.

A leaf module (it imports only pydantic), so that a bearing family or the contact solver can
define its own deck section next to its physics without importing the deck loader
(docs/decisions.md, "Layers").  Key names carry their units (``length_mm``, ``E_GPa``); the
conversion to SI happens in one builder per section.

Every float is finite: ``.inf`` and ``.nan`` are refused at validation with the key's line.
Every number is also within a physical range: a key whose name ends in a unit (``_mm``,
``_GPa``, ``_rpm`` ...) is checked against :data:`UNIT_RANGES` (a field validator of
:class:`DeckModel`, so every section gets it), and a key without a unit has its bounds in its
own ``Field``.  ``tests/unit/test_deck_limits.py`` walks the schema to keep it that way.

Every key is documented by the docstring written under it (an attribute docstring)::

    balls: Annotated[int, Field(ge=3, le=1000)]
    '''Number of balls in each row.'''

:class:`DeckJsonSchema` puts these into the JSON schema as the keys' descriptions when a schema is
generated (``spindlesim schema``), and ``docs/deck-reference.md`` is generated from that schema
(``spindlesim schema --markdown``); ``tests/unit/test_deck_reference.py`` checks that every key has
one.  They are read from the source only then, not when the classes are created (pydantic's
``use_attribute_docstrings`` would read the source of every model at each start: docs/decisions.md).
"""

from __future__ import annotations

import ast
import inspect
import logging
import sys
from functools import lru_cache
from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationInfo, field_validator
from pydantic.json_schema import GenerateJsonSchema

log = logging.getLogger(__name__)

#: largest magnitude of a number that has no unit (sweep values, range ends; their key's unit applies too)
ANY_NUMBER = 1e15

#: physical range (smallest, largest) of a value by the unit its key ends with; the longest suffix wins.
#: Wide on purpose: these catch impossible numbers (E_GPa 1e30, a speed of 1e12 rpm); the plausibility
#: warnings (deck/plausibility.py) catch the likely unit mistakes inside them.
UNIT_RANGES: dict[str, tuple[float, float]] = {
    "_mm": (-1e10, 1e10),           # up to 1e10 mm: a crown radius of 1e9 mm is a straight roller
    "_um": (-1e5, 1e5),             # up to 0.1 m
    "_GPa": (1e-4, 2e3),            # 0.1 MPa (soft elastomer) .. above diamond
    "_kg_m3": (0.0, 1e5),
    "_kg": (0.0, 1e6),
    "_kg_m2": (0.0, 1e6),
    "_N": (-1e9, 1e9),
    "_Nm": (-1e9, 1e9),
    "_N_mm2": (0.0, 1e6),           # specific cutting forces
    "_rpm": (-1e6, 1e6),
    "_hz": (0.0, 1e9),
    "_s": (0.0, 1e5),
    "_us": (0.0, 1e6),
    "_N_m": (-1e13, 1e13),          # stiffness
    "_Ns_m": (-1e10, 1e10),         # damping
    "_Nm_rad": (0.0, 1e12),
    "_Nms_rad": (0.0, 1e9),
    "_Ns_mm": (0.0, 1e7),
    "_N_m2": (0.0, 1e15),           # stiffness per metre of bore
    "_Ns_m2": (0.0, 1e13),
    "_N_per_m_n": (0.0, 1e14),      # Hertz constant K of Q = K delta^n
    "_m_s": (0.0, 1e4),
    "_m_s2": (0.0, 1e4),
    "_Pa_s": (0.0, 1e3),
    "_J_kgK": (0.0, 1e5),
    "_C": (-273.15, 2000.0),
    "_m2": (0.0, 1e4),
    "_W_m2K": (0.0, 1e6),
    "_deg": (-1e4, 1e4),
    "_mrad": (-1e3, 1e3),           # held tilts of a bearing ring
    "_g_mm": (0.0, 1e8),
    "_percent": (0.0, 100.0),
    "_W_mK": (0.0, 1e4),            # thermal conductivity
    "_W": (0.0, 1e9),
    "_kW": (0.0, 1e6),
    "_l_min": (0.0, 1e5),           # coolant flow
    "_min": (0.0, 1e6),             # minutes (warm-up profiles)
}
_SUFFIXES = sorted(UNIT_RANGES, key=len, reverse=True)


def unit_text(suffix: str) -> str:
    """``N/m`` for ``_N_m``: the unit of a key suffix as a reader writes it."""
    special = {"_N_per_m_n": "N/m^n", "_g_mm": "g mm", "_kg_m2": "kg m2", "_hz": "Hz", "_Pa_s": "Pa s",
               "_J_kgK": "J/(kg K)", "_W_m2K": "W/(m2 K)", "_percent": "%", "_W_mK": "W/(m K)",
               "_l_min": "L/min"}
    return special.get(suffix, suffix[1:].replace("_", "/"))


def unit_range(key: str) -> tuple[str, tuple[float, float]] | None:
    """(unit suffix, range) of a deck key, or None when its name carries no unit."""
    for suffix in _SUFFIXES:
        if key.endswith(suffix) and len(key) > len(suffix):
            return suffix, UNIT_RANGES[suffix]
    return None


def _first_out_of_range(value: Any, lo: float, hi: float, where: str = "") -> tuple[str, float] | None:
    """The first number in ``value`` (a number, nested lists, or a {start, stop} range) outside [lo, hi]."""
    if isinstance(value, bool) or value is None:
        return None
    if isinstance(value, (int, float)):
        return None if lo <= value <= hi else (where, value)
    if isinstance(value, (list, tuple)):
        for i, v in enumerate(value):
            bad = _first_out_of_range(v, lo, hi, f"{where}[{i}]")
            if bad is not None:
                return bad
        return None
    if isinstance(value, BaseModel):
        for key in ("start", "stop"):
            v = getattr(value, key, None)
            if isinstance(v, (int, float)) and not isinstance(v, bool) and not lo <= v <= hi:
                return f"{where}.{key}", v
    return None


@lru_cache(maxsize=None)
def _module_tree(path: str) -> ast.Module | None:
    try:
        with open(path, encoding="utf-8") as f:
            return ast.parse(f.read(), path)
    except (OSError, SyntaxError, ValueError) as exc:
        log.debug("no source for the deck keys' docstrings in %s: %s", path, exc)
        return None


def _class_node(tree: ast.Module, qualname: str) -> ast.ClassDef | None:
    body: list[ast.stmt] = tree.body
    node = None
    for part in qualname.split("."):
        node = next((n for n in body if isinstance(n, ast.ClassDef) and n.name == part), None)
        if node is None:
            return None
        body = node.body
    return node


@lru_cache(maxsize=None)
def _own_docstrings(cls: type) -> dict[str, str]:
    """Docstrings written under the annotated attributes in the body of ``cls`` itself."""
    module = sys.modules.get(cls.__module__)
    path = getattr(module, "__file__", None)
    tree = _module_tree(path) if path else None
    node = _class_node(tree, cls.__qualname__) if tree is not None else None
    if node is None:
        return {}
    docs = {}
    for stmt, after in zip(node.body, node.body[1:]):
        if isinstance(stmt, ast.AnnAssign) and isinstance(stmt.target, ast.Name) and isinstance(after, ast.Expr) \
                and isinstance(after.value, ast.Constant) and isinstance(after.value.value, str):
            docs[stmt.target.id] = inspect.cleandoc(after.value.value)
    return docs


def attribute_docstrings(cls: type) -> dict[str, str]:
    """Key -> the docstring written under it, in ``cls`` or the nearest base class that documents it."""
    docs: dict[str, str] = {}
    for base in reversed(cls.__mro__):
        if isinstance(base, type) and issubclass(base, BaseModel) and base is not BaseModel:
            docs.update(_own_docstrings(base))
    return docs


class DeckJsonSchema(GenerateJsonSchema):
    """JSON schema of deck models with each key's attribute docstring as its ``description``."""

    def model_schema(self, schema):  # type: ignore[override]
        json_schema = super().model_schema(schema)
        properties = json_schema.get("properties", {})
        for key, doc in attribute_docstrings(schema["cls"]).items():
            if key in properties:
                properties[key]["description"] = doc
        return json_schema


class DeckModel(BaseModel):
    """Base of every deck section: unknown keys rejected, strict types, immutable, finite floats,
    numbers within the physical range of their unit, text at most 4096 characters."""

    model_config = ConfigDict(extra="forbid", frozen=True, strict=True, allow_inf_nan=False,
                              str_max_length=4096)

    @classmethod
    def model_json_schema(cls, *args: Any, **kwargs: Any) -> dict[str, Any]:
        """pydantic's JSON schema, with the keys' docstrings as their descriptions (:class:`DeckJsonSchema`)."""
        kwargs.setdefault("schema_generator", DeckJsonSchema)
        return super().model_json_schema(*args, **kwargs)

    @field_validator("*", mode="after")
    @classmethod
    def _physical_range(cls, value: Any, info: ValidationInfo) -> Any:
        unit = unit_range(info.field_name or "")
        if unit is None or value is None:
            return value
        suffix, (lo, hi) = unit
        bad = _first_out_of_range(value, lo, hi)
        if bad is not None:
            where, v = bad
            raise ValueError(f"{info.field_name}{where} = {v:g} is outside the physical range of a value in "
                             f"{unit_text(suffix)} ({lo:g} .. {hi:g})")
        return value


PositiveFloat = Annotated[float, Field(gt=0)]
NonNegFloat = Annotated[float, Field(ge=0)]
Fraction = Annotated[float, Field(ge=0.0, lt=1.0)]
#: a number with no unit of its own (range ends, sweep values): finite and below 1e15 in magnitude
AnyNumber = Annotated[float, Field(ge=-ANY_NUMBER, le=ANY_NUMBER)]
#: a node number; the loader checks it against the rotor's nodes (at most deck.limits.MAX_NODES)
NodeNumber = Annotated[int, Field(ge=1, le=100_000, description="1-based node number")]
Matrix2 = Annotated[
    list[Annotated[list[float], Field(min_length=2, max_length=2)]],
    Field(min_length=2, max_length=2),
]
Dof = Literal["x", "y", "theta_x", "theta_y"]
#: the most points of an evenly spaced range (speeds, frequencies, sweeps)
RANGE_COUNT_MAX = 100_000


class Range(DeckModel):
    """An evenly spaced range ``{start, stop, count}`` (both ends included); the unit of its key applies."""

    start: Annotated[float, Field(ge=0, le=ANY_NUMBER)]
    """First value of the range, in the unit of the key the range stands under (rpm under `speeds_rpm`, Hz under
    `frequencies_hz`)."""
    stop: Annotated[float, Field(gt=0, le=ANY_NUMBER)]
    """Last value, in the same unit; both ends are included. The speed and frequency ranges of the rotor
    analyses and of `chatter` need it greater than `start`."""
    count: Annotated[int, Field(ge=2, le=RANGE_COUNT_MAX)]
    """Number of evenly spaced values from `start` to `stop`, both ends included."""


class Load5(DeckModel):
    """A load on the five DOFs of a bearing: forces x, y, z [N] and moments about x, y [N m]."""

    fx_N: float = 0.0
    """Force of the shaft on the bearing along x (horizontal)."""
    fy_N: float = 0.0
    """Force of the shaft on the bearing along y (vertical, up)."""
    fz_N: float = 0.0
    """Axial force of the shaft on the bearing along z (the shaft axis)."""
    mx_Nm: float = 0.0
    """Moment of the shaft on the bearing about x (right-hand rule)."""
    my_Nm: float = 0.0
    """Moment of the shaft on the bearing about y (right-hand rule)."""

    def vector(self) -> list[float]:
        return [self.fx_N, self.fy_N, self.fz_N, self.mx_Nm, self.my_Nm]
