#!/bin/bash
# Simulations saved by adaptive capping and racing the finalists, and the fresh-seed quality of
# the result, on one evolve config: three runs at 2 threads,
#   off    the config as it is
#   on     + [evaluation] capping = true (fraction 0.5) and [reevaluate] race = true
#   on-k2  the same with twice the finalists (top_k x 2): what racing's savings buy at about the same budget
# Usage: scripts/measure-racing.sh CONFIG OUT_DIR [GENERATIONS]   (docs/racing.md)
# CONFIG must leave capping and race unset; GENERATIONS replaces its [budget] generations.
set -euo pipefail
config=$1
out=$2
generations=${3:-}
bin=${SWARMPATH:-build/release/swarmpath}
mkdir -p "$out"
dir=$(cd "$(dirname "$config")" && pwd)
# absolute paths, so the copies in OUT_DIR find the config's params and scenarios
absolute() { sed -E "s#\"(\.\./[^\"]*)\"#\"$dir/\1\"#g" "$1"; }
absolute "$config" > "$out/off.toml"
if [ -n "$generations" ]; then sed -i -E "s/^generations = [0-9]+/generations = $generations/" "$out/off.toml"; fi
sed -E -e 's/^\[evaluation\].*/&\ncapping = true\ncapping_fraction = 0.5/' \
  -e 's/^\[reevaluate\].*/&\nrace = true/' "$out/off.toml" > "$out/on.toml"
top_k=$(grep -E '^top_k = [0-9]+' "$out/off.toml" | head -1 | sed -E 's/top_k = ([0-9]+).*/\1/')
sed -E "s/^top_k = [0-9]+/top_k = $((2 * ${top_k:-3}))/" "$out/on.toml" > "$out/on-k2.toml"
for v in off on on-k2; do
  /usr/bin/time -f "%U %e" -o "$out/$v.time" "$bin" evolve --config "$out/$v.toml" --out "$out/$v" \
    --threads 2 --force --no-wall-time > "$out/$v.log" 2>&1
done
/usr/bin/python3 - "$out" <<'PY'
import json, sys
out = sys.argv[1]
print("| run | CPU s | wall s | generation runs | capped runs | reruns | re-evaluation sims (of) | best's fresh-seed fitness | success |")
print("|---|---|---|---|---|---|---|---|---|")
for v in ["off", "on", "on-k2"]:
    j = json.load(open(f"{out}/{v}/run.json"))
    cpu, wall = open(f"{out}/{v}.time").read().split()
    k = j.get("capping", {})
    r = j.get("racing", {})
    n = len(j["finalists"]) + 1
    reev = len(j["seeds"]["reevaluation"])
    sims = f'{r["simulations"]} ({r["simulations_without_racing"]})' if r else f"{n * reev} ({n * reev})"
    b = j["best"]["reevaluated"]
    print(f'| {v} | {cpu} | {wall} | {j["runs"]} | {k.get("capped_runs", 0)} | {k.get("reruns", 0)} | {sims} | '
          f'{b["fitness"]:.4f} | {b["success_rate"]:.3f} |')
PY
