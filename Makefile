# Two commands do all the set-up on a fresh machine: `make demo` and `make test`.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
# Strict editable install: a tree of links under build/ that type checkers, IDEs and import-graph
# readers resolve (mkm.fem is fem/, ...). A module added or removed changes its folder, which
# installs again. setuptools prints an informational banner (a UserWarning) about folders named
# as the package; here the folder is the package: install quietly. uv resolves and installs the
# same versions as pip, in parallel: the test extras on an empty cache took 37 s of CPU with pip
# and 5 s with uv (3 min and 36 s of wall time, on this machine under load). uv compiles the
# bytecode only when asked, as pip does unasked: where PYTHONDONTWRITEBYTECODE is set, every
# import would compile its modules again (mkm demo took 13 s instead of 8 s).
PIP_INSTALL := PYTHONWARNINGS=ignore::UserWarning $(BIN)/uv pip install --quiet --compile-bytecode --python $(BIN)/python
EDITABLE := --config-settings editable_mode=strict -e
# (with a trailing slash: `bench` is also a target)
PACKAGE_DIRS := $(shell find mkm bench fem surrogate -type d -not -name __pycache__ -printf '%p/ ')

.PHONY: demo test test-fast test-lowest bench docs bench-docs clean

$(BIN)/python:
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip

# (its own target: a .venv made before it was used gets it too)
$(BIN)/uv: | $(BIN)/python
	$(BIN)/python -m pip install --quiet "uv>=0.13"

$(VENV)/.installed: pyproject.toml $(PACKAGE_DIRS) | $(BIN)/uv
	$(PIP_INSTALL) $(EDITABLE) .
	touch $@

$(VENV)/.installed-docs: pyproject.toml $(PACKAGE_DIRS) | $(BIN)/uv
	$(PIP_INSTALL) $(EDITABLE) ".[docs]"
	touch $@ $(VENV)/.installed

$(VENV)/.installed-test: pyproject.toml $(PACKAGE_DIRS) | $(BIN)/uv
	$(PIP_INSTALL) $(EDITABLE) ".[test]"
	touch $@ $(VENV)/.installed

# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

# Everything, then the 15 slowest tests, on both cores (CI's machine has two): a module runs whole
# in one process (its fixtures built once), the longest modules first (tests/conftest.py); meant for
# under 10 minutes on CI, install included. `make test-fast` leaves out the `slow` tier (wheel and venv
# builds, signals, Dask, Chromium, the fine mesh, GP training) while you work.
test: $(VENV)/.installed-test
	$(BIN)/ruff check .
	$(BIN)/python tools/lint_imports.py
	$(BIN)/python tools/check_static_imports.py
	OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 $(BIN)/python -m pytest -q --durations=15 -n 2 --dist loadfile --no-loadscope-reorder

test-fast: $(VENV)/.installed-test
	$(BIN)/ruff check .
	$(BIN)/python tools/lint_imports.py
	$(BIN)/python tools/check_static_imports.py
	OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 $(BIN)/python -m pytest -q -m "not slow" -n 2

# The fast tier against the lowest versions pyproject.toml allows, on the lowest Python, in
# .venv-lowest: tools/lowest-requirements.txt pins each runtime dependency at its lower bound
# (tests/test_layout.py checks they agree), the test extras at the newest that fit. Not part of
# `make test` (minutes on one core); run it after raising or adding a dependency.
PYTHON_LOWEST ?= python3.11
VENV_LOWEST := .venv-lowest
PIP_INSTALL_LOWEST := PYTHONWARNINGS=ignore::UserWarning $(VENV_LOWEST)/bin/python -m pip install --quiet

$(VENV_LOWEST)/bin/python:
	$(PYTHON_LOWEST) -m venv $(VENV_LOWEST)
	$(VENV_LOWEST)/bin/python -m pip install --quiet --upgrade pip

$(VENV_LOWEST)/.installed: pyproject.toml tools/lowest-requirements.txt $(PACKAGE_DIRS) | $(VENV_LOWEST)/bin/python
	$(PIP_INSTALL_LOWEST) -r tools/lowest-requirements.txt $(EDITABLE) ".[test]"
	touch $@

test-lowest: $(VENV_LOWEST)/.installed
	OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 $(VENV_LOWEST)/bin/python -m pytest -q -m "not slow"

bench: $(VENV)/.installed-test
	$(PIP_INSTALL) -e ".[bench]"
	for f in benchmarks/bench_*.py; do $(BIN)/python $$f || exit 1; done

# The documentation site under docs/_build/html: docs/generate.py writes the API pages and the
# measured tables first; warnings are errors; no network.
docs: $(VENV)/.installed-docs
	MPLBACKEND=Agg $(BIN)/sphinx-build -W --keep-going -q -b html docs docs/_build/html
	@echo docs/_build/html/index.html

# Rerun the benchmarks whose results the documentation shows or quotes (docs/measured/; long).
bench-docs: $(VENV)/.installed-test
	$(PIP_INSTALL) -e ".[bench]"
	OPENBLAS_NUM_THREADS=1 $(BIN)/python docs/generate.py --run-benchmarks

clean:
	rm -rf $(VENV) $(VENV_LOWEST) build *.egg-info docs/_build docs/_generated
