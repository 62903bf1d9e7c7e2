# swarmpath: thin wrapper over the CMake presets (see README.md).
#   make run      build (release) and run the main job
#   make test     build and run every test in release and under ASan + UBSan, then check formatting
#   make asan     only the ASan + UBSan build and tests
#   make bench    build (release) and run the benchmarks
#   make format   clang-format every source file in place

JOBS ?= $(shell nproc)
SOURCES := $(shell git ls-files --cached --others --exclude-standard 'sim/*.cpp' 'sim/*.hpp' 'evolve/*.cpp' 'evolve/*.hpp' 'app/*.cpp' 'app/*.hpp' \
             'tests/*.cpp' 'tests/*.hpp' 'bench/*.cpp' 'bench/*.hpp' 2>/dev/null)
SCENARIO ?= configs/scenarios/paper/env4.toml

.PHONY: all build run test asan bench format format-check clean

all: build

build:
	cmake --preset release >/dev/null
	cmake --build --preset release -j $(JOBS)

run: build
	@mkdir -p results
	./build/release/swarmpath simulate --scenario $(SCENARIO) --ticks 3000 --trails --svg results/env4_diffusion.svg
	@echo "picture: results/env4_diffusion.svg"

test: build
	ctest --preset release -j $(JOBS)
	$(MAKE) --no-print-directory asan
	$(MAKE) --no-print-directory format-check

asan:
	cmake --preset asan >/dev/null
	cmake --build --preset asan -j $(JOBS)
	ctest --preset asan -j $(JOBS)

bench: build
	./build/release/bench/sim_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true

format:
	clang-format -i $(SOURCES)

format-check:
	@clang-format --dry-run --Werror $(SOURCES) && echo "format-check: $(words $(SOURCES)) files clean"

clean:
	rm -rf build
