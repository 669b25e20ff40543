#!/usr/bin/env bash
# The ctest check of DESIGN.md §5: in a freshly generated student release the tree builds, every
# exercise test fails, every other test passes, and ./pba grade reports failures.
# Usage: tools/check_student_release.sh SOURCE_ROOT WORK_DIR
set -euo pipefail
src="$1"
work="$2"
rm -rf "$work"
bash "$src/tools/student_release.sh" "$src" "$work/tree"
cd "$work/tree"
echo "== configure and build the student tree"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DPBA_BUILD_BENCH=OFF -DPBA_WARNINGS_AS_ERRORS=ON >/dev/null
cmake --build build -j "${PBA_JOBS:-2}" >/dev/null || { echo "FAIL: the student release does not build"; exit 1; }

tags="$(awk -F'\t' 'NR > 1 && $1 != "" { gsub("-", "_", $1); printf "%s^%s_", (n++ ? "|" : ""), $1 }' resources/exercises.tsv)"
echo "== exercise tests must all fail (regex: $tags)"
set +e
exercise_log="$(ctest --test-dir build -R "$tags" --no-tests=error 2>&1)"
set -e
passed_exercise_tests="$(grep -E '^ *[0-9]+/[0-9]+ Test +#[0-9]+: .* Passed' <<<"$exercise_log" || true)"
total="$(grep -oE 'out of [0-9]+' <<<"$exercise_log" | grep -oE '[0-9]+' | tail -n 1)"
if [[ -z "$total" || "$total" -eq 0 ]]; then echo "FAIL: no exercise tests found"; exit 1; fi
if [[ -n "$passed_exercise_tests" ]]; then
  echo "FAIL: these exercise tests pass against the stubs (they must test the exercise):"
  echo "$passed_exercise_tests"
  exit 1
fi
echo "ok: all $total exercise tests fail against the stubs"

echo "== every other test must pass"
ctest --test-dir build -E "$tags" --output-on-failure -j "${PBA_JOBS:-2}" || { echo "FAIL: non-exercise tests fail in the student release"; exit 1; }

echo "== ./pba grade must report failures"
if bash tools/grade.sh build resources/exercises.tsv; then echo "FAIL: grade passed on stubs"; exit 1; fi
echo "student release check: ok"
