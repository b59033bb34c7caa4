#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Why fgr marches packets of rays on CPUs: renders the canonical Mandelbulb view at each packet
# width (rays per work-item) alternately, ROUNDS times, and prints the best render_ms of each and
# its speedup over one ray per work-item (the layout a GPU uses).
#
#   bench/packet_widths.sh        (WIDTH, HEIGHT, ROUNDS: 640, 480, 5)
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
fgr=$repo/build/bin/fgr
[[ -x $fgr ]] || { echo "packet_widths: build fgr first (./build.sh render)" >&2; exit 1; }
width=${WIDTH:-640}
height=${HEIGHT:-480}
rounds=${ROUNDS:-5}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

declare -A best
packet_widths=(1 4 8 16)
for packets in "${packet_widths[@]}"; do  # warm-up: build and cache each program
    "$fgr" render mandelbulb --packet-width "$packets" --width 8 --height 8 -o "$tmp/warm.png" >/dev/null 2>&1
done
for ((round = 1; round <= rounds; ++round)); do
    echo "round $round/$rounds" >&2
    for packets in "${packet_widths[@]}"; do
        ms=$("$fgr" render mandelbulb --packet-width "$packets" --width "$width" --height "$height" \
                -o "$tmp/out.png" 2>/dev/null | awk '$1 == "render_ms" { print $2 }')
        best[$packets]=$(awk -v a="${best[$packets]:-}" -v b="$ms" 'BEGIN { print (a == "" || b < a) ? b : a }')
    done
done
printf '%-14s %10s %8s\n' packet_width render_ms speedup
for packets in "${packet_widths[@]}"; do
    awk -v p="$packets" -v ms="${best[$packets]}" -v base="${best[1]}" \
        'BEGIN { printf "%-14d %10.1f %8.2f\n", p, ms, base / ms }'
done
