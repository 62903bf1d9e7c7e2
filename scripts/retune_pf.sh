#!/usr/bin/env bash
# Retunes genomes/tuned-pf.toml on the arena families and measures it against the default genome
# on the generalisation benchmark (docs/generalisation.md):
#   1. swarmpath evolve --config configs/evolve/tuned-pf.toml --threads N   (CMA-ES on fresh
#      family arenas every generation; validation arenas choose the final genome)
#   2. its best genome and run.json copied to OUT/tuned-pf.toml and OUT/tuned-pf.run.json
#   3. swarmpath benchmark --config configs/benchmarks/generalisation.toml --params OUT/tuned-pf.toml
#        --against genomes/default.toml --mode pf   (markdown, JSON, SVG into OUT)
# Each step's wall time and command go to OUT/summary.md, with the benchmark's table and verdict.
#
#   scripts/retune_pf.sh [--out DIR] [--threads N] [--generations G] [--resume]
#                        [--config FILE] [--benchmark FILE] [--families a,b] [--no-paper]
#                        [--skip-evolve] [--skip-benchmark] [--swarmpath CMD]
#   scripts/retune_pf.sh --generations 1 --families open,wall-gap --no-paper   # a small check
#   scripts/retune_pf.sh --install DIR     # DIR/tuned-pf.toml and DIR/tuned-pf.run.json into
#                                          # genomes/; genomes/tuned.toml and README name the config
#
# --out: default results/retune-pf. --threads: default every core. --generations: replaces the
# config's budget (with --resume, the total). --swarmpath (or the SWARMPATH environment variable):
# the program to run, a command line that may start with a wrapper (e.g. a bundled loader's
# bin/swarmpath-run, scripts/mpi_scaling.sh --bundle); default build/release/swarmpath, built here
# first when it is missing.
set -euo pipefail
cd "$(dirname "$0")/.."

out=results/retune-pf
threads=$(nproc)
generations=""
resume=""
config=configs/evolve/tuned-pf.toml
benchmark=configs/benchmarks/generalisation.toml
against=genomes/default.toml
families=""
no_paper=""
skip_evolve=""
skip_benchmark=""
install=""
swarmpath_cmd=${SWARMPATH:-}
while (($#)); do
  case $1 in
    --out) out=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --generations) generations=$2; shift 2 ;;
    --resume) resume=yes; shift ;;
    --config) config=$2; shift 2 ;;
    --benchmark) benchmark=$2; shift 2 ;;
    --families) families=$2; shift 2 ;;
    --no-paper) no_paper=yes; shift ;;
    --skip-evolve) skip_evolve=yes; shift ;;
    --skip-benchmark) skip_benchmark=yes; shift ;;
    --swarmpath) swarmpath_cmd=$2; shift 2 ;;
    --install) install=$2; shift 2 ;;
    -h|--help) sed -n '2,22p' "$0"; exit 0 ;;
    *) echo "retune_pf: unknown option $1 (see --help)" >&2; exit 2 ;;
  esac
done

# --install DIR: the genome and its run.json into genomes/, the manifest's entry onto its config
if [ -n "$install" ]; then
  for f in tuned-pf.toml tuned-pf.run.json; do
    [ -f "$install/$f" ] || { echo "retune_pf: $install/$f: no such file" >&2; exit 2; }
  done
  head -1 "$install/tuned-pf.toml" | grep -q '^# swarmpath evolve' ||
    { echo "retune_pf: $install/tuned-pf.toml: not a genome written by swarmpath evolve" >&2; exit 2; }
  grep -q "\"file\": \"$config\"" "$install/tuned-pf.run.json" ||
    { echo "retune_pf: $install/tuned-pf.run.json: not a run of $config" >&2; exit 2; }
  cp "$install/tuned-pf.toml" genomes/tuned-pf.toml
  cp "$install/tuned-pf.run.json" genomes/tuned-pf.run.json
  # the [[genome]] entry whose params = "tuned-pf.toml": its config line names the config
  awk -v cfg="../$config" '
    /^\[\[genome\]\]/ { entry = 0 }
    /^params = "tuned-pf.toml"/ { entry = 1 }
    entry && /^config = / { $0 = "config = \"" cfg "\"" }
    { print }' genomes/tuned.toml >genomes/tuned.toml.new
  mv genomes/tuned.toml.new genomes/tuned.toml
  # README's list of genomes: where tuned-pf.toml comes from
  sed -i 's|`tuned-pf.toml` (+ `tuned-pf.run.json`) the best of `configs/evolve/paper-pf-short.toml`|`tuned-pf.toml` (+ `tuned-pf.run.json`) the best of `configs/evolve/tuned-pf.toml` (path formation tuned on the arena families, scripts/retune_pf.sh)|' README.md
  grep -A2 'params = "tuned-pf.toml"' genomes/tuned.toml
  echo "retune_pf: installed genomes/tuned-pf.toml and genomes/tuned-pf.run.json from $install;"
  echo "  check: ctest --preset release -R Verify (each genome holds what its run chose)"
  exit 0
