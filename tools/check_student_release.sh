#!/usr/bin/env bash
# The exercise checks of docs/architecture.md §5 (ctest exercises.student-release), on this build and two
# generated trees.
#
# Every solution block sits in a .cpp file of the physics library, which is a shared library
# (PBA_PHYSICS_SHARED): a tree that differs from this one only in those blocks needs its physics library
# built, nothing else, and this build's executables run against it with LD_LIBRARY_PATH. So:
#  1. the student release (tools/student_release.sh): it configures, its physics library builds with the
#     release preset's flags and -Werror (the hand-out's own presets leave -Werror off; the check turns it on) (the other files of the hand-out are this tree's, which built),
#     and against it every exercise test fails, every other test passes (the window-driving ui tests
#     too: a check that fails while its lab ran stubs skips, "needs TAG"), ./pba grade reports failures,
#     and no solution's lines appear anywhere in it (check_solution_leaks.py);
#  2. (PBA_CHECK_ISOLATION=0 leaves it out) the switchable tree (each exercise switched to its stub at
#     run time): every tag alone stubbed fails exactly its own tests (check_exercise_isolation.py). Tests
#     that need a display (label display: screenshots and the window-driving ui tests) are left out: they
#     run the same scenes as lab.<lab>.headless, which is rerun for every tag, and only add rendering,
#     which no exercise touches. They pass in step 1. So is label extremes (every parameter at its
#     extremes, minutes per lab): it reruns those scenes with other parameter values, would be rerun for
#     each of a lab's tags, and passes with every stub in step 1.
# The trees compile through this build's compiler cache (its build/ccache) with paths relative to each
# tree, so only the files with solution blocks compile again.
# Usage: tools/check_student_release.sh SOURCE_ROOT BUILD_DIR WORK_DIR [CCACHE_DIR]
set -euo pipefail
src="$(cd "$1" && pwd)"
build="$(cd "$2" && pwd)"
work="$3"
cache="${4:-$src/build/ccache}"
jobs="${PBA_JOBS:-$(nproc 2>/dev/null || echo 2)}"
rm -rf "$work"
mkdir -p "$work"
work="$(cd "$work" && pwd)"
[[ -f "$build/lib/libpba_physics.so" ]] ||
  { echo "FAIL: $build/lib/libpba_physics.so not found (configure with PBA_PHYSICS_SHARED=ON, the default)"; exit 1; }
# Tests that only this repository has (the checks of the exercise machinery itself, the house style).
# shellcheck source=tools/not_in_handout.sh
source "$src/tools/not_in_handout.sh"
# The nested ctest runs read this build's test lists from a copy, so that their logs (Testing/) stay out
# of the build's own; the tests themselves run as registered (this check is RUN_SERIAL: nothing runs beside).
tests_dir="$work/ctest"
mkdir -p "$tests_dir"
(cd "$build" && find . -name CTestTestfile.cmake -exec cp --parents {} "$tests_dir/" \;)

physics_of() {  # physics_of TREE: configure TREE as ./pba run would, build its physics library
  local started=$SECONDS
  (cd "$1" && cmake --preset release -DPBA_BUILD_BENCH=OFF -DPBA_WARNINGS_AS_ERRORS=ON "-DPBA_CCACHE_DIR=$cache" >"$1/configure.log" 2>&1) ||
    { tail -n 40 "$1/configure.log"; echo "FAIL: $1 does not configure"; exit 1; }
  cmake --build "$1/build/release" --target pba_physics -j "$jobs" >"$1/build.log" 2>&1 ||
    { tail -n 40 "$1/build.log"; echo "FAIL: the physics library of $1 does not build"; exit 1; }
  [[ -f "$1/build/release/lib/libpba_physics.so" ]] || { echo "FAIL: $1 built no lib/libpba_physics.so"; exit 1; }
  echo "   its physics library built in $((SECONDS - started)) s"
}

