#!/usr/bin/env python3
"""Tiles 8-bit RGB PNGs (fgr's renders) into one, COLUMNS to a row: tile_pngs.py COLUMNS OUT IN...

Standard library only (zlib, struct): reads the non-interlaced 8-bit RGB PNGs fgr writes."""
import struct
import sys
import zlib


def read_png(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise SystemExit(f"{path}: not a PNG")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour != 2 or interlace:
        raise SystemExit(f"{path}: only 8-bit RGB, not interlaced")
    raw, stride, rows, prev, at = zlib.decompress(idat), width * 3, [], bytearray(width * 3), 0
    for _ in range(height):
        kind, line = raw[at], bytearray(raw[at + 1:at + 1 + stride])
        at += 1 + stride
        for x in range(stride):
            a = line[x - 3] if x >= 3 else 0
            b = prev[x]
            c = prev[x - 3] if x >= 3 else 0
            if kind == 1:
                line[x] = (line[x] + a) & 255
            elif kind == 2:
                line[x] = (line[x] + b) & 255
            elif kind == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return width, height, rows


def chunk(kind, body):
    return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))


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
    raw = b"".join(b"\x00" + bytes(row) for row in canvas)
    header = struct.pack(">IIBBBBB", width, len(canvas), 8, 2, 0, 0, 0)
    with open(out, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 9))
                + chunk(b"IEND", b""))


if __name__ == "__main__":
    main()
