#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The path-traced gallery (docs/user-guide/render-modes.md): the bulb-stage scene under the default sky and in the
# studio, and the Mandelbulb's canonical view under the sky, 256 samples per pixel each, plus the
# studio environment fgr generates, written as .hdr and used from the file (so the IBL path from
# file to image is what renders). Run from the repository root after ./build.sh.
set -euo pipefail
fgr=${FGR:-build/bin/fgr}
out=bench/results/path
mkdir -p "$out"
"$fgr" environment studio -o "$out/studio.hdr" --width 1024
"$fgr" render bulb-stage --spp 256 --width 360 --height 270 -o "$out/bulb-stage-sky.png"
"$fgr" render bulb-stage --spp 256 --width 360 --height 270 --environment "$out/studio.hdr" \
    --no-scene-lights -o "$out/bulb-stage-studio.png"
"$fgr" render mandelbulb --mode path --spp 256 --width 360 --height 270 \
    -o "$out/mandelbulb-sky.png"
