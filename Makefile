# Two entry points a fresh machine needs: `make run` and `make test` (see README.md).
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
PLUGINS := $(wildcard plugins/*/pyproject.toml)

.PHONY: install compile run test bench typecheck fuzz clean

$(STAMP): pyproject.toml $(PLUGINS)
	$(PYTHON) -m venv $(VENV)
	$(BIN)/pip install --quiet --upgrade pip
	$(BIN)/pip install --quiet -e '.[test,render,dask]' $(foreach p,$(PLUGINS),-e $(dir $(p)))
	touch $(STAMP)

# Byte-compile the editable packages (core, dialects, plugins) once, so that a start does not compile
# them again: pip compiles what it copies into site-packages, not an editable source tree, and where
# PYTHONDONTWRITEBYTECODE is set no run writes a .pyc. compileall writes them even then, and skips the
# files whose .pyc is up to date: cheap to repeat after an edit (make test does).
compile: $(STAMP)
	$(BIN)/python -m compileall -q postproc dialects $(foreach p,$(PLUGINS),$(dir $(p)))

install: $(STAMP) compile

run: install
	bash examples/run.sh

test: install
	$(BIN)/python -m pytest

bench: $(STAMP)
	$(BIN)/pip install --quiet -r benchmarks/requirements.txt
	$(BIN)/python benchmarks/run.py $(BENCH_ARGS)

fuzz: $(STAMP)
	$(BIN)/python -m tests.support.fuzz_main --minutes $(or $(MINUTES),10) --out fuzz-failures

typecheck: $(STAMP)
	$(BIN)/pip install --quiet mypy
	$(BIN)/python -m mypy --strict -p postproc -p dialects
	for p in plugins/*/postproc_*/__init__.py; do p=$$(dirname $$p); \
	  (cd $$(dirname $$p) && MYPYPATH=../.. ../../$(BIN)/python -m mypy --strict -p $$(basename $$p)) || exit 1; \
	done

clean:
	rm -rf $(VENV) out .pytest_cache .hypothesis
