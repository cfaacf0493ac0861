#!/usr/bin/env bash
# The table `make all` ends with: each step's wall, CPU and system time, peak memory and page
# faults (results/rebuild_times.csv, written by scripts/step.sh), and the whole run's wall time.
# Usage: scripts/step_report.sh WALL_SECONDS [STEPS_SECONDS]
# WALL_SECONDS: the whole run, the build included; STEPS_SECONDS: from the end of the build on.
set -u
wall=${1:-}
steps=${2:-}
table=results/rebuild_times.csv
[ -f "$table" ] || { echo "step_report: no $table"; exit 0; }
echo
echo "== make all: the steps (results/rebuild_times.csv)"
# The costliest step first; the row "make all" is the whole run, reported below.
awk -F, 'NR > 1 && $1 !~ /^make all/ {
  cpu = $3 + $4; share = cpu > 0 ? 100 * $4 / cpu : 0
  printf "%s\t%-34s %6s s wall %7.1f s cpu %5.0f %% system %7s MiB %9s faults\n", $2, substr($1, 1, 34), $2, cpu, share, $5, $6 }' "$table" |
  sort -t$'\t' -k1,1nr | cut -f2-
awk -F, 'NR > 1 && $1 !~ /^make all/ { total += $2 } END { printf "%-34s %6.0f s, the steps one after another\n", "(sum)", total }' "$table"
if [ -n "$wall" ]; then
  printf 'make all took %s s of wall time, the build included, on %s cores\n' "$wall" "$(getconf _NPROCESSORS_ONLN)"
  if [ -n "$steps" ]; then
    printf 'of which %s s for the steps after the build, and %s s for the build\n' "$steps" "$((wall - steps))"
  fi
  # Kept as the rows "make all" (its wall time alone, from which the document says how long it
  # takes) and "make all: steps" (the same from the end of the build on).
  (
    flock 9
    { echo 'step,seconds,user_seconds,system_seconds,peak_mib,minor_faults'
      tail -n +2 "$table" | awk -F, '$1 !~ /^make all/ && NF == 6'
      printf 'make all,%s,,,,\n' "$wall"
      if [ -n "$steps" ]; then printf 'make all: steps,%s,,,,\n' "$steps"; fi
    } > "$table.tmp.$$" && mv "$table.tmp.$$" "$table"
  ) 9> build/.rebuild_times.lock
fi
exit 0
