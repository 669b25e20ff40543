#!/usr/bin/env bash
# The exercise checks of docs/architecture.md §5 (ctest exercises.student-release), on two generated trees:
#  1. the student release: it builds with -Werror, every exercise test fails, every other test passes,
#     ./pba grade reports failures, and no solution's lines appear anywhere in it (check_solution_leaks.py);
#  2. (PBA_CHECK_ISOLATION=0 leaves it out) the switchable tree (one build, each
#     exercise switched to its stub at run time): every tag alone stubbed fails exactly its own tests
#     (check_exercise_isolation.py). Tests that need a display (label display: screenshots and the
#     window-driving ui tests) are left out: they run the same scenes as lab.<lab>.headless, which is
#     rerun for every tag, and only add rendering, which no exercise touches. They pass in step 1. So is
#     label extremes (every parameter at its extremes, minutes per lab): it reruns those scenes with other
#     parameter values, would be rerun for each of a lab's tags, and passes with every stub in step 1.
# Both trees are built in WORK_DIR; with ccache installed the second build reuses the first one's objects
# (only the files with solution blocks differ). Usage: tools/check_student_release.sh SOURCE_ROOT WORK_DIR
set -euo pipefail
src="$(cd "$1" && pwd)"
work="$2"
jobs="${PBA_JOBS:-$(nproc 2>/dev/null || echo 2)}"
rm -rf "$work"
mkdir -p "$work"
work="$(cd "$work" && pwd)"
cmake_args=(-G Ninja -DCMAKE_BUILD_TYPE=Release -DPBA_BUILD_BENCH=OFF -DPBA_WARNINGS_AS_ERRORS=ON)
if command -v ccache >/dev/null; then
  export CCACHE_DIR="$work/ccache" CCACHE_BASEDIR="$work" CCACHE_NOHASHDIR=1
  cmake_args+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
build_tree() {  # build_tree DIR: configure and build DIR/build
  cmake -S "$1" -B "$1/build" "${cmake_args[@]}" >/dev/null
  cmake --build "$1/build" -j "$jobs" >"$1/build.log" 2>&1 || { tail -n 40 "$1/build.log"; echo "FAIL: $1 does not build"; exit 1; }
}

echo "== the student release"
bash "$src/tools/student_release.sh" "$src" "$work/release"
build_tree "$work/release"
cd "$work/release"
tags="$(awk -F'\t' 'NR > 1 && $1 != "" { gsub("-", "_", $1); printf "%s^%s_", (n++ ? "|" : ""), $1 }' resources/exercises.tsv)"
echo "== exercise tests must all fail against the stubs"
set +e
exercise_log="$(ctest --test-dir build -R "$tags" --no-tests=error -j "$jobs" 2>&1)"
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
ctest --test-dir build -E "$tags" -LE ui --output-on-failure -j "$jobs" || { echo "FAIL: non-exercise tests fail in the student release"; exit 1; }
echo "== ./pba grade must report failures"
if bash tools/grade.sh build resources/exercises.tsv >"$work/grade.log"; then cat "$work/grade.log"; echo "FAIL: grade passed on stubs"; exit 1; fi
echo "ok: grade reports $(grep -c ' FAIL ' "$work/grade.log") failing exercises"
echo "== no solution's lines in the release"
python3 "$src/tools/check_solution_leaks.py" "$src" "$work/release"

echo "student release check: ok"
[[ "${PBA_CHECK_ISOLATION:-1}" == 0 ]] && exit 0

echo "== the switchable tree: each exercise alone stubbed"
bash "$src/tools/student_release.sh" --switchable "$src" "$work/switchable"
build_tree "$work/switchable"
python3 "$src/tools/check_exercise_isolation.py" "$work/switchable/build" "$work/switchable/resources/exercises.tsv" --jobs "$jobs" \
  --skip-label display --skip-label extremes
echo "isolation check: ok"
