"""Result summaries on the terminal (issue 16, item 8): text by default, --quiet, --json."""

import json

import numpy as np
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


def _campbell_file(tmp_path):
    _run(tmp_path, "campbell", "--speeds", "1000:6000:3", "--modes", "4", "--quiet")
    return tmp_path / "campbell.h5"


def test_campbell_summary_reads_the_file_not_the_deck(tmp_path, monkeypatch):
    """The operating speed is campbell.h5's attribute: the summary parses no YAML (issue 24, item 3)."""
    import sys

    import h5py

    from spindlesim.deck import default_deck
    from spindlesim.output.summary import summarize

    path = _campbell_file(tmp_path)
    with h5py.File(path, "r+") as f:
        del f.attrs["deck_text"]
    monkeypatch.setitem(sys.modules, "yaml", None)  # importing yaml now fails
    (_, lines, data), = summarize([path])
    assert data["operating_speed_rpm"] == default_deck("spindle").deck.operating.speed_rpm > 0


def test_campbell_summary_prints_the_analysis_stability_threshold(tmp_path):
    """The threshold is the file's ``first_unstable`` (speed, mode indices), not recomputed from the damping."""
    import h5py

    from spindlesim.output.summary import summarize

    path = _campbell_file(tmp_path)
    with h5py.File(path, "r+") as f:
        g = f["campbell"]
        assert bool(g.attrs["stable"]) and "first_unstable" not in g.attrs
        assert (g["damping_ratio"][()] > 0).all()
        g.attrs["stable"] = False
        g.attrs["first_unstable"] = np.array([1, 2])
        sp, fr = g["speed_rpm"][1], g["frequency_hz"][1, 2]
    (_, lines, data), = summarize([path])
    assert data["stability_threshold"]["speed_rpm"] == sp and data["stability_threshold"]["mode"] == 3
    assert data["stability_threshold"]["frequency_hz"] == fr
    assert any(ln.strip().startswith(f"UNSTABLE from {sp:g} rpm: mode 3") for ln in lines)


def test_first_unstable_is_the_lowest_speed_with_negative_damping():
    from spindlesim.analysis.results import CampbellResult

    z = np.array([[0.1, 0.2, np.nan], [0.1, -0.01, 0.3], [-0.2, -0.1, 0.3]])
    res = CampbellResult(speed_rpm=np.array([0.0, 1000.0, 2000.0]), frequency_hz=np.ones((3, 3)), log_dec=z,
                         damping_ratio=z, whirl=np.full((3, 3), "forward"), critical_speeds_rpm=np.zeros(0),
                         critical_modes=np.zeros(0, int))
    assert res.first_unstable == (1, 1)
    stable = CampbellResult(**{**res.__dict__, "damping_ratio": np.abs(np.nan_to_num(z))})
    assert stable.first_unstable is None
