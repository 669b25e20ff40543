#!/usr/bin/env bash
# tools/cross_windows.sh [--tests-only] [--deps-only]: `./pba cross windows`.
# Proves the Windows build here (docs/architecture.md §6): builds the
# dependencies for MinGW-w64 (the -posix compilers) from Debian's own source packages, once, into a
# cache outside the clone; configures the project with the windows-mingw preset, which finds every
# dependency through its CONFIG package as on Windows with vcpkg; builds every lab and test as .exe;
# runs the unit tests under Wine and each lab's default scene under Wine (headless, then a screenshot
# under Xvfb). Prints the time of each step.
#   --tests-only  stop after the unit tests (no lab runs)
#   --deps-only   stop after the dependency prefixes
# Environment: PBA_CROSS_CACHE (default ${XDG_CACHE_HOME:-~/.cache}/pba-labs/mingw-w64),
# PBA_JOBS, PBA_NO_INSTALL=1 (no apt-get install of the host tools).
# Writes build/windows-mingw (the build) and build/windows-mingw/cross (logs, metrics, screenshots).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
TRIPLE=x86_64-w64-mingw32
TOOLCHAIN="$ROOT/cmake/toolchains/mingw-w64-posix.cmake"
CACHE="${PBA_CROSS_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/pba-labs/mingw-w64}"
JOBS="${PBA_JOBS:-$(nproc 2>/dev/null || echo 2)}"
BUILD="$ROOT/build/windows-mingw"
OUT="$BUILD/cross"

tests_only=0
deps_only=0
for arg in "$@"; do
  case "$arg" in
    --tests-only) tests_only=1 ;;
    --deps-only) deps_only=1 ;;
    -h | --help) sed -n '2,13p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "usage: ./pba cross windows [--tests-only] [--deps-only]" >&2; exit 2 ;;
  esac
done

# ---------------------------------------------------------------------------------------------------
# Host tools
HOST_PACKAGES=(cmake ninja-build pkg-config dpkg-dev mingw-w64 g++-mingw-w64-x86-64-posix
  gcc-mingw-w64-x86-64-posix wine wine64 xvfb xauth)

# ---------------------------------------------------------------------------------------------------
# Debian source packages and the dependency prefixes built from them: tools/debian_sources.sh.
# shellcheck source=tools/debian_sources.sh
source "$ROOT/tools/debian_sources.sh"
LOG_TAG=cross # say, die and step (tools/debian_sources.sh)
DEPS_FOR=MinGW-w64
DEP_CC="$TRIPLE-gcc-posix" # zlib's compiler and archiver (build_zlib)
DEP_AR="$TRIPLE-ar"

# ---------------------------------------------------------------------------------------------------

cross_cmake() { # cross_cmake SOURCE BUILD PREFIX [CMAKE ARGS...]
  local src="$1" bld="$2" prefix="$3"; shift 3
  local deps
  deps="$(IFS=';'; echo "${PREFIXES[*]:-}")"
  cmake -S "$src" -B "$bld" -G Ninja -Wno-dev -DCMAKE_TOOLCHAIN_FILE="$TOOLCHAIN" \
    -DPBA_MINGW_PREFIX_PATH="$deps" -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$prefix" \
    -DBUILD_SHARED_LIBS=OFF -DCMAKE_POSITION_INDEPENDENT_CODE=OFF "$@" >"$bld.configure.log" 2>&1 ||
    { tail -n 40 "$bld.configure.log" >&2; die "configure failed: $src (log $bld.configure.log)"; }
  nice -n 5 cmake --build "$bld" -j "$JOBS" >"$bld.build.log" 2>&1 ||
    { tail -n 40 "$bld.build.log" >&2; die "build failed: $src (log $bld.build.log)"; }
  cmake --install "$bld" >"$bld.install.log" 2>&1 || { tail -n 20 "$bld.install.log" >&2; die "install failed: $src"; }
}

build_glfw3() {
  cross_cmake "$1" "$3" "$2" -DGLFW_BUILD_EXAMPLES=OFF -DGLFW_BUILD_TESTS=OFF -DGLFW_BUILD_DOCS=OFF
}

build_glew() { cross_cmake "$1/build/cmake" "$3" "$2" -DBUILD_UTILS=OFF; }

# Assimp's importers: what the labs, presets and tests read (build_assimp, tools/debian_sources.sh).
ASSIMP_IMPORTERS=(BVH OBJ GLTF FBX COLLADA PLY STL X 3DS MD5)

build_googletest() { cross_cmake "$1" "$3" "$2" -DBUILD_GMOCK=ON -DINSTALL_GTEST=ON -Dgtest_disable_pthreads=OFF; }

# Debian source package, a binary package it builds (for its version), the build function, and
# `headers` where the binary package's headers may stand in for a source the archive lacks.
DEPS=(
  "zlib zlib1g-dev build_zlib"
  "utfcpp libutfcpp-dev build_utfcpp headers"
  "libstb libstb-dev build_libstb"
  "glm libglm-dev build_glm"
  "eigen3 libeigen3-dev build_eigen3"
  "nlohmann-json3 nlohmann-json3-dev build_nlohmann_json3"
  "glfw3 libglfw3-dev build_glfw3"
  "glew libglew-dev build_glew"
  "googletest googletest build_googletest"
  "assimp libassimp-dev build_assimp"
  "imgui libimgui-dev build_imgui"
)

