#!/usr/bin/env python3
"""Hit silhouettes of two renders and how well they agree (issue 20: fgr against Mandelbulber 2).

    silhouette_iou.py A.png B.png [--diff OUT.png]     prints "iou <value> a_only <n> b_only <n>"
    silhouette_iou.py --mask IN.png OUT.png            writes IN's silhouette as a small mask PNG

A pixel is in a render's silhouette when its alpha is over half: fgr's `--alpha` coverage or
Mandelbulber's `--format png16alpha` (alpha 0 where the ray reached the background). The
intersection over union is |A and B| / |A or B|. --diff writes a picture of the disagreement (RGB):
white both, red only A, cyan only B, black neither. --mask writes the silhouette as an 8-bit RGBA
PNG (white and opaque inside, black and clear outside): the fixtures tests/test_mandelbulber.cpp
compares fgr with.

Standard library only (zlib, struct): reads non-interlaced 8- and 16-bit grey, RGB, grey+alpha
and RGBA PNGs."""
import struct
import sys
import zlib

CHANNELS = {0: 1, 2: 3, 4: 2, 6: 4}  # PNG colour type -> samples per pixel


def fail(message):
    raise SystemExit(f"silhouette_iou: {message}")


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    return a if pa <= pb and pa <= pc else b if pb <= pc else c


def unfilter(raw, height, stride, bpp):
    rows, prev, at = [], bytearray(stride), 0
    for _ in range(height):
        kind, line = raw[at], bytearray(raw[at + 1:at + 1 + stride])
        at += 1 + stride
        if kind == 1:
            for x in range(bpp, stride):
                line[x] = (line[x] + line[x - bpp]) & 255
        elif kind == 2:
            for x in range(stride):
                line[x] = (line[x] + prev[x]) & 255
        elif kind == 3:
            for x in range(stride):
                left = line[x - bpp] if x >= bpp else 0
                line[x] = (line[x] + (left + prev[x]) // 2) & 255
        elif kind == 4:
            for x in range(stride):
                left = line[x - bpp] if x >= bpp else 0
                up_left = prev[x - bpp] if x >= bpp else 0
                line[x] = (line[x] + paeth(left, prev[x], up_left)) & 255
        elif kind != 0:
            fail(f"bad PNG filter {kind}")
        rows.append(line)
        prev = line
    return rows


def read_alpha_mask(path):
    """The silhouette of a PNG with alpha: (width, height, list of 0/1 per pixel)."""
    try:
        data = open(path, "rb").read()
    except OSError as error:
        fail(f"cannot read '{path}': {error.strerror}")
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        fail(f"{path}: not a PNG")
    pos, idat, header = 8, b"", None
    while pos + 8 <= len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
    if header is None:
        fail(f"{path}: no IHDR")
    width, height, depth, colour, _, _, interlace = header
    if depth not in (8, 16) or colour not in (4, 6) or interlace:
        fail(f"{path}: needs a non-interlaced 8- or 16-bit PNG with alpha (got depth {depth}, "
             f"colour type {colour})")
    bytes_per_sample = depth // 8
    bpp = CHANNELS[colour] * bytes_per_sample
    rows = unfilter(zlib.decompress(idat), height, width * bpp, bpp)
    alpha_at = bpp - bytes_per_sample  # alpha is the last sample
    half = 128 if depth == 8 else 32768
    mask = []
    for row in rows:
        for x in range(width):
            at = x * bpp + alpha_at
            value = row[at] if depth == 8 else (row[at] << 8) | row[at + 1]
            mask.append(1 if value >= half else 0)
    return width, height, mask


def chunk(kind, body):
    return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))


def write_png(path, width, height, pixels, channels=4):
    """An 8-bit RGBA (channels 4) or RGB (3) PNG of `pixels`, rows top first."""
    stride = width * channels
    raw = b"".join(b"\x00" + bytes(pixels[y * stride:(y + 1) * stride]) for y in range(height))
    header = struct.pack(">IIBBBBB", width, height, 8, 6 if channels == 4 else 2, 0, 0, 0)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 9))
                + chunk(b"IEND", b""))


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
