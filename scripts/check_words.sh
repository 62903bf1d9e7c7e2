#!/usr/bin/env bash
# The project speaks of itself: names behaviours, dates or commits, never how the work was organised.
# Fails (exit 1, listing file:line) when a tracked text file names a work stop ("stop 12", "stops
# 23-24", "stop-27"), an issue number ("issue 4", "issues #5"), a session, or a helper. A stop by a
# distance, a time or a count ("robots stop 70 cm away", "stop 300 ticks") is a behaviour, not a word
# about the work. Pictures (*.svg) and this check and its test are not read.
#   usage: scripts/check_words.sh [ROOT]    (default: the repository this script is in)
set -euo pipefail
root=${1:-$(cd "$(dirname "$0")/.." && pwd)}
cd "$root"
pattern='\b[Ss]tops?[- ][0-9]+(?!-?[0-9]*\s*(cm|mm|m|ticks?|s|%|degrees|robots|links)\b)|\b[Ii]ssues? #?[0-9]+|\b[Ss]essions?\b|\b[Hh]elpers?\b'
if git rev-parse --show-toplevel >/dev/null 2>&1; then
  mapfile -d '' files < <(git ls-files -z --cached --others --exclude-standard -- .)
else
  mapfile -d '' files < <(find . -type f -not -path './build/*' -not -path './.git/*' -print0)
fi
keep=()
for f in "${files[@]}"; do
  case "$f" in
    *.svg | */check_words.sh | check_words.sh | */check_words_test.sh | check_words_test.sh) continue ;;
  esac
  [ -f "$f" ] && keep+=("$f")
done
[ ${#keep[@]} -eq 0 ] && exit 0
if hits=$(grep -nIP -- "$pattern" "${keep[@]}"); then
  echo "check_words: these lines say how the work was organised (a stop, an issue, a session, a helper):"
  echo "$hits"
  echo "check_words: say what the text means instead: the behaviour, a date, a commit, or nothing"
  exit 1
fi
echo "check_words: ${#keep[@]} files clean"
