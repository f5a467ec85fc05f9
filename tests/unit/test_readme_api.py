"""The README's Python API example runs as written (issue 34: each analysis's public function returns its frozen
result; the summary and the verdicts come from that result)."""

from __future__ import annotations

from pathlib import Path

ROOT = Path(__file__).parents[2]


def test_the_readme_api_example_runs(tmp_path, monkeypatch):
    text = (ROOT / "README.md").read_text()
    block = text[text.index("## Python API"):].split("```python", 1)[1].split("```", 1)[0]
    monkeypatch.chdir(ROOT)
    block = block.replace('"out/study"', repr(str(tmp_path / "study")))
    scope: dict = {}
    exec(compile(block, "README.md", "exec"), scope)  # noqa: S102 - the documentation's own example
    assert scope["lines"][0].startswith("50 speeds 0-12000 rpm") and scope["done"].analysis == "campbell"
    assert (tmp_path / "study" / "campbell.h5").is_file()
