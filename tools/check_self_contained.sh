#!/usr/bin/env bash
# ctest repository.stands-on-its-own: no file of the project refers to a design document or folder
# outside the repository; docs/architecture.md is the design. Usage: tools/check_self_contained.sh ROOT
set -euo pipefail
root="$1"
outside="DESIGN""\\.md|\\.\\./""shared|shared/""reference"
if hits="$(grep -rIEn --exclude-dir=.git --exclude-dir=build "$outside" "$root" 2>/dev/null)"; then
  echo "FAIL: these lines refer to documents outside the repository (refer to docs/architecture.md instead):"
  echo "$hits" | head -n 40
  exit 1
fi
echo "ok: no file refers outside the repository"
