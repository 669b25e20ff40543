#!/usr/bin/env bash
# Goldens a correct solution cannot fail
# (docs/decisions/2026-12-02-golden-trajectories-bit-for-bit-or-within-tolerance.md): builds a copy of this tree in
# which some exercises are solved in another, equally correct form (tools/golden_alternatives/ TAG.inc, the lines of
# TAG's solution block: CLOTH-2 with std::fma and glm::normalize, PART-4 and PART-5 reordered, RIGID-2 through another
# formula; a fast path of TAG becomes its stub, the scalar sweep over the alternative, as in the hand-out), and runs
# this build's tests against the copy's physics library (LD_LIBRARY_PATH, as tools/check_student_release.sh):
#  1. the goldens bit for bit (PBA_GOLDEN_COMPARE=exact): reported, expected to differ (the alternatives
#     round otherwise, so the check below is not vacuous);
#  2. the goldens within their tolerances (PBA_GOLDEN_COMPARE=tolerance, as in the hand-out): must pass;
#  3. ./pba grade for the alternatives' tags: must pass;
#  4. with --suite, the hand-out's suite (every test the hand-out registers, goldens within tolerance;
#     display tests and the slow parameter extremes left out unless PBA_SUITE_ALL=1): must pass.
# tools/golden_alternatives is this repository's only: tools/student_release.sh leaves it out of the
# hand-out (its files are working solutions).
# Usage: tools/check_golden_tolerance.sh SOURCE_ROOT BUILD_DIR WORK_DIR [--suite]
set -euo pipefail
src="$(cd "$1" && pwd)"
build="$(cd "$2" && pwd)"
work="$3"
suite="${4:-}"
cache="${PBA_CCACHE_DIR:-$src/build/ccache}"
jobs="${PBA_JOBS:-$(nproc 2>/dev/null || echo 2)}"
alternatives="$src/tools/golden_alternatives"
rm -rf "$work"
mkdir -p "$work/tree"
work="$(cd "$work" && pwd)"
tree="$work/tree"
(cd "$src" && git ls-files --cached --others --exclude-standard | while read -r f; do
  [[ -f "$f" ]] && mkdir -p "$tree/$(dirname "$f")" && cp -p "$f" "$tree/$f"
done)
mapfile -t tags < <(cd "$alternatives" && ls *.inc | sed "s/\.inc$//")
python3 - "$tree" "$alternatives" "${tags[@]}" <<'PY'
import os, re, sys
tree, alternatives, tags = sys.argv[1], sys.argv[2], sys.argv[3:]
for tag in tags:
    body = open(os.path.join(alternatives, tag + ".inc"), encoding="utf-8").read().rstrip("\n").split("\n")
    done = False
    for d, _, files in os.walk(os.path.join(tree, "framework")):
        for name in files:
            if not name.endswith(".cpp"):
                continue
            path = os.path.join(d, name)
            lines = open(path, encoding="utf-8").read().split("\n")
            for i, line in enumerate(lines):
                if "// STUB:" in line and f'"{tag}"' in line:
                    end = max(k for k in range(i) if "// END SOLUTION" in lines[k])
                    begin = max(k for k in range(end) if "// BEGIN SOLUTION" in lines[k])
                    lines[begin + 1:end] = body
                    first_include = next(k for k, l in enumerate(lines) if l.startswith("#include"))
                    lines.insert(first_include + 1, "#include <cmath>")
                    open(path, "w", encoding="utf-8").write("\n".join(lines))
                    print(f"   {tag}: {os.path.relpath(path, tree)} solved by tools/golden_alternatives/{tag}.inc")
                    done = True
                    break
            if done:
                break
        if done:
            break
    if not done:
        sys.exit(f"FAIL: no solution block with a {tag} stub")
    # A fast path of TAG (// FAST PATH: TAG after its block) runs the student's scalar code in the hand-out:
    # its stub lines replace it here too, as tools/student_release.sh does, so that the copy's fast path is
    # the alternative's and the tests that compare the two see the hand-out's pairing.
    for d, _, files in os.walk(os.path.join(tree, "framework")):
        for name in files:
            path = os.path.join(d, name)
            if not name.endswith(".cpp"):
                continue
            lines = open(path, encoding="utf-8").read().split("\n")
            marks = [i for i, line in enumerate(lines) if re.match(rf"\s*// FAST PATH: {tag}\b", line)]
            for i in reversed(marks):
                end = max(k for k in range(i) if "// END SOLUTION" in lines[k])
                begin = max(k for k in range(end) if "// BEGIN SOLUTION" in lines[k])
                last = i + 1
                while last < len(lines) and "// STUB: " in lines[last]:
                    last += 1
                stub = [line.replace("// STUB: ", "", 1) for line in lines[i + 1:last]]
                lines[begin:last] = stub
                print(f"   {tag}: {os.path.relpath(path, tree)}'s fast path runs the alternative, as in the hand-out")
            if marks:
                open(path, "w", encoding="utf-8").write("\n".join(lines))
