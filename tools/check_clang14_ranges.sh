#!/usr/bin/env bash
# ctest repository.builds-with-clang14: the fuzz preset (./pba fuzz, run by CI) compiles everything with
# Debian 12's clang 14, which cannot compile libstdc++ 12's range views (std::views::iota and friends fail
# inside <ranges>). The release build uses GCC and accepts them, so without this check a view reaches main
# and only CI's last stage notices. Range algorithms (std::ranges::fill, copy) compile and are allowed.
# Usage: tools/check_clang14_ranges.sh ROOT
set -euo pipefail
root="$1"
pattern='std::views::|std::ranges::views::|std::ranges::[a-z_]+_view|#include <ranges>'
dirs=()
for d in framework labs tests bench; do [[ -d "$root/$d" ]] && dirs+=("$root/$d"); done
if hits="$(grep -rIEn --include='*.cpp' --include='*.h' "$pattern" "${dirs[@]}")"; then
  echo "FAIL: range views do not compile with clang 14 (the fuzz preset); use an index loop or a callable:"
  echo "$hits" | head -n 40
  exit 1
fi
echo "ok: no range views (clang 14 builds the fuzz preset)"
