"""The one map from how a command ended to its exit code (README, "Exit codes").

    0    finished
    1    solver failure (nothing written); ``run`` and ``sweep``: an analysis or a case failed
    2    deck or input error (a rotor that cannot be solved as given, an output folder that cannot
         be written); nothing run
    3    ran but incomplete (files marked complete = False)
    130  interrupted (SIGINT / Ctrl-C; what was computed is written, marked incomplete)

:func:`exit_code_of` maps an exception, :func:`outcome_code` the outcome of a command that runs
several analyses or cases.  The module imports nothing at import time (the CLI uses it at start-up):
an exception class is looked up among the modules already loaded, since an exception of a class
whose module was never imported cannot exist.
"""

from __future__ import annotations

import sys

EXIT_OK = 0
EXIT_FAILED = 1
EXIT_DECK_ERROR = 2
EXIT_INCOMPLETE = 3
EXIT_INTERRUPTED = 130  # 128 + SIGINT, what a shell reports for a Ctrl-C'd program

#: (module, class): the input describes what cannot be solved as given (a deck error; a rotor not held,
#: stiffnesses apart by a unit mistake; a fluid film at rest; a measurement file that cannot be read, measurements
#: that cannot be analysed), exit 2 wherever it is met in a failure's chain
INPUT_ERRORS = (("spindlesim.deck.errors", "DeckError"),
                ("spindlesim.analysis.operating", "SingularRotorError"),
                ("spindlesim.bearings.base", "SpeedRequiredError"),
                ("spindlesim.chatter.readers", "FrfFileError"),  # a measured FRF or impact record file (located)
                ("spindlesim.measured.errors", "MeasurementInputError"))
#: (module, class): a run that wrote its files but did not finish (its ``interrupted`` flag: by Ctrl-C)
INCOMPLETE = ("spindlesim.runs.status", "IncompleteRun")


def _loaded(*classes: tuple[str, str]) -> tuple[type, ...]:
    return tuple(getattr(sys.modules[m], name) for m, name in classes if m in sys.modules)


def exit_code_of(exc: BaseException) -> int:
    """The exit code of a command ended by ``exc``: 130 for Ctrl-C, 130 or 3 for an incomplete run
    (interrupted or not), 2 for an input error anywhere in the chain of causes (a bearing's failure
    wrapped by the solver that met it), else 1 (a solver failure)."""
    if isinstance(exc, KeyboardInterrupt):
        return EXIT_INTERRUPTED
    incomplete = _loaded(INCOMPLETE)
    if incomplete and isinstance(exc, incomplete):
        return EXIT_INTERRUPTED if exc.interrupted else EXIT_INCOMPLETE
    inputs = _loaded(*INPUT_ERRORS)
    seen: BaseException | None = exc
    while seen is not None:
        if inputs and isinstance(seen, inputs):
            return EXIT_DECK_ERROR
        seen = seen.__cause__
    return EXIT_FAILED


def outcome_code(failed: bool = False, incomplete: bool = False, interrupted: bool = False) -> int:
    """The exit code of a command that ran several analyses (``run``) or cases (``sweep``): interrupted
    before any failure, a failure before any incomplete one, else 0."""
    if interrupted:
        return EXIT_INTERRUPTED
    if failed:
        return EXIT_FAILED
    if incomplete:
        return EXIT_INCOMPLETE
    return EXIT_OK
