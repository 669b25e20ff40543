#!/usr/bin/env bash
# ./pba demo FILE [--step K] [--check]: plays a lecture demo script (resources/demos/*.json) across labs.
# Each lab window plays the script's consecutive steps of its own lab (PageDown / PageUp); when the next
# step belongs to another lab the window closes after writing that step's number to a hand-off file, and
# this loop starts the next lab there. --check validates every step in its lab and renders each lab's
# first step to build/demos/. Without a display the steps are rendered to PNG files instead.
# Usage: demo.sh ROOT BUILD_DIR FILE [--step K] [--check]
set -uo pipefail
root="$1" build="$2" file="${3:-}"
shift 3 || true
[[ -n "$file" ]] || { echo "usage: ./pba demo FILE.json [--step K] [--check]" >&2; exit 2; }
[[ -f "$file" ]] || { echo "pba demo: $file: cannot open the file" >&2; exit 2; }
step=1 check=0
while [[ $# -gt 0 ]]; do
  case "$1" in
    --step) step="${2:?--step needs a number}"; shift 2 ;;
    --check) check=1; shift ;;
    *) echo "pba demo: unknown option '$1'" >&2; exit 2 ;;
  esac
done
py="$(command -v /usr/bin/python3 || command -v python3)"
# The lab of every step, one a line (the labs themselves check the rest of the file).
labs="$("$py" -c 'import json,sys
try:
    d = json.load(open(sys.argv[1]))
    print("\n".join(s["lab"] for s in d["steps"]))
except Exception as e:
    print(sys.argv[1] + ": not a demo script: " + str(e), file=sys.stderr); sys.exit(2)' "$file")" || exit 2
mapfile -t step_labs <<<"$labs"
count=${#step_labs[@]}
for lab in $(printf '%s\n' "${step_labs[@]}" | sort -u); do
  [[ -x "$build/bin/pba-$lab" ]] || { echo "pba demo: $file: a step names lab '$lab', which does not exist" >&2; exit 2; }
done
name="$(basename "$file" .json)"
display=1
[[ -n "${DISPLAY:-}" || -n "${WAYLAND_DISPLAY:-}" ]] || display=0
in_display() { if [[ $display -eq 1 ]]; then "$@"; else bash "$root/tools/with_xvfb.sh" -s "-screen 0 1280x720x24" "$@"; fi; }

if [[ $check -eq 1 ]]; then
  mkdir -p "$build/demos"
  done_labs=" "
  for ((i = 0; i < count; i++)); do
    lab="${step_labs[$i]}"
    [[ "$done_labs" == *" $lab "* ]] && continue
    done_labs+="$lab "
    "$build/bin/pba-$lab" --demo "$file" --demo-check || exit 2
    png="$build/demos/$name-step$((i + 1)).png"
    in_display "$build/bin/pba-$lab" --demo "$file" --demo-step $((i + 1)) --frames 30 --screenshot "$png" >/dev/null ||
      { echo "pba demo: $file: step $((i + 1)) did not render" >&2; exit 1; }
    echo "rendered step $((i + 1)) ($lab): $png"
  done
  exit 0
fi

if [[ $display -eq 0 ]]; then
  mkdir -p "$build/demos/$name"
  echo "[pba] no display: rendering each step's first 2 s to $build/demos/$name/" >&2
  for ((i = step - 1; i < count; i++)); do
    png="$build/demos/$name/step-$((i + 1)).png"
    in_display "$build/bin/pba-${step_labs[$i]}" --demo "$file" --demo-step $((i + 1)) --frames 120 --screenshot "$png" ||
      exit $?
    echo "step $((i + 1)) of $count (${step_labs[$i]}): $png"
  done
  exit 0
fi

handoff="$(mktemp)"
trap 'rm -f "$handoff"' EXIT
while [[ $step -ge 1 && $step -le $count ]]; do
  : >"$handoff"
  "$build/bin/pba-${step_labs[$((step - 1))]}" --demo "$file" --demo-step "$step" --demo-next "$handoff" || exit $?
  next="$(cat "$handoff")"
  [[ -n "$next" ]] || break  # the window was closed, or the script ended
  step="$next"
done
