#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The formula library's contact sheet: every formula scene fgr ships (plugins/formulas/, the
# formulas alone, then the hybrids) rendered small from its default view, tiled six to a row into
# bench/results/formula_sheet.png (or OUT), and the order printed (README "Formula library and
# hybrids"). LEVELS=N keeps N levels a channel (tile_pngs.py --levels): a smaller file.
#
#   bench/formula_sheet.sh            (SIZE=200x150 by default)
#   SIZE=128x96 LEVELS=40 OUT=docs/images/formula-sheet.png bench/formula_sheet.sh   (the docs')
#
# Needs python3 (standard library only) to tile the PNGs.
set -euo pipefail

script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$script_dir/.." && pwd)
fgr=$repo/build/bin/fgr
size=${SIZE:-200x150}
[[ $size =~ ^([1-9][0-9]*)x([1-9][0-9]*)$ ]] || { echo "formula_sheet: SIZE must be WxH" >&2; exit 1; }
width=${BASH_REMATCH[1]} height=${BASH_REMATCH[2]}
[[ -x $fgr ]] || { echo "formula_sheet: build fgr first (./build.sh)" >&2; exit 1; }
command -v python3 > /dev/null || { echo "formula_sheet: needs python3" >&2; exit 1; }

tmp=$(mktemp -d "${TMPDIR:-/tmp}/fgr_formula_sheet.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

# Formulas alone first, then hybrids (files with "hybrid" in their tags), each by name.
alone=() hybrids=()
for file in "$repo"/plugins/formulas/*.formula.json; do
    id=$(basename "$file" .formula.json)
    if grep -q '"hybrid"' "$file"; then hybrids+=("$id"); else alone+=("$id"); fi
done
images=()
for id in "${alone[@]}" "${hybrids[@]}"; do
    echo "rendering $id" >&2
    "$fgr" render "$id" --width "$width" --height "$height" -o "$tmp/$id.png" > /dev/null
    images+=("$tmp/$id.png")
done
out=${OUT:-$repo/bench/results/formula_sheet.png}
mkdir -p "$(dirname "$out")"
python3 "$script_dir/tile_pngs.py" --levels="${LEVELS:-256}" 6 "$out" "${images[@]}"
echo "wrote $out, six a row:"
printf '%s\n' "${alone[@]}" "${hybrids[@]}" | paste -d' ' - - - - - -
