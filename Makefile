# Kovtunenko (1994), a clamped plate over a rigid obstacle: build, test, reproduce.
# `make all` and `make test` install what is missing (make deps) and build first.
BUILD ?= build
JOBS  ?= $(shell nproc 2>/dev/null || echo 2)

.PHONY: all test deps build clean help

all: build ## build everything (later issues add results, figures and the paper)

help: ## list the targets
	@grep -E '^[a-z]+:.*## ' $(MAKEFILE_LIST) | sed 's/:.*## /\t/' | expand -t 12

deps: ## install missing Debian packages (apt-get; root or sudo)
	@scripts/deps.sh

$(BUILD)/CMakeCache.txt: CMakeLists.txt | deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release

build: deps $(BUILD)/CMakeCache.txt ## compile the solver, the plate program and the tests
	cmake --build $(BUILD) -j $(JOBS)

test: build ## run the test suite
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

clean: ## remove build products (not results/)
	rm -rf $(BUILD)
