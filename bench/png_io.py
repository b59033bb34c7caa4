# SPDX-License-Identifier: Apache-2.0
"""Reading and writing the PNGs the bench scripts handle, with Python's standard library only
(zlib, struct): non-interlaced 8- and 16-bit grey, RGB, grey+alpha and RGBA."""
import struct
import zlib

CHANNELS = {0: 1, 2: 3, 4: 2, 6: 4}  # PNG colour type -> samples per pixel


class PngError(Exception):
    pass


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    return a if pa <= pb and pa <= pc else b if pb <= pc else c


def unfilter(raw, height, stride, bpp):
    """The rows of the decompressed image data, each `stride` bytes, filters undone."""
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
            raise PngError(f"bad PNG filter {kind}")
        rows.append(line)
        prev = line
    return rows


def read_png(path):
    """(width, height, bit depth, colour type, rows of raw sample bytes) of a PNG."""
    try:
        data = open(path, "rb").read()
    except OSError as error:
        raise PngError(f"cannot read '{path}': {error.strerror}") from error
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise PngError(f"{path}: not a PNG")
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
        raise PngError(f"{path}: no IHDR")
    width, height, depth, colour, _, _, interlace = header
    if depth not in (8, 16) or colour not in CHANNELS or interlace:
        raise PngError(f"{path}: needs a non-interlaced 8- or 16-bit grey, RGB or RGBA PNG "
                       f"(got depth {depth}, colour type {colour})")
    bpp = CHANNELS[colour] * depth // 8
    return width, height, depth, colour, unfilter(zlib.decompress(idat), height, width * bpp, bpp)


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
