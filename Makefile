# Set-up and the jobs the README promises. Needs Python 3.11+ with pip and venv.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed
CODE := src tests benchmarks examples

.PHONY: setup demo test test-fast lint format clean

# pip shows its progress: the first install takes a few minutes (numba, scipy, dask, ...)
$(STAMP): pyproject.toml
	@echo "installing bearinglab and its dependencies into $(VENV) (a few minutes the first time)..."
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --progress-bar on -e ".[test]"
	touch $(STAMP)

setup: $(STAMP)

# The main job on a real example: the CWRU drive-end bearing at the data set's 1797 rpm,
# and the diagnosis of a real CWRU outer-race recording when ../shared is beside the checkout.
demo: setup
	$(BIN)/bearinglab info 6205-2RS
	$(BIN)/bearinglab frequencies 6205-2RS --speed-rpm 1797
	$(BIN)/bearinglab contact 6205-2RS --ball-load-n 1000
	$(BIN)/bearinglab info 180205
	$(BIN)/bearinglab static 6205-2RS --radial-load-n 1000 --speed-rpm 1797
	$(BIN)/bearinglab simulate ER-16K --speed-rpm 1750 --radial-load-n 50 \
	    --defect outer:width_mm=1.2,depth_mm=0.25 --defect ball:width_mm=1.2 \
	    --duration-s 2 --sample-rate-hz 20000
	@if [ -f ../shared/data/real/cwru/12k_DE/130.mat ]; then \
	    $(BIN)/bearinglab analyze ../shared/data/real/cwru/12k_DE/130.mat \
	        --sample-rate-hz 12000 --designation 6205-2RS; fi

# Everything, as CI runs it (long simulations included), on every core (pytest-xdist).
test: setup
	$(BIN)/python -m pytest -q -n auto

# Your own loop: the tests not marked slow (about 3 minutes on 2 cores).
test-fast: setup
	$(BIN)/python -m pytest -q -n auto -m "not slow"

# ruff's rules (pyproject.toml) and its formatting; CI runs this before the tests.
lint: setup
	$(BIN)/ruff check $(CODE)
	$(BIN)/ruff format --check $(CODE)

format: setup
	$(BIN)/ruff format $(CODE)

clean:
	rm -rf $(VENV) .pytest_cache .hypothesis
