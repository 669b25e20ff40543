#!/usr/bin/env bash
# ./pba bench: runs the kernel benchmarks (bench/*_bench.cpp, Google Benchmark) and the scene
# benchmarks (every scene of every lab headless), prints a table and writes docs/performance.md.
# Usage: tools/bench.sh ROOT BUILD_DIR
set -euo pipefail
root="$1"
build="$2"
out="$root/docs/performance.md"
frames="${PBA_BENCH_FRAMES:-600}"
budget_ms=2.0
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

cpu="$(grep -m1 'model name' /proc/cpuinfo 2>/dev/null | sed 's/.*: //' || echo unknown)"
cores="$(nproc 2>/dev/null || echo '?')"
date_utc="$(date -u +%Y-%m-%d)"
commit="$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)"

{
  echo "# Performance"
  echo
  echo "Written by \`./pba bench\` on $date_utc (commit $commit). Machine: $cpu, $cores cores; release preset"
  echo "(\`-O2\`), one thread. Regenerate with \`./pba bench\`; each row names the command that reproduces it."
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
for exe in "$build"/bin/pba-*; do jobs=$((jobs + $("$exe" --list-scenes | wc -l))); done
for b in "$build"/bench/pba_*_bench; do [[ -x "$b" ]] && jobs=$((jobs + 1)); done
pba_progress_start
for exe in "$build"/bin/pba-*; do
  lab="${exe##*/pba-}"
  for scene in $("$exe" --list-scenes | awk '{print $1}'); do
    done_jobs=$((done_jobs + 1))
    pba_progress bench "$done_jobs" "$jobs" "scenes and kernels"
    "$exe" --headless --scene "$scene" --frames "$frames" --metrics "$tmp/m.json" >/dev/null 2>&1 || { echo "bench: $lab/$scene failed" >&2; continue; }
    read -r median p95 max < <(tr -d ' \n' <"$tmp/m.json" | grep -oE '"step_ms":\{[^}]*\}' |
      sed -E 's/.*"max":([0-9.e+-]+).*"median":([0-9.e+-]+).*"p95":([0-9.e+-]+).*/\2 \3 \1/')
    ok="yes"
    awk -v m="$median" -v b="$budget_ms" 'BEGIN { exit !(m > b) }' && { ok="**no**"; over=$((over + 1)); }
    printf '| %s | %s | %s | %.4f | %.4f | %.4f | %s |\n' "$lab" "$scene" "$frames" "$median" "$p95" "$max" "$ok" >>"$tmp/doc.md"
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
echo "bench: wrote $out ($over scene(s) over the ${budget_ms} ms budget)"
