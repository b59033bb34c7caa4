#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The gigapixel benchmark (docs/user-guide/gigapixel.md): the Menger sponge at
# 4000x3000 (tiled), 16000x12000 and 40000x30000, each as a streamed PNG, with its wall time and
# peak memory (GNU time's maximum resident set size and fgr's own peak_memory_mib).
# Usage: bench/gigapixel.sh [BUILD_DIR] [OUTPUT_DIR]   (about 1 GB of disk for the outputs)
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
fgr=${1:-$repo/build}/bin/fgr
out=${2:-$repo/build/gigapixel}
mkdir -p "$out"
command -v /usr/bin/time > /dev/null || { echo "needs GNU time: apt-get install time" >&2; exit 1; }
for width in 4000 16000 40000; do
    height=$((width * 3 / 4))
    log="$out/menger_$width.log"
    /usr/bin/time -v "$fgr" render menger --width "$width" --height "$height" --tile-size 512 \
        -o "$out/menger_$width.png" > "$log" 2> "$log.err"
    echo "${width}x$height: $(grep -E '^(render_ms|peak_memory_mib|tiles) ' "$log" | tr '\n' ' ')" \
         "rss_kib $(grep 'Maximum resident' "$log.err" | awk '{print $NF}')"
done
