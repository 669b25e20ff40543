#!/usr/bin/env bash
# ./pba grade: runs each exercise's tests (ctest names start with the tag, '-' written '_') and
# prints one row per exercise: tag, title, pass/FAIL, and a hint when failing.
# Usage: tools/grade.sh BUILD_DIR CATALOG.tsv [TAG...]   (no TAG: every exercise of the catalog)
# Exit status: 0 when every graded exercise passes, 1 when one fails, 2 on bad usage or an unknown TAG.
set -uo pipefail
build="${1:-}"
catalog="${2:-}"
[[ -d "$build" ]] || { echo "grade: no build directory $build" >&2; exit 2; }
[[ -f "$catalog" ]] || { echo "grade: no exercise catalog $catalog" >&2; exit 2; }
shift 2
wanted=("$@")
for tag in "${wanted[@]}"; do
  awk -F'\t' -v t="$tag" 'NR > 1 && $1 == t { found = 1 } END { exit !found }' "$catalog" ||
    { echo "grade: unknown exercise '$tag' (the tags are in $catalog)" >&2; exit 2; }
done
jobs="${PBA_JOBS:-$(nproc 2>/dev/null || echo 2)}"

passed=0
failed=0
printf '%-8s  %-44s  %5s  %-6s  %s\n' "TAG" "EXERCISE" "TIME" "RESULT" "HINT"
printf '%-8s  %-44s  %5s  %-6s  %s\n' "--------" "--------------------------------------------" "-----" "------" "----"
while IFS=$'\t' read -r tag lab title minutes hint; do
  [[ "$tag" == "tag" || -z "$tag" ]] && continue
  if [[ ${#wanted[@]} -gt 0 && " ${wanted[*]} " != *" $tag "* ]]; then continue; fi
  prefix="^${tag//-/_}_"
  log="$(ctest --test-dir "$build" -R "$prefix" --no-tests=error -j "$jobs" 2>&1)"
  status=$?
  total="$(grep -oE 'out of [0-9]+' <<<"$log" | grep -oE '[0-9]+' | tail -n 1)"
  if [[ $status -eq 0 && -n "$total" ]]; then
    printf '%-8s  %-44s  %5s  %-6s\n' "$tag" "$title" "${minutes}m" "pass"
    passed=$((passed + 1))
  else
    if grep -q 'No tests were found' <<<"$log"; then hint="no tests named ${tag//-/_}_* were found (build the tests first)"; fi
    printf '%-8s  %-44s  %5s  %-6s  %s\n' "$tag" "$title" "${minutes}m" "FAIL" "$hint"
    failed=$((failed + 1))
  fi
done <"$catalog"
echo
echo "grade: $passed passed, $failed failed"
[[ $failed -eq 0 ]]
