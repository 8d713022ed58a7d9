#!/usr/bin/env bash
# Photographs the viewer comparing a render with its reference image, for the README: a copy of
# scenes/showcase.txt with a typical student's slip (MaxDepth 1 instead of 5: mirrors reflect no mirrors)
# is laid out as a course kit would be (scenes/ beside reference-images/ holding the course's
# showcase.png), so the viewer finds the reference by itself. Takes two pictures with
# tools/screenshot-viewer.sh: the difference heat map (docs/images/viewer-compare.png) and the
# reference shown with the pointer on a pixel (docs/images/viewer-reference.png).
#   tools/screenshot-compare.sh
set -euo pipefail
cd "$(dirname "$0")/.."
kit=$(mktemp -d)
trap 'rm -rf "$kit"' EXIT
mkdir -p "$kit/scenes" "$kit/reference-images"
sed 's/^MaxDepth 5$/MaxDepth 1/' scenes/showcase.txt > "$kit/scenes/showcase.txt"
grep -q '^MaxDepth 1$' "$kit/scenes/showcase.txt" || { echo "screenshot-compare: scenes/showcase.txt has no 'MaxDepth 5' line" >&2; exit 1; }
cp reference-images/showcase.png "$kit/reference-images/"
VIEWER_KEYS="ctrl+4" VIEWER_POINTER="330 240" tools/screenshot-viewer.sh docs/images/viewer-compare.png "$kit/scenes/showcase.txt"
