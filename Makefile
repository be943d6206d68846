# Two commands for a fresh machine: `make demo` and `make test`. Both create .venv when missing.
PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed
EXTRAS := test,plot,units,report

.PHONY: demo test lint pyc generate check accuracy benchmark mutation clean

$(STAMP): pyproject.toml constraints.txt
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -c constraints.txt -e ".[$(EXTRAS)]"
	touch $(STAMP)

# the derived relations, then the main job: the built-in tour of scenes (Problems 1-8, figures)
demo: $(STAMP)
	$(PY) -m hertzmdr.numeric.demo
	$(VENV)/bin/hertzmdr run --out out/tour --force

lint: $(STAMP)
	$(VENV)/bin/ruff check pkg derive numeric tests benchmarks examples

check: $(STAMP)
	$(PY) -m hertzmdr.derive --check

# the suite runs the --check itself (tests/test_generated.py); on as many workers as CI has
# cores (pytest-xdist; `make test WORKERS=0` runs it in one process). loadgroup: the tests of
# a file that share one costly module fixture (the benchmarks' quick run, the regenerated
# files, the MDR's bound references: GROUPED in tests/conftest.py) run on one worker, so the
# fixture is built once. The 20 slowest tests are listed at the end: the suite's budget is
# 10 minutes on 2 cores, and a test over 5 s belongs behind the sweep marker
WORKERS ?= 2
test: lint pyc
	$(PY) -m pytest -q -n $(WORKERS) --dist loadgroup --durations=20

# the package's bytecode, written once: where PYTHONDONTWRITEBYTECODE is set (this machine, CI)
# Python never writes it, and every process the tests start (workers, the benchmarks' scripts,
# the CLI) compiled numeric/_generated.py (0.8 MB) again, ~0.3 s each
pyc: $(STAMP)
	$(PY) -m compileall -q pkg derive numeric examples

accuracy: $(STAMP)
	OPENBLAS_NUM_THREADS=1 $(VENV)/bin/hertzmdr accuracy --out docs/accuracy.md

# every benchmark and report in docs/, in order, one progress line per script
# (benchmarks/run_all.py; see benchmarks/README.md), with the peers of the bench extra
BENCH_STAMP := $(VENV)/.installed-bench
$(BENCH_STAMP): $(STAMP)
	$(PY) -m pip install --quiet -c constraints.txt -e ".[$(EXTRAS),bench]"
	touch $(BENCH_STAMP)

benchmark: $(BENCH_STAMP)
	$(PY) benchmarks/run_all.py

# mutation testing of numeric/ (mutmut, module by module, one worker, nice 19): docs/mutation.md
$(VENV)/.mutation: $(STAMP)
	$(PY) -m pip install --quiet -c constraints.txt -e ".[$(EXTRAS),mutation]"
	touch $@

mutation: $(VENV)/.mutation
	$(PY) benchmarks/mutation.py

generate: $(STAMP)
	$(PY) -m hertzmdr.derive

clean:
	rm -rf $(VENV) .pytest_cache .hypothesis .ruff_cache
