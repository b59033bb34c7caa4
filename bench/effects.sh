#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# What each effect costs: renders each scene's default view at 640x480 with no effects, with each
# effect alone, and with all of them, alternately round by round (so machine noise hits every
# configuration alike), and prints each configuration's best render_ms and its ratio to no effects
# as a Markdown table.
#
# The "disabled glow, strength 20" row renders with no effects compiled in but the glow's
# parameters changed: a disabled effect is not in the kernel, so it must cost nothing (ratio 1.00
# within noise).
#
#   bench/effects.sh [SCENE...]     (default: mandelbulb sdf-gallery; WIDTH, HEIGHT, ROUNDS: 640, 480, 3)
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
fgr=$repo/build/bin/fgr
[[ -x $fgr ]] || { echo "effects.sh: build fgr first (./build.sh render)" >&2; exit 1; }
width=${WIDTH:-640}
height=${HEIGHT:-480}
rounds=${ROUNDS:-3}
scenes=("$@")
[[ ${#scenes[@]} -gt 0 ]] || scenes=(mandelbulb sdf-gallery)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# label|--effects value|extra arguments
configs=(
    "none|none|"
    "disabled glow, strength 20|none|--set glow_strength=20"
    "shadows|none,+shadows|"
    "soft_shadows|none,+soft_shadows|"
    "ambient_occlusion (step count)|none,+ambient_occlusion|"
    "sampled_occlusion|none,+sampled_occlusion|"
    "reflections (1 bounce)|none,+reflections|"
    "glow|none,+glow|"
    "fog|none,+fog|"
    "depth_of_field (1 sample)|none,+depth_of_field|"
    "refraction|none,+refraction|"
    "anti-aliasing, 4 samples|none|--spp 4"
    "all effects|none,+soft_shadows,+ambient_occlusion,+sampled_occlusion,+reflections,+glow,+fog,+depth_of_field,+refraction|"
)

render_ms() {  # scene effects extra...
    local scene=$1 effects=$2
    shift 2
    "$fgr" render "$scene" --effects "$effects" "$@" --width "$width" --height "$height" \
        -o "$tmp/out.png" 2>/dev/null | awk '$1 == "render_ms" { print $2 }'
}

for scene in "${scenes[@]}"; do
    declare -A best=()
    echo "warming up $scene (building ${#configs[@]} kernels)" >&2
    for config in "${configs[@]}"; do
        IFS='|' read -r label effects extra <<<"$config"
        # shellcheck disable=SC2086  # extra holds separate arguments
        "$fgr" render "$scene" --effects "$effects" $extra --width 16 --height 16 \
            -o "$tmp/warm.png" >/dev/null 2>&1
    done
    for ((round = 1; round <= rounds; ++round)); do
        echo "$scene: round $round/$rounds" >&2
        for config in "${configs[@]}"; do
            IFS='|' read -r label effects extra <<<"$config"
            # shellcheck disable=SC2086
            ms=$(render_ms "$scene" "$effects" $extra)
            best[$label]=$(awk -v a="${best[$label]:-}" -v b="$ms" \
                'BEGIN { print (a == "" || b + 0 < a + 0) ? b : a }')
        done
    done
    echo
    echo "**$scene**, ${width}x${height}, best of $rounds:"
    echo
    echo "| effects | render_ms | ratio to none |"
    echo "| --- | ---: | ---: |"
    for config in "${configs[@]}"; do
        IFS='|' read -r label _ _ <<<"$config"
        awk -v l="$label" -v ms="${best[$label]}" -v base="${best[none]}" \
            'BEGIN { printf "| %s | %.1f | %.2f |\n", l, ms, ms / base }'
    done
    unset best
done
