#!/usr/bin/env bash
# scripts/check_words.sh flags words about how the work was organised and leaves behaviours alone.
set -euo pipefail
check="$(cd "$(dirname "$0")/../.." && pwd)/scripts/check_words.sh"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "check_words_test: $1"; exit 1; }
# legitimate text: distances, times and counts after "stop", and other words that contain the patterns
printf '%s\n' "A forming robot may stop 70 cm from its target." "robots stop 300 ticks later" \
  "the tissue 4 of the journal" "stop as a subgoal" "the robots stop-and-go" "stops 5-10 cm short" > "$dir/ok.md"
out=$(bash "$check" "$dir") || fail "flagged legitimate text: $out"
for bad in "measured at stop 27" "Stop 33: the second allocation" "stops 23-24" "the stop-24 host" \
  "see issue 4" "issues #12 and 13" "this session" "Sessions" "a helper" "Helpers shared by"; do
  printf '%s\n' "fine line" "$bad" > "$dir/bad.md"
  if out=$(bash "$check" "$dir"); then fail "did not flag: $bad"; fi
  [[ $out == *"bad.md:2:"* ]] || fail "flagged the wrong line for: $bad ($out)"
done
echo "check_words_test: ok"
