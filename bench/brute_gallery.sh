#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The brute-force gallery and cost figures (docs/user-guide/brute-force.md): the inside-only scenes (no distance estimator:
# stereographic-julia, bristorbrot) from two cameras each, and two DE scenes rendered from the sign of
# their DE, all at 360x270 with 64 passes; then the convergence sweep of the Mandelbulb's depth
# against the sphere tracer's (`fgr bench accuracy --mode brute`, 320x240, 3 timing rounds) and of
# stereographic-julia's against 1024 passes. Run from the repository root after ./build.sh.
set -euo pipefail
fgr=${FGR:-build/bin/fgr}
out=bench/results/brute
mkdir -p "$out"
render() { # scene, output name, extra options...
    local scene=$1 name=$2
    shift 2
    "$fgr" render "$scene" --mode brute --spp 64 --width 360 --height 270 -o "$out/$name.png" "$@" |
        sed -n "s/^render_ms \(.*\)/$name: \1 ms/p"
}
render stereographic-julia stereographic-julia
render stereographic-julia stereographic-julia-spiral --camera spiral
render bristorbrot bristorbrot
render bristorbrot bristorbrot-whorl --camera whorl
render mandelbulb mandelbulb
render menger menger
"$fgr" bench accuracy mandelbulb --mode brute --repeats 3 -o "$out/convergence-mandelbulb"
"$fgr" bench accuracy stereographic-julia --mode brute --repeats 1 \
    -o "$out/convergence-stereographic-julia"
