#!/usr/bin/env bash
# ./pba mark STUDENT_TREE [--coursework N] [--csv FILE]: marks a student's coursework against the rubric
# (resources/coursework/rubric.tsv, docs/course/instructor-workflow.md "Marking with ./pba mark").
#  1. Copies the student's tree (without build/ and .git) into a work folder and puts this repository's
#     tests/coursework/ in it, public and held-out tests alike (a student's edits to the tests do not count).
#  2. Configures it as ./pba run would (release preset, no benchmarks; again without -Werror if warnings
#     stop it) through this repository's compiler cache, and builds the coursework tests and the budget
#     measurer only.
#  3. Runs the coursework tests (label coursework) and the budget measurer of each coursework marked.
#  4. Prints one row per criterion; writes the automatic ones to the CSV (coursework,criterion,weight,
#     score,max) and lists the criteria a person marks as left to mark.
# Every step has a time limit (PBA_MARK_BUILD_S, PBA_MARK_TEST_S for all the tests, PBA_MARK_TEST_EACH_S,
# PBA_MARK_RUN_S): a tree that does not
# compile, crashes or hangs scores 0 on what it could not run, with a line naming the log.
# Scores: a tests criterion earns weight × passed / tests matched; a budget criterion earns its weight when
# the median frame time is within the budget, half within twice the budget, else 0, and 0 when the run
# was not finite or ran a stub. Exit: 0 marked (whatever the marks), 2 bad arguments, 1 internal failure.
# Usage: tools/mark.sh INSTRUCTOR_ROOT STUDENT_TREE [--coursework N] [--csv FILE] [--work DIR]
set -uo pipefail
root="$(cd "$1" && pwd)"
shift
die2() { echo "mark: $*" >&2; exit 2; }
rubric="$root/resources/coursework/rubric.tsv"
[[ -f "$rubric" ]] || { echo "mark: no rubric $rubric" >&2; exit 1; }
student="" only="" csv="" work=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --coursework) [[ $# -ge 2 ]] || die2 "--coursework needs a number"; only="$2"; shift 2 ;;
    --csv) [[ $# -ge 2 ]] || die2 "--csv needs a file name"; csv="$2"; shift 2 ;;
    --work) [[ $# -ge 2 ]] || die2 "--work needs a folder"; work="$2"; shift 2 ;;
    -*) die2 "unknown option '$1' (usage: ./pba mark STUDENT_TREE [--coursework N] [--csv FILE])" ;;
    *) [[ -z "$student" ]] || die2 "one student tree at a time ('$student' and '$1')"; student="$1"; shift ;;
  esac
done
[[ -n "$student" ]] || die2 "usage: ./pba mark STUDENT_TREE [--coursework N] [--csv FILE]"
[[ -d "$student" ]] || die2 "$student: no such folder"
[[ -f "$student/CMakeLists.txt" && -d "$student/framework/physics" ]] || die2 "$student: not a PBA Labs tree (no CMakeLists.txt or framework/physics)"
mapfile -t courseworks < <(awk -F'\t' 'NR > 1 && $1 != "" { print $1 }' "$rubric" | sort -u)
if [[ -n "$only" ]]; then
  [[ " ${courseworks[*]} " == *" $only "* ]] || die2 "--coursework $only: the rubric has courseworks ${courseworks[*]}"
  courseworks=("$only")
fi
if [[ -n "$csv" ]]; then
  [[ -d "$(dirname "$csv")" ]] || die2 "--csv $csv: no folder $(dirname "$csv")"
fi
student="$(cd "$student" && pwd)"
work="${work:-$root/build/mark/$(basename "$student")}"
jobs="${PBA_JOBS:-2}"
build_s="${PBA_MARK_BUILD_S:-1200}" test_s="${PBA_MARK_TEST_S:-1200}" run_s="${PBA_MARK_RUN_S:-120}"
test_each_s="${PBA_MARK_TEST_EACH_S:-60}"  # one test; the slowest takes about a second here
# The compiler cache of this repository's release build (its PBA_CCACHE_DIR), unless one is given.
cache="${PBA_MARK_CCACHE_DIR:-$(sed -n 's/^PBA_CCACHE_DIR:PATH=//p' "$root/build/release/CMakeCache.txt" 2>/dev/null)}"
cache="${cache:-$root/build/ccache}"

# The work folder is emptied first: never one that holds the student's tree or this repository.
work_abs="$(realpath -m "$work")"
[[ "$student/" != "$work_abs/"* && "$root/" != "$work_abs/"* ]] || die2 "--work $work holds $student or $root"
rm -rf "$work" && mkdir -p "$work" || { echo "mark: cannot create $work" >&2; exit 1; }
work="$(cd "$work" && pwd)"
tree="$work/tree"
mkdir -p "$tree"
echo "mark: $student -> $tree (logs in $work)"
(cd "$student" && tar --exclude=./build --exclude=./.git -cf - .) | (cd "$tree" && tar -xf -) ||
  { echo "mark: cannot copy $student" >&2; exit 1; }
rm -rf "$tree/tests/coursework"
cp -R "$root/tests/coursework" "$tree/tests/coursework"
grep -q 'add_subdirectory(coursework)' "$tree/tests/CMakeLists.txt" 2>/dev/null ||
  printf '\nadd_subdirectory(coursework)\n' >>"$tree/tests/CMakeLists.txt"

# Configured as ./pba run would (release preset, -Werror) so that the compiler cache serves every file
# the student did not change; a tree that builds only without -Werror is built again that way.
configure() {  # configure [CMAKE_ARGS...]
  (cd "$tree" && timeout "$build_s" cmake --preset release -DPBA_BUILD_BENCH=OFF "-DPBA_CCACHE_DIR=$cache" "$@" \
    >"$work/configure.log" 2>&1)
}
build() {
  timeout "$build_s" cmake --build "$tree/build/release" -j "$jobs" --target pba_coursework_public_tests \
    pba_coursework_heldout_tests pba_coursework_budget >"$work/build.log" 2>&1
}
built=1
if ! configure; then
  built=0
  echo "mark: FAILED: the tree does not configure (or took over ${build_s} s); every automatic criterion scores 0; log: $work/configure.log"
elif ! build; then
  if [[ $? != 124 ]] && grep -q '\[-Werror=' "$work/build.log" && configure -DPBA_WARNINGS_AS_ERRORS=OFF && build; then
    echo "mark: note: the tree builds only without -Werror (warnings in $work/build.log)"
  else
    built=0
    echo "mark: FAILED: the coursework does not build (or took over ${build_s} s); every automatic criterion scores 0; log: $work/build.log"
    grep -m 5 -E ': (fatal )?error' "$work/build.log" | sed 's/^/  /'
  fi
fi
: >"$work/passed.txt"
: >"$work/listed.txt"
if [[ $built == 1 ]]; then
  # The test list: ctest -N; the results: one line per test. A test over its time limit fails.
  ctest --test-dir "$tree/build/release" -N -L '^coursework$' 2>/dev/null |
    sed -nE 's/^ *Test +#[0-9]+: ([^ ]+).*/\1/p' >"$work/listed.txt"
  timeout "$test_s" ctest --test-dir "$tree/build/release" -L '^coursework$' -j "$jobs" --timeout "$test_each_s" \
    >"$work/tests.log" 2>&1
  status=$?
  [[ $status == 124 ]] && echo "mark: FAILED: the tests ran over ${test_s} s and were stopped; log: $work/tests.log"
  sed -nE 's/^ *[0-9]+\/[0-9]+ Test +#[0-9]+: ([^ ]+) \.+ +Passed.*/\1/p' "$work/tests.log" >"$work/passed.txt"
  grep -E '\*\*\*(Failed|Exception|Timeout)|Not Run' "$work/tests.log" | sed -nE 's/.*Test +#[0-9]+: ([^ ]+) .*(\*\*\*[A-Za-z]+|Not Run).*/  \1: \2/p' \
    >"$work/failed.txt"
  [[ -s "$work/failed.txt" ]] && echo "mark: $(wc -l <"$work/failed.txt") tests did not pass (log: $work/tests.log)"
fi

budget_json() {  # budget_json N: the measurer's JSON line, or nothing when it crashed or hung
  [[ $built == 1 ]] || return 0
  timeout "$run_s" "$tree/build/release/tests/coursework/pba_coursework_budget" --coursework "$1" \
    >"$work/budget-$1.json" 2>"$work/budget-$1.err"
  local rc=$?
  if [[ $rc != 0 ]]; then
    echo "mark: FAILED: the budget run of coursework $1 exited $rc$([[ $rc == 124 ]] && echo " (over ${run_s} s)"); log: $work/budget-$1.err" >&2
    : >"$work/budget-$1.json"
  fi
}
for n in "${courseworks[@]}"; do budget_json "$n"; done

python3 - "$rubric" "$work" "$csv" "${courseworks[@]}" <<'PY'
import csv, json, os, re, sys
rubric, work, csv_path, wanted = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
listed = open(os.path.join(work, "listed.txt")).read().split()
passed = set(open(os.path.join(work, "passed.txt")).read().split())
rows, person = [], []
with open(rubric, encoding="utf-8") as f:
    for r in csv.DictReader(f, delimiter="\t"):
        if r["coursework"] not in wanted:
            continue
        weight = float(r["weight"])
        if r["kind"] == "person":
            person.append(r); continue
        if r["kind"] == "tests":
            pattern = re.compile(r["select"])
            mine = [t for t in listed if pattern.search(t)]
            got = sum(t in passed for t in mine)
            score = round(weight * got / len(mine), 2) if mine else 0.0
            note = f"{got}/{len(mine)} tests" if mine else "no tests ran"
        else:
            budget = float(r["select"])
            path = os.path.join(work, f"budget-{r['coursework']}.json")
            text = open(path).read().strip() if os.path.exists(path) else ""
            if not text:
                score, note = 0.0, "the measurement did not run"
            else:
                m = json.loads(text)
                median = m["frame_ms"]["median"]
                if not m["finite"]:
                    score, note = 0.0, "the state went non-finite"
                elif m["not_implemented"]:
                    score, note = 0.0, "stubs ran: " + ", ".join(m["not_implemented"])
                else:
                    score = weight if median <= budget else weight / 2 if median <= 2 * budget else 0.0
                    note = f"median {median:.3f} ms, budget {budget:g} ms"
        rows.append((r["coursework"], r["criterion"], weight, score, weight, note))
print(f"\n{'CW':<3} {'CRITERION':<22} {'WEIGHT':>6} {'SCORE':>6}  NOTE")
for cw, name, weight, score, top, note in rows:
    print(f"{cw:<3} {name:<22} {weight:>6g} {score:>6g}  {note}")
for cw in wanted:
    auto = [r for r in rows if r[0] == cw]
    print(f"coursework {cw}: automatic {sum(r[3] for r in auto):g} / {sum(r[4] for r in auto):g}")
total = sum(r[3] for r in rows)
print(f"automatic total: {total:g} / {sum(r[4] for r in rows):g}")
if person:
    print("left to mark (a person):")
    for r in person:
        print(f"  coursework {r['coursework']} {r['criterion']} ({r['weight']}): {r['description']}")
if csv_path:
    with open(csv_path, "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(["coursework", "criterion", "weight", "score", "max"])
        for cw, name, weight, score, top, _ in rows:
            w.writerow([cw, name, f"{weight:g}", f"{score:g}", f"{top:g}"])
    print(f"wrote {csv_path}")
PY
