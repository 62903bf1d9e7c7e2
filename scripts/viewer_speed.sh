#!/usr/bin/env bash
# How fast the web viewer draws: records 1 000 robots (tests/data/open_1000.toml, path formation,
# 300 s) and env4 at 100 robots, writes their pages and times them in headless Chromium
# (tests/web/viewer_speed.mjs: render() with the drawing flushed, and frames drawn while playing).
# A measurement for `make bench`; skipped when chromium or node is missing.
set -euo pipefail
cd "$(dirname "$0")/.."
B=build/release/swarmpath
out=build/release/viewer-speed
mkdir -p "$out"
if ! command -v node >/dev/null || ! { command -v chromium || command -v chromium-browser; } >/dev/null; then
  echo "viewer_speed: skipped (node or chromium missing: scripts/install-deps.sh installs them)"
  exit 0
fi
$B simulate --scenario tests/data/open_1000.toml --mode pf --record "$out/open_1000.swrec" >/dev/null
$B simulate --scenario configs/scenarios/paper/env4.toml --mode pf --record "$out/env4.swrec" >/dev/null
for run in open_1000 env4; do
  $B view "$out/$run.swrec" --out "$out/$run.html" >/dev/null
  node tests/web/viewer_speed.mjs --page "$out/$run.html"
done
