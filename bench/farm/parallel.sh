#!/usr/bin/env bash
# Rendering over ssh with GNU parallel and fgr's split and merge: parallel hands the pieces to the
# hosts as they free up (a slow host takes fewer), brings each piece's file back (--return) and
# deletes it there (--cleanup); this machine then merges. Every host needs fgr on its PATH and
# passwordless ssh; ':' in the host list is this machine.
#
#   bench/farm/parallel.sh still host1,host2,:    # a 16k x 8k Menger sponge in 16 tiles
#   bench/farm/parallel.sh path  host1,host2      # a path-traced print: 16 seeds x 64 spp
#   bench/farm/parallel.sh video host1,host2      # a 1080p flight in 16 frame ranges
#
# FGR (default: fgr) and JOBS (pieces, default 16) are taken from the environment; a failed piece
# is retried on another host (--retries 2), and the merge runs only when every piece came back.
set -euo pipefail

FGR=${FGR:-fgr}
JOBS=${JOBS:-16}
what=${1:-still}
hosts=${2:-:}
run=(parallel -S "$hosts" --retries 2 --halt "now,fail=1" --cleanup)

case $what in
still)
    "${run[@]}" --return part_{}.exr \
        "$FGR render menger --width 16384 --height 8192 --spp 4 --tile {}/$JOBS -o part_{}.exr" \
        ::: $(seq 1 "$JOBS")
    "$FGR" merge part_*.exr -o menger-16k.png
    ;;
path)
    "${run[@]}" --return seed_{}.exr \
        "$FGR render mandelbulb --mode path --width 4096 --height 3072 --spp 64 --seed {} --part -o seed_{}.exr" \
        ::: $(seq 1 "$JOBS")
    "$FGR" merge seed_*.exr -o mandelbulb-print.exr --aov depth
    ;;
video)
    # 900 frames (30 s at 30 fps); piece I renders frames (I-1)*900/JOBS .. I*900/JOBS-1 into its
    # own directory, returned here and gathered into frames/ (the numbers are the whole video's).
    frames=900
    ranges=()
    for i in $(seq 1 "$JOBS"); do ranges+=("$(( (i - 1) * frames / JOBS )):$(( i * frames / JOBS - 1 ))"); done
    "${run[@]}" --return 'range_{#}' \
        "$FGR video mandelbulb --camera-path orbit --width 1920 --height 1080 --spp 4 --fps 30 --duration 30 --frames 'range_{#}' --frame-range {}" \
        ::: "${ranges[@]}"
    mkdir -p frames
    mv range_*/frame_*.png frames/
    rmdir range_*
    "$FGR" merge --frames frames -o orbit.mp4 --fps 30
    ;;
*)
    echo "usage: $0 still|path|video [HOSTS]" >&2
    exit 2
    ;;
esac
