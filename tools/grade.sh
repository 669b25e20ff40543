#!/usr/bin/env bash
# ./pba grade: runs each exercise's tests (ctest names start with the tag, '-' written '_') and
# prints one row per exercise: tag, title, pass/FAIL, and a hint when failing.
# Usage: tools/grade.sh BUILD_DIR CATALOG.tsv    Exit status: 0 when every exercise passes.
set -uo pipefail
build="$1"
catalog="$2"
[[ -d "$build" ]] || { echo "grade: no build directory $build" >&2; exit 2; }
[[ -f "$catalog" ]] || { echo "grade: no exercise catalog $catalog" >&2; exit 2; }

passed=0
failed=0
printf '%-8s  %-36s  %-6s  %s\n' "TAG" "EXERCISE" "RESULT" "HINT"
printf '%-8s  %-36s  %-6s  %s\n' "--------" "------------------------------------" "------" "----"
while IFS=$'\t' read -r tag lab title hint; do
  [[ "$tag" == "tag" || -z "$tag" ]] && continue
  prefix="^${tag//-/_}_"
  log="$(ctest --test-dir "$build" -R "$prefix" --no-tests=error 2>&1)"
  status=$?
  total="$(grep -oE 'out of [0-9]+' <<<"$log" | grep -oE '[0-9]+' | tail -n 1)"
  if [[ $status -eq 0 && -n "$total" ]]; then
    printf '%-8s  %-36s  %-6s\n' "$tag" "$title" "pass"
    passed=$((passed + 1))
  else
    if grep -q 'No tests were found' <<<"$log"; then hint="no tests named ${tag//-/_}_* were found (build the tests first)"; fi
    printf '%-8s  %-36s  %-6s  %s\n' "$tag" "$title" "FAIL" "$hint"
    failed=$((failed + 1))
  fi
done <"$catalog"
echo
echo "grade: $passed passed, $failed failed"
[[ $failed -eq 0 ]]
