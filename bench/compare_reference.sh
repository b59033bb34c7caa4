#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Compares fgr with the scalar C++ reference renderer on the canonical Mandelbulb view.
#
#   bench/compare_reference.sh
#
# Builds the reference (../shared/reference next to the repository, or $FGR_REFERENCE_DIR) into a
# temporary directory, builds fgr if build/bin/fgr is missing, then renders both alternately
# ROUNDS times and keeps each one's best render_ms. Progress goes to stderr; stdout ends with:
#
#   fgr_ms <best>
#   reference_ms <best>
#   fgr_hits <n>
#   reference_hits <n>
#   hit_difference_percent <|fgr - reference| / reference * 100>
#   speedup <reference_ms / fgr_ms>
#
# Environment: WIDTH (640), HEIGHT (480), ROUNDS (5), FGR_REFERENCE_DIR.
set -euo pipefail

width=${WIDTH:-640}
height=${HEIGHT:-480}
rounds=${ROUNDS:-5}

die() {
    echo "compare_reference: $*" >&2
    exit 1
}

for value in "$width" "$height" "$rounds"; do
    [[ $value =~ ^[1-9][0-9]*$ ]] || die "WIDTH, HEIGHT and ROUNDS must be positive integers"
done

script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(git -C "$script_dir" rev-parse --show-toplevel 2>/dev/null) || repo=$(cd "$script_dir/.." && pwd)
reference_dir=${FGR_REFERENCE_DIR:-$repo/../shared/reference}
fgr=$repo/build/bin/fgr

[[ -f $reference_dir/build.sh ]] || die "no reference renderer at $reference_dir (set FGR_REFERENCE_DIR)"

tmp=$(mktemp -d "${TMPDIR:-/tmp}/fgr_compare.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

echo "building the reference renderer from $reference_dir" >&2
sh "$reference_dir/build.sh" "$tmp/reference" >&2
reference=$tmp/reference/mandelbulb_ref_fast
[[ -x $reference ]] || die "reference build did not produce $reference"

if [[ ! -x $fgr ]]; then
    echo "building fgr in $repo/build" >&2
    cmake -S "$repo" -B "$repo/build" -DCMAKE_BUILD_TYPE=Release >&2
    cmake --build "$repo/build" -j"$(nproc)" >&2
    [[ -x $fgr ]] || die "the build did not produce $fgr"
fi

# Prints the value of the "KEY value" line in text $2 for key $1; fails if there is none.
field() {
    local value
    value=$(awk -v key="$1" '$1 == key { print $2; found = 1; exit } END { exit !found }' <<<"$2") ||
        die "no '$1' line in output:"$'\n'"$2"
    printf '%s\n' "$value"
}

run_fgr() {
    # The reference's march rule exactly (t += DE): fgr's defaults step 0.8 DE, over-relaxed.
    "$fgr" render mandelbulb --camera canonical --set step_factor=1 --set over_relaxation=1 \
        --width "$width" --height "$height" -o "$tmp/fgr.png"
}

run_reference() {
    "$reference" "$width" "$height" "$tmp/ref.pgm"
}

# min of two decimal numbers; an empty first argument means "none yet".
min() {
    awk -v a="$1" -v b="$2" 'BEGIN { print (a == "" || b + 0 < a + 0) ? b : a }'
}

echo "warm-up: fgr ${width}x${height}" >&2
run_fgr >/dev/null

fgr_best=""
reference_best=""
fgr_hits=""
reference_hits=""
for ((round = 1; round <= rounds; round++)); do
    out=$(run_fgr)
    ms=$(field render_ms "$out")
    fgr_hits=$(field hits "$out")
    fgr_best=$(min "$fgr_best" "$ms")
    echo "round $round/$rounds fgr render_ms $ms hits $fgr_hits" >&2

    out=$(run_reference)
    ms=$(field render_ms "$out")
    reference_hits=$(field hits "$out")
    reference_best=$(min "$reference_best" "$ms")
    echo "round $round/$rounds reference render_ms $ms hits $reference_hits" >&2
done

echo "fgr_ms $fgr_best"
echo "reference_ms $reference_best"
echo "fgr_hits $fgr_hits"
echo "reference_hits $reference_hits"
awk -v f="$fgr_hits" -v r="$reference_hits" 'BEGIN {
    d = f - r; if (d < 0) d = -d
    if (r > 0) printf "hit_difference_percent %.3f\n", d / r * 100
    else print "hit_difference_percent " (d > 0 ? "inf" : "0.000")
}'
awk -v f="$fgr_best" -v r="$reference_best" 'BEGIN {
    if (f > 0) printf "speedup %.2f\n", r / f; else print "speedup inf"
}'
