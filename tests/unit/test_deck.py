"""Deck loading: every error class is located as file:line:col: key.path: message, all collected."""

import pytest

from spindlesim.deck import DeckError, default_deck, parse_deck

GOOD = """title: ok
shaft:
  elements:
    - [52.6, 22.0, 28.0, 7833, 206.8, 80.0, 0.3, 0.0]
    - [57.6, 22.0, 28.0, 7833, 206.8, 80.0, 0.3, 0.0]
bearings:
  - {name: a, node: 1, type: linear, K_N_m: [[1.0e8, 0], [0, 1.0e8]], C_Ns_m: [[1.0e3, 0], [0, 1.0e3]]}
  - {name: b, node: 3, type: linear, K_N_m: [[412.62e6, 373.86e6], [-338.35e6, 467.71e6]]}
operating:
  speed_rpm: 2170
"""


def errors(text):
    with pytest.raises(DeckError) as exc:
        parse_deck(text, "deck.yaml")
    return [str(i) for i in exc.value.issues]


def test_good_deck_and_yaml12_floats():
    d = parse_deck(GOOD, "deck.yaml").deck
    assert d.bearings[1].K_N_m[0][0] == 412.62e6  # "412.62e6" is a float, as in YAML 1.2


@pytest.mark.parametrize("name,btype", [("spindle", "three_lobe"), ("spindle_linear", "linear")])
def test_default_decks_are_seed003_table1(name, btype):
    d = default_deck(name).deck
    assert len(d.shaft.elements) == 25
    assert [b.node for b in d.bearings] == [7, 18]
    assert {b.type for b in d.bearings} == {btype}
    assert d.operating.speed_rpm == 2170


@pytest.mark.parametrize("old,new,expect", [
    ("title: ok", "title: ok\ncolour: red", "deck.yaml:2:1: colour: unknown key"),
    ("speed_rpm: 2170", "speed_rpm: fast", "deck.yaml:10:3: operating.speed_rpm: Input should be a valid number"),
    ("22.0, 28.0, 7833, 206.8, 80.0, 0.3, 0.0]\n    - [57.6", "22.0, -28.0, 7833, 206.8, 80.0, 0.3, 0.0]\n    - [57.6",
     "deck.yaml:4:20: shaft.elements[0][2]: length_mm must be > 0"),
    ("[57.6, 22.0, 28.0", "[57.6, 0.0, 0.0", "deck.yaml:5:19: shaft.elements[1][2]: length_mm must be > 0"),
    ("[52.6, 22.0,", "[52.6, 60.0,", "deck.yaml:4:14: shaft.elements[0][1]: inner_dia_mm 60.0 must be smaller"),
    ("name: b, node: 3", "name: b, node: 4", "deck.yaml:8:15: bearings[1].node: node 4 is out of range: the rotor has nodes 1..3"),
    ("title: ok", "title: ok\ntitle: again", "deck.yaml:2:1: title: duplicate key (first defined on line 1)"),
    ("speed_rpm: 2170", "speed_rpm: [2170", "deck.yaml:11:1: invalid YAML"),
    ("type: linear, K_N_m: [[412", "type: linearr, K_N_m: [[412",
     "deck.yaml:8:5: bearings[1]: unknown type; expected one of ball, dtrb, linear, plain, roller, three_lobe"),
    ("  elements:\n", "  elemnts:\n", "deck.yaml:2:1: shaft.elements: required key is missing"),
    ("0.3, 0.0]\n    - [57.6", "0.3]\n    - [57.6", "deck.yaml:4:7: shaft.elements[0]: List should have at least 8 items"),
])
def test_error_classes_are_located(old, new, expect):
    assert old in GOOD
    msgs = errors(GOOD.replace(old, new, 1))
    assert any(m.startswith(expect) for m in msgs), msgs


def test_all_errors_collected_not_just_the_first():
    text = GOOD.replace("title: ok", "title: ok\nfoo: 1").replace("speed_rpm: 2170", "speed_rpm: -5")
    text = text.replace("name: a, node: 1,", "name: a, node: 1, bogus: 2,")
    msgs = errors(text)
    assert len(msgs) == 3, msgs
    assert any("foo: unknown key" in m for m in msgs)
    assert any("operating.speed_rpm" in m for m in msgs)
    assert any("bearings[0].bogus: unknown key" in m for m in msgs)


def test_empty_and_non_mapping_decks():
    assert errors("")[0] == "deck.yaml:1:1: the deck is empty"
    assert "must be a mapping" in errors("- 1\n- 2\n")[0]


def test_rotor_analyses_require_shaft_and_operating():
    from spindlesim.deck import require_rotor

    loaded = parse_deck(GOOD.replace("operating:\n  speed_rpm: 2170\n", ""), "deck.yaml")
    with pytest.raises(DeckError) as exc:
        require_rotor(loaded, "modal")
    assert str(exc.value.issues[0]) == "deck.yaml:1:1: operating: required for the modal analysis"
