# Set-up and the two jobs the README promises. Needs Python 3.11+ with pip and venv.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed

.PHONY: setup demo test lint clean

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e ".[test]"
	touch $(STAMP)

setup: $(STAMP)

# The main job on a real example: the CWRU drive-end bearing at the data set's 1797 rpm.
demo: setup
	$(BIN)/bearinglab info 6205-2RS
	$(BIN)/bearinglab frequencies 6205-2RS --speed-rpm 1797
	$(BIN)/bearinglab contact 6205-2RS --ball-load-n 1000
	$(BIN)/bearinglab info 180205
	$(BIN)/bearinglab static 6205-2RS --radial-load-n 1000 --speed-rpm 1797
	$(BIN)/bearinglab simulate ER-16K --speed-rpm 1750 --radial-load-n 50 \
	    --defect outer:width_mm=1.2,depth_mm=0.25 --defect ball:width_mm=1.2 \
	    --duration-s 2 --sample-rate-hz 20000

test: setup
	$(BIN)/python -m pytest -q

lint: setup
	$(BIN)/python -m pip install --quiet ruff
	$(BIN)/ruff check src tests

clean:
	rm -rf $(VENV) .pytest_cache .hypothesis
