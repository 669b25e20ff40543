#!/usr/bin/env bash
# ctest coursework.mark: `./pba mark` gives the marks the rubric says (resources/coursework/rubric.tsv) to
#   the reference tree (this one): every automatic mark;
#   a fresh student hand-out (tools/student_release.sh): zero;
#   a half-solved tree: this tree with the second task of each coursework (CW1-2, CW2-2, CW3-2) turned back
#     into its stub: the first tasks' criteria, public and held-out, and nothing that runs a stub (the whole
#     walker, the coupled step, the rest test and the whole fall, the budgets);
# and that bad arguments exit 2 with one line, a tree that does not compile scores 0 with a line naming its
# log, and a tree whose code hangs is stopped at the time limits (shortened here) with a line for each.
# The three trees build through the given compiler cache, so only the files that differ compile.
# Usage: tools/check_mark.sh SOURCE_ROOT WORK_DIR [CCACHE_DIR]
set -euo pipefail
src="$(cd "$1" && pwd)"
work="$2"
export PBA_MARK_CCACHE_DIR="${3:-$src/build/ccache}"
rm -rf "$work" && mkdir -p "$work"
work="$(cd "$work" && pwd)"

# expected_total COURSEWORK CRITERION...: the sum of those criteria's weights in the rubric.
weights() { awk -F'\t' -v want=" $* " 'NR > 1 && $3 != "person" && index(want, " " $1 ":" $2 " ") { s += $4 } END { print s + 0 }' \
  "$src/resources/coursework/rubric.tsv"; }
all_automatic="$(awk -F'\t' 'NR > 1 && $3 != "person" { s += $4 } END { print s }' "$src/resources/coursework/rubric.tsv")"
half="$(weights 1:foot-cycle 1:foot-cycle-heldout 2:contact 2:contact-heldout 3:hand-over 3:hand-over-heldout)"

mark_total() {  # mark_total NAME TREE: marks TREE, prints the CSV's total
  bash "$src/tools/mark.sh" "$src" "$2" --csv "$work/$1.csv" --work "$work/$1" >"$work/$1.log" 2>&1 ||
    { cat "$work/$1.log"; echo "FAIL: ./pba mark $1 exited $?" >&2; exit 1; }
  awk -F, 'NR > 1 { s += $4 } END { print s + 0 }' "$work/$1.csv"
}
check() {  # check NAME GOT EXPECTED
  if awk -v a="$2" -v b="$3" 'BEGIN { exit !(a == b) }'; then echo "ok: $1: $2 (expected $3)"
  else cat "$work/$1.log"; echo "FAIL: $1 got $2 automatic marks, the rubric says $3"; exit 1; fi
}

# The reference: this tree's files (what git tracks, without build outputs).
mkdir -p "$work/src/reference"
(cd "$src" && git ls-files --cached --others --exclude-standard -z | xargs -0 tar -cf -) | (cd "$work/src/reference" && tar -xf -)
bash "$src/tools/student_release.sh" "$src" "$work/src/handout" >/dev/null
cp -R "$work/src/reference" "$work/src/half"
python3 - "$work/src/half" <<'PY'
import re, sys
# Turn the CW1-2, CW2-2 and CW3-2 blocks back into their stubs, as the hand-out has them.
for path, tag in (("framework/physics/coursework/walker.cpp", "CW1-2"),
                  ("framework/physics/coursework/ball_on_cloth.cpp", "CW2-2"),
                  ("framework/physics/coursework/stairs_fall.cpp", "CW3-2")):
    full = f"{sys.argv[1]}/{path}"
    text = open(full, encoding="utf-8").read()
    block = re.compile(r"[ \t]*// BEGIN SOLUTION\n(?:(?!// BEGIN SOLUTION).)*?// END SOLUTION\n([ \t]*)// STUB: ([^\n]*\"" + tag + r"\"[^\n]*)\n", re.S)
    text, n = block.subn(lambda m: m.group(1) + m.group(2) + "\n", text)
    assert n == 1, f"{path}: no solution block of {tag}"
    open(full, "w", encoding="utf-8").write(text)
PY

# Bad arguments: one line, exit status 2.
for args in "--coursework 9 $work/src/reference" "$work/no-such-tree" "$work/src/reference --bogus"; do
  set +e
  # shellcheck disable=SC2086
  message="$(bash "$src/tools/mark.sh" "$src" $args 2>&1 >/dev/null)"
  status=$?
  set -e
  [[ $status == 2 && $(wc -l <<<"$message") == 1 ]] || { echo "FAIL: mark $args: exit $status, '$message' (expected one line, exit 2)"; exit 1; }
done
echo "ok: bad arguments give one line and exit status 2"

check reference "$(mark_total reference "$work/src/reference")" "$all_automatic"
check handout "$(mark_total handout "$work/src/handout")" 0
check half "$(mark_total half "$work/src/half")" "$half"
grep -q 'left to mark' "$work/reference.log" || { echo "FAIL: the marks table lists no criteria left to mark"; exit 1; }

# A tree that does not compile, and one whose code hangs: marked, with a clear line, never a hung run.
cp -R "$work/src/half" "$work/src/broken"
printf '\nthis does not compile\n' >>"$work/src/broken/framework/physics/coursework/walker.cpp"
cp -R "$work/src/reference" "$work/src/hangs"
python3 - "$work/src/hangs/framework/physics/coursework/walker.cpp" <<'PY'
import sys
path = sys.argv[1]
text = open(path, encoding="utf-8").read()
# footOffset spins for ever (a volatile counter: a loop the compiler must keep).
text = text.replace("Vec3 footOffset(const GaitDesc& gait, Real phase) {",
                    "Vec3 footOffset(const GaitDesc& gait, Real phase) {\n  for (volatile unsigned spin = 0;;) {\n    spin = spin + 1;\n  }", 1)
open(path, "w", encoding="utf-8").write(text)
PY
mark_one() {  # mark_one NAME: coursework 1 of src/NAME with short time limits (5 s a test, 10 s a budget run)
  PBA_MARK_TEST_S=300 PBA_MARK_TEST_EACH_S=5 PBA_MARK_RUN_S=10 bash "$src/tools/mark.sh" "$src" "$work/src/$1" --coursework 1 \
    --csv "$work/$1.csv" --work "$work/$1" >"$work/$1.log" 2>&1 || { cat "$work/$1.log"; echo "FAIL: mark $1 exited $?"; exit 1; }
}
mark_one broken
grep -q 'mark: FAILED: the coursework does not build' "$work/broken.log" || { cat "$work/broken.log"; echo "FAIL: no line saying the tree does not build"; exit 1; }
check broken "$(awk -F, 'NR > 1 { s += $4 } END { print s + 0 }' "$work/broken.csv")" 0
mark_one hangs
grep -q 'tests did not pass' "$work/hangs.log" || { cat "$work/hangs.log"; echo "FAIL: no line saying tests did not pass"; exit 1; }
grep -q 'Timeout' "$work/hangs/failed.txt" || { cat "$work/hangs.log"; echo "FAIL: no test stopped at its time limit"; exit 1; }
grep -q 'budget run of coursework 1 exited 124' "$work/hangs.log" || { cat "$work/hangs.log"; echo "FAIL: no line saying the budget run hung"; exit 1; }
# The tests that never call the hanging task still earn their marks: CW1-2's, public and held-out.
check hangs "$(awk -F, 'NR > 1 { s += $4 } END { print s + 0 }' "$work/hangs.csv")" "$(weights 1:reach 1:reach-heldout)"
echo "ok: a tree that does not compile scores 0 with its log; a hanging one is stopped at its time limits"
echo "mark check: ok"
