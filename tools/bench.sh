#!/usr/bin/env bash
# ./pba bench: runs the kernel benchmarks (bench/*_bench.cpp, Google Benchmark) and the scene
# benchmarks (every scene of every lab headless), records them in BUILD_DIR/bench-run.json
# (tools/bench_run.py; a --filter run merges into the one before), writes the whole of
# docs/performance.md from it (tools/bench_page.py; release preset without --filter, else
# BUILD_DIR/performance.md), and every figure as JSON to BUILD_DIR/bench-results.json; --compare REF.json
# prints each figure's change against an earlier run's JSON (keep one with
# `cp build/release/bench-results.json ref.json` before a change). Exit status 1 when a scene that its lab
# does not mark heavy is over the budget of 2 ms of physics per frame, 2 for bad input.
# Usage: tools/bench.sh ROOT BUILD_DIR [--preset NAME] [--filter REGEX] [--compare REF.json]
set -euo pipefail
root="$1"
build="$2"
shift 2
preset=release filter="" compare=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --preset) preset="${2:?--preset needs a name}"; shift 2 ;;
    --filter) filter="${2:?--filter needs a regular expression}"; shift 2 ;;
    --compare) compare="${2:?--compare needs a file}"; shift 2 ;;
    *) echo "pba bench: unknown option '$1' (options: --preset NAME, --filter REGEX, --compare REF.json)" >&2; exit 2 ;;
  esac
done
if [[ -n "$compare" ]]; then
  [[ -f "$compare" ]] || { echo "pba bench: --compare: no file $compare" >&2; exit 2; }
  python3 "$root/tools/bench_results.py" check "$compare" || exit 2
fi
# A filtered run or another preset must not replace the release figures of the repository.
out="$root/docs/performance.md"
[[ "$preset" == release && -z "$filter" ]] || out="$build/performance.md"
frames="${PBA_BENCH_FRAMES:-600}"
budget_ms=2.0 min_time=0.2
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
mkdir "$tmp/scenes" "$tmp/kernels"
# selected NAME: true when no --filter was given or NAME matches it.
selected() { [[ -z "$filter" || "$1" =~ $filter ]]; }

date_utc="$(date -u +%Y-%m-%d)"
commit="$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)"
# The page this run rewrites does not count as a change of the tree it measures.
[[ -z "$(git -C "$root" status --porcelain --untracked-files=no -- . ':!docs/performance.md' 2>/dev/null)" ]] ||
  commit+=" with uncommitted changes"
load_start="$(python3 "$root/tools/bench_run.py" load)"
started=$(date +%s)

# shellcheck source=tools/progress.sh
source "$root/tools/progress.sh"
jobs=0 done_jobs=0
for exe in "$build"/bin/pba-*; do
  for scene in $("$exe" --list-scenes | awk '{print $1}'); do
    selected "${exe##*/pba-}/$scene" && jobs=$((jobs + 1))
  done
done
for b in "$build"/bench/pba_*_bench; do [[ -x "$b" ]] && selected "${b##*/}" && jobs=$((jobs + 1)); done
pba_progress_start
# Every scene of every lab, in the labs' order (the number of the report keeps it across filtered runs).
order=0
for exe in "$build"/bin/pba-*; do
  lab="${exe##*/pba-}"
  for scene in $("$exe" --list-scenes | awk '{print $1}'); do
    order=$((order + 1))
    selected "$lab/$scene" || continue
    done_jobs=$((done_jobs + 1))
    pba_progress bench "$done_jobs" "$jobs" "scenes and kernels"
    report="$(printf '%s/scenes/%04d.json' "$tmp" "$order")"
    "$exe" --headless --scene "$scene" --frames "$frames" --metrics "$report" >/dev/null 2>&1 ||
      { echo "bench: $lab/$scene failed" >&2; rm -f "$report"; }
  done
done
for b in "$build"/bench/pba_*_bench; do
  [[ -x "$b" ]] || continue
  name="${b##*/}"
  selected "$name" || continue
  done_jobs=$((done_jobs + 1))
  pba_progress bench "$done_jobs" "$jobs" "scenes and kernels"
  binary_started=$(date +%s)
  "$b" --benchmark_min_time="$min_time" --benchmark_out="$tmp/kernels/$name.json" --benchmark_out_format=json \
    >/dev/null 2>&1 || { echo "bench: $name failed" >&2; rm -f "$tmp/kernels/$name.json"; }
  echo $(($(date +%s) - binary_started)) >"$tmp/kernels/$name.seconds"
done

# A filtered run merges into the results of the runs before it, so its page keeps every other row.
run="$build/bench-run.json"
[[ -n "$filter" ]] || rm -f "$run"
python3 "$root/tools/bench_run.py" record "$run" --scenes "$tmp/scenes" --kernels "$tmp/kernels" --build "$build" \
  --commit "$commit" --preset "$preset" --date "$date_utc" --load-start "$load_start" --filter "$filter" \
  --seconds "$(($(date +%s) - started))" --frames "$frames" || exit 2
status=0
python3 "$root/tools/bench_page.py" "$run" "$out" --budget-ms "$budget_ms" --min-time "$min_time" \
  --topics "$root"/docs/performance-*.md || status=$?
((status <= 1)) || exit 2
python3 "$root/tools/bench_run.py" figures "$run" >"$tmp/figures.tsv"
results="$build/bench-results.json"
python3 "$root/tools/bench_results.py" write "$tmp/figures.tsv" "$results" --commit "$commit" --preset "$preset" \
  --date "$date_utc"
echo "bench: wrote $out, $results and $run in $(($(date +%s) - started)) s"
[[ -z "$compare" ]] || python3 "$root/tools/bench_results.py" compare "$compare" "$results"
# A scene over its budget fails the run (after everything is written), so that it cannot pass unseen.
exit "$status"
