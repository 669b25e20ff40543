# Functions behind ./pba. Sourced, not run. Every command installs what it needs, configures and
# builds incrementally with the CMake presets, then does its work.

PBA_PACKAGES=(cmake ninja-build g++ pkg-config libglm-dev libglfw3-dev libglew-dev libimgui-dev
  libassimp-dev nlohmann-json3-dev libstb-dev libeigen3-dev googletest libgtest-dev libbenchmark-dev
  xvfb xauth assimp-testmodels python3 python3-matplotlib ccache xdotool clang-format ffmpeg
  clang libclang-rt-14-dev)
# What only this repository's own checks need: Google Benchmark (bench/), clang for the fuzz and clang-14
# checks, clang-format for the format check. The student hand-out (.student-release) does not install them.
PBA_DEVELOPER_PACKAGES=(libbenchmark-dev clang-format clang libclang-rt-14-dev)
# The peers that ./pba bench measures ours against (bench/CMakeLists.txt): Bullet and Orocos KDL.
PBA_BENCH_PEER_PACKAGES=(libbullet-dev liborocos-kdl-dev)
if [[ -f "${ROOT:-.}/.student-release" ]]; then
  pba_developer_only=" ${PBA_DEVELOPER_PACKAGES[*]} "
  pba_student_packages=()
  for pba_package in "${PBA_PACKAGES[@]}"; do
    [[ "$pba_developer_only" == *" $pba_package "* ]] || pba_student_packages+=("$pba_package")
  done
  PBA_PACKAGES=("${pba_student_packages[@]}")
  unset pba_developer_only pba_student_packages pba_package
fi
PBA_JOBS="${PBA_JOBS:-$(nproc 2>/dev/null || sysctl -n hw.ncpu 2>/dev/null || echo 2)}"
# The preset of run and test: on macOS the vcpkg one (README.md, "On your own machine"), else release.
if [[ "$(uname -s)" == Darwin ]]; then PBA_DEFAULT_PRESET=macos; else PBA_DEFAULT_PRESET=release; fi

pba_say() {
  if [[ -t 2 ]]; then printf '\033[1m[pba]\033[0m %s\n' "$*" >&2; else printf '[pba] %s\n' "$*" >&2; fi
}
pba_die() { printf 'pba: %s\n' "$1" >&2; exit "${2:-1}"; }

# pba_missing_packages PACKAGE...: those of the list that are not installed.
pba_missing_packages() {
  local p missing=()
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
  done
  echo "${missing[@]:-}"
}

# Installs missing system packages with apt-get (sudo when not root; non-interactive).
# pba_ensure_packages [EXTRA...]: the base list plus the extra packages one command needs.
pba_ensure_packages() {
  [[ "${PBA_NO_INSTALL:-0}" == 1 ]] && return 0
  if ! command -v dpkg-query >/dev/null; then
    pba_say "not a Debian/Ubuntu system: install what README.md, \"On your own machine\", lists for yours"
    return 0
  fi
  local missing
  missing="$(pba_missing_packages "${PBA_PACKAGES[@]}" "$@")"
  [[ -z "${missing// /}" ]] && return 0
  local sudo=()
  if [[ $(id -u) -ne 0 ]]; then
    command -v sudo >/dev/null || pba_die "missing packages ($missing) and no sudo: install them as root"
    sudo=(sudo)
  fi
  pba_say "installing: $missing"
  export DEBIAN_FRONTEND=noninteractive
  "${sudo[@]}" apt-get update -qq >&2 || pba_die "apt-get update failed"
  # shellcheck disable=SC2086
  "${sudo[@]}" apt-get install -y -qq --no-install-recommends $missing >&2 || pba_die "apt-get install failed for: $missing"
}

