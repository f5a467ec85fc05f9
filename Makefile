# Two commands do everything on a fresh machine: `make run` and `make test`.
PY ?= python3
VENV ?= .venv
BIN := $(VENV)/bin
OUT ?= out

.PHONY: run test test-fast fuzz bench venv install install-test clean golden

$(BIN)/python:
	$(PY) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip

install: $(BIN)/python
	$(BIN)/python -m pip install --quiet -e .

install-test: $(BIN)/python
	$(BIN)/python -m pip install --quiet -e '.[test]'

run: install
	$(BIN)/spindlesim run -o $(OUT)/spindle
	$(BIN)/spindlesim contact -o $(OUT)/contact
	$(BIN)/spindlesim dtrb -o $(OUT)/dtrb
	$(BIN)/spindlesim transient --rollers 8 -o $(OUT)/transient
	$(BIN)/spindlesim run decks/seed001_dtrb_rotor.yaml -o $(OUT)/seed001_dtrb_rotor

# Two worker processes (pytest-xdist), each test file whole in one of them (its module fixtures built once):
# the suite in about 7 minutes on two cores instead of 14 (docs/decisions.md, "The suite on both cores").
XDIST = -n 2 --dist loadfile
test: install-test
	OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 MPLBACKEND=Agg $(BIN)/python -m pytest $(XDIST)

# The developers' lane: everything but the tests marked slow (long physics checks, real processes, every deck).
test-fast: install-test
	OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 MPLBACKEND=Agg $(BIN)/python -m pytest $(XDIST) -m "not slow"

# Property tests of the deck loader with many more examples than `make test` (20,000 a test: about 28 minutes);
# FUZZ=long for ten times as many.  A failure prints the deck text that reproduces it.
FUZZ ?= fuzz
fuzz: install-test
	SPINDLESIM_FUZZ=$(FUZZ) OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 MPLBACKEND=Agg $(BIN)/python -m pytest \
	  -p no:cacheprovider tests/property --hypothesis-show-statistics

bench: install-test
	OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 MPLBACKEND=Agg $(BIN)/python benchmarks/run.py

golden: install-test
	$(BIN)/python -m tests.golden.regenerate

clean:
	rm -rf $(VENV) $(OUT) build *.egg-info
