#!/usr/bin/env bash
# tools/with_xvfb.sh [-s "SERVER ARGUMENTS"] COMMAND [ARGS...]
# Runs COMMAND on a private Xvfb (default screen 1280x720x24) and returns its exit status. The server
# picks a free display number itself and reports it once it accepts clients (Xvfb -displayfd), so tests
# that run in parallel never race for a number. `xvfb-run -a` does race: two runs can choose the same
# number, one server fails, and its command connects to the other run's server, which refuses its
# authorisation cookie ("Failed to open display :100"), a failure measured once in 126 UI tests.
set -u
server_args="-screen 0 1280x720x24"
if [[ "${1:-}" == -s ]]; then
  server_args="${2:?with_xvfb.sh: -s needs the server arguments}"
  shift 2
fi
[[ $# -ge 1 ]] || { echo "usage: with_xvfb.sh [-s \"SERVER ARGUMENTS\"] COMMAND [ARGS...]" >&2; exit 2; }
command -v Xvfb >/dev/null || { echo "with_xvfb.sh: Xvfb is not installed (apt-get install xvfb)" >&2; exit 2; }

dir="$(mktemp -d "${TMPDIR:-/tmp}/pba-xvfb.XXXXXX")"
server=""
cleanup() {
  if [[ -n "$server" ]]; then
    kill "$server" 2>/dev/null
    wait "$server" 2>/dev/null
  fi
  rm -rf "$dir"
}
trap cleanup EXIT
trap 'exit 143' TERM INT

mkfifo "$dir/display"
# shellcheck disable=SC2086  # the server arguments are words
Xvfb -displayfd 3 -nolisten tcp $server_args 3>"$dir/display" 2>"$dir/xvfb.log" &
server=$!
# The read blocks until the server writes its display number (it does so once it is ready) or exits.
display=""
read -r -t 60 display <"$dir/display" || true
if [[ ! "$display" =~ ^[0-9]+$ ]]; then
  echo "with_xvfb.sh: Xvfb did not start: $(tail -n 3 "$dir/xvfb.log" | tr '\n' ' ')" >&2
  exit 1
fi
DISPLAY=":$display" "$@"
status=$?
exit "$status"
