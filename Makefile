# Two entry points a fresh machine needs: `make run` and `make test` (see README.md).
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
PLUGINS := $(wildcard plugins/*/pyproject.toml)

.PHONY: install run test bench typecheck fuzz clean

$(STAMP): pyproject.toml $(PLUGINS)
	$(PYTHON) -m venv $(VENV)
	$(BIN)/pip install --quiet --upgrade pip
	$(BIN)/pip install --quiet -e '.[test,render,dask]' $(foreach p,$(PLUGINS),-e $(dir $(p)))
	touch $(STAMP)

install: $(STAMP)

run: $(STAMP)
	bash examples/run.sh

test: $(STAMP)
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
