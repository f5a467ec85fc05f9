"""`spindlesim tools` (issue 30, item 5): the tool library's file, summary and figures, the lobes of each tool
equal to the chatter analysis of the rotor with that tool, and every bad tool entry a located deck error (exit 2,
nothing written)."""

from __future__ import annotations

from pathlib import Path

import h5py
import numpy as np
import pytest
from click.testing import CliRunner

from spindlesim.cli import main

ROOT = Path(__file__).parents[2]
LIBRARY = ROOT / "decks" / "tool_library.yaml"


def _run(args, tmp_path):
    out = tmp_path / "out"
    res = CliRunner().invoke(main, ["tools", *map(str, args), "-o", str(out)])
    return res, out


def _small_library(tmp_path, chatter: str = "") -> Path:
    """The tool library deck with three of its tools and, optionally, a cheap chatter section."""
    text = LIBRARY.read_text()
    head, rest = text.split("\ntools:\n", 1)
    entries, tail = rest.split("\ndisks:\n", 1)
    keep = [e for e in ("\n" + entries).split("\n  - name: ")[1:] if e.split()[0] in
            ("em16_shrink_60", "em8_shrink_32", "em20_er32_70")]
    text = head + "\ntools:\n" + "".join("  - name: " + e + ("\n" if not e.endswith("\n") else "") for e in keep) \
        + "disks:\n" + tail
    if chatter:
        start = text.index("\nchatter:\n")
        end = text.index("\n\n", start + 1)
        text = text[:start] + "\n" + chatter + text[end:]
    p = tmp_path / "library.yaml"
    p.write_text(text)
    return p


def test_the_library_file_summary_and_figure(tmp_path):
    deck = _small_library(tmp_path)
    res, out = _run([deck, "--no-lobes", "--speed", "12000"], tmp_path)
    assert res.exit_code == 0, res.output
    assert "3 tool(s) coupled onto node 1 at 12000 rpm" in res.output
    for name in ("em16_shrink_60", "em8_shrink_32", "em20_er32_70"):
        assert name in res.output
    with h5py.File(out / "tools.h5") as f:
        assert list(f["tools"].attrs["tools"]) == ["em16_shrink_60", "em8_shrink_32", "em20_er32_70"]
        H = f["tools/em8_shrink_32/receptance_m_N"][:]
        assert H.shape == (len(f["tools/em8_shrink_32/frequency_hz"]), 2, 2)
        assert f["tools/em8_shrink_32/receptance_m_N"].attrs["units"] == "m/N"
        assert np.all(np.isfinite(H))
        # gravity on: each tool's weight loads the bearings differently, one spindle state each
        assert f["tools/spindle/receptance"].shape[0] == 3
        load = f["tools/em8_shrink_32/nose_load"][:]
        m = float(f["tools/em8_shrink_32/mass_kg"][()])
        assert load[1] == pytest.approx(-9.80665 * m, rel=1e-9)
    assert (out / "tools_frf.png").exists() and not (out / "tools_lobes.png").exists()


CHEAP_CHATTER = """chatter:
  operation: milling
  speeds_rpm: {start: 8000, stop: 24000, count: 24}
  method: zero_order
  Kt_N_mm2: 767.0
  Kn_N_mm2: 168.8
  teeth: 4
  tool_diameter_mm: 16.0
  radial_depth_mm: 16.0
  mode: down
  frf: rotor
  frf_at_each_speed: false"""


def test_each_tools_lobes_are_the_chatter_analysis_of_the_rotor_with_that_tool(tmp_path):
    """The first tool of the library is the deck's own `tool:`: its lobes equal `spindlesim chatter` of the same
    deck with the FRF at the operating speed (zero order, full slot: the method is exact there)."""
    deck = _small_library(tmp_path, CHEAP_CHATTER)
    res, out = _run([deck], tmp_path)
    assert res.exit_code == 0, res.output
    assert "min depth" in res.output and (out / "tools_lobes.png").exists()
    ch = CliRunner().invoke(main, ["chatter", str(deck), "-o", str(tmp_path / "ch"), "-q"])
    assert ch.exit_code == 0, ch.output
    with h5py.File(out / "tools.h5") as f, h5py.File(tmp_path / "ch" / "chatter.h5") as c:
        names = [str(n) for n in f["tools/lobes/tool"][:].astype(str)]
        i = names.index("em16_shrink_60")
        ours = f["tools/em16_shrink_60/lobes/limit_depth_m"][:]
        theirs = c["chatter/limit_depth_m"][:]
        assert np.allclose(f["tools/em16_shrink_60/lobes/speed_rpm"][:], c["chatter/speed_rpm"][:])
        assert np.allclose(ours, theirs, rtol=1e-6, equal_nan=True)
        assert f["tools/lobes/min_depth_m"][i] == pytest.approx(c["chatter"].attrs["minimum_limit_depth_m"], rel=1e-6)
        # another tool, other lobes
        other = f["tools/em8_shrink_32/lobes/limit_depth_m"][:]
        assert np.nanmin(other) != pytest.approx(np.nanmin(ours), rel=1e-3)


