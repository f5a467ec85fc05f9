"""Golden-file regression guard for the default deck. It proves nothing about correctness (see
tests/validation for that); it catches unintended changes. Regenerate with `make golden`."""

import json
from pathlib import Path

import numpy as np
import pytest

from tests.golden.golden_values import compute

GOLDEN = json.loads(Path(__file__).with_name("default_spindle.json").read_text())


@pytest.fixture(scope="module")
def now():
    return compute()


@pytest.mark.parametrize("key", sorted(GOLDEN))
def test_matches_golden(now, key):
    if key == "modal_whirl":
        assert now[key] == GOLDEN[key]
    elif key == "frf_phase_rad":
        np.testing.assert_allclose(now[key], GOLDEN[key], atol=1e-6)
    else:
        scale = np.max(np.abs(GOLDEN[key]))
        np.testing.assert_allclose(now[key], GOLDEN[key], rtol=1e-6, atol=1e-9 * scale)
