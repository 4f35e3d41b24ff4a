# Two entry points a fresh machine needs: `make run` and `make test` (see README.md). `make run` shows the tool
# working on the pure-Python build: it does not compile the hot path, three quarters of a fresh install's CPU
# time (docs/compiled.md); `make install` (and `make test`, `make bench`, which need it) compiles it.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
RUNTIME := $(VENV)/.runtime
STAMP  := $(VENV)/.installed
PLUGINS := $(wildcard plugins/*/pyproject.toml)
# The hot modules compiled with mypyc (pyproject.toml [tool.postproc] compiled) and the stamp of their build.
HOT    := $(shell sed -n '/^compiled = \[/,/^\]/p' pyproject.toml | grep -o '"[^"]*\.py"' | tr -d '"')
NATIVE := $(VENV)/.compiled

.PHONY: install compile bytecode run test bench callgrind typecheck fuzz differential clean

# The build's own requirements (pyproject.toml [build-system] requires: setuptools, the pinned mypy, pydantic),
# installed into the venv once, so that no pip install below makes a throw-away build environment of its
# own (two of them on a fresh machine, each fetching mypy) and the compile step starts at once. Built in the
# venv, setuptools' warning that an editable install is editable would print a box per package: silenced.
# The editable installs are setuptools' `compat` mode: a `.pth` line naming the checkout, where the default
# mode installs an import hook per package that every interpreter of the venv runs at start-up (with pathlib,
# urllib and importlib.util: 52.6M of a bare `python -c pass`'s 92.7M instructions, half its CPU). The peers
# of `make bench` run in this venv too: with the hooks, their starts carried that cost, which a user's own
# installation never has (docs/benchmarks.md, "Editable installs").
TOML = $(PYTHON) -c 'import tomllib; t = tomllib.load(open("pyproject.toml", "rb")); print(" ".join(chr(39) + r + chr(39) for r in $(1)))'
BUILD_REQUIRES = $(shell $(call TOML,t["build-system"]["requires"]))
SETUPTOOLS = $(shell $(call TOML,t["build-system"]["requires"] if r.startswith("setuptools")))

# Each step says what it does and, when done, how long it took (wall seconds: on a loaded machine CPU
# seconds are the figure to compare, docs/compiled.md).
# `make run` needs only the first: postproc and its plugins (pure Python) with their dependencies, and the
# setuptools their editable install builds with; the build tools and the extras are half the venv's CPU
# time (docs/benchmarks.md, branch suitetime). The second, which compiling and the suite need, installs
# everything (and so counts as the first too): a venv made before the split stays valid, nothing compiles again.
# A venv whose .venv/.installed is newer than these files (made before the split) has it all already: it is
# not installed again, which would also remove its compiled tree (a pure install does) behind make's back.
$(RUNTIME): pyproject.toml setup.py $(PLUGINS)
	@if [ -f $(STAMP) ] && [ -z "$$(find pyproject.toml setup.py $(PLUGINS) -newer $(STAMP))" ]; then \
	  echo "make: [venv] $(VENV) is there (.venv/.installed)"; else \
	echo "make: [venv] creating $(VENV): postproc and its plugins (pure Python) with their dependencies" && \
	start=$$(date +%s) && set -x && \
	$(PYTHON) -m venv $(VENV) && \
	$(BIN)/pip install --quiet $(SETUPTOOLS) && \
	POSTPROC_PURE=1 PYTHONWARNINGS=ignore::UserWarning $(BIN)/pip install --quiet --no-build-isolation --config-settings editable_mode=compat -e . $(foreach p,$(PLUGINS),-e $(dir $(p))) && \
	{ set +x; } 2>/dev/null && echo "make: [venv] $(VENV) made in $$(( $$(date +%s) - start )) s"; fi
	touch $(RUNTIME)

$(STAMP): pyproject.toml setup.py $(PLUGINS)
	@echo "make: [venv] creating $(VENV): postproc, its plugins, their dependencies, the build tools (mypy) and what the suite needs (pytest, hypothesis, pillow, dask)"
	@start=$$(date +%s) && set -x && \
	$(PYTHON) -m venv $(VENV) && \
	$(BIN)/pip install --quiet $(BUILD_REQUIRES) && \
	POSTPROC_PURE=1 PYTHONWARNINGS=ignore::UserWarning $(BIN)/pip install --quiet --no-build-isolation --config-settings editable_mode=compat -e '.[test,render,dask]' $(foreach p,$(PLUGINS),-e $(dir $(p))) && \
	{ set +x; } 2>/dev/null && echo "make: [venv] $(VENV) made in $$(( $$(date +%s) - start )) s"
	touch $(STAMP) $(RUNTIME)

# Compiles the hot path (pure Python where there is no C compiler), again when a hot module is edited
# (meanwhile postproc runs it as pure Python: postproc --version says which). mypyc type-checks and writes
# a C file a module (about a minute on one core), then the C compiler runs on every core (setup.py).
# Guided by a profile (PGO=1, the default; setup.py's POSTPROC_PGO): built instrumented, trained on the
# bench's workloads (benchmarks/pgo_training.py), built again: ~8% less CPU time on every row, for about
# twice the compile time (docs/compiled.md). `make compile PGO=0` builds once, without a profile.
PGO ?= 1
$(NATIVE): $(STAMP) $(HOT)
	@start=$$(date +%s); \
	if [ "$(PGO)" = 1 ]; then \
	  echo "make: [compile] 1/3 compiling the $(words $(HOT)) hot modules with mypyc, instrumented for a profile: type-checking, then C on $$(nproc) cores (a few minutes; postproc already runs, as pure Python)" && \
	  POSTPROC_PGO=generate PYTHONWARNINGS=ignore::UserWarning $(BIN)/pip install --quiet --no-deps --no-build-isolation --config-settings editable_mode=compat -e . && \
	  echo "make: [compile] 2/3 training the instrumented build on the bench's workloads (benchmarks/pgo_training.py)" && \
	  $(BIN)/python benchmarks/pgo_training.py && \
	  echo "make: [compile] 3/3 compiling them again, optimised by the profile" && \
	  POSTPROC_PGO=use PYTHONWARNINGS=ignore::UserWarning $(BIN)/pip install --quiet --no-deps --no-build-isolation --config-settings editable_mode=compat -e .; \
	else \
	  echo "make: [compile] compiling the $(words $(HOT)) hot modules with mypyc: type-checking, then C on $$(nproc) cores (a few minutes; postproc already runs, as pure Python)" && \
	  PYTHONWARNINGS=ignore::UserWarning $(BIN)/pip install --quiet --no-deps --no-build-isolation --config-settings editable_mode=compat -e .; \
	fi && echo "make: [compile] compiled in $$(( $$(date +%s) - start )) s: $$($(BIN)/postproc --version)"
	touch $(NATIVE)

# Byte-compile the editable packages (core, dialects, plugins) once, so that a start does not compile
# them again: pip compiles what it copies into site-packages, not an editable source tree, and where
# PYTHONDONTWRITEBYTECODE is set no run writes a .pyc. compileall writes them even then, and skips the
# files whose .pyc is up to date: cheap to repeat after an edit (make test does). On every core (-j 0).
bytecode: $(RUNTIME)
	@echo "make: [byte code] byte-compiling the core, the dialects and the plugins (what is up to date is skipped)"
	@start=$$(date +%s) && $(BIN)/python -m compileall -q -j 0 postproc dialects $(foreach p,$(PLUGINS),$(dir $(p))) && \
	  echo "make: [byte code] written in $$(( $$(date +%s) - start )) s"

compile: $(NATIVE) bytecode

install: compile

# The examples on whichever build is installed: pure Python on a fresh machine (identical results; the
# compiled hot path only runs faster), compiled once `make install` has run.
run: bytecode
	@echo "make: [examples] translating and verifying the bundled examples: $$($(BIN)/postproc --version)"
	$(BIN)/python examples/run.py
	@echo "make: [examples] done; 'make install' compiles the hot path (a few minutes), which 'make test' and 'make bench' do too"

# The whole suite against the compiled hot path, then against the pure-Python fallback (skipped where
# nothing was compiled: the first run was pure already). Each run spreads its tests over every core
# (pytest-xdist; JOBS=1 runs them in one process); a worker idle at the end takes tests from a busy one.
# The second run skips the tests marked one_build, the same in both builds (they run no compiled module:
# tests/conftest.py), with POSTPROC_SECOND_BUILD=1.
# A plugin's own suite (plugins/*/tests: the conformance suite with the settings of its pyproject.toml,
# about 8 s of CPU for the example plugin) runs from its folder, after the core's.
JOBS ?= auto
PYTEST := $(CURDIR)/$(BIN)/python -m pytest -n $(JOBS) --dist worksteal
PLUGIN_TESTS := $(patsubst %/tests/,%,$(wildcard plugins/*/tests/))
test: install
	$(BIN)/postproc --version
	$(PYTEST) && for p in $(PLUGIN_TESTS); do (cd $$p && $(PYTEST)) || exit 1; done
	if [ -f postproc/_compiled/manifest.txt ]; then \
	  POSTPROC_PURE=1 $(BIN)/postproc --version && POSTPROC_PURE=1 POSTPROC_SECOND_BUILD=1 $(PYTEST) && \
	  for p in $(PLUGIN_TESTS); do (cd $$p && POSTPROC_PURE=1 POSTPROC_SECOND_BUILD=1 $(PYTEST)) || exit 1; done; fi

bench: compile
	$(BIN)/pip install --quiet -r benchmarks/requirements.txt
	$(BIN)/python benchmarks/run.py $(BENCH_ARGS)

# The same rows in instructions (valgrind's callgrind, one row at a time, niced; docs/benchmarks.md): a
# baseline's instructions, the ratio, PASS/MISS. Sizes: CALLGRIND_SMALL / CALLGRIND_LARGE (thousand blocks, hundred holes);
# CALLGRIND_ARGS="--rows grblhal toolpath" for some rows, "--reuse" to keep rows measured before.
callgrind: compile
	$(BIN)/pip install --quiet -r benchmarks/requirements.txt
	$(BIN)/python benchmarks/callgrind_summary.py $(CALLGRIND_ARGS)

# The seeded differentials against LinuxCNC's rs274 at the full run's size (issue 26: 2,000 programs each, 200 in
# `make test`): cutter and tool length compensation (and its grbl lowering), frames. Not in CI (about ten times
# the make-test share of those files); PROGRAMS=n sets another count. Skips with its reason where rs274 is absent.
PROGRAMS ?= 2000
differential: $(STAMP)
	POSTPROC_COMPENSATION_PROGRAMS=$(PROGRAMS) POSTPROC_FRAME_PROGRAMS=$(PROGRAMS) $(BIN)/python -m pytest -n $(JOBS) \
	  tests/test_cutter_compensation_rs274.py tests/test_cutter_compensation_grbl.py tests/test_frames.py

fuzz: $(STAMP)
	$(BIN)/python -m tests.support.fuzz_main --minutes $(or $(MINUTES),10) --out fuzz-failures

typecheck: $(STAMP)
	$(BIN)/pip install --quiet mypy
	$(BIN)/python -m mypy --strict -p postproc -p dialects
	for p in plugins/*/postproc_*/__init__.py; do p=$$(dirname $$p); \
	  (cd $$(dirname $$p) && MYPYPATH=../.. ../../$(BIN)/python -m mypy --strict -p $$(basename $$p)) || exit 1; \
	done

clean:
	rm -rf $(VENV) out .pytest_cache .hypothesis build postproc/_compiled
