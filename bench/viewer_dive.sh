#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# How sharp the viewer's preview is while flying: plays the Mandelbulb's `dive` camera path in
# `fgr view` at 1280x720 with the 33 ms target, scripted (bench/viewer/dive.replay: wait for the
# refined default view, press P, quit just before the 8 s path ends), under Xvfb, ROUNDS times,
# and prints each run's reduced-resolution frames and their mean resolution scale, then the mean
# over the runs.
#
#   bench/viewer_dive.sh
#
# Environment: ROUNDS (3), TARGET_MS (33); BEFORE=path/to/an/older/fgr runs it too, alternately
# (it needs `fgr view --path`).
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
fgr=$repo/build/bin/fgr
[[ -x $fgr ]] || { echo "viewer_dive: build fgr first (./build.sh render)" >&2; exit 1; }
command -v xvfb-run >/dev/null || { echo "viewer_dive: needs xvfb-run (Debian package xvfb)" >&2; exit 1; }
rounds=${ROUNDS:-3}
target_ms=${TARGET_MS:-33}
before=${BEFORE:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export FGR_CACHE_DIR=${FGR_CACHE_DIR:-$tmp/cache}

fly() {  # fly FGR: prints "preview_frames N mean_scale S render_ms_mean M"
    xvfb-run -a -s "-screen 0 1920x1080x24" "$1" view mandelbulb --path dive \
        --width 1280 --height 720 --target-ms "$target_ms" \
        --replay "$repo/bench/viewer/dive.replay" --stats 2>/dev/null |
        awk '$1 == "preview_frames" { frames = $2; scale = $4 }
             $1 == "render_ms" { mean = $5 }
             END { printf "preview_frames %s mean_scale %s render_ms_mean %s\n", frames, scale, mean }'
}

binaries=("$fgr")
names=(fgr)
if [[ -n $before ]]; then
    binaries=("$before" "$fgr")
    names=(before fgr)
fi
declare -A sum
for ((round = 1; round <= rounds; ++round)); do
    for i in "${!binaries[@]}"; do
        line=$(fly "${binaries[$i]}")
        echo "round $round ${names[$i]}: $line"
        scale=$(awk '{ print $4 }' <<<"$line")
        sum[${names[$i]}]=$(awk -v a="${sum[${names[$i]}]:-0}" -v b="$scale" 'BEGIN { print a + b }')
    done
done
for name in "${names[@]}"; do
    awk -v name="$name" -v total="${sum[$name]}" -v n="$rounds" \
        'BEGIN { printf "%s mean_scale %.3f (mean of %d runs)\n", name, total / n, n }'
done