PY
started=$SECONDS
(cd "$tree" && cmake --preset release -DPBA_BUILD_BENCH=OFF "-DPBA_CCACHE_DIR=$cache" >"$work/configure.log" 2>&1) ||
  { tail -n 40 "$work/configure.log"; echo "FAIL: the copy does not configure"; exit 1; }
cmake --build "$tree/build/release" --target pba_physics -j "$jobs" >"$work/build.log" 2>&1 ||
  { tail -n 40 "$work/build.log"; echo "FAIL: the copy's physics library does not build"; exit 1; }
echo "   its physics library built in $((SECONDS - started)) s"
export LD_LIBRARY_PATH="$tree/build/release/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
# The nested ctest runs read this build's test lists from a copy (their logs stay out of the build's own).
tests_dir="$work/ctest"
mkdir -p "$tests_dir"
(cd "$build" && find . -name CTestTestfile.cmake -exec cp --parents {} "$tests_dir/" \;)

echo "== the goldens bit for bit (expected to differ somewhere)"
set +e
PBA_GOLDEN_COMPARE=exact ctest --test-dir "$tests_dir" -R "^lab\.[a-z]+\.golden$" -j "$jobs" >"$work/exact.log" 2>&1
set -e
grep -E 'tests passed|Failed' "$work/exact.log" | sed 's/^/   /'
echo "== the goldens within tolerance"
PBA_GOLDEN_COMPARE=tolerance ctest --test-dir "$tests_dir" -R "^lab\.[a-z]+\.golden$" -j "$jobs" -V >"$work/tolerance.log" 2>&1 ||
  { grep -E 'FAIL|failed' "$work/tolerance.log"; echo "FAIL: a correct solution leaves the golden tolerances"; exit 1; }
grep -oE 'golden ok: [^ ]+ .*within tolerance.*' "$work/tolerance.log" | sed -E 's/^golden ok: //' |
  sort -t'(' -k2 -g | sed 's/^/   /'
echo "== ./pba grade ${tags[*]}"
bash "$src/tools/grade.sh" "$tests_dir" "$src/resources/exercises.tsv" "${tags[@]}" || { echo "FAIL: grade"; exit 1; }
if [[ "$suite" == --suite ]]; then
  echo "== the hand-out's suite with these solutions"
  # shellcheck source=tools/not_in_handout.sh
  source "$src/tools/not_in_handout.sh"
  skip_labels='^(ui|lab-screenshots|display|extremes|coursework|web)$'
  [[ "${PBA_SUITE_ALL:-0}" == 1 ]] && skip_labels='^(ui|lab-screenshots|display|coursework|web)$'
  PBA_GOLDEN_COMPARE=tolerance ctest --test-dir "$tests_dir" -E "$not_in_handout" -LE "$skip_labels" -j "$jobs" \
    --output-on-failure >"$work/suite.log" 2>&1 || { tail -n 60 "$work/suite.log"; echo "FAIL: the suite"; exit 1; }
  grep -E 'tests passed' "$work/suite.log" | sed 's/^/   /'
fi
echo "golden tolerance check: ok"
