#!/usr/bin/env bash
# ./pba student-release DIR: writes the student hand-out generated from this repository.
# Every block between "// BEGIN SOLUTION" and "// END SOLUTION" is removed and the "// STUB: code"
# lines that follow it become code: the stub compiles, reports "TAG not implemented" through
# pba::exercises::notImplemented and returns a safe default, so every lab still runs.
#
# --switchable writes the isolation build instead (tools/check_exercise_isolation.py): every block
# stays, behind a run-time switch that runs the stub when PBA_STUB_EXERCISES names the tag (see
# ExerciseSwitch in framework/physics/exercises/not_implemented.h). Either way a block must end its
# function: the stub lines are followed by the function's closing brace.
#
# A fast path (docs/architecture.md §5, "Fast paths") is a block whose stub calls the student's scalar
# exercise instead of notImplemented; a "// FAST PATH: TAG ..." line between END SOLUTION and the stub
# names its exercise. It stays as a comment in the hand-out, and in the switchable tree it gives the
# switch its tag, so the fast path switches to its stub together with its exercise.
set -euo pipefail
mode=release
if [[ "${1:-}" == --switchable ]]; then mode=switchable; shift; fi
[[ $# -eq 2 ]] || { echo "usage: student_release.sh [--switchable] SOURCE_ROOT OUT_DIR" >&2; exit 2; }
src="$1"
out="$2"
[[ -e "$out" && -n "$(ls -A "$out" 2>/dev/null)" ]] && { echo "student-release: $out exists and is not empty" >&2; exit 2; }
mkdir -p "$out"
out="$(cd "$out" && pwd)"

# The files to hand out: what git tracks (or the whole tree without build outputs).
if git -C "$src" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git -C "$src" ls-files --cached --others --exclude-standard)
else
  mapfile -t files < <(cd "$src" && find . -type f -not -path './build/*' -not -path './.git/*' | sed 's|^\./||')
fi

blocks=0
for f in "${files[@]}"; do
  [[ -f "$src/$f" ]] || continue
  # Working solutions in another form (tools/check_golden_tolerance.sh): this repository's only.
  [[ "$f" == tools/golden_alternatives/* ]] && continue
  # The courseworks' held-out tests: the instructor's, added back by ./pba mark (tools/mark.sh).
  [[ "$f" == tests/coursework/heldout/* ]] && continue
  # Tests whose reference route is a working copy of an exercise (they prove where a fixture comes from).
  [[ "$f" == tests/labs/instructor/* ]] && continue
  mkdir -p "$out/$(dirname "$f")"
  if [[ "$f" == *.cpp || "$f" == *.h ]] && grep -q '// BEGIN SOLUTION' "$src/$f"; then
    if ! awk -v file="$f" -v mode="$mode" '
      function flush_block(   i, tag, returns) {
        if (mode == "release") { for (i = 1; i <= nstub; i++) print stub[i]; return }
        tag = fasttag
        for (i = 1; i <= nstub; i++) if (tag == "" && match(stub[i], /"[A-Z]+[0-9]*-[0-9]+"/)) tag = substr(stub[i], RSTART, RLENGTH)
        if (tag == "") { print file ":" NR ": no exercise tag in the STUB lines" > "/dev/stderr"; exit 3 }
        print indent "static const ::pba::exercises::ExerciseSwitch pbaExerciseSwitch(" tag ");"
        print indent "if (pbaExerciseSwitch.stub()) {"
        returns = 0
        for (i = 1; i <= nstub; i++) { print "  " stub[i]; if (stub[i] ~ /^[ \t]*return[ ;]/) returns = 1 }
        if (!returns) print indent "  return;"
        print indent "}"
        for (i = 1; i <= nsol; i++) print sol[i]
      }
      /\/\/ BEGIN SOLUTION/ {
        if (inside) { print file ":" NR ": nested BEGIN SOLUTION" > "/dev/stderr"; exit 3 }
        inside = 1; nsol = 0; nstub = 0; indent = $0; sub(/\/\/ BEGIN SOLUTION.*/, "", indent); next
      }
      /\/\/ END SOLUTION/ { if (!inside) { print file ":" NR ": END SOLUTION without BEGIN" > "/dev/stderr"; exit 3 } inside = 0; ended = 1; next }
      inside { sol[++nsol] = $0; next }
      ended && !nstub && /^[ \t]*\/\/ FAST PATH: [A-Z]+-[0-9]+/ {
        if (fasttag != "") { print file ":" NR ": two FAST PATH lines" > "/dev/stderr"; exit 3 }
        match($0, /[A-Z]+-[0-9]+/); fasttag = "\"" substr($0, RSTART, RLENGTH) "\""; print; next
      }
      ended && /^[ \t]*\/\/ STUB: / { line = $0; sub(/\/\/ STUB: /, "", line); stub[++nstub] = line; next }
      ended {
        if (!nstub) { print file ":" NR ": a solution block must be followed by // STUB: lines" > "/dev/stderr"; exit 3 }
        if ($0 !~ /^[ \t]*}/) { print file ":" NR ": a solution block and its stub must end the function (expected })" > "/dev/stderr"; exit 3 }
        flush_block(); ended = 0; fasttag = ""
      }
      { print }
      END { if (inside || ended) { print file ": BEGIN SOLUTION without END, or a block at the end of the file" > "/dev/stderr"; exit 3 } }
    ' "$src/$f" >"$out/$f"; then
      echo "student-release: malformed solution block in $f" >&2
      exit 1
    fi
    blocks=$((blocks + $(grep -c '// BEGIN SOLUTION' "$src/$f")))
  else
    cp -p "$src/$f" "$out/$f"
  fi
done
if grep -rl 'BEGIN SOLUTION' "$out" --include='*.cpp' --include='*.h' >/dev/null 2>&1; then
  echo "student-release: solution markers left in the output" >&2
  exit 1
fi
if [[ $mode == switchable ]]; then
  echo "This tree is a PBA Labs isolation build: solutions behind run-time stub switches." >"$out/.student-release"
  echo "student-release: wrote the switchable tree $out (${#files[@]} files, $blocks solution blocks behind switches)"
  exit 0
fi
# A student's build does not stop at a warning (the repository's does): the hand-out's presets build
# without -Werror. tools/check_student_release.sh still builds the stubs with it.
sed -i.orig 's/"PBA_WARNINGS_AS_ERRORS": "ON"/"PBA_WARNINGS_AS_ERRORS": "OFF"/' "$out/CMakePresets.json" && rm -f "$out/CMakePresets.json.orig"
grep -q '"PBA_WARNINGS_AS_ERRORS": "ON"' "$out/CMakePresets.json" && { echo "student-release: -Werror left in CMakePresets.json" >&2; exit 1; }
echo "This tree is a PBA Labs student release: exercise solutions are stubs." >"$out/.student-release"
echo "student-release: wrote $out (${#files[@]} files, $blocks solution blocks replaced by stubs)"
