#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Rendering on a Slurm cluster with fgr's split and merge: one job array renders the pieces, a job
# that depends on it (afterok: only once every piece succeeded) merges them. Nothing passes between
# the nodes but files, so run it in a directory every node sees (the cluster's shared home or
# scratch).
#
#   bench/farm/slurm.sh still    # a 16k x 8k Menger sponge in 16 tiles (--tile I/16)
#   bench/farm/slurm.sh path     # a path-traced print: 16 seeds x 64 spp = 1024 spp
#   bench/farm/slurm.sh video    # the Mandelbulb's orbit at 1080p: 16 frame ranges, one encode
#
# From the environment: FGR (default: fgr on PATH), JOBS (pieces, default 16), SBATCH_OPTIONS
# (e.g. "--partition=gpu --gres=gpu:1 --time=01:00:00"), and the sizes STILL, PRINT, VIDEO (fgr
# options) and SECONDS_OF_VIDEO.
set -euo pipefail

FGR=${FGR:-fgr}
JOBS=${JOBS:-16}
SBATCH_OPTIONS=${SBATCH_OPTIONS:-}
STILL=${STILL:-"--width 16384 --height 8192 --spp 4"}
PRINT=${PRINT:-"--width 4096 --height 3072 --spp 64"}
VIDEO=${VIDEO:-"--width 1920 --height 1080 --spp 4"}
SECONDS_OF_VIDEO=${SECONDS_OF_VIDEO:-10}
what=${1:-still}

# Submits the array (each task sees its index 1..JOBS in SLURM_ARRAY_TASK_ID: escaped below, so
# the task expands it), then the merge, to run once all of the array succeeded.
submit() {
    local pieces=$1 merge=$2 array
    # shellcheck disable=SC2086
    array=$(sbatch --parsable $SBATCH_OPTIONS --array=1-"$JOBS" --job-name="fgr-$what" \
        --output="fgr-$what-%A_%a.log" --wrap "$pieces")
    # shellcheck disable=SC2086
    sbatch --parsable $SBATCH_OPTIONS --dependency=afterok:"${array%%;*}" \
        --job-name="fgr-$what-merge" --output="fgr-$what-merge-%j.log" --wrap "$merge"
    echo "submitted array $array and its merge; watch them with: squeue -u $USER"
}

case $what in
still)
    # Tile I of N is rows floor((I-1)*H/N) .. floor(I*H/N)-1: equal shares, no gap, no overlap.
    submit "$FGR render menger $STILL --tile \${SLURM_ARRAY_TASK_ID}/$JOBS \
-o part_\${SLURM_ARRAY_TASK_ID}.exr" \
        "$FGR merge part_*.exr -o menger.png"
    ;;
path)
    # Every task renders the whole image with its own seed; the merge sums their samples.
    submit "$FGR render mandelbulb --mode path $PRINT --seed \${SLURM_ARRAY_TASK_ID} --part \
-o seed_\${SLURM_ARRAY_TASK_ID}.exr" \
        "$FGR merge seed_*.exr -o mandelbulb-print.exr --aov depth"
    ;;
video)
    # At 30 fps the orbit has SECONDS_OF_VIDEO * 30 frames; task I renders its share of them
    # into frames/, numbered as in the whole video, and the merge encodes the directory once.
    frames=$((SECONDS_OF_VIDEO * 30))
    submit "first=\$(( (SLURM_ARRAY_TASK_ID - 1) * $frames / $JOBS )); \
last=\$(( SLURM_ARRAY_TASK_ID * $frames / $JOBS - 1 )); \
$FGR video mandelbulb --camera-path orbit $VIDEO --fps 30 --duration $SECONDS_OF_VIDEO \
--frames frames --frame-range \$first:\$last" \
        "$FGR merge --frames frames -o orbit.mp4 --fps 30"
    ;;
*)
    echo "usage: $0 still|path|video" >&2
    exit 2
    ;;
esac
