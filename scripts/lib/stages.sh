# Stage timing for the scripts (sourced, not run): each stage prints its wall time when it
# ends, and `stages_table` prints them all. A script started by another one (test.sh runs
# sanitizers.sh) adds its stages to the same table through SD_STAGES_FILE.
#   stage "name"     ends the running stage (if any) and starts "name"
#   stage_end        ends the running stage
#   stages_table     the table of every stage recorded in SD_STAGES_FILE, with the total

if [ -z "${SD_STAGES_FILE:-}" ]; then
  SD_STAGES_FILE="$(mktemp "${TMPDIR:-/tmp}/swarmdesign-stages.XXXXXX")"
  export SD_STAGES_FILE
  sd_stages_owner=1
fi

sd_stage_name=""
sd_stage_start=0

stage_end() {
  local status="${1:-ok}"
  if [ -n "$sd_stage_name" ]; then
    local took=$((SECONDS - sd_stage_start))
    printf '%s\t%s\t%s\n' "$sd_stage_name" "$took" "$status" >> "$SD_STAGES_FILE"
    echo "== $sd_stage_name: $status in $(sd_format_seconds "$took")"
    sd_stage_name=""
  fi
}

stage() {
  stage_end
  sd_stage_name="$1"
  sd_stage_start=$SECONDS
  echo "== $1"
}

sd_format_seconds() {
  printf '%dm%02ds' $(($1 / 60)) $(($1 % 60))
}

stages_table() {
  [ -s "$SD_STAGES_FILE" ] || return 0
  local total=0 name took status
  echo
  printf '%-44s %9s  %s\n' "stage" "wall" "result"
  while IFS=$'\t' read -r name took status; do
    printf '%-44s %9s  %s\n' "$name" "$(sd_format_seconds "$took")" "$status"
    total=$((total + took))
  done < "$SD_STAGES_FILE"
  printf '%-44s %9s\n' "total" "$(sd_format_seconds "$total")"
}

# The script that made the table file prints it at exit, also when a stage failed (the
# failing stage is marked), and removes it.
sd_stages_exit() {
  local code=$?
  if [ -n "$sd_stage_name" ]; then
    if [ "$code" -eq 0 ]; then stage_end; else stage_end "FAILED (exit $code)"; fi
  fi
  if [ -n "${sd_stages_owner:-}" ]; then
    stages_table
    rm -f "$SD_STAGES_FILE"
  fi
  return "$code"
}
trap sd_stages_exit EXIT
