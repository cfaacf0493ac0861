# Kovtunenko (1994), a clamped plate over a rigid obstacle: build, test, reproduce.
# `make all` and `make test` install what is missing (make deps) and build first.
BUILD ?= build
JOBS  ?= $(shell nproc 2>/dev/null || echo 2)
BINS  := $(BUILD)/plate $(BUILD)/crosscheck $(BUILD)/plate_tests

.PHONY: all test deps build crosscheck clean help FORCE

all: build ## build everything (later issues add results, figures and the paper)

help: ## list the targets
	@grep -E '^[a-z]+:.*## ' $(MAKEFILE_LIST) | sed 's/:.*## /\t/' | expand -t 12

deps: ## install missing Debian packages (apt-get; root or sudo)
	@scripts/deps.sh

# First configuration only: cmake --build re-configures by itself when CMakeLists.txt changes.
$(BUILD)/CMakeCache.txt: | deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release

# cmake --build is incremental: it relinks a program only when its sources changed, so the
# results that depend on a program are remade only then.
$(BINS) &: FORCE | deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)

build: $(BINS) ## compile the solver, the plate program and the tests

test: build ## run the test suite
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

crosscheck: results/crosscheck.md ## FreeFEM (HCT, gmsh) against this code: results/crosscheck.md

results/crosscheck.md results/crosscheck.csv &: $(BUILD)/crosscheck reference/square_with_circle.geo reference/penalty_hct.edp | deps
	$(BUILD)/crosscheck --out results --work $(BUILD)/crosscheck-work

clean: ## remove build products (not results/)
	rm -rf $(BUILD)

FORCE:
