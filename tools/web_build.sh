#!/usr/bin/env bash
# tools/web_build.sh [--deps-only | --physics-tests] [LAB...]: `./pba web`.
# Builds the labs for the browser (WebAssembly + WebGL2) with the system's Emscripten (Debian's
# `emscripten` package): the dependencies once, from Debian's own source packages, into a cache outside
# the clone (tools/debian_sources.sh, as `./pba cross windows` does); then the project with the
# `web` preset, one page per lab (build/web/pba-LAB.html with its .js, .wasm and .data), and an
# index.html listing the labs. No Emscripten port is used (ports are downloaded).
#   --deps-only      stop after the dependency prefixes
#   --physics-tests  instead of the pages, build the physics unit tests with emcc (build/web-tests) and
#                    run them in node
# Environment: PBA_WEB_LABS (the labs when none is named), PBA_WEB_CACHE (default ${XDG_CACHE_HOME:-~/.cache}/pba-labs/emscripten), PBA_JOBS,
# PBA_NO_INSTALL=1 (no apt-get install of the host tools).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
TOOLCHAIN="$ROOT/cmake/toolchains/emscripten.cmake"
CACHE="${PBA_WEB_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/pba-labs/emscripten}"
JOBS="${PBA_JOBS:-$(nproc 2>/dev/null || echo 2)}"
BUILD="$ROOT/build/web-build"
SITE="$ROOT/build/web"
# Debian's Emscripten runs its JavaScript tools with the system's node, whose modules (acorn) live in
# /usr/share/nodejs; a node from another source does not look there by itself.
export NODE_PATH="${NODE_PATH:+$NODE_PATH:}/usr/share/nodejs"
# Debian's Emscripten was packaged for Debian's python3 (another python3 may come first on the PATH).
[[ -x /usr/bin/python3 ]] && export EMSDK_PYTHON="${EMSDK_PYTHON:-/usr/bin/python3}"

deps_only=0
physics_tests=0
labs=()
for arg in "$@"; do
  case "$arg" in
    --deps-only) deps_only=1 ;;
    --physics-tests) physics_tests=1 ;;
    -h | --help) sed -n '2,12p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "usage: ./pba web [--deps-only | --physics-tests] [LAB...]" >&2; exit 2 ;;
    *) labs+=("$arg") ;;
  esac
done

HOST_PACKAGES=(cmake ninja-build pkg-config dpkg-dev emscripten nodejs node-acorn)

# shellcheck source=tools/debian_sources.sh
source "$ROOT/tools/debian_sources.sh"
LOG_TAG=web # say, die and step (tools/debian_sources.sh)
DEPS_FOR=Emscripten
DEP_CC=emcc # zlib's compiler and archiver (build_zlib)
DEP_AR=emar
DEP_CFLAGS="-DHAVE_UNISTD_H" # zlib's configure would find unistd.h (lseek) here
# Assimp's importers: the files the labs' presets and scenes read in the browser.
ASSIMP_IMPORTERS=(BVH OBJ GLTF X)

cross_cmake() { # cross_cmake SOURCE BUILD PREFIX [CMAKE ARGS...]
  local src="$1" bld="$2" prefix="$3"; shift 3
  local deps
  deps="$(IFS=';'; echo "${PREFIXES[*]:-}")"
  cmake -S "$src" -B "$bld" -G Ninja -Wno-dev -DCMAKE_TOOLCHAIN_FILE="$TOOLCHAIN" \
    -DPBA_WEB_PREFIX_PATH="$deps" -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$prefix" \
    -DBUILD_SHARED_LIBS=OFF "$@" >"$bld.configure.log" 2>&1 ||
    { tail -n 40 "$bld.configure.log" >&2; die "configure failed: $src (log $bld.configure.log)"; }
  nice -n 5 cmake --build "$bld" -j "$JOBS" >"$bld.build.log" 2>&1 ||
    { tail -n 40 "$bld.build.log" >&2; die "build failed: $src (log $bld.build.log)"; }
  cmake --install "$bld" >"$bld.install.log" 2>&1 || { tail -n 20 "$bld.install.log" >&2; die "install failed: $src"; }
}

