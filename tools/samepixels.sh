#!/usr/bin/env bash
# usage: tools/samepixels.sh OLD_LAUNCHER NEW_LAUNCHER [scene.txt ...]   (default: every scenes/*.txt of this checkout)
# Whether a change keeps every image pixel-identical (stricter than GoldenImageTest's one 8-bit step):
# OLD and NEW are two builds' bin/raytracer (gradle installDist in two worktrees).
# Renders each scene with both launchers into temp dirs and compares pixels exactly (ImageMagick AE metric).
set -u
old=$1; new=$2; shift 2
scenes=("$@")
if [ ${#scenes[@]} -eq 0 ]; then scenes=("$(cd "$(dirname "$0")/.." && pwd)"/scenes/*.txt); fi
d=$(mktemp -d); bad=0
for s in "${scenes[@]}"; do
  n=$(basename "$s" .txt); mkdir -p "$d/a/$n" "$d/b/$n"
  cp "$(dirname "$s")"/* "$d/a/$n/" 2>/dev/null; cp "$(dirname "$s")"/* "$d/b/$n/" 2>/dev/null
  "$old" "$d/a/$n/$n.txt" >/dev/null 2>&1 || { echo "old failed: $n"; continue; }
  "$new" "$d/b/$n/$n.txt" >/dev/null 2>&1 || { echo "NEW FAILED: $n"; bad=1; continue; }
  ae=$(compare -metric AE "$d/a/$n/$n.png" "$d/b/$n/$n.png" null: 2>&1)
  [ "$ae" = "0" ] || { echo "DIFFERENT: $n ($ae pixels)"; bad=1; }
done
rm -rf "$d"; [ $bad = 0 ] && echo "all ${#scenes[@]} scenes pixel-identical"; exit $bad
