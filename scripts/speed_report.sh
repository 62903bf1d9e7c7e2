#!/usr/bin/env bash
# The speed report of docs/speed.md on this host, in one command:
#  1. the table against ARGoS (bench/speed_report: diffusion at 100 and 1 000 robots, whole pf and
#     TA runs in env4, 100 robots, seed 3), each whole run on one core (pinned with taskset when
#     there is one), CPU time best and median of --repeat; ARGoS takes 10 physics sub-steps a tick,
#     swarmpath one Box2D step;
#  2. evolution throughput on configs/evolve/default.toml: simulations per second at each of
#     --threads (default 1, 2 and every core) for --generations generations, and the speed-up over
#     one thread (target at 2 threads: >= 1.9x).
# Writes OUT/table.md, OUT/evolve.md and OUT/summary.md (both, with the host). About 1 minute plus
# 2-3 minutes per thread count on a 16-core machine.
#
#   scripts/speed_report.sh [--repeat 3] [--threads "1 2 16"] [--generations 2] [--out DIR] [--build DIR]
#   scripts/speed_report.sh --repeat 1 --threads "1 2" --generations 1     # a small check, 2 cores
set -euo pipefail
cd "$(dirname "$0")/.."

repeat=3
threads="1 2 $(nproc)"
generations=2
out=results/speed_report
build_dir=build/release
while (($#)); do
  case $1 in
    --repeat) repeat=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --generations) generations=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --build) build_dir=$2; shift 2 ;;
    -h|--help) sed -n '2,15p' "$0"; exit 0 ;;
    *) echo "speed_report: unknown option $1 (see --help)" >&2; exit 2 ;;
  esac
done
[[ $repeat =~ ^[1-9][0-9]*$ && $generations =~ ^[1-9][0-9]*$ ]] ||
  { echo "speed_report: --repeat and --generations take a whole number >= 1" >&2; exit 2; }
for t in $threads; do
  [[ $t =~ ^[1-9][0-9]*$ ]] || { echo "speed_report: --threads takes whole numbers >= 1 (\"$threads\")" >&2; exit 2; }
done

if ! [ -x "$build_dir/bench/speed_report" ] || ! [ -x "$build_dir/swarmpath" ]; then
  [ "$build_dir" = build/release ] || { echo "speed_report: no speed_report or swarmpath in $build_dir" >&2; exit 2; }
  cmake --preset release >/dev/null
  cmake --build --preset release -j "$(nproc)" --target speed_report swarmpath
fi
mkdir -p "$out"

# 1. the table, on one core (the last: the first often takes the system's interrupts)
pin=()
if command -v taskset >/dev/null; then pin=(taskset -c "$(($(nproc) - 1))"); fi
echo "speed_report: the table (${pin[*]:-unpinned}), best of $repeat" >&2
"${pin[@]}" "$build_dir/bench/speed_report" --repeat "$repeat" | tee "$out/table.md"

# 2. evolution throughput at each thread count
echo "speed_report: evolution throughput, configs/evolve/default.toml, $generations generation(s)" >&2
{
  echo "Evolution throughput: swarmpath evolve --config configs/evolve/default.toml --generations $generations"
  echo "(every simulation of the run, the finalists' re-evaluation included; wall time; $(nproc) cores)"
  echo
  echo "| threads | simulations | seconds | simulations/s | speed-up over 1 thread | threads busy |"
  echo "|---|---|---|---|---|---|"
} >"$out/evolve.md"
base=""
for t in $threads; do
  log=$out/evolve-t$t.log
  "$build_dir/swarmpath" evolve --config configs/evolve/default.toml --generations "$generations" \
    --threads "$t" --out "$out/evolve-t$t" --force >"$log.out" 2>"$log"
  # "done in X s (...): N simulations in S s (R per s) on T threads; threads busy B %"
  line=$(grep -m1 'simulations in' "$log") || { echo "speed_report: no summary in $log" >&2; exit 1; }
  sims=$(sed -E 's/.*: ([0-9]+) simulations in.*/\1/' <<<"$line")
  secs=$(sed -E 's/.* simulations in ([0-9.]+) s.*/\1/' <<<"$line")
  rate=$(sed -E 's/.*\(([0-9.]+) per s\).*/\1/' <<<"$line")
  busy=$(sed -E 's/.*threads busy ([0-9]+) %.*/\1/' <<<"$line")
  [ -n "$base" ] || base=$rate
  speedup=$(awk -v r="$rate" -v b="$base" 'BEGIN { printf "%.2f", r / b }')
  echo "| $t | $sims | $secs | $rate | ${speedup}x | $busy % |" >>"$out/evolve.md"
  echo "  $t thread(s): $rate simulations/s (${speedup}x)" >&2
done
cat "$out/evolve.md"
{
  echo "# Speed report, $(date -u +%Y-%m-%d), commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown)"
  echo
  cat "$out/table.md"
  echo
  cat "$out/evolve.md"
} >"$out/summary.md"
echo "speed_report: $out/summary.md" >&2
