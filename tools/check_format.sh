#!/usr/bin/env bash
# ctest repository.formatted: every C++ file of the project is in the house style of .clang-format
# (clang-format 14, Debian's clang-format package). Without clang-format the check says so and fails,
# since ./pba doctor installs it. Usage: tools/check_format.sh ROOT   (fix: tools/check_format.sh ROOT --fix)
set -euo pipefail
root="$1"
cd "$root"
tool="$(command -v clang-format-14 || command -v clang-format || true)"
[[ -n "$tool" ]] || { echo "FAIL: clang-format not found (apt-get install clang-format)"; exit 1; }
mapfile -t files < <(git ls-files '*.cpp' '*.h' 2>/dev/null || find framework labs tests bench tools -name '*.cpp' -o -name '*.h')
if [[ "${2:-}" == --fix ]]; then
  "$tool" -i "${files[@]}"
  echo "formatted ${#files[@]} files"
  exit 0
fi
bad=()
for f in "${files[@]}"; do
  "$tool" --dry-run -Werror "$f" >/dev/null 2>&1 || bad+=("$f")
done
if ((${#bad[@]})); then
  echo "FAIL: ${#bad[@]} files are not in the house style (.clang-format); run tools/check_format.sh . --fix:"
  printf '  %s\n' "${bad[@]:0:40}"
  exit 1
fi
echo "ok: ${#files[@]} C++ files in the house style"