BAD = [
    ("  - name: em16_shrink_60 ", "  - name: em16_shrink_60\n    toll: {} ", "tools[0].toll", "unknown key"),
    ("  - name: em16_shrink_90 ", "  - name: em16_shrink_60 ", "tools[1].name", "duplicate tool name"),
    ("  - name: em8_shrink_32\n", "  - name: a/b\n", "tools[2].name", "no '/'"),
    ("        - [8.0, 0.0, 12.0,", "        - [8.0, 9.0, 12.0,", "tools[2].tool.elements[0][1]", "inner_dia_mm"),
    # issue 33, item 4: a 12 mm shank into the 8 mm bore of its shrink-fit chuck does not go in
    ("        - [8.0, 0.0, 12.0,", "        - [12.0, 0.0, 12.0,", "tools[2].tool.elements[0][0]",
     "larger than the holder's bore (inner_dia_mm 8"),
    # ... nor the 16 mm end mill of the tool: section into a holder bored for 12 mm
    ("  - name: em16_shrink_90             # the same end mill 90 mm out of the same chuck\n",
     "  - name: em16_shrink_90\n    holder:\n      elements:\n        - [63.0, 12.0, 20.0, 7850.0, 210.0, 80.8, 0.3, 0.0]\n",
     "tools[1].tool.elements[0][0]", "bore (inner_dia_mm 12 of the holder's last row): it does not go in"),
]


@pytest.mark.parametrize("old,new,key,message", BAD, ids=[b[2] for b in BAD])
def test_a_bad_tool_entry_is_a_located_deck_error(tmp_path, old, new, key, message):
    text = LIBRARY.read_text()
    assert old in text
    deck = tmp_path / "bad.yaml"
    deck.write_text(text.replace(old, new, 1))
    res, out = _run([deck, "--no-lobes"], tmp_path)
    assert res.exit_code == 2, res.output
    assert f"bad.yaml:" in res.output and key in res.output and message in res.output, res.output
    assert "Traceback" not in res.output
    assert not out.exists() or not list(out.iterdir())


def test_entries_without_a_tool_section_must_give_every_part(tmp_path):
    text = LIBRARY.read_text()
    start = text.index("\ntool:\n")
    end = text.index("\n# The tool library")
    deck = tmp_path / "bad.yaml"
    deck.write_text(text[:start] + text[end:])
    res, _ = _run([deck, "--no-lobes"], tmp_path)
    assert res.exit_code == 2, res.output
    assert "tool 'em16_shrink_60' needs holder, joint, tool" in res.output


def test_a_load_on_the_decks_tool_is_refused_for_the_library(tmp_path):
    text = LIBRARY.read_text().replace("  - {node: 1, fx_N: 200.0}", "  - {node: 26, fx_N: 200.0}")
    deck = tmp_path / "bad.yaml"
    deck.write_text(text)
    res, _ = _run([deck, "--no-lobes"], tmp_path)
    assert res.exit_code == 2, res.output
    assert "loads[0].node" in res.output and "sits on the deck's holder or tool" in res.output


def test_ctrl_c_in_the_lobes_keeps_the_receptances_and_the_tools_done(tmp_path, monkeypatch):
    """Issue 33, item 4: a Ctrl-C in the second tool's lobes: exit 130, tools.h5 marked incomplete with every
    tool's receptance and the first tool's lobes, the summary says so."""
    import spindlesim.analysis.tool_library as lib

    real, calls = lib.tool_lobes, []

    def second_stops(*a, **k):
        calls.append(1)
        if len(calls) == 2:
            raise KeyboardInterrupt
        return real(*a, **k)

    monkeypatch.setattr(lib, "tool_lobes", second_stops)
    res, out = _run([_small_library(tmp_path, CHEAP_CHATTER)], tmp_path)
    assert res.exit_code == 130, res.output
    assert "interrupted by the user in the lobes of tool 'em8_shrink_32'" in res.output
    with h5py.File(out / "tools.h5") as f:
        assert not f.attrs["complete"]
        assert "lobes of 1 of 3 tools" in f.attrs["incomplete_reason"]
        assert [str(n) for n in f["tools/lobes/tool"][:].astype(str)] == ["em16_shrink_60"]
        for name in ("em16_shrink_60", "em8_shrink_32", "em20_er32_70"):
            assert np.isfinite(f[f"tools/{name}/receptance_m_N"][:]).all()
    assert "min depth" in res.output and (out / "tools_lobes.png").exists()
