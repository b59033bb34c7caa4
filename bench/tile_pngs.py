#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Tiles 8-bit RGB PNGs (fgr's renders) into one, COLUMNS to a row: tile_pngs.py COLUMNS OUT IN...

With --levels=N first (2 to 256), each channel keeps N levels: 40 makes a sheet for the docs
about 60% the size, with only a faint banding of the background at thumbnail size.

Standard library only (png_io.py): reads the non-interlaced 8-bit RGB PNGs fgr writes."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from png_io import PngError, read_png as read_any_png, write_png  # noqa: E402


def read_png(path):
    """(width, height, rows) of an 8-bit RGB PNG."""
    try:
        width, height, depth, colour, rows = read_any_png(path)
    except PngError as error:
        raise SystemExit(str(error)) from error
    if depth != 8 or colour != 2:
        raise SystemExit(f"{path}: only 8-bit RGB")
    return width, height, rows


def main():
    args = sys.argv[1:]
    levels = 256
    if args and args[0].startswith("--levels="):
        levels = int(args.pop(0)[len("--levels="):])
        if not 2 <= levels <= 256:
            raise SystemExit("--levels must be 2 to 256")
    columns, out, inputs = int(args[0]), args[1], args[2:]
    images = [read_png(path) for path in inputs]
    tile_w = max(w for w, _, _ in images)
    tile_h = max(h for _, h, _ in images)
    grid_rows = (len(images) + columns - 1) // columns
    width = columns * tile_w
    canvas = [bytearray(width * 3) for _ in range(grid_rows * tile_h)]
    for index, (w, h, rows) in enumerate(images):
        x0, y0 = (index % columns) * tile_w * 3, (index // columns) * tile_h
        for y in range(h):
            canvas[y0 + y][x0:x0 + w * 3] = rows[y]
    pixels = b"".join(bytes(row) for row in canvas)
    if levels < 256:
        step = 256 / levels
        table = bytes(min(255, round(int(v / step) * step + step / 2)) for v in range(256))
        pixels = pixels.translate(table)
    write_png(out, width, len(canvas), pixels, channels=3)


if __name__ == "__main__":
    main()
