#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Speed-up of `mpirun -np 2 fgr ...` over one process on a 2-core machine, each rank on one core
# (PoCL limited to one thread, ranks bound to cores), for a shaded still, a path-traced still and
# a short video; and what rank 0 exchanged per tile or frame. Runs A/B alternating, best of
# $REPEATS each, kernels cached beforehand. Usage: bench/mpi_scaling.sh [BUILD_DIR]
set -euo pipefail
build=${1:-build}
fgr=$(realpath "$build/bin/fgr")
repeats=${REPEATS:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export POCL_MAX_PTHREAD_COUNT=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpi=(mpirun --bind-to core --mca btl self,vader --mca btl_vader_single_copy_mechanism none)

# seconds COMMAND...: wall time of one run, its output in $work/out.
seconds() {
    local start end
    start=$(date +%s.%N)
    "$@" > "$work/out" 2>/dev/null
    end=$(date +%s.%N)
    awk -v a="$start" -v b="$end" 'BEGIN { printf "%.3f", b - a }'
}

min() { awk -v a="$1" -v b="$2" 'BEGIN { print (a < b) ? a : b }'; }

# compare NAME "ONE-PROCESS ARGS" "TWO-RANK ARGS" TASK_WORD
compare() {
    local name=$1 one=$2 two=$3 best1=1e9 best2=1e9 t
    # shellcheck disable=SC2086
    "$fgr" $one > /dev/null 2>&1  # warm the kernel caches
    for _ in $(seq "$repeats"); do
        # shellcheck disable=SC2086
        t=$(seconds taskset -c 0 "$fgr" $one); best1=$(min "$t" "$best1")
        # shellcheck disable=SC2086
        t=$(seconds "${mpi[@]}" -np 2 "$fgr" $two); best2=$(min "$t" "$best2")
    done
    local tasks traffic
    tasks=$(grep -o 'mpi_tasks_by_rank.*' "$work/out" | cut -d' ' -f2-)
    traffic=$(grep -o 'mpi_traffic.*' "$work/out" | cut -d' ' -f2-)
    printf '%-34s %8.2f s %8.2f s %6.2fx   tasks %s; rank 0 moved %s\n' "$name" "$best1" "$best2" \
        "$(awk -v a="$best1" -v b="$best2" 'BEGIN { print a / b }')" "$tasks" "$traffic"
}

cd "$work"
printf '%-34s %10s %10s %7s\n' "" "1 rank" "2 ranks" "speed-up"
compare "shaded still 3200x2400" \
    "render mandelbulb --width 3200 --height 2400 -o one.png" \
    "render mandelbulb --width 3200 --height 2400 -o two.png"
cmp -s one.png two.png && echo "  (same PNG, byte for byte)"
compare "path-traced still 320x240, 64 spp" \
    "render mandelbulb --mode path --width 320 --height 240 --spp 64 -o one.exr" \
    "render mandelbulb --mode path --width 320 --height 240 --spp 32 -o two.exr"
compare "video 48 frames 480x360" \
    "video mandelbulb --camera-path orbit --duration 4 --fps 12 --width 480 --height 360 -o one.mp4" \
    "video mandelbulb --camera-path orbit --duration 4 --fps 12 --width 480 --height 360 -o two.mp4"
cmp -s one.mp4 two.mp4 && echo "  (same MP4, byte for byte)"
