#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# What the cone-marched depth prepass saves: renders every built-in scene's default view with
# `--prepass off` and `--prepass on`, alternately, ROUNDS times, and prints per scene the best
# render_ms of each, the DE evaluations per pixel (primary march, normals and the prepass's cones),
# the primary march's lane utilisation and the hit counts.
#
#   bench/prepass.sh [SCENE...]     (default: every scene `fgr list` shows)
#
# Environment: WIDTH, HEIGHT, ROUNDS (640, 480, 5); BEFORE=path/to/an/older/fgr adds its best
# render_ms as a first column (an fgr without --prepass, e.g. one built from an earlier commit).
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
fgr=$repo/build/bin/fgr
[[ -x $fgr ]] || { echo "prepass: build fgr first (./build.sh render)" >&2; exit 1; }
width=${WIDTH:-640}
height=${HEIGHT:-480}
rounds=${ROUNDS:-5}
before=${BEFORE:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export FGR_CACHE_DIR=${FGR_CACHE_DIR:-$tmp/cache}

if [[ $# -gt 0 ]]; then
    scenes=("$@")
else
    mapfile -t scenes < <("$fgr" list --ids 2>/dev/null)
fi

# field KEY FILE: the first word after KEY on the line starting with KEY.
field() { awk -v key="$1" '$1 == key { print $2; exit }' "$2"; }
# per_pixel KEY FILE: the number in "(X per pixel" on KEY's line.
per_pixel() { awk -v key="$1" '$1 == key { gsub(/\(/, "", $3); print $3; exit }' "$2"; }
smaller() { awk -v a="$1" -v b="$2" 'BEGIN { print (a == "" || b + 0 < a + 0) ? b : a }'; }

declare -A best
render() {  # render SCENE SETTING OUT: SETTING is off, on or before
    local scene=$1 setting=$2 out=$3
    if [[ $setting == before ]]; then
        "$before" render "$scene" --stats --width "$width" --height "$height" -o "$tmp/img.png" >"$out" 2>/dev/null
    else
        "$fgr" render "$scene" --stats --prepass "$setting" --width "$width" --height "$height" \
            -o "$tmp/img.png" >"$out" 2>/dev/null
    fi
}

settings=(off on)
[[ -n $before ]] && settings=(before off on)
for scene in "${scenes[@]}"; do
    echo "$scene: warm-up" >&2
    for setting in "${settings[@]}"; do render "$scene" "$setting" "$tmp/$scene.$setting"; done
    for ((round = 1; round <= rounds; ++round)); do
        echo "$scene: round $round/$rounds" >&2
        for setting in "${settings[@]}"; do
            render "$scene" "$setting" "$tmp/run"
            ms=$(field render_ms "$tmp/run")
            best[$scene.$setting]=$(smaller "${best[$scene.$setting]:-}" "$ms")
        done
    done
done

printf '| scene |'
[[ -n $before ]] && printf ' before ms |'
printf ' off ms | on ms | speedup | DE/px off | DE/px on | of which cones | lanes off | lanes on | hits off | hits on |\n'
printf '| --- |'
[[ -n $before ]] && printf ' --- |'
printf ' --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n'
for scene in "${scenes[@]}"; do
    off=$tmp/$scene.off on=$tmp/$scene.on
    printf '| %s |' "$scene"
    [[ -n $before ]] && printf ' %s |' "${best[$scene.before]}"
    awk -v off="${best[$scene.off]}" -v on="${best[$scene.on]}" \
        'BEGIN { printf " %s | %s | %.2f |", off, on, off / on }'
    printf ' %s | %s | %s | %s | %s | %s | %s |\n' \
        "$(per_pixel de_evaluations "$off")" "$(per_pixel de_evaluations "$on")" \
        "$(per_pixel prepass_de_evaluations "$on")" \
        "$(field primary_lane_utilisation "$off")" "$(field primary_lane_utilisation "$on")" \
        "$(field hits "$off")" "$(field hits "$on")"
done
