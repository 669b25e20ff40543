#!/usr/bin/env bash
# ctest coursework.mark: `./pba mark` gives the marks the rubric says (resources/coursework/rubric.tsv) to
#   the reference tree (this one): every automatic mark;
#   a fresh student hand-out (tools/student_release.sh): zero;
#   a half-solved tree: this tree with the second task of each coursework (CW1-2, CW2-2) turned back into
#     its stub: the first tasks' criteria, public and held-out, and nothing that runs a stub (the whole
#     walker, the coupled step, the budgets).
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
half="$(weights 1:foot-cycle 1:foot-cycle-heldout 2:contact 2:contact-heldout)"

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
# Turn the CW1-2 and CW2-2 blocks back into their stubs, as the hand-out has them.
for path, tag in (("framework/physics/coursework/walker.cpp", "CW1-2"),
                  ("framework/physics/coursework/ball_on_cloth.cpp", "CW2-2")):
    full = f"{sys.argv[1]}/{path}"
    text = open(full, encoding="utf-8").read()
    block = re.compile(r"[ \t]*// BEGIN SOLUTION\n(?:(?!// BEGIN SOLUTION).)*?// END SOLUTION\n([ \t]*)// STUB: ([^\n]*\"" + tag + r"\"[^\n]*)\n", re.S)
    text, n = block.subn(lambda m: m.group(1) + m.group(2) + "\n", text)
    assert n == 1, f"{path}: no solution block of {tag}"
    open(full, "w", encoding="utf-8").write(text)
PY

check reference "$(mark_total reference "$work/src/reference")" "$all_automatic"
check handout "$(mark_total handout "$work/src/handout")" 0
check half "$(mark_total half "$work/src/half")" "$half"
grep -q 'left to mark' "$work/reference.log" || { echo "FAIL: the marks table lists no criteria left to mark"; exit 1; }
echo "mark check: ok"
