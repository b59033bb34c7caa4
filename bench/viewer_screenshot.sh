#!/usr/bin/env bash
# Screenshot of the viewer window (panel included) for the README: runs `fgr view` in a virtual X
# server, waits until it has refined the still view, and grabs the screen with ImageMagick.
#
#   [FGR_SCENE=ID] bench/viewer_screenshot.sh [OUT.png]   (default: mandelbulb, bench/results/viewer.png)
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
printf '0 wait_idle\n10 quit\n' > "$work/replay.txt"
cat > "$work/session.sh" <<SESSION
#!/usr/bin/env bash
set -e
"$build_dir/bin/fgr" -v view ${FGR_SCENE:-mandelbulb} --width 1280 --height 720 --samples 4 \
    --replay "$work/replay.txt" --exit-after 600 2> "$work/log" &
until grep -q "view refined" "$work/log"; do
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
