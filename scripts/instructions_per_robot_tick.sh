#!/usr/bin/env bash
# Instructions per robot-tick of the diffusion controller in tiled env4 at 100 and 10,000
# robots, counted by valgrind (repeatable, unlike wall time): the difference between two run
# lengths cancels the set-up. Usage: scripts/instructions_per_robot_tick.sh [build dir]
set -euo pipefail
build=${1:-build/release}
command -v valgrind >/dev/null || { echo "needs valgrind (apt-get install valgrind)" >&2; exit 2; }
count() { valgrind --tool=callgrind --callgrind-out-file=/dev/null "$build/bench/tick_count" "$1" "$2" 2>&1 |
          sed -n 's/.*Collected : \([0-9]*\).*/\1/p'; }
for spec in "1 1000" "10 10"; do
  set -- $spec
  tiles=$1; ticks=$2; robots=$((100 * tiles * tiles))
  base=$(count "$tiles" 0); run=$(count "$tiles" "$ticks")
  echo "$robots robots: $(( (run - base) / (robots * ticks) )) instructions per robot-tick"
done
