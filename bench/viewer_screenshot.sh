#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Screenshot of the viewer window (panel included) for the docs: runs `fgr view` in a virtual X
# server, waits until it has refined the still view, and grabs the screen with ImageMagick.
#
#   [FGR_SCENE=ID] bench/viewer_screenshot.sh [OUT.png]   (default: mandelbulb, bench/results/viewer.png)
#
# FGR_REPLAY (replay lines, default "0 wait_idle") drives the viewer first and FGR_READY (default
# "view refined") is the log line to wait for before the grab; the formula browser's screenshot:
#
#   FGR_SCENE=bulb-box FGR_REPLAY=$'0 browser_search hybrid\n0 wait_thumbnails\n0 hybrid_add quaternion\n0 wait_reload\n0 wait_idle\n0 key F12' \
#       FGR_READY="screenshot: wrote" bench/viewer_screenshot.sh bench/results/viewer_browser.png
#
# Needs a built tree (BUILD_DIR, default build) and xvfb, xauth and imagemagick.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
build_dir=${BUILD_DIR:-$repo/build}
out=$(realpath -m "${1:-$repo/bench/results/viewer.png}")
for tool in xvfb-run import; do
    command -v "$tool" >/dev/null ||
        { echo "viewer_screenshot.sh: needs $tool (apt-get install -y xvfb xauth imagemagick)" >&2; exit 1; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf '%s\n10 quit\n' "${FGR_REPLAY:-0 wait_idle}" > "$work/replay.txt"
ready=${FGR_READY:-view refined}
cat > "$work/session.sh" <<SESSION
#!/usr/bin/env bash
set -e
"$build_dir/bin/fgr" -v view ${FGR_SCENE:-mandelbulb} --width 1280 --height 720 --samples 4 \
    --replay "$work/replay.txt" --output-dir "$work" --exit-after 600 2> "$work/log" &
until grep -q "$ready" "$work/log"; do
    kill -0 \$! 2>/dev/null || { cat "$work/log" >&2; exit 1; }
    sleep 0.5
done
sleep 1
import -window root "$work/shot.png"
wait
SESSION
chmod +x "$work/session.sh"
xvfb-run -a -s "-screen 0 1280x720x24" "$work/session.sh"
mv "$work/shot.png" "$out"
echo "wrote $out"