fi

if [ -n "$swarmpath_cmd" ]; then
  read -r -a swarmpath <<<"$swarmpath_cmd"
else
  if [ ! -x build/release/swarmpath ]; then
    echo "retune_pf: building build/release/swarmpath"
    cmake --preset release >/dev/null
    cmake --build --preset release -j "$(nproc)" --target swarmpath
  fi
  swarmpath=(build/release/swarmpath)
fi

mkdir -p "$out"
summary=$out/summary.md
[ -n "$skip_evolve" ] && [ -f "$summary" ] || : >"$summary"
say() { echo "$@" | tee -a "$summary"; }
now() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.0f", b - a }'; }

cpu=$(awk -F': ' '/model name/ { print $2; exit }' /proc/cpuinfo 2>/dev/null || true)
say "## Retuning tuned-pf: $(date -u +%FT%TZ), $(uname -n), $(nproc) cores${cpu:+ ($cpu)}, --threads $threads"
say ""

if [ -z "$skip_evolve" ]; then
  evolve=(evolve --config "$config" --out "$out/evolve" --threads "$threads")
  [ -n "$generations" ] && evolve+=(--generations "$generations")
  if [ -n "$resume" ]; then evolve+=(--resume); else evolve+=(--force); fi
  say "evolve: \`swarmpath ${evolve[*]}\`"
  t0=$(now)
  "${swarmpath[@]}" "${evolve[@]}" 2>&1 | tee "$out/evolve.log"
  t1=$(now)
  cp "$out/evolve/best.toml" "$out/tuned-pf.toml"
  cp "$out/evolve/run.json" "$out/tuned-pf.run.json"
  gens=$(($(wc -l <"$out/evolve/log.csv") - 1))
  say ""
  say "evolve wall time: $(elapsed "$t0" "$t1") s ($gens generations in log.csv, finalists re-evaluated)"
  say "best genome: $out/tuned-pf.toml (its run: $out/tuned-pf.run.json)"
  say ""
fi

if [ -z "$skip_benchmark" ]; then
  [ -f "$out/tuned-pf.toml" ] || { echo "retune_pf: $out/tuned-pf.toml: no genome (run the evolve step)" >&2; exit 2; }
  bench=(benchmark --config "$benchmark" --params "$out/tuned-pf.toml" --against "$against" --mode pf
         --threads "$threads" --json "$out/benchmark.json" --md "$out/benchmark.md" --svg "$out/benchmark.svg")
  [ -n "$families" ] && bench+=(--families "$families")
  [ -n "$no_paper" ] && bench+=(--no-paper)
  say "benchmark: \`swarmpath ${bench[*]}\`"
  t0=$(now)
  "${swarmpath[@]}" "${bench[@]}" >"$out/benchmark.log" 2>&1 || { tail -20 "$out/benchmark.log" >&2; exit 1; }
  t1=$(now)
  say ""
  say "benchmark wall time: $(elapsed "$t0" "$t1") s"
  say ""
  cat "$out/benchmark.md" >>"$summary"
  grep -E '^\*\*A (beats|does not beat) B\*\*' "$out/benchmark.md" || true
fi
echo "retune_pf: $summary"
