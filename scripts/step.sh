#!/usr/bin/env bash
# One step of `make`: says what it makes and about how long it takes here, runs it, and says how
# long it took (also appended to build/step-times.log), keeping the command's exit status.
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
exit $status
