#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# What exact IFS tracing costs as detail grows (docs/user-guide/ifs.md): each shipped IFS scene's default
# view at 320x240 (shaded mode, default shadows), at every depth the slider allows, rendered three
# times (the fastest counts): rays per second and nodes visited per pixel (fgr render --stats).
# Then the Sierpinski tetrahedron and the Menger sponge against their DE scenes at equal images
# (the same camera, 640x480, IFS depth = DE iterations): render time and hits. Plots with gnuplot.
# Run from the repository root after ./build.sh has built fgr.
set -euo pipefail
fgr=${FGR:-build/bin/fgr}
out=bench/results/ifs
mkdir -p "$out"
export FGR_CACHE_DIR=${FGR_CACHE_DIR:-$(mktemp -d)}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# field NAME: the first number after NAME in fgr render's output on stdin.
field() { sed -n "s/^$1 \\([0-9.]*\\).*/\\1/p" | head -1; }

# fastest SCENE ARGS...: the quickest of three renders' output (their figures otherwise agree).
fastest() {
    local scene=$1 best="" best_ms=""
    shift
    for _ in 1 2 3; do
        local run ms
        run=$("$fgr" render "$scene" -o "$scratch/x.png" --stats "$@" 2>/dev/null)
        ms=$(field render_ms <<<"$run")
        if [[ -z $best_ms ]] || awk -v a="$ms" -v b="$best_ms" 'BEGIN { exit !(a < b) }'; then
            best=$run
            best_ms=$ms
        fi
    done
    printf '%s\n' "$best"
}

: > "$out/cost.dat"
for file in plugins/ifs/*.ifs.json; do
    id=$(sed -n 's/^ *"id": *"\([^"]*\)".*/\1/p' "$file" | head -1)
    max=$(sed -n 's/.*"depth": *{"default": *[0-9]*, *"max": *\([0-9]*\)}.*/\1/p' "$file" | head -1)
    max=${max:-12}
    echo "$id: depth 0 to $max" >&2
    for depth in $(seq 0 "$max"); do
        run=$(fastest "$id" --width 320 --height 240 --set "ifs_depth=$depth")
        ms=$(field render_ms <<<"$run")
        nodes=$(field ifs_nodes_per_ray <<<"$run")
        reached=$(field ifs_depth_reached <<<"$run")
        echo "$id $depth $ms $(awk -v ms="$ms" 'BEGIN { printf "%.4f", 320 * 240 / ms / 1000 }') $nodes $reached"
    done >> "$out/cost.dat"
    printf '\n\n' >> "$out/cost.dat"
done

: > "$out/versus_de.dat"
for pair in "sierpinski-ifs sierpinski" "menger-ifs menger"; do
    read -r ifs de <<<"$pair"
    for depth in 1 2 3 4 5 6 7 8; do
        a=$(fastest "$ifs" --width 640 --height 480 --set "ifs_depth=$depth")
        b=$(fastest "$de" --width 640 --height 480 --set "iterations=$depth")
        echo "$ifs $depth $(field render_ms <<<"$a") $(field hits <<<"$a") $(field render_ms <<<"$b") $(field hits <<<"$b")"
    done >> "$out/versus_de.dat"
done

cat > "$scratch/cost.gp" <<GP
set terminal pngcairo size 900,380 font ",10"
set output "$out/cost.png"
set multiplot layout 1,2 title "Exact IFS tracing: cost against depth (320x240, default views, shadows on)"
set key top right font ",8"
set grid
set xlabel "depth slider"
set logscale y
set ylabel "million rays per second"
plot for [i=0:5] "$out/cost.dat" index i using 2:4 with linespoints title columnhead(1) noenhanced
set ylabel "nodes visited per pixel"
plot for [i=0:5] "$out/cost.dat" index i using 2:5 with linespoints title columnhead(1) noenhanced
unset multiplot
GP
# columnhead needs a header line per block: rewrite the blocks with their scene id first.
awk 'BEGIN { id = "" } NF == 0 { print; id = ""; next } { if (id == "") { print $1; id = $1 } print }' \
    "$out/cost.dat" > "$scratch/cost_with_heads.dat"
sed -i "s|\"$out/cost.dat\"|\"$scratch/cost_with_heads.dat\"|g" "$scratch/cost.gp"
gnuplot "$scratch/cost.gp"
echo "wrote $out/cost.png, $out/cost.dat and $out/versus_de.dat"
