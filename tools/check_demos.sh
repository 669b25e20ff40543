#!/usr/bin/env bash
# ctest demos.shipped: one demo script per workbook chapter (resources/demos/NN-name.json beside
# docs/workbook/NN-name.md), and every shipped script validates in each of its labs (scenes, parameters,
# cameras) with its first step of each lab rendered (tools/demo.sh --check).
# Usage: check_demos.sh ROOT BUILD_DIR
set -uo pipefail
root="$1" build="$2"
status=0
for chapter in "$root"/docs/workbook/[0-9][0-9]-*.md; do
  name="$(basename "$chapter" .md)"
  [[ -f "$root/resources/demos/$name.json" ]] || { echo "FAIL: no demo script resources/demos/$name.json for $name.md"; status=1; }
done
for script in "$root"/resources/demos/*.json; do
  bash "$root/tools/demo.sh" "$root" "$build" "$script" --check || { echo "FAIL: $script"; status=1; }
done
[[ $status -eq 0 ]] && echo "ok: every chapter has a demo script and every script validates and renders"
exit $status
