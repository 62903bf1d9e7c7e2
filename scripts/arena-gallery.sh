#!/usr/bin/env bash
# Redraws the gallery of docs/arena-families.md: two seeds of every arena family at its defaults.
#   bash scripts/arena-gallery.sh [build/release/swarmpath]
set -euo pipefail
cd "$(dirname "$0")/.."
B=${1:-build/release/swarmpath}
mkdir -p docs/arenas
for family in open clutter wall-gap u-trap corridor serpentine rooms mixed; do
  for seed in 1 2; do
    "$B" arena generate --family "$family" --seed "$seed" --svg "docs/arenas/$family-$seed.svg" --px-per-m 16 >/dev/null
  done
done
echo "wrote docs/arenas/*.svg"
