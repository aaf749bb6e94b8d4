# Two commands do all set-up on a fresh machine with Python 3.11 + pip:
#   make run    -> creates .venv, installs, runs the main job
#   make test   -> same set-up, then the whole test suite
#   make test-fast -> the same without the tests marked slow
PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed

.PHONY: run test test-fast bench report docs clean venv

venv: $(STAMP)

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -e ".[test]"
	$(PY) -m sie.warmup    # compile the numba kernels into the on-disk cache once
	$(PY) -m compileall -q sie contact    # bytecode, as pip writes it for an installed package
	touch $(STAMP)

run: $(STAMP)
	$(PY) -m contact run --out contact-out

# the slowest tests listed at the end: the suite must stay under 10 minutes on 2 cores
test: $(STAMP)
	$(PY) -m pytest -q --durations=15

# the everyday subset: everything not marked slow (the doctests included), < 2 min on 2 cores
test-fast: $(STAMP)
	$(PY) -m pytest -q -m "not slow"

bench: $(STAMP)
	$(PY) -m pip install --quiet -e ".[bench]"
	$(PY) -m validation.bench_sie
	$(PY) -m validation.bench_sie2
	$(PY) -m validation.bench_contact
	$(PY) -m validation.bench_sweep

report: $(STAMP)
	$(PY) -m pip install --quiet -e ".[report]"
	$(PY) -m validation.report

# the site (theory, API reference, the executed gallery) and the validation report inside it;
# warnings are errors
docs: $(STAMP)
	$(PY) -m pip install --quiet -e ".[docs]"
	$(PY) -m sphinx -W --keep-going -b html docs docs/_build/html
	$(PY) -m validation.report --out docs/_build/html/report
	$(PY) docs/check_links.py docs/_build/html

clean:
	rm -rf $(VENV) build *.egg-info validation/out contact-out docs/_build docs/auto_examples \
		docs/api/generated docs/sg_execution_times.rst
