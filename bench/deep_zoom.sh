#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Renders a deep zoom into the Mandelbulb in float and in double, side by side: a view 1e-7
# units across, 2e-6 in front of the surface where the canonical view's central ray meets it
# (bench/deep_zoom.json; the surface point comes from a double-precision march down to 1e-12).
# A pixel there spans ~3e-10 units, while float's coordinates near the bulb step by 6e-8: float
# rounds hundreds of neighbouring rays onto one point (flat blocks, jagged edges); double
# resolves the surface.
#
#   bench/deep_zoom.sh [WIDTH HEIGHT]      (default 320 240)
#
# Writes bench/results/deep_zoom.png (float left, double right, labelled) and prints each
# precision's render time. ImageMagick (Debian's imagemagick) is installed if missing.
set -euo pipefail

width=${1:-320}
height=${2:-240}
[[ $width =~ ^[1-9][0-9]*$ && $height =~ ^[1-9][0-9]*$ ]] ||
    { echo "deep_zoom: WIDTH and HEIGHT must be positive integers" >&2; exit 1; }

script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$script_dir/.." && pwd)
fgr=$repo/build/bin/fgr
if [[ ! -x $fgr ]]; then
    echo "building fgr in $repo/build" >&2
    cmake -S "$repo" -B "$repo/build" -G Ninja -DCMAKE_BUILD_TYPE=Release >&2
    cmake --build "$repo/build" -j "$(nproc)" >&2
    [[ -x $fgr ]] || { echo "deep_zoom: the build did not produce $fgr" >&2; exit 1; }
fi

if ! command -v montage > /dev/null; then
    echo "installing imagemagick (Debian package)" >&2
    sudo=()
    [[ $(id -u) -eq 0 ]] || sudo=(sudo)
    "${sudo[@]}" apt-get update -q >&2
    DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -q imagemagick >&2
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for precision in float double; do
    ms=$("$fgr" render mandelbulb --camera-path "$script_dir/deep_zoom.json" --time 0 \
        --precision "$precision" --width "$width" --height "$height" \
        -o "$work/$precision.png" 2> "$work/$precision.log" | awk '/^render_ms/ {print $2}') ||
        { cat "$work/$precision.log" >&2; exit 1; }
    echo "${precision}_ms $ms"
    labels+=(-label "$precision: $ms ms" "$work/$precision.png")
done
mkdir -p "$repo/bench/results"
montage "${labels[@]}" -tile 2x1 -geometry +4+4 -pointsize 14 "$work/montage.png"
mv "$work/montage.png" "$repo/bench/results/deep_zoom.png"
echo "wrote bench/results/deep_zoom.png" >&2
