#!/usr/bin/env bash
# ./pba student-release DIR: writes the student hand-out generated from this repository.
# Every block between "// BEGIN SOLUTION" and "// END SOLUTION" is removed and the "// STUB: code"
# lines that follow it become code: the stub compiles, reports "TAG not implemented" through
# pba::exercises::notImplemented and returns a safe default, so every lab still runs.
set -euo pipefail
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
  mkdir -p "$out/$(dirname "$f")"
  if [[ "$f" == *.cpp || "$f" == *.h ]] && grep -q '// BEGIN SOLUTION' "$src/$f"; then
    if ! awk -v file="$f" '
      /\/\/ BEGIN SOLUTION/ { if (inside) { print file ":" NR ": nested BEGIN SOLUTION" > "/dev/stderr"; exit 3 } inside = 1; next }
      /\/\/ END SOLUTION/   { if (!inside) { print file ":" NR ": END SOLUTION without BEGIN" > "/dev/stderr"; exit 3 } inside = 0; ended = 1; next }
      inside { next }
      ended && /^[ \t]*\/\/ STUB: / { sub(/\/\/ STUB: /, ""); print; stubs++; next }
      { if (ended && !stubs) { print file ":" NR ": a solution block must be followed by // STUB: lines" > "/dev/stderr"; exit 3 } ended = 0; stubs = 0; print }
      END { if (inside) { print file ": BEGIN SOLUTION without END" > "/dev/stderr"; exit 3 } }
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
echo "This tree is a PBA Labs student release: exercise solutions are stubs." >"$out/.student-release"
echo "student-release: wrote $out (${#files[@]} files, $blocks solution blocks replaced by stubs)"
