#!/usr/bin/env bash
# One step of `make`: says what it makes and about how long it takes here, runs it, and says how
# long it took and what it cost. Its wall, user and system seconds, peak memory and page faults (GNU
# time's, over the step and every child it waited for) are appended to build/step-times.log and,
# when the step succeeded, kept as that step's row of results/rebuild_times.csv (a timing file, like
# *_timings.csv: it differs on every machine), under a lock, since `make all` runs steps side by side.
# Usage: scripts/step.sh "WHAT" "ESTIMATE" command [args...]
set -u
what=$1 estimate=$2
shift 2
printf '\n== make: %s (about %s)\n' "$what" "$estimate"
mkdir -p build
usage=$(mktemp build/.step-usage.XXXXXX)
# %e wall, %U user, %S system (seconds), %M peak resident KiB, %R minor and %F major page faults.
/usr/bin/time -o "$usage" -f '%e %U %S %M %R %F' "$@"
status=$?
read -r wall user sys rss_kib minor major < <(tail -n 1 "$usage")
rm -f "$usage"
seconds=$(printf '%.0f' "$wall")
share=$(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.0f", (u + s > 0) ? 100 * s / (u + s) : 0 }')
printf '== make: %s: %s s (user %s s, system %s s = %s %% of CPU; peak %s MiB; %s page faults)%s\n' "$what" "$seconds" \
  "$user" "$sys" "$share" "$((rss_kib / 1024))" "$minor" "$([ $status -eq 0 ] || echo ", exit $status")"
printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$(date -u +%FT%TZ)" "$seconds" "$user" "$sys" "$((rss_kib / 1024))" "$minor" "$what" \
  >> build/step-times.log
if [ $status -eq 0 ] && [ -d results ]; then
  # The step's name is its text up to the colon (the file it makes); commas would break the CSV.
  step=$(printf '%s' "${what%%:*}" | tr ',' ';')
  table=results/rebuild_times.csv
  (
    flock 9
    { echo 'step,seconds,user_seconds,system_seconds,peak_mib,minor_faults'
      [ -f "$table" ] && tail -n +2 "$table" | awk -F, -v s="$step" '$1 != s && NF == 6'
      printf '%s,%s,%s,%s,%s,%s\n' "$step" "$seconds" "$user" "$sys" "$((rss_kib / 1024))" "$minor"
    } > "$table.tmp.$$" && mv "$table.tmp.$$" "$table"
  ) 9> build/.rebuild_times.lock
fi
exit $status
