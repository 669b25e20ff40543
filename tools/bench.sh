#!/usr/bin/env bash
# ./pba bench: runs the kernel benchmarks (bench/*_bench.cpp, Google Benchmark) and the scene
# benchmarks (every scene of every lab headless), prints a table, writes docs/performance.md (release
# preset, every figure) or BUILD_DIR/performance.md (another preset, or --filter), and every figure as
# JSON to BUILD_DIR/bench-results.json; --compare REF.json prints each figure's change against an earlier
# run's JSON (keep one with `cp build/release/bench-results.json ref.json` before a change).
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
budget_ms=2.0
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
: >"$tmp/figures.tsv"
# selected NAME: true when no --filter was given or NAME matches it.
selected() { [[ -z "$filter" || "$1" =~ $filter ]]; }

cpu="$(grep -m1 'model name' /proc/cpuinfo 2>/dev/null | sed 's/.*: //' || echo unknown)"
cores="$(nproc 2>/dev/null || echo '?')"
date_utc="$(date -u +%Y-%m-%d)"
commit="$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)"

{
  echo "# Performance"
  echo
  echo "Written by \`./pba bench\` on $date_utc (commit $commit). Machine: $cpu, $cores cores; $preset preset"
  echo "($(grep -m1 '^CMAKE_CXX_FLAGS_RELWITHDEBINFO' "$build/CMakeCache.txt" 2>/dev/null | sed 's/.*=//' || echo '?')), one thread. Regenerate with \`./pba bench\`; each row names the command that reproduces it."
  echo "Figures from one run: medians where the tool reports them; compare rows of the same run only."
  echo
  echo "## Scenes (physics time per displayed frame, budget $budget_ms ms on one core)"
  echo
  echo "Command: \`build/release/bin/pba-LAB --headless --scene SCENE --frames $frames --metrics -\`"
  echo
  echo "| lab | scene | frames | median ms | p95 ms | max ms | within budget |"
  echo "|---|---|---:|---:|---:|---:|---|"
} >"$tmp/doc.md"

# shellcheck source=tools/progress.sh
source "$root/tools/progress.sh"
over=0
jobs=0 done_jobs=0
for exe in "$build"/bin/pba-*; do
  for scene in $("$exe" --list-scenes | awk '{print $1}'); do selected "${exe##*/pba-}/$scene" && jobs=$((jobs + 1)); done
done
for b in "$build"/bench/pba_*_bench; do [[ -x "$b" ]] && selected "${b##*/}" && jobs=$((jobs + 1)); done
pba_progress_start
for exe in "$build"/bin/pba-*; do
  lab="${exe##*/pba-}"
  for scene in $("$exe" --list-scenes | awk '{print $1}'); do
    selected "$lab/$scene" || continue
    done_jobs=$((done_jobs + 1))
    pba_progress bench "$done_jobs" "$jobs" "scenes and kernels"
    "$exe" --headless --scene "$scene" --frames "$frames" --metrics "$tmp/m.json" >/dev/null 2>&1 || { echo "bench: $lab/$scene failed" >&2; continue; }
    read -r median p95 max < <(tr -d ' \n' <"$tmp/m.json" | grep -oE '"step_ms":\{[^}]*\}' |
      sed -E 's/.*"max":([0-9.e+-]+).*"median":([0-9.e+-]+).*"p95":([0-9.e+-]+).*/\2 \3 \1/')
    ok="yes"
    awk -v m="$median" -v b="$budget_ms" 'BEGIN { exit !(m > b) }' && { ok="**no**"; over=$((over + 1)); }
    printf '| %s | %s | %s | %.4f | %.4f | %.4f | %s |\n' "$lab" "$scene" "$frames" "$median" "$p95" "$max" "$ok" >>"$tmp/doc.md"
    printf 'scene/%s/%s median\t%s\tms\nscene/%s/%s p95\t%s\tms\n' "$lab" "$scene" "$median" "$lab" "$scene" "$p95" >>"$tmp/figures.tsv"
  done
done

{
  echo
  echo "## Kernels (Google Benchmark)"
  echo
} >>"$tmp/doc.md"
for b in "$build"/bench/pba_*_bench; do
  [[ -x "$b" ]] || continue
  name="${b##*/}"
  selected "$name" || continue
  done_jobs=$((done_jobs + 1))
  pba_progress bench "$done_jobs" "$jobs" "scenes and kernels"
  "$b" --benchmark_format=csv --benchmark_min_time=0.2 >"$tmp/$name.csv" 2>/dev/null || { echo "bench: $name failed" >&2; continue; }
  {
    echo "### $name"
    echo
    echo "Command: \`build/release/bench/$name\`"
    echo
    echo "| benchmark | CPU time | unit | items/s | label |"
    echo "|---|---:|---|---:|---|"
    awk -F',' 'NR > 1 && $1 != "" {
      gsub(/"/, "", $1); items = ($7 == "" ? "" : sprintf("%.3g", $7));
      printf "| %s | %.4g | %s | %s | %s |\n", $1, $4, $5, items, $8 }' "$tmp/$name.csv"
    echo
  } >>"$tmp/doc.md"
  awk -F',' -v bench="$name" 'NR > 1 && $1 != "" { gsub(/"/, "", $1); printf "kernel/%s/%s\t%s\t%s\n", bench, $1, $4, $5 }' \
    "$tmp/$name.csv" >>"$tmp/figures.tsv"
done

# The peer comparisons (Bullet, KDL) and per-topic summaries below the marker are measured by the topic
# benches with their own method (docs/performance-*.md) and kept as they are.
marker='<!-- kept by ./pba bench: peer comparisons and per-topic summaries -->'
if [[ -f "$out" ]] && line="$(grep -nF -- "$marker" "$out" | head -1 | cut -d: -f1)" && [[ -n "$line" ]]; then
  {
    echo
    tail -n +"$line" "$out"
  } >>"$tmp/doc.md"
fi
cp "$tmp/doc.md" "$out"
cat "$out"
echo
results="$build/bench-results.json"
python3 "$root/tools/bench_results.py" write "$tmp/figures.tsv" "$results" --commit "$commit" --preset "$preset" \
  --date "$date_utc"
echo "bench: wrote $out ($over scene(s) over the ${budget_ms} ms budget) and $results"
[[ -z "$compare" ]] || python3 "$root/tools/bench_results.py" compare "$compare" "$results"
