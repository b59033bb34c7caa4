#!/usr/bin/env bash
# Rendering on a Slurm cluster with fgr's split and merge: one job array renders the pieces, a
# job that depends on it (afterok: only when every piece succeeded) merges them. Nothing runs
# between the nodes but files, so the working directory must be on a filesystem every node sees
# (the cluster's shared home or scratch).
#
#   bench/farm/slurm.sh still    # a 16k x 8k Menger sponge in 16 tiles (--tile I/16)
#   bench/farm/slurm.sh path     # a path-traced print: 16 seeds x 64 spp = 1024 spp
#   bench/farm/slurm.sh video    # a 1080p flight: 16 frame ranges, then one encode
#
# FGR (default: fgr on PATH), JOBS (default 16) and SBATCH_OPTIONS (partition, GPUs, time:
# e.g. "--partition=gpu --gres=gpu:1 --time=01:00:00") are taken from the environment.
set -euo pipefail

FGR=${FGR:-fgr}
JOBS=${JOBS:-16}
SBATCH_OPTIONS=${SBATCH_OPTIONS:-}
what=${1:-still}

# Submits the array (each task sees its index 1..JOBS in SLURM_ARRAY_TASK_ID; single quotes keep
# it for the task to expand), then the merge after all of it succeeded.
submit() {
    local pieces=$1 merge=$2
    local array
    # shellcheck disable=SC2086
    array=$(sbatch --parsable $SBATCH_OPTIONS --array=1-"$JOBS" --job-name="fgr-$what" \
        --output="fgr-$what-%A_%a.log" --wrap "$pieces")
    # shellcheck disable=SC2086
    sbatch --parsable $SBATCH_OPTIONS --dependency=afterok:"${array%%;*}" \
        --job-name="fgr-$what-merge" --output="fgr-$what-merge-%j.log" --wrap "$merge"
    echo "submitted array $array and its merge; watch with: squeue -u $USER"
}

case $what in
still)
    # Tile I of N is rows floor((I-1)*H/N) .. floor(I*H/N)-1: equal shares, no gap, no overlap.
    submit "$FGR render menger --width 16384 --height 8192 --spp 4 \
--tile \${SLURM_ARRAY_TASK_ID}/$JOBS -o part_\${SLURM_ARRAY_TASK_ID}.exr" \
        "$FGR merge part_*.exr -o menger-16k.png"
    ;;
path)
    # Every task renders the whole image with its own seed; the merge sums the samples.
    submit "$FGR render mandelbulb --mode path --width 4096 --height 3072 --spp 64 \
--seed \${SLURM_ARRAY_TASK_ID} --part -o seed_\${SLURM_ARRAY_TASK_ID}.exr" \
        "$FGR merge seed_*.exr -o mandelbulb-print.exr --aov depth"
    ;;
video)
    # 30 s at 30 fps = 900 frames, frames 0..899: task I renders its share of them into frames/,
    # numbered as in the whole video; the merge encodes the directory once.
    frames=900
    submit "first=\$(( (SLURM_ARRAY_TASK_ID - 1) * $frames / $JOBS )); \
last=\$(( SLURM_ARRAY_TASK_ID * $frames / $JOBS - 1 )); \
$FGR video mandelbulb --camera-path orbit --width 1920 --height 1080 --spp 4 --fps 30 \
--duration 30 --frames frames --frame-range \$first:\$last" \
        "$FGR merge --frames frames -o orbit.mp4 --fps 30"
    ;;
*)
    echo "usage: $0 still|path|video" >&2
    exit 2
    ;;
esac
