#!/usr/bin/env python3
"""Tiles 8-bit RGB PNGs (fgr's renders) into one, COLUMNS to a row: tile_pngs.py COLUMNS OUT IN...

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
    columns, out, inputs = int(sys.argv[1]), sys.argv[2], sys.argv[3:]
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
    write_png(out, width, len(canvas), b"".join(bytes(row) for row in canvas), channels=3)


if __name__ == "__main__":
    main()