recipe_hash() { # recipe_hash FUNCTION
  { declare -f "$1" cross_cmake; [[ "$1" == build_imgui ]] && cat "$ROOT/cmake/cross/imgui/CMakeLists.txt";
    [[ "$1" == build_assimp ]] && echo "${ASSIMP_IMPORTERS[*]} ${PREFIXES[*]}"; true; } | sha256sum | cut -c1-16
}

# ---------------------------------------------------------------------------------------------------
# Wine: a private prefix in the cache, created once.
WINE=wine
wine_init() {
  WINE="$(command -v wine || command -v wine64)" || die "wine is not installed"
  export WINEPREFIX="$CACHE/wineprefix" WINEDEBUG=-all WINEDLLOVERRIDES="mscoree,mshtml="
  export WINEARCH=win64
  if [[ ! -f "$WINEPREFIX/system.reg" ]]; then
    wineboot -i >/dev/null 2>&1 || die "wineboot -i failed (WINEPREFIX=$WINEPREFIX)"
  fi
  wineserver -w 2>/dev/null || true
}

# The smoke project of cmake/cross/smoke against the prefixes: a window with GLFW + GLEW + ImGui
# under Xvfb, and a GoogleTest test, both under Wine. Says whether the prefixes work before the
# project's own code is compiled.
smoke_prefix() {
  local bld="$BUILD/cross-smoke"
  mkdir -p "$OUT"
  cmake -S "$ROOT/cmake/cross/smoke" -B "$bld" -G Ninja -DCMAKE_TOOLCHAIN_FILE="$TOOLCHAIN" \
    -DCMAKE_BUILD_TYPE=Release >"$OUT/smoke-configure.log" 2>&1 ||
    { tail -n 30 "$OUT/smoke-configure.log" >&2; die "smoke: configure failed ($OUT/smoke-configure.log)"; }
  nice -n 5 cmake --build "$bld" -j "$JOBS" >"$OUT/smoke-build.log" 2>&1 ||
    { grep -E 'error|undefined' "$OUT/smoke-build.log" | head -n 30 >&2; die "smoke: build failed ($OUT/smoke-build.log)"; }
  (cd "$OUT" && wine "$bld/smoke_gtest.exe" --gtest_brief=1) >"$OUT/smoke-gtest.log" 2>&1 ||
    { cat "$OUT/smoke-gtest.log" >&2; die "smoke: the GoogleTest test failed under Wine"; }
  (cd "$OUT" && xvfb "$WINE" "$bld/smoke_window.exe" smoke.png) >"$OUT/smoke-window.log" 2>&1 ||
    { cat "$OUT/smoke-window.log" >&2; die "smoke: the window failed under Wine + Xvfb"; }
  sed 's/^/  /' "$OUT/smoke-window.log" >&2
}

# Wine's desktop process outlives a program for a few seconds and keeps the display it started with
# (none, or an Xvfb that has gone): each run starts from a stopped wineserver. The prefix is private.
wine_fresh() { wineserver -k 2>/dev/null || true; wineserver -w 2>/dev/null || true; }
# The screen is larger than the labs' 1280 x 720 window: on a 1280 x 720 screen Wine fits the window
# and its caption into the screen, and the frame came out 1280 x 705.
XVFB_SCREEN="-screen 0 1920x1080x24"
xvfb() { wine_fresh; bash "$ROOT/tools/with_xvfb.sh" -s "$XVFB_SCREEN" "$@"; }

FAILED=()
MAX_RSS_KB=$((${PBA_CROSS_MAX_RSS_MB:-4096} * 1024))

# limited SECONDS COMMAND...: runs COMMAND in a session of its own and kills the session when it runs
# past SECONDS or its processes together hold more than PBA_CROSS_MAX_RSS_MB (4096) resident: a
# program whose memory bound does not hold on Windows must not take the machine down with it.
limited() {
  local limit_s="$1" ticks=0 rss pid
  shift
  setsid "$@" &
  pid=$!
  while kill -0 "$pid" 2>/dev/null; do
    rss="$(ps -o rss= --sid "$pid" 2>/dev/null | awk '{ s += $1 } END { print s + 0 }')"
    if ((rss > MAX_RSS_KB || ticks >= limit_s)); then
      if ((rss > MAX_RSS_KB)); then echo "cross: killed at $((rss / 1024)) MB resident"; else echo "cross: killed after ${limit_s} s"; fi
      kill -9 -- "-$pid" 2>/dev/null
      wait "$pid" 2>/dev/null
      return 137
    fi
    sleep 1
    ticks=$((ticks + 1))
  done
  wait "$pid"
}

configure_project() {
  mkdir -p "$OUT"
  (cd "$ROOT" && cmake --preset windows-mingw) >"$OUT/configure.log" 2>&1 ||
    { tail -n 40 "$OUT/configure.log" >&2; die "configure failed ($OUT/configure.log)"; }
}

