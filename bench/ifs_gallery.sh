#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The IFS gallery (docs/user-guide/ifs.md): the six shipped IFS scenes (plugins/ifs/) from their default cameras at
# 300x225, shaded with shadows and 4 samples per pixel, and the Menger sponge path traced under
# the sky (256 samples per pixel). Run from the repository root after ./build.sh.
set -euo pipefail
fgr=${FGR:-build/bin/fgr}
out=bench/results/ifs
mkdir -p "$out"
for id in sierpinski-ifs menger-ifs jerusalem-cube tree koch-snowflake spiral-shell; do
    "$fgr" render "$id" --width 300 --height 225 --spp 4 -o "$out/$id.png"
done
"$fgr" render menger-ifs --mode path --spp 256 --width 300 --height 225 -o "$out/menger-ifs-path.png"
