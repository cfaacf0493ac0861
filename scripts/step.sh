#!/usr/bin/env bash
# One step of `make`: says what it makes and about how long it takes here, runs it, and says how
# long it took. The time is appended to build/step-times.log and, when the step succeeded, kept as
# that step's row of results/rebuild_times.csv (a timing file, like *_timings.csv: it differs on
# every machine), from which the document states how long `make all` takes.
# Usage: scripts/step.sh "WHAT" "ESTIMATE" command [args...]
set -u
what=$1 estimate=$2
shift 2
printf '\n== make: %s (about %s)\n' "$what" "$estimate"
start=$(date +%s.%N)
"$@"
status=$?
seconds=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.0f", b - a }')
printf '== make: %s: %s s%s\n' "$what" "$seconds" "$([ $status -eq 0 ] || echo ", exit $status")"
mkdir -p build 2>/dev/null && printf '%s\t%s\t%s\n' "$(date -u +%FT%TZ)" "$seconds" "$what" >> build/step-times.log 2>/dev/null
if [ $status -eq 0 ] && [ -d results ]; then
  # The step's name is its text up to the colon (the file it makes); commas would break the CSV.
  step=$(printf '%s' "${what%%:*}" | tr ',' ';')
  table=results/rebuild_times.csv
  { echo 'step,seconds'
    [ -f "$table" ] && tail -n +2 "$table" | awk -F, -v s="$step" '$1 != s'
    printf '%s,%s\n' "$step" "$seconds"
  } > "$table.tmp.$$" && mv "$table.tmp.$$" "$table"
fi
exit $status
