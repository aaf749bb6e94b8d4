# Two commands do all set-up on a fresh machine with Python 3.11 + pip:
#   make run    -> creates .venv, installs, runs the main job
#   make test   -> same set-up, then the whole test suite
PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed

.PHONY: run test bench report clean venv

venv: $(STAMP)

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -e ".[test]"
	$(PY) -m sie.warmup    # compile the numba kernels into the on-disk cache once
	touch $(STAMP)

run: $(STAMP)
	$(PY) -m contact run --out contact-out

test: $(STAMP)
	$(PY) -m pytest -q

bench: $(STAMP)
	$(PY) -m pip install --quiet -e ".[bench]"
	$(PY) -m validation.bench_sie
	$(PY) -m validation.bench_sie2
	$(PY) -m validation.bench_contact
	$(PY) -m validation.bench_sweep

report: $(STAMP)
	$(PY) -m pip install --quiet -e ".[report]"
	$(PY) -m validation.report

clean:
	rm -rf $(VENV) build *.egg-info validation/out contact-out