# pba_build PRESET [TARGET...]: configure once, then build incrementally.
pba_build() {
  local preset="$1"; shift
  local dir="$ROOT/build/$preset"
  if [[ ! -f "$dir/build.ninja" ]]; then
    pba_say "configuring ($preset)"
    cmake --preset "$preset" >&2 || pba_die "configure failed (./pba doctor lists what is missing)"
  fi
  pba_say "building ($preset${*:+: $*})"
  if [[ $# -eq 0 ]]; then
    # The build preset's own targets (the libcxx preset builds only the physics and app tests).
    cmake --build --preset "$preset" -j "$PBA_JOBS" >&2 || pba_die "build failed"
    return
  fi
  local targets=()
  local t
  for t in "$@"; do targets+=(--target "$t"); done
  cmake --build "$dir" -j "$PBA_JOBS" "${targets[@]}" >&2 || pba_die "build failed"
}

pba_list_labs() {
  local d
  for d in "$ROOT"/labs/*/; do
    [[ -f "$d/CMakeLists.txt" ]] && basename "$d"
  done
}

pba_has_display() { [[ -n "${DISPLAY:-}" || -n "${WAYLAND_DISPLAY:-}" ]]; }

# Runs a command under Xvfb when there is no display.
pba_with_display() {
  if pba_has_display; then "$@"; else bash "$ROOT/tools/with_xvfb.sh" -s "-screen 0 1280x720x24" "$@"; fi
}

pba_cmd_run() {
  local lab="hello"
  if [[ $# -gt 0 && "$1" != -* ]]; then lab="$1"; shift; fi
  [[ -f "$ROOT/labs/$lab/CMakeLists.txt" ]] || pba_die "unknown lab '$lab' (labs: $(pba_list_labs | tr '\n' ' '))" 2
  pba_ensure_packages
  pba_build "$PBA_DEFAULT_PRESET" "pba-$lab"
  local exe="$ROOT/build/$PBA_DEFAULT_PRESET/bin/pba-$lab"
  local arg
  for arg in "$@"; do
    case "$arg" in
      --headless | --help | -h | --list-scenes) exec "$exe" "$@" ;;
      --screenshot | --screenshot=*) pba_with_display "$exe" "$@"; return ;;
    esac
  done
  if pba_has_display; then
    exec "$exe" "$@"
  fi
  mkdir -p "$ROOT/build/screenshots"
  local png="$ROOT/build/screenshots/$lab.png"
  pba_say "no display: rendering under Xvfb to a screenshot"
  bash "$ROOT/tools/with_xvfb.sh" -s "-screen 0 1280x720x24" "$exe" "$@" --screenshot "$png" --metrics -
  pba_say "screenshot written to $png"
}

# pba_take_preset DEFAULT ARGS...: PBA_PRESET from `--preset P` or `--preset=P` anywhere in ARGS (else
# DEFAULT), PBA_ARGS the other arguments in their order (test, grade and bench share it).
pba_take_preset() {
  PBA_PRESET="$1"
  shift
  PBA_ARGS=()
  while [[ $# -gt 0 ]]; do
    case "$1" in
      --preset) PBA_PRESET="${2:?--preset needs a value}"; shift 2 ;;
      --preset=*) PBA_PRESET="${1#--preset=}"; shift ;;
      *) PBA_ARGS+=("$1"); shift ;;
    esac
  done
}

# Packages only one preset needs, beyond the base list.
pba_preset_packages() {
  case "$1" in
    libcxx) echo "libc++-14-dev libc++abi-14-dev" ;;
  esac
}

pba_cmd_test() {
  pba_take_preset "$PBA_DEFAULT_PRESET" "$@"
  # shellcheck disable=SC2046
  pba_ensure_packages $(pba_preset_packages "$PBA_PRESET")
  pba_build "$PBA_PRESET"
  pba_say "running the tests ($PBA_PRESET)"
  # ${A[@]+...}: an empty array is "unbound" to bash before 4.4 under set -u (macOS has bash 3.2).
  ctest --preset "$PBA_PRESET" -j "$PBA_JOBS" ${PBA_ARGS[@]+"${PBA_ARGS[@]}"}
}

pba_cmd_grade() {
  pba_take_preset release "$@"
  pba_ensure_packages
  # Everything: exercise tests include command-line tests of the lab executables, and a partial
  # build would grade stale binaries.
  pba_build "$PBA_PRESET"
  bash "$ROOT/tools/grade.sh" "$ROOT/build/$PBA_PRESET" "$ROOT/resources/exercises.tsv" "${PBA_ARGS[@]}"
}

# ./pba mark STUDENT_TREE [--coursework N] [--csv FILE]: marks a student's coursework (tools/mark.sh).
pba_cmd_mark() {
  [[ $# -ge 1 ]] || pba_die "usage: ./pba mark STUDENT_TREE [--coursework N] [--csv FILE]" 2
  bash "$ROOT/tools/mark.sh" "$ROOT" "$@"
}

pba_cmd_student_release() {
  [[ $# -eq 1 ]] || pba_die "usage: ./pba student-release DIR" 2
  bash "$ROOT/tools/student_release.sh" "$ROOT" "$1"
}

# ./pba fuzz [SECONDS]: builds the fuzz preset (clang, libFuzzer, ASan + UBSan) and runs each target
# for SECONDS of wall time (default 60), PBA_JOBS targets at a time, seeded from the repository and
# Debian's assimp-testmodels (read in place, never copied). Fails on any sanitizer report, property
# violation, hang or memory blow-up, and copies the input that caused it to tests/corpora/fuzz/TARGET/
# (the replay ctest's regression inputs).
PBA_FUZZ_TARGETS=(scene_file command_line model_import ik_skeleton anim_clip)

# pba_fuzz_one TARGET SECONDS: one libFuzzer run; its exit status goes to build/fuzz/runs/TARGET/rc.
pba_fuzz_one() {
  local target="$1" seconds="$2" models=/usr/share/assimp/models  # where Debian's assimp-testmodels puts them
  local work="$ROOT/build/fuzz/runs/$target" seeds=() sub subs=()
  rm -rf "$work" && mkdir -p "$work/corpus" "$work/artifacts"
  case "$target" in
    scene_file) seeds=("$ROOT/resources/scenes" "$ROOT/tests/corpora/scenes") ;;
    command_line) seeds=("$ROOT/tests/fuzz/seeds/command_line") ;;
    model_import) seeds=("$ROOT/tests/fuzz/seeds/model_import" "$ROOT/resources/models" "$ROOT/tests/corpora/models") ;;
    ik_skeleton | anim_clip) seeds=("$ROOT/resources/models" "$ROOT/tests/corpora/models") ;;
  esac
  # Debian's test models of the formats the labs import (inputs are cut at -max_len, 1 MiB).
  case "$target" in
    model_import) subs=(BVH OBJ glTF2 Collada FBX X) ;;
    ik_skeleton) subs=(BVH) ;;
    anim_clip) subs=(BVH X) ;;
  esac
  for sub in "${subs[@]}"; do [[ -d "$models/$sub" ]] && seeds+=("$models/$sub"); done
  [[ -d "$ROOT/tests/corpora/fuzz/$target" ]] && seeds+=("$ROOT/tests/corpora/fuzz/$target")
  local rc=0
  ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:handle_sigfpe=0" UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1" \
    LSAN_OPTIONS="suppressions=$ROOT/tests/support/lsan.supp:print_suppressions=0" \
    "$ROOT/build/fuzz/bin/pba_fuzz_$target" -max_total_time="$seconds" -timeout=20 -rss_limit_mb=2048 \
    -max_len=1048576 -print_final_stats=1 -artifact_prefix="$work/artifacts/" "$work/corpus" "${seeds[@]}" \
    >"$work/log.txt" 2>&1 || rc=$?
  echo "$rc" >"$work/rc"
}

pba_cmd_fuzz() {
  local seconds="${1:-60}"
  [[ "$seconds" =~ ^[0-9]+$ && "$seconds" -ge 1 ]] || pba_die "usage: ./pba fuzz [SECONDS] (a whole number >= 1)" 2
  pba_ensure_packages
  pba_build fuzz pba_fuzz_targets
  local failed=0 target running=0
  pba_say "fuzzing ${PBA_FUZZ_TARGETS[*]} for $seconds s each, $PBA_JOBS at a time"
  for target in "${PBA_FUZZ_TARGETS[@]}"; do
    if [[ $running -ge $PBA_JOBS ]]; then wait -n || true; running=$((running - 1)); fi
    pba_fuzz_one "$target" "$seconds" &
    running=$((running + 1))
  done
  wait || true
  for target in "${PBA_FUZZ_TARGETS[@]}"; do
    local work="$ROOT/build/fuzz/runs/$target" rc runs speed
    rc="$(cat "$work/rc" 2>/dev/null || echo '?')"
    runs="$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$work/log.txt" | grep -o '[0-9]*$' || true)"
    speed="$(grep -o 'stat::average_exec_per_sec: *[0-9]*' "$work/log.txt" | grep -o '[0-9]*$' || true)"
    echo "$target: ${runs:-?} runs, ${speed:-?} exec/s, exit $rc (log: $work/log.txt)"
    if [[ "$rc" != 0 ]] || compgen -G "$work/artifacts/*" >/dev/null; then
      failed=1
      mkdir -p "$ROOT/tests/corpora/fuzz/$target"
      cp "$work"/artifacts/* "$ROOT/tests/corpora/fuzz/$target/" 2>/dev/null || true
      pba_say "$target failed: the input is in tests/corpora/fuzz/$target/; the report is in $work/log.txt"
      tail -n 30 "$work/log.txt" >&2
    fi
  done
  [[ $failed -eq 0 ]] || pba_die "fuzzing found a defect"
  pba_say "every fuzz target ran $seconds s clean"
}

# ./pba bench [--preset release|native] [--filter REGEX] [--compare REF.json] (tools/bench.sh).
pba_cmd_bench() {
  pba_take_preset release "$@"
  local preset="$PBA_PRESET" args=("${PBA_ARGS[@]}")
  [[ "$preset" == release || "$preset" == native ]] || pba_die "bench: --preset $preset: benchmarks build in release or native" 2
  local i  # a bad --compare file fails before the build, not after it
  for ((i = 0; i < ${#args[@]}; i++)); do
    if [[ "${args[i]}" == --compare ]]; then
      [[ -f "${args[i + 1]:-}" ]] || pba_die "bench: --compare: no file ${args[i + 1]:-(none given)}" 2
      python3 "$ROOT/tools/bench_results.py" check "${args[i + 1]}" || exit 2
    fi
  done
  local new_peers
  new_peers="$(pba_missing_packages "${PBA_BENCH_PEER_PACKAGES[@]}")"
  pba_ensure_packages "${PBA_BENCH_PEER_PACKAGES[@]}"
  if [[ -n "${new_peers// /}" && -f "$ROOT/build/$preset/CMakeCache.txt" ]]; then
    # pkg-config's answer is cached: look for the peers again now that they are installed.
    cmake --preset "$preset" -U '__pkg_config_checked_PBA_PEER_*' >/dev/null || pba_die "configure failed"
  fi
  pba_build "$preset"
  bash "$ROOT/tools/bench.sh" "$ROOT" "$ROOT/build/$preset" --preset "$preset" "${args[@]}"
}

# Debian's python3 (its python3-matplotlib draws the sweep plots), else whatever python3 is first on PATH.
pba_python() { if [[ -x /usr/bin/python3 ]]; then echo /usr/bin/python3; else command -v python3; fi; }

pba_cmd_sweep() {
  [[ $# -ge 1 && "$1" != -* ]] || pba_die "usage: ./pba sweep LAB --set NAME=VALUES [...] (./pba sweep LAB --help)" 2
  [[ -f "$ROOT/labs/$1/CMakeLists.txt" ]] || pba_die "unknown lab '$1' (labs: $(pba_list_labs | tr '\n' ' '))" 2
  pba_ensure_packages
  pba_build release "pba-$1"
  "$(pba_python)" "$ROOT/tools/sweep.py" "$@"
}

pba_cmd_demo() {
  pba_ensure_packages
  pba_build release
  bash "$ROOT/tools/demo.sh" "$ROOT" "$ROOT/build/release" "$@"
}

pba_cmd_screenshots() {
  pba_ensure_packages
  pba_build release
  bash "$ROOT/tools/screenshots.sh" "$ROOT" "$ROOT/build/release"
}

pba_cmd_doctor() {
  local ok=1 missing
  missing="$(pba_missing_packages "${PBA_PACKAGES[@]}")"
  if [[ -n "${missing// /}" ]]; then
    echo "packages: MISSING $missing  (./pba test installs them, or: sudo apt-get install $missing)"
    ok=0
  else
    echo "packages: all ${#PBA_PACKAGES[@]} installed"
  fi
  if pba_has_display; then echo "display: ${DISPLAY:-$WAYLAND_DISPLAY}"; else echo "display: none (labs render under Xvfb: tools/with_xvfb.sh)"; fi
  command -v Xvfb >/dev/null && echo "Xvfb: $(command -v Xvfb)" || { echo "Xvfb: MISSING (apt-get install xvfb)"; ok=0; }
  local exe="$ROOT/build/release/bin/pba-hello"
  if [[ -x "$exe" ]]; then
    local tmp
    tmp="$(mktemp -d)"
    if pba_with_display "$exe" --screenshot "$tmp/doctor.png" --frames 1 --metrics "$tmp/m.json" >"$tmp/log" 2>&1; then
      echo "OpenGL: $(grep -o '"gl_renderer": *"[^"]*"' "$tmp/m.json" | sed 's/.*: *//') (window and screenshot work)"
    else
      echo "OpenGL: FAILED to open a window: $(tail -n 1 "$tmp/log")"
      ok=0
    fi
    rm -rf "$tmp"
  else
    echo "OpenGL: not checked (build first: ./pba run)"
  fi
  [[ $ok == 1 ]] && echo "doctor: all good" || { echo "doctor: problems found"; return 1; }
}

# ./pba golden [--update] [LAB...]: checks every scene of every lab (or the LABs named) against its golden
# trajectory in tests/golden/LAB.json, or rewrites those files from this build (--update; say why in the
# commit message: the physics changed on purpose).
pba_cmd_golden() {
  local mode="--check-golden" labs=() lab failed=0
  for lab in "$@"; do
    case "$lab" in
      --update) mode="--update-golden" ;;
      -*) pba_die "usage: ./pba golden [--update] [LAB...]" 2 ;;
      *) [[ -f "$ROOT/labs/$lab/CMakeLists.txt" ]] || pba_die "unknown lab '$lab' (labs: $(pba_list_labs | tr '\n' ' '))" 2
         labs+=("$lab") ;;
    esac
  done
  [[ ${#labs[@]} -gt 0 ]] || mapfile -t labs < <(pba_list_labs)
  pba_ensure_packages
  local targets=()
  for lab in "${labs[@]}"; do targets+=("pba-$lab"); done
  pba_build release "${targets[@]}"
  mkdir -p "$ROOT/tests/golden"
  for lab in "${labs[@]}"; do
    "$ROOT/build/release/bin/pba-$lab" "$mode" "$ROOT/tests/golden/$lab.json" || failed=1
  done
  [[ $failed -eq 0 ]] || pba_die "golden trajectories: see the lines above"
}

# ./pba soak [MINUTES] [--seed N]: every lab's soak (app/checks/soak_run.h) for MINUTES (default 60) of wall time,
# as many labs at a time as there are cores; logs in build/soak/LAB.log. Fails on a failed soak, a crash
# (a signal) or a hang (the lab still running 5 minutes after its time).
pba_cmd_soak() {
  local minutes=60 seed=1
  while [[ $# -gt 0 ]]; do
    case "$1" in
      --seed) seed="${2:?--seed needs a value}"; shift 2 ;;
      *) minutes="$1"; shift ;;
    esac
  done
  [[ "$minutes" =~ ^[0-9]+([.][0-9]+)?$ ]] && awk "BEGIN{exit !($minutes > 0)}" ||
    pba_die "usage: ./pba soak [MINUTES] [--seed N] (MINUTES > 0)" 2
  [[ "$seed" =~ ^[0-9]+$ ]] || pba_die "--seed: expected a whole number, got '$seed'" 2
  pba_ensure_packages
  local labs=() lab
  mapfile -t labs < <(pba_list_labs)
  local targets=()
  for lab in "${labs[@]}"; do targets+=("pba-$lab"); done
  pba_build release "${targets[@]}"
  local seconds limit dir="$ROOT/build/soak"
  seconds="$(awk "BEGIN{print $minutes * 60}")"
  limit="$(awk "BEGIN{print int($seconds + 300)}")"
  mkdir -p "$dir"
  pba_say "soaking ${#labs[@]} labs for $minutes min each (seed $seed), $PBA_JOBS at a time; logs in $dir"
  printf '%s\n' "${labs[@]}" | xargs -P "$PBA_JOBS" -I{} bash -c \
    'timeout "$3" "$1/build/release/bin/pba-$0" --soak "$2" --seed "$4" >"$5/$0.log" 2>&1; echo $? >"$5/$0.rc"' \
    {} "$ROOT" "$seconds" "$limit" "$seed" "$dir"
  local failed=0 rc
  for lab in "${labs[@]}"; do
    rc="$(cat "$dir/$lab.rc" 2>/dev/null || echo missing)"
    case "$rc" in
      0) grep '^soak ' "$dir/$lab.log" ;;
      124) echo "soak $lab: HUNG (still running ${limit} s after start; killed)"; failed=1 ;;
      1) cat "$dir/$lab.log"; failed=1 ;;
      *) echo "soak $lab: CRASHED (exit $rc); the end of $dir/$lab.log:"; tail -n 20 "$dir/$lab.log"; failed=1 ;;
    esac
  done
  [[ $failed -eq 0 ]] || pba_die "soak failed"
  pba_say "every lab soaked $minutes min clean"
}

# ./pba cross windows [--tests-only]: the Windows build proved here (tools/cross_windows.sh).
# ./pba web [LAB...]: the labs as web pages (tools/web_build.sh); ./pba web --serve [PORT]: serves them.
pba_cmd_web() {
  if [[ "${1:-}" == --serve ]]; then
    local port="${2:-8000}"
    [[ -f "$ROOT/build/web/index.html" ]] || pba_die "no build/web/index.html: run ./pba web first" 1
    [[ "$port" =~ ^[0-9]+$ ]] || pba_die "web --serve: the port must be a number, not '$port'" 2
    echo "Serving build/web at http://127.0.0.1:$port/ (Ctrl+C stops)"
    exec python3 -m http.server "$port" --bind 127.0.0.1 --directory "$ROOT/build/web"
  fi
  bash "$ROOT/tools/web_build.sh" "$@"
}

pba_cmd_cross() {
  case "${1:-}" in
    windows) shift; bash "$ROOT/tools/cross_windows.sh" "$@" ;;
    *) pba_die "usage: ./pba cross windows [--tests-only]" 2 ;;
  esac
}
