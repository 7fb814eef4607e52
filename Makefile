# contact4foam: the README's commands.
#   make run    install what is missing, build, run the default tutorial
#               (in a copy under $FOAM_RUN; it prints where)
#   make test   install what is missing, build, run all tests (pytest on
#               every core; a subset: make test PYTEST_ARGS="-k penalty")
#   make bench  run the benchmarks
#   make clean  remove all build output (distclean: also the OpenFOAM kit)

SHELL  := /bin/bash
PREFIX ?= $(or $(C4F_PREFIX),$(HOME)/.contact4foam)
ENV    := source etc/bashrc
# The clone this make runs in, not the one that last ran bin/bootstrap
export C4F_ROOT := $(CURDIR)
PY     := /usr/bin/python3
# pytest: a worker per core, the tests that share a run kept on one worker
PYTEST := $(PY) -m pytest tests -n auto --dist loadgroup
PYTEST_ARGS ?=
DEFAULT_TUTORIAL := tutorials/hertzCylinder

.PHONY: all bootstrap build run test bench clean distclean shellcheck

all: build

bootstrap:
	@bin/bootstrap

build: bootstrap
	@$(ENV) && ./Allwmake

# The default tutorial in a fresh copy under the run directory ($FOAM_RUN,
# $(PREFIX)/run), as OpenFOAM's habit is: the source tree stays clean
run: build
	@$(ENV) && case="$$FOAM_RUN/$(notdir $(DEFAULT_TUTORIAL))" \
	    && rm -rf "$$case" && mkdir -p "$$FOAM_RUN" \
	    && cp -r $(DEFAULT_TUTORIAL) "$$case" && "$$case/Allclean" >/dev/null \
	    && "$$case/Allrun" \
	    && echo "results: $$case (VTK/ for ParaView, log.* and postProcessing/contactReport)"

test: build
	@$(ENV) && $(PYTEST) $(PYTEST_ARGS)

bench: build
	@$(ENV) && $(PY) tests/bench/run.py && $(PY) tests/bench/searchBench.py

clean:
	@./Allclean

distclean: clean
	rm -rf "$(PREFIX)"

shellcheck:
	shellcheck -x bin/bootstrap Allwmake Allclean .ci/run bin/tools/c4fRunFunctions \
	    tutorials/*/Allrun tutorials/*/Allclean
