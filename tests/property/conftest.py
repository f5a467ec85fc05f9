"""Hypothesis profiles of the deck property tests, chosen by the environment variable SPINDLESIM_FUZZ.

* unset or ``ci`` (``make test``): few examples per test, derandomized, about a minute for the folder;
* ``fuzz`` (``make fuzz``): many examples, random each run;
* ``long``: the ``fuzz`` profile with ten times as many examples.

No example database is written into the working tree (``database=None``); a failing case is printed
by Hypothesis with the deck text that reproduces it.
"""

from __future__ import annotations

import os

from hypothesis import HealthCheck, settings

_COMMON = dict(deadline=None, database=None, print_blob=True,
               suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                      HealthCheck.filter_too_much])
settings.register_profile("ci", max_examples=100, derandomize=True, **_COMMON)
settings.register_profile("fuzz", max_examples=20000, **_COMMON)
settings.register_profile("long", max_examples=200000, **_COMMON)
settings.load_profile(os.environ.get("SPINDLESIM_FUZZ", "ci") or "ci")