# Builds every target; keeps going past errors so that the log lists them all and what built still runs.
build_project() {
  if ! nice -n 5 cmake --build "$BUILD" -j "$JOBS" -- -k 0 >"$OUT/build.log" 2>&1; then
    grep -E ': (fatal )?error|undefined reference|: multiple definition' "$OUT/build.log" | sort -u | head -n 60 >&2
    FAILED+=(build)
    say "build failed ($OUT/build.log): what did build is run below"
  fi
  local warnings
  warnings="$(grep -c ': warning:' "$OUT/build.log" || true)"
  [[ "$warnings" -gt 0 ]] && say "$warnings compiler warnings (grep ': warning:' $OUT/build.log)"
  say "$(find "$BUILD" -name '*.exe' -not -path '*/CMakeFiles/*' -not -path '*/cross-smoke/*' | wc -l) programs (.exe) in $BUILD"
}

# Each GoogleTest program once, the whole suite in one Wine process (ctest would start Wine once a test).
run_tests() {
  local exe name t0 summary
  mkdir -p "$OUT/tests"
  while IFS= read -r exe; do
    name="$(basename "$exe" .exe)"
    t0=$SECONDS
    wine_fresh
    if (cd "$OUT/tests" && limited 1200 "$WINE" "$exe" --gtest_brief=1) >"$OUT/tests/$name.log" 2>&1; then
      summary="$(grep -E '^\[  PASSED  \]' "$OUT/tests/$name.log" | tail -n1)"
      say "  $name: ${summary:-passed} ($((SECONDS - t0)) s)"
    else
      FAILED+=("$name")
      say "  $name: FAILED ($((SECONDS - t0)) s, $OUT/tests/$name.log):"
      grep -E '^\[  FAILED  \]|Failure|^cross: killed' "$OUT/tests/$name.log" | sort -u | head -n 20 | sed 's/^/    /' >&2
    fi
  done < <(find "$BUILD" -name 'pba_*_tests.exe' -not -path '*/cross-smoke/*' | sort)
}

# Each lab's default scene: headless with its metrics, then a screenshot under Xvfb.
run_labs() {
  local lab exe t0
  mkdir -p "$OUT/labs"
  for lab in $(cd "$ROOT/labs" && for d in */; do [[ -f "$d/CMakeLists.txt" ]] && echo "${d%/}"; done); do
    exe="$BUILD/bin/pba-$lab.exe"
    [[ -f "$exe" ]] || { FAILED+=("$lab (no $exe)"); continue; }
    t0=$SECONDS
    wine_fresh
    if (cd "$OUT/labs" && limited 600 "$WINE" "$exe" --headless --metrics -) >"$OUT/labs/$lab.headless.log" 2>&1; then
      say "  $lab --headless: ok ($((SECONDS - t0)) s)"
    else
      FAILED+=("$lab --headless")
      say "  $lab --headless: FAILED ($((SECONDS - t0)) s): $(tail -n 3 "$OUT/labs/$lab.headless.log" | tr '\n' ' ')"
    fi
    t0=$SECONDS
    rm -f "$OUT/labs/$lab.png"
    wine_fresh
    if (cd "$OUT/labs" && limited 600 bash "$ROOT/tools/with_xvfb.sh" -s "$XVFB_SCREEN" \
      "$WINE" "$exe" --screenshot "$lab.png") >"$OUT/labs/$lab.screenshot.log" 2>&1 && [[ -s "$OUT/labs/$lab.png" ]]; then
      say "  $lab --screenshot: $OUT/labs/$lab.png ($((SECONDS - t0)) s)"
    else
      FAILED+=("$lab --screenshot")
      say "  $lab --screenshot: FAILED ($((SECONDS - t0)) s): $(tail -n 3 "$OUT/labs/$lab.screenshot.log" | tr '\n' ' ')"
    fi
  done
}

main() {
  command -v apt-get >/dev/null || die "needs a Debian or Ubuntu host (apt-get source)"
  ensure_host_tools
  WORK="$(mktemp -d "${TMPDIR:-/tmp}/pba-cross.XXXXXX")"
  step "dependencies (MinGW-w64, Debian sources)" build_deps
  [[ $deps_only == 1 ]] && return 0
  export PBA_MINGW_PREFIX_PATH
  PBA_MINGW_PREFIX_PATH="$(IFS=':'; echo "${PREFIXES[*]}")"
  step "wine prefix" wine_init
  step "prefix smoke (GLFW + GLEW + ImGui window, GoogleTest) under Wine" smoke_prefix
  step "configure (windows-mingw)" configure_project
  step "build (.exe)" build_project
  step "unit tests under Wine" run_tests
  [[ $tests_only == 0 ]] && step "labs under Wine (headless, then a screenshot under Xvfb)" run_labs
  if [[ ${#FAILED[@]} -gt 0 ]]; then
    say "failed: ${FAILED[*]}"
    return 1
  fi
  say "all passed under Wine; logs, metrics and screenshots in $OUT"
}

main; exit $?