# GoogleTest for the physics suite in node: no threads in this build.
build_googletest() { cross_cmake "$1" "$3" "$2" -DBUILD_GMOCK=OFF -DINSTALL_GTEST=ON -Dgtest_disable_pthreads=ON; }

DEPS=(
  "zlib zlib1g-dev build_zlib"
  "utfcpp libutfcpp-dev build_utfcpp headers"
  "libstb libstb-dev build_libstb"
  "glm libglm-dev build_glm"
  "eigen3 libeigen3-dev build_eigen3"
  "nlohmann-json3 nlohmann-json3-dev build_nlohmann_json3"
  "assimp libassimp-dev build_assimp"
  "imgui libimgui-dev build_imgui"
  "googletest googletest build_googletest"
)

recipe_hash() { # recipe_hash FUNCTION
  { declare -f "$1" cross_cmake; emcc --version 2>/dev/null | head -n1; cat "$TOOLCHAIN";
    [[ "$1" == build_imgui ]] && cat "$ROOT/cmake/cross/imgui/CMakeLists.txt";
    [[ "$1" == build_assimp ]] && echo "${ASSIMP_IMPORTERS[*]} ${PREFIXES[*]}"; true; } | sha256sum | cut -c1-16
}

# The labs of cmake/web/labs.tsv (lab, default scene, second scene, a parameter, description), or those named.
LABS_TSV="$ROOT/cmake/web/labs.tsv"
all_labs() { awk -F'\t' '!/^#/ && NF >= 5 { print $1 }' "$LABS_TSV"; }

build_project() {
  local prefixes targets=() lab
  prefixes="$(IFS=':'; echo "${PREFIXES[*]}")"
  for lab in "${labs[@]}"; do targets+=("pba-$lab"); done
  mkdir -p "$(dirname "$BUILD")" # a fresh clone has no build/ yet (the logs sit beside the build folder)
  # The preset is read from the current folder: ctest runs this from its own (web.build).
  cd "$ROOT"
  PBA_WEB_PREFIX_PATH="$prefixes" cmake --preset web -DPBA_WEB_PREFIX_PATH="$prefixes" >"$BUILD.configure.log" 2>&1 ||
    { tail -n 40 "$BUILD.configure.log" >&2; die "configure failed (log $BUILD.configure.log)"; }
  nice -n 5 cmake --build "$BUILD" -j "$JOBS" --target "${targets[@]}" >"$BUILD.build.log" 2>&1 ||
    { grep -E 'error|undefined' "$BUILD.build.log" | head -n 30 >&2; die "build failed (log $BUILD.build.log)"; }
}

