"""Result summaries on the terminal (issue 16, item 8): text by default, --quiet, --json."""

import json

import pytest
from click.testing import CliRunner

from spindlesim.cli import main
from spindlesim.analysis.resonance import required_separation_margin


@pytest.mark.parametrize("af,below,expect", [
    (2.0, True, 0.0),  # AF < 2.5: critically damped, no margin (API 684)
    (5.0, True, 0.17 * (1 - 1 / 3.5)),  # 12.1 %
    (5.0, False, 0.10 + 0.17 * (1 - 1 / 3.5)),  # 22.1 %
    (100.0, True, 0.16),  # capped at 16 % below the operating speed
    (100.0, False, 0.26),  # capped at 26 % above
])
def test_api684_separation_margin(af, below, expect):
    assert required_separation_margin(af, below) == pytest.approx(expect, rel=1e-12)


def _run(tmp_path, *args):
    res = CliRunner().invoke(main, [*args, "-o", str(tmp_path)])
    assert res.exit_code == 0, res.output
    return res.output


def test_modal_prints_a_table_after_the_paths(tmp_path):
    out = _run(tmp_path, "modal", "--modes", "4")
    lines = out.splitlines()
    assert lines[0].endswith("modal.h5")
    assert any("frequency Hz" in ln and "whirl" in ln for ln in lines)
    rows = [ln for ln in lines if ln.strip()[:2].strip().isdigit() and "Hz" not in ln]
    assert len(rows) == 4


def test_static_names_the_stiffness_and_bearing_reactions(tmp_path):
    out = _run(tmp_path, "static")
    assert "static stiffness at node 1 x" in out and "N/um" in out
    assert "bearing front" in out and "bearing rear" in out


def test_quiet_prints_only_paths(tmp_path):
    out = _run(tmp_path, "static", "--quiet")
    assert all(ln.endswith((".h5", ".png")) for ln in out.splitlines() if ln.strip())


def test_json_summary_is_machine_readable(tmp_path):
    out = _run(tmp_path, "campbell", "--speeds", "500:12000:12", "--json")
    doc = json.loads(out.splitlines()[-1])
    assert any(p.endswith("campbell.h5") for p in doc["paths"])
    s = doc["summary"]["campbell.h5"]
    assert "critical_speeds" in s and "stability_threshold" in s
