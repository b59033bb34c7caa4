#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The denoiser's figures (docs/user-guide/denoising.md): for the Mandelbulb and bulb-stage under
# the sky at 160x120, two renders of N/2 samples (seeds 1 and 2) with their albedo, normal and
# depth, and a 2048-sample reference (seed 100); bench/denoise/denoise_quality.cpp denoises their
# mean with each method, with and without features, and prints 1 - SSIM overall and on the detail
# pixels, RMSE and the time. Run from the repository root after ./build.sh; the reference renders
# take minutes each.
set -euo pipefail
fgr=${FGR:-build/bin/fgr}
out=bench/results/denoise
mkdir -p "$out"
tool="$out/denoise_quality"
g++ -std=c++20 -O3 -Ihost -I/usr/include/OpenEXR -I/usr/include/Imath \
    bench/denoise/denoise_quality.cpp host/denoise/denoise.cpp host/util/parallel_bands.cpp \
    -o "$tool" -lOpenEXR -lImath -lfmt -lpthread
size=(--width 160 --height 120)
for scene in mandelbulb bulb-stage; do
    [ -f "$out/${scene}_ref.exr" ] ||
        "$fgr" render "$scene" --mode path "${size[@]}" --spp 2048 --seed 100 --no-cost-limit \
            -o "$out/${scene}_ref.exr" > /dev/null
    for spp in 16 64; do
        for seed in 1 2; do
            "$fgr" render "$scene" --mode path "${size[@]}" --spp $((spp / 2)) --seed $seed \
                --aov albedo,normal,depth -o "$out/${scene}_${spp}_$seed.exr" > /dev/null
        done
        echo "$scene, $spp samples per pixel"
        "$tool" "$out/${scene}_${spp}_1.exr" "$out/${scene}_${spp}_2.exr" "$out/${scene}_ref.exr"
    done
done | tee "$out/quality.txt"