echo "== the student release"
bash "$src/tools/student_release.sh" "$src" "$work/release"
physics_of "$work/release"
base_library_path="${LD_LIBRARY_PATH:-}"
use_physics_of() { export LD_LIBRARY_PATH="$1/build/release/lib${base_library_path:+:$base_library_path}"; }
use_physics_of "$work/release"
probe="$("$build/bin/pba-hello" --headless --frames 1 --metrics - 2>/dev/null || true)"
# The metrics list the stubs that ran ("not_implemented": [...]); an empty list means the swap did not happen.
if ! grep -q '"not_implemented": \[' <<<"$probe" || grep -q '"not_implemented": \[\]' <<<"$probe"; then
  echo "FAIL: this build's labs do not load the release's physics library (pba-hello reports no stub)"
  exit 1
fi
tags="$(awk -F'\t' 'NR > 1 && $1 != "" { gsub("-", "_", $1); printf "%s^%s_", (n++ ? "|" : ""), $1 }' "$src/resources/exercises.tsv")"
echo "== exercise tests must all fail against the stubs"
set +e
exercise_log="$(ctest --test-dir "$tests_dir" -R "$tags" --no-tests=error -j "$jobs" 2>&1)"
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
ctest --test-dir "$tests_dir" -E "$tags|$not_in_handout" -LE "^(lab-screenshots|coursework|web)$" --output-on-failure -j "$jobs" ||
  { echo "FAIL: non-exercise tests fail in the student release"; exit 1; }
echo "== ./pba grade must report failures"
if bash "$work/release/tools/grade.sh" "$tests_dir" "$work/release/resources/exercises.tsv" >"$work/grade.log"; then
  cat "$work/grade.log"; echo "FAIL: grade passed on stubs"; exit 1
fi
echo "ok: grade reports $(grep -c ' FAIL ' "$work/grade.log") failing exercises"
echo "== no solution's lines in the release"
python3 "$src/tools/check_solution_leaks.py" "$src" "$work/release"

echo "== the courseworks: held-out tests left out, public tests do not pass against the starter"
[[ ! -e "$work/release/tests/coursework/heldout" ]] || { echo "FAIL: tests/coursework/heldout is in the release"; exit 1; }
mapfile -t heldout_suites < <(grep -ohE 'TEST(_F)?\((CW[0-9]+_[A-Za-z0-9_]*HeldOut)' "$src"/tests/coursework/heldout/*.cpp |
  sed -E 's/.*\(//' | sort -u)
[[ ${#heldout_suites[@]} -gt 0 ]] || { echo "FAIL: no held-out coursework suites found in $src/tests/coursework/heldout"; exit 1; }
# A test of a held-out suite, anywhere in the release (the rubric may name the suites; no file defines one).
for suite in "${heldout_suites[@]}"; do
  if grep -rqE "TEST(_F)?\\($suite," "$work/release"; then echo "FAIL: a test of the held-out suite $suite is in the release"; exit 1; fi
done
echo "ok: ${#heldout_suites[@]} held-out suites, none of their tests (nor their folder) in the release"
set +e
coursework_log="$(ctest --test-dir "$tests_dir" -L '^coursework$' -E 'HeldOut' --no-tests=error -j "$jobs" 2>&1)"
set -e
if grep -qE 'Test +#[0-9]+: .* Passed' <<<"$coursework_log"; then
  echo "FAIL: these coursework tests pass against the starter:"; grep -E 'Test +#[0-9]+: .* Passed' <<<"$coursework_log"; exit 1
fi
echo "ok: no public coursework test passes against the starter"

echo "student release check: ok"
[[ "${PBA_CHECK_ISOLATION:-1}" == 0 ]] && exit 0

echo "== the switchable tree: each exercise alone stubbed"
bash "$src/tools/student_release.sh" --switchable "$src" "$work/switchable"
physics_of "$work/switchable"
use_physics_of "$work/switchable"
python3 "$src/tools/check_exercise_isolation.py" "$tests_dir" "$src/resources/exercises.tsv" --jobs "$jobs" \
  --work "$work/isolation" --exclude "$not_in_handout" --skip-label display --skip-label extremes --skip-label web
echo "isolation check: ok"
