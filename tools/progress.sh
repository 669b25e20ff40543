# Sourced by the driver's long jobs (./pba screenshots, ./pba bench): the same one-line progress as the
# labs' (framework/app/runner/progress_line.h): "[label] [#####      ] 12/52 scenes, 40 s elapsed, ~130 s left".
# On a terminal it redraws in place on stderr; piped, it prints a line per item.
pba_progress_start() { PBA_PROGRESS_T0=$(date +%s); }
# pba_progress LABEL DONE TOTAL UNIT
pba_progress() {
  local label="$1" done="$2" total="$3" unit="$4" width=30
  local elapsed=$(($(date +%s) - PBA_PROGRESS_T0))
  local filled=$((total > 0 ? width * done / total : 0))
  local bar tail
  bar="$(printf '%*s' "$filled" '' | tr ' ' '#')$(printf '%*s' $((width - filled)) '')"
  tail="$done/$total $unit, $elapsed s elapsed"
  ((done > 0 && done < total)) && tail+=", ~$((elapsed * (total - done) / done)) s left"
  if [[ -t 2 ]]; then
    printf '\r[%s] [%s] %s' "$label" "$bar" "$tail" >&2
    ((done >= total)) && printf '\n' >&2
  else
    printf '[%s] [%s] %s\n' "$label" "$bar" "$tail" >&2
  fi
  return 0
}
