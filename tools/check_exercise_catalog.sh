#!/usr/bin/env bash
# ctest exercises.catalog: resources/exercises.tsv, the solution blocks and the tests agree. Every tag of
# a stub has a catalog row, every row has a stub, a starred block and at least one test named after it.
# Lists tests only (ctest -N), runs none: no test runs ctest on another test's files.
# Usage: tools/check_exercise_catalog.sh SOURCE_ROOT BUILD_DIR
set -euo pipefail
src="$1"
build="$2"
catalog="$src/resources/exercises.tsv"
mapfile -t rows < <(awk -F'\t' 'NR > 1 && $1 != "" { print $1 }' "$catalog")
# The columns: tag, lab, title, minutes (the estimated time, a whole number of minutes), hint.
header="$(head -n 1 "$catalog")"
[[ "$header" == $'tag\tlab\ttitle\tminutes\thint' ]] || { echo "FAIL: $catalog: header is not tag, lab, title, minutes, hint"; exit 1; }
bad_rows="$(awk -F'\t' 'NR > 1 && $1 != "" && (NF != 5 || $4 !~ /^[1-9][0-9]*$/ || $4 > 120) { print $1 }' "$catalog")"
[[ -z "$bad_rows" ]] || { echo "FAIL: rows without five columns or an estimated time of 1-120 minutes: $bad_rows"; exit 1; }
mapfile -t stubs < <(grep -rhoE '// STUB: .*notImplemented\("[A-Z]+-[0-9]+"|// STUB: .*markNotImplemented\("[A-Z]+-[0-9]+"' \
  "$src/framework" "$src/labs" | grep -oE '[A-Z]+-[0-9]+' | sort -u)
# Membership through associative arrays: `printf | grep -q` under pipefail fails at random when grep
# exits at its first match and printf takes SIGPIPE.
declare -A in_rows=() in_stubs=()
for tag in "${rows[@]}"; do in_rows[$tag]=1; done
for tag in "${stubs[@]}"; do in_stubs[$tag]=1; done
fail=0
for tag in "${stubs[@]}"; do
  [[ -n "${in_rows[$tag]:-}" ]] || { echo "FAIL: $tag has a stub but no row in $catalog"; fail=1; }
done
# ctest -N writes Testing/Temporary/LastTest.log: list from a copy of the test lists, or this check would
# overwrite the log of the ctest run it is part of.
lists="$(mktemp -d)"
trap 'rm -rf "$lists"' EXIT
(cd "$build" && find . -name CTestTestfile.cmake -exec cp --parents {} "$lists/" \;)
listing="$(ctest --test-dir "$lists" -N)"
for tag in "${rows[@]}"; do
  [[ -n "${in_stubs[$tag]:-}" ]] || { echo "FAIL: $tag has a catalog row but no solution block with a stub"; fail=1; }
  grep -rqE "// \*\*\*\*\* $tag: " "$src/framework" "$src/labs" || { echo "FAIL: $tag has no starred block (// ***** $tag: title *****)"; fail=1; }
  n="$(grep -cE "Test +#[0-9]+: ${tag//-/_}_" <<<"$listing" || true)"
  if [[ "$n" -eq 0 ]]; then echo "FAIL: $tag has no tests named ${tag//-/_}_*"; fail=1; else echo "ok: $tag: $n tests"; fi
done
exit "$fail"
