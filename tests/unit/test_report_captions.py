"""Every figure a run writes has a written caption in the HTML report (issue 23, item 6), not a caption made
from its file name: the figure names are read from the sources (PNG literals, and the ball-bearing figure
dictionary's keys), so a new figure without a caption fails here."""

import re
from pathlib import Path

import spindlesim
from spindlesim.output.report import CAPTIONS

ROOT = Path(spindlesim.__file__).parent


def _figure_stems() -> set[str]:
    stems = set()
    for path in ROOT.rglob("*.py"):
        text = path.read_text()
        for m in re.finditer(r"[\"']([a-z][a-z_]*)(\{[^}]*\})?\.png[\"']", text):
            stems.add(m.group(1).rstrip("_") + "_" if m.group(2) else m.group(1))
    ball = (ROOT / "bearings" / "ball" / "plots.py").read_text()
    stems |= set(re.findall(r"[\"'](ball_[a-z_]+)[\"']\s*[:\]]", ball))
    return stems


def _captioned(stem: str) -> bool:
    if stem in CAPTIONS:
        return True
    return any(k.endswith("_") and stem.startswith(k) for k in CAPTIONS)


def test_every_figure_name_has_a_caption():
    stems = _figure_stems()
    assert {"thermal_warm_up", "campbell_thermal", "ball_contact_ellipses", "chatter_simulation_"} <= stems
    missing = sorted(s for s in stems if not _captioned(s))
    assert not missing, f"figures without a caption in output/report.py CAPTIONS: {missing}"
