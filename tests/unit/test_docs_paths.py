"""The docs name what exists (issue "Every analysis returns its result", item 4): every file of the repository
that docs/*.md or the README cites by its path (spindlesim/..., tests/..., benchmarks/..., scripts/..., decks/...)
is there.  A module moved or renamed without its docs fails here with the document and line."""

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
CITED = re.compile(r"(?<![\w/.])((?:spindlesim|tests|benchmarks|scripts|decks)/[\w/.\-]+\.(?:py|yaml|csv|uff))")


def test_every_file_the_docs_cite_exists():
    docs = sorted((ROOT / "docs").glob("*.md")) + [ROOT / "README.md"]
    assert len(docs) > 3
    cited, missing = 0, []
    for md in docs:
        for i, line in enumerate(md.read_text(encoding="utf-8").splitlines(), 1):
            for m in CITED.finditer(line):
                cited += 1
                if not (ROOT / m.group(1)).exists():
                    missing.append(f"{md.relative_to(ROOT)}:{i}: {m.group(1)}")
    assert cited > 100  # the pattern finds the citations (a broken pattern would pass everything)
    assert not missing, "\n".join(missing)
