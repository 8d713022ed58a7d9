#!/usr/bin/env bash
# Photographs the viewer for the README: opens a scene (default scenes/showcase.txt) in the installed
# launcher on a throw-away X server, waits until the render is done, and writes the window as a PNG
# (default docs/images/viewer.png). Needs Xvfb, xdotool and ImageMagick (Debian: xvfb xdotool imagemagick);
# runs `gradle installDist` first if the launcher is not built. Once the render is done, VIEWER_KEYS (xdotool
# key names, e.g. "ctrl+4" for the difference to the scene's reference image) are pressed and the pointer is
# put at VIEWER_POINTER ("x y" in the window) so the pixel readout shows, before the picture is taken.
#   tools/screenshot-viewer.sh [out.png] [scene.txt]
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-docs/images/viewer.png}
scene=${2:-scenes/showcase.txt}
launcher=build/install/raytracer/bin/raytracer
[ -x "$launcher" ] || gradle -q installDist

tmp=$(mktemp -d)
xvfb=""; viewer=""
cleanup() {
    if [ -n "$viewer" ]; then kill "$viewer" 2>/dev/null; wait "$viewer" 2>/dev/null || true; fi
    if [ -n "$xvfb" ]; then kill "$xvfb" 2>/dev/null; wait "$xvfb" 2>/dev/null || true; fi
    rm -rf "$tmp" || true
}
trap cleanup EXIT

# -displayfd: Xvfb picks a free display and writes its number once it accepts clients
Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp 3>"$tmp/display" 2>"$tmp/xvfb.log" &
xvfb=$!
for _ in $(seq 1 100); do [ -s "$tmp/display" ] && break; sleep 0.1; done
[ -s "$tmp/display" ] || { echo "screenshot-viewer: Xvfb did not start: $(cat "$tmp/xvfb.log")" >&2; exit 1; }
export DISPLAY=":$(tr -d '[:space:]' < "$tmp/display")"

JAVA_OPTS="-Djava.util.prefs.userRoot=$tmp/prefs" "$launcher" --view "$scene" >"$tmp/viewer.log" 2>&1 &
viewer=$!
name=$(basename "$scene" | sed 's/[.^$*+?()|[\]/\\&/g')
win=""
for _ in $(seq 1 600); do
    win=$(xdotool search --name "^RayTracer viewer - $name\$" 2>/dev/null | head -1 || true)
    [ -n "$win" ] && break
    kill -0 "$viewer" 2>/dev/null || { echo "screenshot-viewer: the viewer ended: $(cat "$tmp/viewer.log")" >&2; exit 1; }
    sleep 0.1
done
[ -n "$win" ] || { echo "screenshot-viewer: no viewer window within 60 s" >&2; exit 1; }

# done when the window stops changing for a second (while rendering, the status line ticks 5 times a second)
prev=""; same=0
for _ in $(seq 1 600); do
    sleep 0.25
    sum=$(import -window "$win" ppm:- | md5sum)
    if [ "$sum" = "$prev" ]; then same=$((same + 1)); else same=0; fi
    prev=$sum
    [ "$same" -ge 4 ] && break
done
wait_still() {
    prev=""; same=0
    for _ in $(seq 1 200); do
        sleep 0.25
        sum=$(import -window "$win" ppm:- | md5sum)
        if [ "$sum" = "$prev" ]; then same=$((same + 1)); else same=0; fi
        prev=$sum
        [ "$same" -ge 4 ] && break
    done
}
if [ -n "${VIEWER_KEYS:-}${VIEWER_POINTER:-}" ]; then
    xdotool mousemove --window "$win" 60 60 click 1    # no window manager: a click gives the window the keyboard
    sleep 0.5
    # shellcheck disable=SC2086
    [ -z "${VIEWER_KEYS:-}" ] || xdotool key --delay 150 $VIEWER_KEYS
    # shellcheck disable=SC2086
    [ -z "${VIEWER_POINTER:-}" ] || xdotool mousemove --window "$win" $VIEWER_POINTER
    wait_still
fi
mkdir -p "$(dirname "$out")"
import -window "$win" -strip "png:$out"
echo "wrote $out"
