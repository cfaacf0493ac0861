#!/usr/bin/env bash
# Prints how many pages the document's main text (everything before the first appendix) takes when
# Chromium prints it with its default page size, as a reader printing results/paper.html would.
# Usage: scripts/page_count.sh [results/paper.html]   (needs chromium and pdfinfo: make deps)
set -euo pipefail
html=${1:-results/paper.html}
[ -s "$html" ] || { echo "page_count: no $html" >&2; exit 2; }
for tool in chromium pdfinfo; do
  command -v "$tool" >/dev/null || { echo "page_count: $tool is missing (make deps installs it)" >&2; exit 2; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The main text ends where the first appendix heading begins (pandoc's id "appendix-...").
awk '/<h1[^>]* id="appendix/ { print "</body></html>"; exit } { print }' "$html" > "$work/main.html"
grep -q '</body></html>' "$work/main.html" || { echo "page_count: no appendix heading in $html" >&2; exit 2; }
chromium --headless --no-sandbox --disable-gpu --disable-background-networking --disable-component-update \
  --disable-sync --no-first-run --user-data-dir="$work/profile" --no-pdf-header-footer \
  --print-to-pdf="$work/main.pdf" "file://$work/main.html" >/dev/null 2>&1
pdfinfo "$work/main.pdf" | awk '/^Pages:/ { print $2 }'
