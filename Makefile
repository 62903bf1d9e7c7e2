# swarmpath: thin wrapper over the CMake presets (see README.md).
#   make run      build (release), evolve with configs/evolve/default.toml, evaluate the best against
#                 genomes/default.toml on fresh seeds, export it for ARGoS, write the run's report page
#   make test     build and run every test in release and under ASan + UBSan, then check formatting
#   make asan     only the ASan + UBSan build and tests
#   make bench    build (release) and run the benchmarks (the viewer's drawing speed too)
#   make format   clang-format every source file in place
#   make verify-genomes  (not in CI: minutes) re-run every shipped tuned genome (genomes/tuned.toml)
#                 against the default on fresh seeds and arenas: does each still win?
#   make benchmark       (not in CI: about half an hour on 2 cores) the generalisation benchmark of
#                 genomes/default.toml, into results/benchmark/

JOBS ?= $(shell nproc)
SOURCES := $(shell git ls-files --cached --others --exclude-standard 'sim/*.cpp' 'sim/*.hpp' 'evolve/*.cpp' 'evolve/*.hpp' 'app/*.cpp' 'app/*.hpp' \
             'tests/*.cpp' 'tests/*.hpp' 'bench/*.cpp' 'bench/*.hpp' 'python/*.cpp' 'python/*.hpp' 2>/dev/null)

.PHONY: all build run test asan bench format format-check clean verify-genomes benchmark

all: build

build:
	cmake --preset release >/dev/null
	cmake --build --preset release -j $(JOBS)

run: build
	@mkdir -p results
	./build/release/swarmpath evolve --config configs/evolve/default.toml --threads $(JOBS) --force
	./build/release/swarmpath evaluate --params results/evolve/default/best.toml --against genomes/default.toml \
	  --scenarios configs/scenarios/paper/env1.toml configs/scenarios/paper/env3.toml configs/scenarios/paper/env4.toml \
	  --robots 60 --seeds 4 --seed-base 1000 --threads $(JOBS) --json results/evolve/default/evaluate.json
	./build/release/swarmpath export --params results/evolve/default/best.toml --format argos \
	  --out results/evolve/default/best.argos.xml
	./build/release/swarmpath report results/evolve/default --out results/evolve/default/report.html --threads $(JOBS)
	@echo "files: results/evolve/default/ (best.toml, log.csv, fitness.svg, run.json, checkpoint.json, evaluate.json, best.argos.xml)"
	@echo "report: results/evolve/default/report.html (open it in a browser)"

test: build
	ctest --preset release -j $(JOBS)
	$(MAKE) --no-print-directory asan
	$(MAKE) --no-print-directory format-check

asan:
	cmake --preset asan >/dev/null
	cmake --build --preset asan -j $(JOBS)
	ctest --preset asan -j $(JOBS)

bench: build
	./build/release/bench/sim_bench --benchmark_repetitions=9 --benchmark_enable_random_interleaving=true \
		--benchmark_report_aggregates_only=true
	./build/release/bench/growth 15
	./build/release/bench/speed_report --repeat 3
	bash scripts/viewer_speed.sh

verify-genomes: build
	./build/release/swarmpath verify --manifest genomes/tuned.toml --threads $(JOBS)

benchmark: build
	@mkdir -p results/benchmark
	./build/release/swarmpath benchmark --config configs/benchmarks/generalisation.toml --params genomes/default.toml \
	  --threads $(JOBS) --json results/benchmark/paper.json --md results/benchmark/paper.md --svg results/benchmark/paper.svg

format:
	clang-format -i $(SOURCES)

format-check:
	@clang-format --dry-run --Werror $(SOURCES) && echo "format-check: $(words $(SOURCES)) files clean"

clean:
	rm -rf build
