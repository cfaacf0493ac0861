#!/bin/sh
# The document's three worked `plate` commands ("Using it on your own scene"): runs each and writes
# what it prints after the echo of its options (the status line to the certificate; the time line
# left out, since it differs on every run) to one Markdown file, whole: a temporary file renamed at
# the end. Usage: scripts/own_scenes.sh PLATE OUT.md
set -eu
plate=$1 out=$2
tmp=$(mktemp "$out.XXXXXX")
trap 'rm -f "$tmp"' EXIT
trap 'exit 130' INT TERM
run() {
  printf '`plate %s`\n\n```\n' "$1" >> "$tmp"
  # Each command is a scene of the section; a failure is kept and shown, with its exit status.
  status=0
  eval "\"$plate\" $1" > "$tmp.run" 2>&1 || status=$?
  sed -n '/^converged\|^NOT CONVERGED\|bad input/,$p' "$tmp.run" | grep -v '^time:' >> "$tmp"
  rm -f "$tmp.run"
  printf 'exit status %s\n```\n\n' "$status" >> "$tmp"
}
printf 'Made by `make own-scenes` (`scripts/own_scenes.sh`): what `plate` prints for each worked command of the section, after its echo of every option.\n\n' > "$tmp"
run "-n 96 --lx 1.5 --centre 0.6,0.45"
run "-n 64 --obstacle '0.05-0.4*((x-0.5)^2+(y-0.5)^2)' --load -1"
run "-n 64 --obstacle 'abs(x-0.5)<=0.2 && abs(y-0.5)<=0.2 ? 0.05 : -1' --edge 'polygon:0.3,0.3;0.7,0.3;0.7,0.7;0.3,0.7'"
mv "$tmp" "$out"
trap - EXIT
