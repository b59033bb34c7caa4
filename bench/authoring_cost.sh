#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# What the iterate-function contract (kernels/fractals/fgr_iterate.cl) costs (docs/performance.md): each SDK
# example written with it (sdk/examples/icosahedral-kifs, pseudo-kleinian) against the same maths
# written out by hand in packet form (bench/authoring/*_packet.cl, timed through `fgr bench
# --kernel-source`). Both play the example's camera path, 12 frames at 640x480, in alternating
# rounds (A, B, A, B, ...) so that drift in the machine's speed hits both alike; the ratio of the
# median frame times is the contract's cost. Also the per-pixel DE evaluations and hits of one
# still from each (fgr render --stats, --kernel-source): equal work, equal image.
# Run from the repository root after ./build.sh test has built fgr and the SDK examples.
set -euo pipefail
fgr=${FGR:-build/bin/fgr}
rounds=${ROUNDS:-7}
out=bench/results/authoring
mkdir -p "$out"
export FGR_CACHE_DIR=${FGR_CACHE_DIR:-$(mktemp -d)}
export FGR_PLUGIN_PATH=${FGR_PLUGIN_PATH:-build/tests/fixtures/sdk_examples}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# mean_ms FILE.json: the frame time averaged over the run.
mean_ms() { python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["average"]["mean_ms"])' "$1"; }
# median: of the numbers on stdin.
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
# field NAME: the first number after NAME in fgr render's --stats output on stdin.
field() { sed -n "s/^$1 \\([0-9.]*\\).*/\\1/p" | head -1; }

{
    echo "# scene  contract_ms  packet_ms  ratio  contract_de_per_px  packet_de_per_px  contract_hits  packet_hits"
    for example in ${EXAMPLES:-icosahedral-kifs:icosahedral_kifs pseudo-kleinian:pseudo_kleinian}; do
        scene=${example%%:*}
        packet=bench/authoring/${example##*:}_packet.cl
        "$fgr" bench "$scene" --width 640 --height 480 --frames 2 -o "$scratch/warm" >/dev/null 2>&1
        "$fgr" bench "$scene" --width 640 --height 480 --frames 2 -o "$scratch/warm" \
            --kernel-source "$packet" >/dev/null 2>&1
        : > "$scratch/a" && : > "$scratch/b"
        for round in $(seq "$rounds"); do
            echo "$scene: round $round/$rounds" >&2
            "$fgr" bench "$scene" --width 640 --height 480 --frames 12 -o "$scratch/run" >/dev/null 2>&1
            mean_ms "$scratch/run.json" >> "$scratch/a"
            "$fgr" bench "$scene" --width 640 --height 480 --frames 12 -o "$scratch/run" \
                --kernel-source "$packet" >/dev/null 2>&1
            mean_ms "$scratch/run.json" >> "$scratch/b"
        done
        a=$(median < "$scratch/a")
        b=$(median < "$scratch/b")
        stats_a=$("$fgr" render "$scene" -o "$scratch/a.png" --stats 2>/dev/null)
        stats_b=$("$fgr" render "$scene" -o "$scratch/b.png" --stats --kernel-source "$packet" 2>/dev/null)
        printf '%s  %.2f  %.2f  %.3f  %s  %s  %s  %s\n' "$scene" "$a" "$b" "$(awk -v a="$a" -v b="$b" 'BEGIN { print a / b }')" \
            "$(field de_evaluations <<<"$stats_a" | head -1)" "$(field de_evaluations <<<"$stats_b" | head -1)" \
            "$(field hits <<<"$stats_a")" "$(field hits <<<"$stats_b")"
    done
} | tee "$out/cost.txt"
