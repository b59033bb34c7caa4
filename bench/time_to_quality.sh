#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Time to quality: how long each configuration of the path tracer takes to reach 1 - SSIM <= 0.005
# against a converged reference, on three scenes: bulb-stage under the sky, the Mandelbulb in the
# studio, and the Menger sponge in a closed room (menger-room), where most light arrives after
# several bounces.
#
#   bench/time_to_quality.sh references   the references (~12 min in all)
#   bench/time_to_quality.sh measure      the ladders, the table and the plot (~25 min)
#   bench/time_to_quality.sh              both; references that exist are kept
#
# A reference must be far closer to the truth than the threshold, or no image can reach it: two
# 4096-spp renders of menger-room with different seeds differ by 1 - SSIM = 0.016, of bulb-stage
# by 0.0075, so their references take 32768 samples per pixel (that noise falls as 1 / spp), the
# Mandelbulb's 4096 (0.0008 between two).
#
# Each configuration is one line of the table below: its name, the flags it adds to
# `fgr render SCENE --mode path`, and what its ladder varies: "spp" (1, 2, 4 ... 4096 samples per
# pixel) or "threshold" (--noise-threshold T from 0.3 down to 0.002, the sample cap
# --spp THRESHOLD_CAP). A configuration's ladder stops at the first render at or below the
# threshold: the crossing lies between it and the one before. Every render of a scene has the
# same seed, the reference others. Each render's time is the render_ms fgr prints (the
# denoiser's time included), the best of REPEATS rounds that alternate the configurations; its
# error is `fgr bench compare`'s 1 - SSIM of the display luma against the scene's reference. A configuration whose flags this fgr does not
# have is left out with a note, and so is one that adds to regrouping where fgr has none (no
# --no-regroup); the baseline then runs without --no-regroup (it is the only path tracer there is).
#
# Writes to OUT (default bench/results/quality): ref-SCENE.exr (the references, kept between
# runs), time_to_quality.csv (every render: scene, configuration, budget, render_ms,
# one_minus_ssim, samples), and through `fgr bench quality` time_to_quality.md (the crossing times
# and speed-ups over the first configuration), .gp and .png (error against time, log-log, one panel
# a scene, one line a configuration, the threshold dashed).
#
# PREVIOUS_FGR, when set, is an earlier fgr (the release before these techniques: see
# docs/performance.md for how to build it) measured as a configuration of its own, "previous
# release", in the same alternating rounds and first in the table, so that the speed-ups are
# against it; PREVIOUS_PLUGIN_PATH gives it the scene plugins it lacks (its FGR_PLUGIN_PATH).
#
# Environment: FGR (default build/bin/fgr), OUT, WIDTH x HEIGHT (160x120), REFERENCE_SPP (each
# scene's own, below), REPEATS (2), THRESHOLD (0.005), SPP_LADDER ("1 2 4 ... 4096", fgr's most),
# THRESHOLD_LADDER ("0.3 0.2 0.1 0.05 0.03 0.02 0.01 0.005 0.003 0.002"), THRESHOLD_CAP (4096),
# SCENES (a subset of the scene names below), QUICK=1 (48x36, 64-spp references, short ladders,
# one round: tries the harness in a minute, into OUT=/tmp/fgr-quality-quick unless OUT is set).
set -euo pipefail
export LC_ALL=C

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
FGR=${FGR:-$repo/build/bin/fgr}
if [[ ${QUICK:-0} == 1 ]]; then
    OUT=${OUT:-/tmp/fgr-quality-quick}
    WIDTH=${WIDTH:-48} HEIGHT=${HEIGHT:-36} REFERENCE_SPP=${REFERENCE_SPP:-64} REPEATS=${REPEATS:-1}
    SPP_LADDER=${SPP_LADDER:-"1 4 16"} THRESHOLD_LADDER=${THRESHOLD_LADDER:-"0.2 0.05"}
    THRESHOLD_CAP=${THRESHOLD_CAP:-32}
fi
OUT=${OUT:-$repo/bench/results/quality}
WIDTH=${WIDTH:-160}
HEIGHT=${HEIGHT:-120}
REFERENCE_SPP=${REFERENCE_SPP:-}
REPEATS=${REPEATS:-2}
THRESHOLD=${THRESHOLD:-0.005}
SPP_LADDER=${SPP_LADDER:-"1 2 4 8 16 32 64 128 256 512 1024 2048 4096"}
THRESHOLD_LADDER=${THRESHOLD_LADDER:-"0.3 0.2 0.1 0.05 0.03 0.02 0.01 0.005 0.003 0.002"}
THRESHOLD_CAP=${THRESHOLD_CAP:-4096}
SEED=7               # every measured render
REFERENCE_SEED=1000  # the references (and their parts, 1000, 1001 ...): noise of their own

