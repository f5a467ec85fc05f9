"""The seed studies under decks/studies/ are valid decks whose every case validates."""

from pathlib import Path

import pytest

from spindlesim.runs import analyses
from spindlesim.deck import load_deck, parse_deck
from spindlesim.sweep import build_cases
from spindlesim.sweep.cases import parse_values

ALL_STUDIES = sorted((Path(__file__).parents[2] / "decks" / "studies").glob("*.yaml"))
#: the sweep studies (the others are optimisation studies: tests/sweep/test_optimize.py)
STUDIES = [p for p in ALL_STUDIES if "\nsweep:" in p.read_text()]
OPTIMIZE = [p for p in ALL_STUDIES if "\noptimize:" in p.read_text()]


@pytest.mark.parametrize("path", STUDIES, ids=[p.stem for p in STUDIES])
def test_study_deck_cases_validate(path):
    loaded = load_deck(path)
    sw = loaded.deck.sweep
    assert sw is not None and sw.analysis in analyses()
    params = {k: (list(v) if isinstance(v, list) else parse_values(f"{v.start}:{v.stop}:{v.count}"))
              for k, v in sw.parameters.items()}
    cases = build_cases(loaded.text, params, sw.analysis, sw.mode)
    assert len(cases) >= 3
    for c in cases:
        parse_deck(c.deck_text, f"{path.name} case {c.index}")


@pytest.mark.slow
def test_seed003_speed_study_runs_and_coefficients_change(tmp_path):
    from spindlesim.sweep import run_sweep
    from spindlesim.sweep.report import scalar_table

    loaded = load_deck(next(p for p in STUDIES if "seed003" in p.name))
    cases = build_cases(loaded.text, {"operating.speed_rpm": [1000.0, 4000.0]}, "coefficients",
                        options={"plots": False})
    res = run_sweep(cases, tmp_path, workers=1)
    assert [r["status"] for r in res.records] == ["done", "done"], [r.get("error") for r in res.records]
    table = scalar_table(res)
    key = next(k for k in table if k.endswith("front/sommerfeld"))
    assert table[key][1] > table[key][0]  # faster: higher Sommerfeld number (lighter relative load)


@pytest.mark.parametrize("path", OPTIMIZE, ids=[p.stem for p in OPTIMIZE])
def test_optimize_study_decks_pass_their_checks(path):
    from spindlesim.sweep.optimize_inputs import check_problem

    problem = check_problem(load_deck(path))
    assert problem.variables and problem.objectives
