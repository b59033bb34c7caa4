#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Hit silhouettes of two renders and how well they agree (fgr against Mandelbulber 2).

    silhouette_iou.py A.png B.png [--diff OUT.png]     prints "iou <value> a_only <n> b_only <n>"
    silhouette_iou.py --mask IN.png OUT.png            writes IN's silhouette as a small mask PNG

A pixel is in a render's silhouette when its alpha is over half: fgr's `--alpha` coverage or
Mandelbulber's `--format png16alpha` (alpha 0 where the ray reached the background). The
intersection over union is |A and B| / |A or B|. --diff writes a picture of the disagreement (RGB):
white both, red only A, cyan only B, black neither. --mask writes the silhouette as an 8-bit RGBA
PNG (white and opaque inside, black and clear outside): the fixtures tests/scene/test_mandelbulber.cpp
compares fgr with.

Standard library only (png_io.py): reads non-interlaced 8- and 16-bit grey+alpha and RGBA
PNGs."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from png_io import PngError, read_png, write_png  # noqa: E402


def fail(message):
    raise SystemExit(f"silhouette_iou: {message}")


def read_alpha_mask(path):
    """The silhouette of a PNG with alpha: (width, height, list of 0/1 per pixel)."""
    try:
        width, height, depth, colour, rows = read_png(path)
    except PngError as error:
        fail(str(error))
    if colour not in (4, 6):
        fail(f"{path}: has no alpha (colour type {colour})")
    bytes_per_sample = depth // 8
    bpp = (2 if colour == 4 else 4) * bytes_per_sample
    alpha_at = bpp - bytes_per_sample  # alpha is the last sample
    half = 128 if depth == 8 else 32768
    mask = []
    for row in rows:
        for x in range(width):
            at = x * bpp + alpha_at
            value = row[at] if depth == 8 else (row[at] << 8) | row[at + 1]
            mask.append(1 if value >= half else 0)
    return width, height, mask


def write_mask(path, width, height, mask):
    pixels = bytearray()
    for inside in mask:
        pixels += b"\xff\xff\xff\xff" if inside else b"\x00\x00\x00\x00"
    write_png(path, width, height, pixels)


DIFF_COLOURS = {(1, 1): b"\xff\xff\xff", (1, 0): b"\xff\x30\x30", (0, 1): b"\x30\xff\xff",
                (0, 0): b"\x00\x00\x00"}


def write_diff(path, width, height, a, b):
    pixels = bytearray()
    for pair in zip(a, b):
        pixels += DIFF_COLOURS[pair]
    write_png(path, width, height, pixels, channels=3)


def main(argv):
    if len(argv) == 3 and argv[0] == "--mask":
        width, height, mask = read_alpha_mask(argv[1])
        write_mask(argv[2], width, height, mask)
        return
    if len(argv) not in (2, 4) or (len(argv) == 4 and argv[2] != "--diff"):
        fail("usage: silhouette_iou.py A.png B.png [--diff OUT.png] | --mask IN.png OUT.png")
    wa, ha, a = read_alpha_mask(argv[0])
    wb, hb, b = read_alpha_mask(argv[1])
    if (wa, ha) != (wb, hb):
        fail(f"the images differ in size ({wa}x{ha} and {wb}x{hb})")
    both = sum(1 for x, y in zip(a, b) if x and y)
    either = sum(1 for x, y in zip(a, b) if x or y)
    a_only = sum(a) - both
    b_only = sum(b) - both
    iou = both / either if either else 1.0
    print(f"iou {iou:.4f} a_only {a_only} b_only {b_only}")
    if len(argv) == 4:
        write_diff(argv[3], wa, ha, a, b)


if __name__ == "__main__":
    main(sys.argv[1:])