# The scenes: name|scene id|flags|reference spp (the view is each scene's first camera).
all_scenes=(
    "bulb-stage-sky|bulb-stage|--environment sky|32768"
    "mandelbulb-studio|mandelbulb|--environment studio|4096"
    "menger-room|menger-room||32768"
)
# The configurations: name|flags|ladder|flags fgr must have for it to mean anything ({} in the
# flags is the ladder's threshold)|which fgr renders it ("previous": PREVIOUS_FGR). The first is
# the baseline the speed-ups are against.
configurations=()
if [[ -n ${PREVIOUS_FGR:-} ]]; then
    [[ -x $PREVIOUS_FGR ]] || {
        echo "time_to_quality: no fgr at PREVIOUS_FGR=$PREVIOUS_FGR" >&2
        exit 1
    }
    configurations+=("previous release||spp||previous")
fi
configurations+=(
    "path tracer|--no-regroup|spp|"
    "+ regrouping||spp|--no-regroup"
    "+ adaptive|--noise-threshold {} --min-spp 4 --spp $THRESHOLD_CAP|threshold|--no-regroup"
    "+ denoiser|--noise-threshold {} --min-spp 4 --spp $THRESHOLD_CAP --denoise|threshold|--no-regroup"
    "regrouping + denoiser|--denoise|spp|--no-regroup"
)

[[ -x $FGR ]] || { echo "time_to_quality: no fgr at $FGR (build it, or set FGR)" >&2; exit 1; }
mkdir -p "$OUT"
work=$(mktemp -d /tmp/fgr-quality.XXXXXX)
trap 'rm -rf "$work"' EXIT
size=(--width "$WIDTH" --height "$HEIGHT")
render_help=$("$FGR" render --help)

selected_scenes=()
for entry in "${all_scenes[@]}"; do
    name=${entry%%|*}
    if [[ -z ${SCENES:-} || " $SCENES " == *" $name "* ]]; then selected_scenes+=("$entry"); fi
done

# fields ENTRY: splits name|a|b into the array `field`.
fields() { IFS='|' read -r -a field <<< "$1|"; }

references() {
    for entry in "${selected_scenes[@]}"; do
        fields "$entry"
        local name=${field[0]} scene=${field[1]} flags=${field[2]}
        local reference=$OUT/ref-$name.exr reference_spp=${REFERENCE_SPP:-${field[3]}}
        if [[ -e $reference ]]; then
            echo "reference $name: kept $reference"
            continue
        fi
        # Over fgr's 4096 samples a render, the reference is parts of 4096 with seeds of their
        # own, which `fgr merge` averages (as a render farm would make it).
        local parts=$(((reference_spp + 4095) / 4096)) part part_files=()
        local part_spp=$((reference_spp / parts))
        echo "reference $name: $((part_spp * parts)) spp at ${WIDTH}x$HEIGHT ($parts of $part_spp)"
        for ((part = 0; part < parts; ++part)); do
            local file=$work/ref-$name-$part.exr
            # shellcheck disable=SC2086  # flags are words
            "$FGR" render "$scene" --mode path $flags "${size[@]}" --spp "$part_spp" --part \
                --seed $((REFERENCE_SEED + part)) --no-cost-limit -o "$file" > "$work/ref.log" 2>&1 || {
                echo "time_to_quality: the reference of $name failed:" >&2
                cat "$work/ref.log" >&2
                exit 1
            }
            grep -E '^render_ms' "$work/ref.log" | sed "s/^/  /"
            part_files+=("$file")
        done
        "$FGR" merge "${part_files[@]}" -o "$reference" > "$work/ref.log" 2>&1 || {
            echo "time_to_quality: merging the reference of $name failed:" >&2
            cat "$work/ref.log" >&2
            exit 1
        }
        rm -f "${part_files[@]}"
    done
}

# The flags of a configuration this fgr has, or the word "missing" and the flag.
usable_flags() {
    local flags=$1 needs=$2 out=() word
    for word in $needs; do
        if ! grep -qE -- "(^|[ ,])$word([ =,]|$)" <<< "$render_help"; then
            echo "missing $word"
            return
        fi
    done
    for word in $flags; do
        if [[ $word == --* ]] && ! grep -qE -- "(^|[ ,])$word([ =,]|$)" <<< "$render_help"; then
            if [[ $word == --no-regroup ]]; then continue; fi  # the path tracer there is
            echo "missing $word"
            return
        fi
        out+=("$word")
    done
    echo "${out[*]}"
}

# render BINARY SCENE FLAGS... -o FILE: prints "render_ms samples" (with --denoise, render_ms
# includes the denoiser's time, which fgr also prints as denoise_ms). BINARY: "previous" for
# PREVIOUS_FGR, anything else for FGR.
render_once() {
    local log=$work/render.log binary=$1
    shift
    local command=("$FGR")
    if [[ $binary == previous ]]; then
        command=(env ${PREVIOUS_PLUGIN_PATH:+"FGR_PLUGIN_PATH=$PREVIOUS_PLUGIN_PATH"} "$PREVIOUS_FGR")
    fi
    "${command[@]}" render "$@" --mode path "${size[@]}" --seed "$SEED" --no-cost-limit > "$log" 2>&1 || {
        echo "time_to_quality: fgr render $* failed:" >&2
        cat "$log" >&2
        exit 1
    }
    awk '$1 == "render_ms" { ms = $2 } $1 == "samples_per_pixel" { spp = $2 }
         END { printf "%.3f %s\n", ms, spp }' "$log"
}

