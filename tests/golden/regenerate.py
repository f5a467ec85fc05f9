"""Rewrite the golden file after an intended change: `make golden`. Review the diff before committing."""

import json
from pathlib import Path

from tests.golden.golden_values import compute, compute_three_lobe

if __name__ == "__main__":
    path = Path(__file__).with_name("default_spindle.json")
    path.write_text(json.dumps({**compute(), **compute_three_lobe()}, indent=1) + "\n")
    print(f"wrote {path}")
