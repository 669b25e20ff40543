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
mapfile -t stubs < <(grep -rhoE '// STUB: .*notImplemented\("[A-Z]+-[0-9]+"|// STUB: .*markNotImplemented\("[A-Z]+-[0-9]+"' \
  "$src/framework" "$src/labs" | grep -oE '[A-Z]+-[0-9]+' | sort -u)
fail=0
for tag in "${stubs[@]}"; do
  printf '%s\n' "${rows[@]}" | grep -qx "$tag" || { echo "FAIL: $tag has a stub but no row in $catalog"; fail=1; }
done
listing="$(ctest --test-dir "$build" -N)"
for tag in "${rows[@]}"; do
  printf '%s\n' "${stubs[@]}" | grep -qx "$tag" || { echo "FAIL: $tag has a catalog row but no solution block with a stub"; fail=1; }
  grep -rqE "// \*\*\*\*\* $tag: " "$src/framework" "$src/labs" || { echo "FAIL: $tag has no starred block (// ***** $tag: title *****)"; fail=1; }
  n="$(grep -cE "Test +#[0-9]+: ${tag//-/_}_" <<<"$listing" || true)"
  if [[ "$n" -eq 0 ]]; then echo "FAIL: $tag has no tests named ${tag//-/_}_*"; fail=1; else echo "ok: $tag: $n tests"; fi
done
exit "$fail"
