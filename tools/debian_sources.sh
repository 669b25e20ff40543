#!/usr/bin/env bash
# tools/debian_sources.sh: sourced by the scripts that build the dependencies for another platform from
# Debian's own source packages (tools/cross_windows.sh for MinGW-w64, tools/web_build.sh for Emscripten).
# The caller defines say, die, CACHE (the cache folder of its platform), DEPS (entries "SOURCE BINARY
# FUNCTION [headers]"), DEPS_FOR (the platform, in words), the build functions, and recipe_hash FUNCTION
# (a hash of everything that decides what FUNCTION builds). WORK is a temporary folder, removed on exit.

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
