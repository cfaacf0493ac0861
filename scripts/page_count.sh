#!/usr/bin/env bash
# Prints how many pages Chromium takes to print the start of the document, with its default page
# size and the document's print style (folded listings open), as a reader printing
# results/paper.html would see it.
#   scripts/page_count.sh [results/paper.html]            the main text: up to the first appendix
#   scripts/page_count.sh --part-i [results/paper.html]   Part I: up to the heading of Part II
# (needs chromium and pdfinfo: make deps)
set -euo pipefail
stop='appendix'
if [ "${1:-}" = "--part-i" ]; then stop='part-ii'; shift; fi
html=${1:-results/paper.html}
[ -s "$html" ] || { echo "page_count: no $html" >&2; exit 2; }
for tool in chromium pdfinfo; do
  command -v "$tool" >/dev/null || { echo "page_count: $tool is missing (make deps installs it)" >&2; exit 2; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Cut where the first heading whose id starts with $stop begins; the script that opens the folded
# listings for print comes after the body, so it is kept.
awk -v stop="$stop" '
  !cut && $0 ~ "<h1[^>]* id=\"" stop { cut = 1 }
  !cut { print; next }
  /<script>/ { keep = 1 }
  keep { print }
  /<\/script>/ { keep = 0 }
  END { print "</body></html>" }' "$html" > "$work/main.html"
grep -q "<h1[^>]* id=\"$stop" "$html" || { echo "page_count: no heading id=\"$stop...\" in $html" >&2; exit 2; }
chromium --headless --no-sandbox --disable-gpu --disable-background-networking --disable-component-update \
  --disable-sync --no-first-run --user-data-dir="$work/profile" --no-pdf-header-footer \
  --print-to-pdf="$work/main.pdf" "file://$work/main.html" >/dev/null 2>&1
pdfinfo "$work/main.pdf" | awk '/^Pages:/ { print $2 }'
[ -n "${PAGE_COUNT_KEEP:-}" ] && cp "$work/main.pdf" "$PAGE_COUNT_KEEP" || true
