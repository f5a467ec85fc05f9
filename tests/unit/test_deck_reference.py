"""Every deck key is documented from one source (issue 23, item 3): the docstring written under the key in
its deck model becomes the key's description in the JSON schema, and docs/deck-reference.md is generated
from that schema (``spindlesim schema --markdown``), so it cannot go stale."""

from __future__ import annotations

import json
from pathlib import Path

from click.testing import CliRunner

from spindlesim.cli import main
from spindlesim.deck.reference import REGENERATE, deck_reference, deck_schema
from spindlesim.fields import DeckModel, attribute_docstrings

REFERENCE = Path(__file__).parents[2] / "docs" / "deck-reference.md"


def _properties(schema: dict):
    """(model, key, property schema) of every key of the deck schema."""
    for model, node in [("Deck", schema)] + list(schema.get("$defs", {}).items()):
        for key, prop in node.get("properties", {}).items():
            yield model, key, prop


def test_every_deck_key_has_a_description():
    schema = deck_schema()
    props = list(_properties(schema))
    missing = [f"{model}.{key}" for model, key, prop in props if not str(prop.get("description", "")).strip()]
    assert len(props) > 350
    assert not missing, (f"{len(missing)} deck keys have no description; write a docstring under each key in its "
                         f"deck model (meaning, unit, what a default of None means): {', '.join(missing)}")


def test_the_reference_is_what_the_generator_writes_today():
    expected = deck_reference()
    assert REFERENCE.exists(), f"docs/deck-reference.md is missing: run `{REGENERATE}`"
    assert REFERENCE.read_text(encoding="utf-8") == expected, (
        f"docs/deck-reference.md is out of date with the deck models: run `{REGENERATE}`")


def test_every_key_of_the_schema_has_a_row_in_the_reference():
    text = deck_reference()
    rows = {line.split("`")[1].rsplit(".", 1)[-1].removesuffix("[]") for line in text.splitlines()
            if line.startswith("| `")}
    keys = {key for _, key, _ in _properties(deck_schema())}
    assert keys - rows == set()


def test_the_reference_gives_unit_default_and_range_of_a_key():
    line = next(row for row in deck_reference().splitlines() if row.startswith("| `bearings[].radial_clearance_um`"))
    cells = [c.strip() for c in line.strip("|").split(" | ")]
    assert cells[1:5] == ["number", "um", "`0`", "[-100000, 100000]"]
    assert "diametral" in cells[5]
    speeds = next(row for row in deck_reference().splitlines() if row.startswith("| `campbell.speeds_rpm`"))
    assert "| range | rpm | `{start: 0, stop: 12000, count: 50}` | ends in [0, 1e6] |" in speeds


class Base(DeckModel):
    a_mm: float = 1.0
    """The base's key."""
    b: int = 0


class Child(Base):
    b: int = 2
    """The child's own key."""


def test_attribute_docstrings_follow_the_class_hierarchy():
    assert attribute_docstrings(Child) == {"a_mm": "The base's key.", "b": "The child's own key."}
    props = Child.model_json_schema()["properties"]
    assert props["a_mm"]["description"] == "The base's key." and props["b"]["description"] == "The child's own key."


def test_schema_command_writes_the_json_schema_with_descriptions_and_the_markdown_reference(tmp_path):
    res = CliRunner().invoke(main, ["schema", "-o", str(tmp_path / "deck.schema.json")])
    assert res.exit_code == 0, res.output
    schema = json.loads((tmp_path / "deck.schema.json").read_text())
    assert "ball diameter" in schema["$defs"]["BallBearingEntry"]["properties"]["ball_diameter_mm"]["description"].lower()
    res = CliRunner().invoke(main, ["schema", "--markdown", "-o", str(tmp_path / "reference.md")])
    assert res.exit_code == 0, res.output
    assert (tmp_path / "reference.md").read_text(encoding="utf-8") == deck_reference()


def test_tilt_keys_in_mrad_carry_their_unit():
    """Issue 23: the held tilts `theta_x_mrad` / `theta_y_mrad` showed no unit in the reference."""
    from spindlesim.fields import unit_range, unit_text

    assert unit_range("theta_x_mrad")[0] == "_mrad" and unit_text("_mrad") == "mrad"
    text = (Path(__file__).parents[2] / "docs" / "deck-reference.md").read_text()
    assert "| `bearing.held.theta_x_mrad` | number | mrad |" in text
