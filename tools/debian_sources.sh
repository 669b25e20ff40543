#!/usr/bin/env bash
# tools/debian_sources.sh: sourced by the scripts that build the dependencies for another platform from
# Debian's own source packages (tools/cross_windows.sh for MinGW-w64, tools/web_build.sh for Emscripten).
# The caller defines LOG_TAG (the word its messages start with), CACHE (the cache folder of its platform),
# DEPS (entries "SOURCE BINARY FUNCTION [headers]"), DEPS_FOR (the platform, in words), the build
# functions, and recipe_hash FUNCTION (a hash of everything that decides what FUNCTION builds). WORK is a
# temporary folder, removed on exit.

say() { printf '[%s] %s\n' "$LOG_TAG" "$*" >&2; }
die() { printf '%s: %s\n' "$LOG_TAG" "$*" >&2; exit 1; }

# step NAME COMMAND...: runs COMMAND and prints how long it took.
step() {
  local name="$1"; shift
  local t0=$SECONDS
  say "$name ..."
  "$@"
  say "$name: $((SECONDS - t0)) s"
}

# ensure_host_tools: installs the caller's HOST_PACKAGES that are missing (not with PBA_NO_INSTALL=1).
ensure_host_tools() {
  local p missing=()
  for p in "${HOST_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
  done
  [[ ${#missing[@]} -eq 0 ]] && return 0
  [[ "${PBA_NO_INSTALL:-0}" == 1 ]] && die "missing packages: ${missing[*]} (PBA_NO_INSTALL=1)"
  local sudo=()
  [[ $(id -u) -ne 0 ]] && sudo=(sudo)
  say "installing: ${missing[*]}"
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2 ||
    die "apt-get install failed for: ${missing[*]}"
}


# Debian source packages through a private apt state: deb-src entries derived from the machine's own
# apt sources (every `deb` entry, as `deb-src`), in a temporary folder removed on exit. The system's
# apt configuration and lists are not touched.
WORK=""
APT_OPTS=()
cleanup() { [[ -n "$WORK" ]] && rm -rf "$WORK"; }
trap cleanup EXIT

apt_private_init() {
  [[ ${#APT_OPTS[@]} -gt 0 ]] && return 0
  local dir="$WORK/apt" f
  mkdir -p "$dir/sources.list.d" "$dir/lists/partial" "$dir/cache/archives/partial"
  : >"$dir/sources.list"
  for f in /etc/apt/sources.list.d/*.sources; do
    [[ -f "$f" ]] || continue
    # deb822 stanzas whose Types name `deb` become deb-src stanzas.
    awk 'BEGIN { RS = ""; ORS = "\n\n" }
         /(^|\n)Types:[^\n]*[ \t]deb([ \t]|\n|$)/ { sub(/Types:[^\n]*/, "Types: deb-src"); print }' \
      "$f" >"$dir/sources.list.d/$(basename "$f")"
  done
  for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
    [[ -f "$f" ]] || continue
    sed -n 's/^[[:space:]]*deb[[:space:]]/deb-src /p' "$f" >>"$dir/sources.list"
  done
  APT_OPTS=(-o "Dir::Etc::SourceList=$dir/sources.list" -o "Dir::Etc::SourceParts=$dir/sources.list.d"
    -o "Dir::State::Lists=$dir/lists" -o "Dir::Cache=$dir/cache" -o "APT::Sandbox::User=$(id -un)")
  apt-get "${APT_OPTS[@]}" update -qq >&2 || die "apt-get update (deb-src) failed"
}

# src_version SOURCE BINARY: the version of SOURCE that built the candidate of BINARY in the system's
# apt lists (the Debian packages the native build uses); read offline.
src_version() {
  local src="$1" bin="$2" info v
  info="$(apt-cache show --no-all-versions "$bin" 2>/dev/null)" || true
  v="$(sed -n "s/^Source: $src (\(.*\))$/\1/p" <<<"$info" | head -n1)"
  [[ -n "$v" ]] || v="$(sed -n 's/^Version: //p' <<<"$info" | head -n1)"
  [[ -n "$v" ]] || v="$(dpkg-query -W -f='${Version}' "$bin" 2>/dev/null || true)"
  [[ -n "$v" ]] || die "no version of $bin in apt's lists (apt-get update)"
  echo "$v"
}

# fetch_source SOURCE VERSION DIR [BINARY]: unpacks Debian's source package (patches applied) into
# DIR/src and prints the path of the tree. Falls back to the other versions apt knows when the archive
# lacks this one, and for a header-only package (BINARY given) to the files of its binary package.
fetch_source() {
  local src="$1" version="$2" dir="$3" bin="${4:-}" v tree
  apt_private_init
  mkdir -p "$dir/src"
  local versions=("$version")
  mapfile -t -O 1 versions < <(apt-cache "${APT_OPTS[@]}" showsrc "$src" 2>/dev/null |
    sed -n 's/^Version: //p' | grep -vxF "$version" | sort -urV)
  for v in "${versions[@]}"; do
    if (cd "$dir/src" && apt-get "${APT_OPTS[@]}" source -qq --only-source "$src=$v" >/dev/null 2>&1); then
      tree="$(find "$dir/src" -mindepth 1 -maxdepth 1 -type d | head -n1)"
      [[ "$v" != "$version" ]] && say "$src $version is not in the source archive: building $v"
      echo "source package $src $v" >"$dir/fetched"
      echo "$tree"
      return 0
    fi
    rm -rf "${dir:?}/src"/*
  done
  if [[ -n "$bin" ]] && (cd "$dir" && apt-get download -qq "$bin=$version" >/dev/null 2>&1); then
    say "$src $version: no source in the archive, taking the headers of $bin"
    dpkg-deb -x "$dir"/"${bin}"_*.deb "$dir/src/$bin"
    echo "binary package $bin $version (headers)" >"$dir/fetched"
    echo "$dir/src/$bin"
    return 0
  fi
  die "apt-get source $src=$version failed"
}


# Dependency prefixes: $CACHE/<source>-<version>/, one a source package, each built once. A prefix is
# complete when its .pba-recipe holds the hash of the recipe that built it (the build function below
# and the imgui glue), so a changed recipe rebuilds it; .pba-source says what was built (the archive
# may hold only an older source than the binary package's).
PREFIXES=()

build_deps() {
  local entry src bin fn kind version prefix hash t0 built=0
  mkdir -p "$CACHE"
  for entry in "${DEPS[@]}"; do
    read -r src bin fn kind <<<"$entry"
    version="$(src_version "$src" "$bin")"
    prefix="$CACHE/$src-${version#*:}" # the folder's name without the epoch
    hash="$(recipe_hash "$fn")"
    if [[ -f "$prefix/.pba-recipe" && "$(cat "$prefix/.pba-recipe")" == "$hash" ]]; then
      PREFIXES+=("$prefix")
      continue
    fi
    t0=$SECONDS
    say "building $src $version for $DEPS_FOR ..."
    local dir="$WORK/$src" tree
    mkdir -p "$dir"
    apt_private_init # here, not in fetch_source's subshell, so that it runs once
    tree="$(fetch_source "$src" "$version" "$dir" "${kind:+$bin}")"
    rm -rf "$prefix" "$prefix.partial"
    "$fn" "$tree" "$prefix.partial" "$dir/build"
    # The prefix paths written into .pc and CMake files name the final folder.
    { grep -rlF "$prefix.partial" "$prefix.partial" || true; } | xargs -r sed -i "s|$prefix.partial|$prefix|g"
    cp "$dir/fetched" "$prefix.partial/.pba-source"
    echo "$hash" >"$prefix.partial/.pba-recipe"
    mv "$prefix.partial" "$prefix"
    rm -rf "$dir"
    PREFIXES+=("$prefix")
    built=$((built + 1))
    say "built $src $version: $((SECONDS - t0)) s"
  done
  say "dependency prefixes ($built built, $((${#DEPS[@]} - built)) cached): $CACHE ($(du -sch "${PREFIXES[@]}" | tail -n1 | cut -f1))"
}

# ---------------------------------------------------------------------------------------------------
# Build recipes shared by the platforms. Each builds SOURCE-TREE into PREFIX (BUILD-DIR for its
# objects) through the caller's cross_cmake SOURCE BUILD PREFIX [CMAKE ARGS...], with DEP_CC, DEP_AR
# and DEP_CFLAGS (optional) for zlib, which is compiled directly.
build_zlib() { # zlib (libz.a) and its contrib/minizip (libminizip.a + minizip.pc), compiled directly:
  # Debian's source has no win32/ makefile, and zlib's CMake names its Windows libraries zlib*.
  local src="$1" prefix="$2" bld="$3" f
  mkdir -p "$prefix/include/minizip" "$prefix/lib/pkgconfig" "$bld/z" "$bld/minizip"
  for f in adler32 compress crc32 deflate gzclose gzlib gzread gzwrite inflate infback inftrees inffast \
    trees uncompr zutil; do
    nice -n 5 "$DEP_CC" -O2 ${DEP_CFLAGS:-} -I"$src" -c "$src/$f.c" -o "$bld/z/$f.o"
  done
  "$DEP_AR" rcs "$prefix/lib/libz.a" "$bld"/z/*.o
  cp "$src/zlib.h" "$src/zconf.h" "$prefix/include/"
  local win32=()
  [[ "$DEP_CC" == *mingw* ]] && win32=(iowin32) # minizip's Win32 file functions
  for f in ioapi unzip zip "${win32[@]}"; do
    nice -n 5 "$DEP_CC" -O2 ${DEP_CFLAGS:-} -I"$prefix/include" -c "$src/contrib/minizip/$f.c" -o "$bld/minizip/$f.o"
    cp "$src/contrib/minizip/$f.h" "$prefix/include/minizip/"
  done
  cp "$src/contrib/minizip/crypt.h" "$prefix/include/minizip/"
  "$DEP_AR" rcs "$prefix/lib/libminizip.a" "$bld"/minizip/*.o
  cat >"$prefix/lib/pkgconfig/minizip.pc" <<PC
prefix=$prefix
libdir=\${prefix}/lib
includedir=\${prefix}/include
Name: minizip
Description: zip and unzip on top of zlib (zlib's contrib/minizip)
Version: 1.2
Libs: -L\${libdir} -lminizip -lz
Cflags: -I\${includedir}/minizip -I\${includedir}
PC
}

build_utfcpp() { # header-only: utf8.h and utf8/ as Debian installs them (include/utf8cpp)
  local src="$1" prefix="$2"
  mkdir -p "$prefix/include/utf8cpp"
  if [[ -d "$src/source" ]]; then
    cp -r "$src/source/." "$prefix/include/utf8cpp/"
  else # the binary package's headers (fetch_source's fallback for header-only packages)
    cp -r "$src/usr/include/utf8cpp/." "$prefix/include/utf8cpp/"
  fi
}

build_libstb() { # header-only: include/stb/*.h as Debian installs them, and no .pc file (as vcpkg):
  # the project then compiles the implementations itself
  local src="$1" prefix="$2"
  mkdir -p "$prefix/include/stb"
  cp "$src"/*.h "$prefix/include/stb/"
}

build_glm() { cross_cmake "$1" "$3" "$2" -DGLM_TEST_ENABLE=OFF -DBUILD_TESTING=OFF; }

build_eigen3() {
  cross_cmake "$1" "$3" "$2" -DBUILD_TESTING=OFF -DEIGEN_BUILD_DOC=OFF -DEIGEN_BUILD_PKGCONFIG=ON \
    -DCMAKE_Fortran_COMPILER=NOTFOUND -DEIGEN_TEST_NOQT=ON
}

build_nlohmann_json3() { cross_cmake "$1" "$3" "$2" -DJSON_BuildTests=OFF -DJSON_Install=ON; }

# Assimp: the importers in ASSIMP_IMPORTERS (the caller's: what its labs, presets and tests read); no
# exporters, tools, tests or samples.
# Debian's source leaves out zlib, minizip, utf8cpp and stb: they come from their own prefixes. Its
# patch that links Debian's libdraco is taken back (Draco, glTF's mesh compression, stays off).
build_assimp() {
  local src="$1" prefix="$2" bld="$3" imp flags=() inc=""
  if [[ -f "$src/debian/patches/use-system-libdraco.patch" ]]; then
    patch -d "$src" -R -p1 -s <"$src/debian/patches/use-system-libdraco.patch" || die "assimp: cannot revert use-system-libdraco.patch"
  fi
  for imp in "${ASSIMP_IMPORTERS[@]}"; do flags+=("-DASSIMP_BUILD_${imp}_IMPORTER=ON"); done
  for imp in "${PREFIXES[@]}"; do
    [[ -d "$imp/include/utf8cpp" ]] && inc+=" -I$imp/include/utf8cpp"
    [[ -d "$imp/include/stb" ]] && inc+=" -I$imp/include"
  done
  cross_cmake "$src" "$bld" "$prefix" -DASSIMP_BUILD_ALL_IMPORTERS_BY_DEFAULT=OFF "${flags[@]}" \
    -DASSIMP_NO_EXPORT=ON -DASSIMP_BUILD_ALL_EXPORTERS_BY_DEFAULT=OFF -DASSIMP_BUILD_TESTS=OFF \
    -DASSIMP_BUILD_ASSIMP_TOOLS=OFF -DASSIMP_BUILD_SAMPLES=OFF -DASSIMP_BUILD_DOCS=OFF \
    -DASSIMP_BUILD_ZLIB=OFF -DASSIMP_BUILD_DRACO=OFF -DASSIMP_WARNINGS_AS_ERRORS=OFF \
    -DASSIMP_INSTALL_PDB=OFF -DASSIMP_BUILD_ASSIMP_VIEW=OFF -DCMAKE_CXX_FLAGS="$inc" -DCMAKE_C_FLAGS="$inc"
  # assimp exports minizip and z as bare names (pkg-config's), which a consumer's linker cannot find:
  # name the archives of the zlib prefix instead.
  local zlib targets
  for zlib in "${PREFIXES[@]}"; do [[ -f "$zlib/lib/libminizip.a" ]] && break; done
  targets="$(find "$prefix/lib/cmake" -name assimpTargets.cmake)"
  grep -q ';minizip;z"' "$targets" || die "assimp: no bare minizip;z in $targets"
  sed -i "s|;minizip;z\"|;$zlib/lib/libminizip.a;$zlib/lib/libz.a\"|" "$targets"
}

build_imgui() {
  cross_cmake "$ROOT/cmake/cross/imgui" "$3" "$2" -DIMGUI_SOURCE_DIR="$1"
}