# build/web/: each page with its files, the screenshots of the docs, and index.html listing the labs.
make_site() {
  local lab ext scene second set text
  mkdir -p "$SITE/images"
  for lab in "${labs[@]}"; do
    for ext in html js wasm data; do cp "$BUILD/bin/pba-$lab.$ext" "$SITE/"; done
  done
  {
    cat <<'HTML'
<!doctype html>
<html lang="en">
<head><meta charset="utf-8"><meta name="viewport" content="width=device-width, initial-scale=1">
<title>PBA Labs in the browser</title>
<style>
  body { font-family: sans-serif; max-width: 1100px; margin: 2em auto; color: #234; }
  .labs { display: grid; grid-template-columns: repeat(auto-fill, minmax(320px, 1fr)); gap: 1.2em; }
  .lab { border: 1px solid #cbd5df; border-radius: 6px; padding: 0.6em; }
  .lab img { width: 100%; border-radius: 4px; }
  .lab h2 { margin: 0.2em 0; font-size: 1.2em; }
  code { background: #eef2f6; padding: 0 0.2em; }
</style></head>
<body>
<h1>PBA Labs in the browser</h1>
<p>Every lab of the course, running in this page with nothing installed (WebAssembly and WebGL2).
Look around here; do the exercises in the native build (see the README). A link can open a prepared
setup: <code>pba-cloth.html?scene=flag&amp;set=wind=8</code> picks the scene and sets a parameter;
<code>&amp;lecture=1</code> starts in lecture mode.</p>
<div class="labs">
HTML
    while IFS=$'\t' read -r lab scene second set text; do
      [[ "$lab" == \#* || -z "$text" ]] && continue
      [[ -f "$SITE/pba-$lab.html" ]] || continue
      if [[ -f "$ROOT/docs/images/$lab-$scene.png" ]]; then
        cp "$ROOT/docs/images/$lab-$scene.png" "$SITE/images/"
      fi
      printf '<div class="lab"><a href="pba-%s.html"><img src="images/%s-%s.png" alt="the %s lab, scene %s"></a>\n' \
        "$lab" "$lab" "$scene" "$lab" "$scene"
      printf '<h2><a href="pba-%s.html">%s</a></h2><p>%s</p></div>\n' "$lab" "$lab" "$text"
    done <"$LABS_TSV"
    printf '</div>\n</body>\n</html>\n'
  } >"$SITE/index.html"
}

# The physics suite in node: its own build folder, tests on, GoogleTest from its prefix.
physics_tests() {
  local prefixes bld="$ROOT/build/web-tests"
  prefixes="$(IFS=';'; echo "${PREFIXES[*]}")"
  cmake -S "$ROOT" -B "$bld" -G Ninja -DCMAKE_TOOLCHAIN_FILE="$TOOLCHAIN" -DCMAKE_BUILD_TYPE=Release \
    -DPBA_WEB_PREFIX_PATH="$prefixes" -DPBA_BUILD_BENCH=OFF -DPBA_CCACHE=OFF -DPBA_BUILD_TESTS=ON -DPBA_PHYSICS_SHARED=OFF \
    -DCMAKE_GTEST_DISCOVER_TESTS_DISCOVERY_MODE=PRE_TEST \
    -DCMAKE_CROSSCOMPILING_EMULATOR="$(command -v node);--no-experimental-fetch" >"$bld.configure.log" 2>&1 ||
    { tail -n 40 "$bld.configure.log" >&2; die "configure failed (log $bld.configure.log)"; }
  nice -n 5 cmake --build "$bld" -j "$JOBS" --target pba_physics_tests >"$bld.build.log" 2>&1 ||
    { grep -E 'error|undefined' "$bld.build.log" | head -n 30 >&2; die "build failed (log $bld.build.log)"; }
  # Node 18 and later have fetch(), which Emscripten 3.1.6's loader then tries on a file path: off.
  (cd "$bld/tests" && node --no-experimental-fetch pba_physics_tests.js --gtest_brief=1) ||
    die "the physics tests failed in node"
}

main() {
  local t0=$SECONDS lab
  [[ ${#labs[@]} -gt 0 || -z "${PBA_WEB_LABS:-}" ]] || read -r -a labs <<<"$PBA_WEB_LABS"
  [[ ${#labs[@]} -gt 0 ]] || mapfile -t labs < <(all_labs)
  for lab in "${labs[@]}"; do
    grep -q "^$lab"$'\t' "$LABS_TSV" || { echo "web: no lab '$lab' in cmake/web/labs.tsv" >&2; exit 2; }
  done
  ensure_host_tools
  WORK="$(mktemp -d "${TMPDIR:-/tmp}/pba-web.XXXXXX")"
  step "dependencies (Emscripten, Debian sources)" build_deps
  [[ $deps_only == 1 ]] && return 0
  if [[ $physics_tests == 1 ]]; then
    step "physics tests in node" physics_tests
    return 0
  fi
  step "pages (${labs[*]})" build_project
  step "site" make_site
  say "total: $((SECONDS - t0)) s; pages in $SITE (./pba web --serve)"
}

main