measure() {
    local csv=$work/time_to_quality.csv
    echo "scene,configuration,budget,render_ms,one_minus_ssim,samples" > "$csv"
    local active=() entry
    for entry in "${configurations[@]}"; do
        fields "$entry"
        local flags
        flags=${field[1]}
        [[ ${field[4]:-} == previous ]] || flags=$(usable_flags "${field[1]}" "${field[3]}")
        if [[ $flags == missing* ]]; then
            echo "configuration '${field[0]}': left out, this fgr has no ${flags#missing }"
            continue
        fi
        active+=("${field[0]}|$flags|${field[2]}|${field[4]:-}")
        local shown=${flags:-no flags}
        echo "configuration '${field[0]}': $shown, ladder over ${field[2]}"
    done
    for entry in "${selected_scenes[@]}"; do
        fields "$entry"
        local name=${field[0]} scene=${field[1]} scene_flags=${field[2]}
        local reference=$OUT/ref-$name.exr
        [[ -e $reference ]] || { echo "time_to_quality: no $reference (run references first)" >&2; exit 1; }
        declare -A best=() error=() samples=() crossed=()
        local round rung c
        local spp=($SPP_LADDER) thresholds=($THRESHOLD_LADDER)
        local rungs=$((${#spp[@]} > ${#thresholds[@]} ? ${#spp[@]} : ${#thresholds[@]}))
        for ((round = 1; round <= REPEATS; ++round)); do
            echo "$name: round $round of $REPEATS"
            for ((rung = 0; rung < rungs; ++rung)); do
                for ((c = 0; c < ${#active[@]}; ++c)); do  # alternating configurations
                    fields "${active[$c]}"
                    local flags=${field[1]} ladder=${field[2]} binary=${field[3]:-} budget run_flags
                    if [[ $ladder == spp ]]; then
                        budget=${spp[$rung]:-}
                        run_flags="$flags --spp $budget"
                        # The denoiser measures the noise from two halves of the samples.
                        if [[ $flags == *--denoise* && -n $budget && $budget -lt 2 ]]; then continue; fi
                    else
                        budget=${thresholds[$rung]:-}
                        run_flags=${flags//\{\}/$budget}
                    fi
                    [[ -n $budget ]] || continue
                    # Past the threshold the ladder stops; later rounds repeat only its renders.
                    if [[ -n ${crossed[$c]:-} && -z ${error["$c|$budget"]:-} ]]; then continue; fi
                    local key="$c|$budget" image=$work/image.exr result ms
                    # shellcheck disable=SC2086  # flags are words
                    result=$(render_once "$binary" "$scene" $scene_flags $run_flags -o "$image")
                    ms=${result% *}
                    if [[ -z ${best[$key]:-} ]] || awk -v a="$ms" -v b="${best[$key]}" 'BEGIN { exit !(a < b) }'; then
                        best[$key]=$ms
                    fi
                    if [[ -z ${error[$key]:-} ]]; then
                        error[$key]=$("$FGR" bench compare "$image" "$reference" | awk '$1 == "one_minus_ssim" { print $2 }')
                        samples[$key]=${result#* }
                        if awk -v e="${error[$key]}" -v t="$THRESHOLD" 'BEGIN { exit !(e <= t) }'; then
                            crossed[$c]=1
                        fi
                    fi
                done
            done
        done
        for ((c = 0; c < ${#active[@]}; ++c)); do
            fields "${active[$c]}"
            local configuration=${field[0]} ladder=${field[2]} budgets
            if [[ $ladder == spp ]]; then budgets=$SPP_LADDER; else budgets=$THRESHOLD_LADDER; fi
            for budget in $budgets; do
                local key="$c|$budget"
                [[ -n ${best[$key]:-} ]] || continue  # a budget this configuration skips
                echo "$name,$configuration,$budget,${best[$key]},${error[$key]},${samples[$key]}" >> "$csv"
            done
        done
        unset best error samples crossed
    done
    cp "$csv" "$OUT/time_to_quality.csv"
    "$FGR" bench quality "$OUT/time_to_quality.csv" --threshold "$THRESHOLD" \
        -o "$OUT/time_to_quality"
}

t0=$SECONDS
case ${1:-all} in
    references) references ;;
    measure) measure ;;
    all) references && measure ;;
    *) echo "usage: bench/time_to_quality.sh [references|measure|all]" >&2; exit 2 ;;
esac
echo "time_to_quality: $((SECONDS - t0)) s; results in $OUT"
