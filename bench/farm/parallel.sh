#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Rendering over ssh with GNU parallel and fgr's split and merge: parallel hands the pieces to the
# hosts as they free up (a slow host takes fewer), brings each piece's file back (--return),
# deletes it there (--cleanup) and retries a failed piece (--retries); this machine then merges.
# Every host needs fgr on its PATH and passwordless ssh; ':' in the host list is this machine.
#
#   bench/farm/parallel.sh still host1,host2,:    # a 16k x 8k Menger sponge in 16 tiles
#   bench/farm/parallel.sh path  host1,host2      # a path-traced print: 16 seeds x 64 spp
#   bench/farm/parallel.sh video host1,host2      # the Mandelbulb's orbit at 1080p, 16 ranges
#
# From the environment: FGR (default: fgr), JOBS (pieces, default 16), and the sizes STILL,
# PRINT, VIDEO (fgr options) and SECONDS_OF_VIDEO.
set -euo pipefail

FGR=${FGR:-fgr}
JOBS=${JOBS:-16}
STILL=${STILL:-"--width 16384 --height 8192 --spp 4"}
PRINT=${PRINT:-"--width 4096 --height 3072 --spp 64"}
VIDEO=${VIDEO:-"--width 1920 --height 1080 --spp 4"}
SECONDS_OF_VIDEO=${SECONDS_OF_VIDEO:-10}
what=${1:-still}
hosts=${2:-:}
# The merge runs only when every piece came back: parallel stops at the first piece that failed
# all its tries.
run=(parallel -S "$hosts" --retries 2 --halt "now,fail=1" --cleanup)

case $what in
still)
    "${run[@]}" --return 'part_{}.exr' \
        "$FGR render menger $STILL --tile {}/$JOBS -o part_{}.exr" ::: $(seq 1 "$JOBS")
    "$FGR" merge part_*.exr -o menger.png
    ;;
path)
    "${run[@]}" --return 'seed_{}.exr' \
        "$FGR render mandelbulb --mode path $PRINT --seed {} --part -o seed_{}.exr" \
        ::: $(seq 1 "$JOBS")
    "$FGR" merge seed_*.exr -o mandelbulb-print.exr --aov depth
    ;;
video)
    # At 30 fps the orbit has SECONDS_OF_VIDEO * 30 frames; piece I renders its share into a
    # directory of its own, returned here and gathered into frames/ (numbered as in the whole
    # video), which is then encoded once.
    frames=$((SECONDS_OF_VIDEO * 30))
    ranges=()
    for i in $(seq 1 "$JOBS"); do
        ranges+=("$(( (i - 1) * frames / JOBS )):$(( i * frames / JOBS - 1 ))")
    done
    "${run[@]}" --return 'range_{#}' \
        "$FGR video mandelbulb --camera-path orbit $VIDEO --fps 30 --duration $SECONDS_OF_VIDEO --frames range_{#} --frame-range {}" \
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
