#!/usr/bin/env python3
"""Writes the course's own textures (no downloaded images): ch04_wood.png, 64 x 64 texels of wood rings in
sRGB, from a formula, with nothing but Python's zlib. Run it from anywhere; the PNG lands beside this script.
The bytes are the same on every machine (integer arithmetic after one rounding per texel)."""
import math
import pathlib
import struct
import zlib

SIZE = 64
LIGHT = (222, 170, 112)  # sRGB bytes: pale wood
DARK = (120, 66, 30)     # a ring


def wood(x, y):
    # Rings about a centre off the image, warped by two slow waves so they are not perfect circles.
    u, v = x / SIZE, y / SIZE
    r = math.hypot(u + 0.35, 1.6 * (v - 0.45)) * 9 + 0.6 * math.sin(7 * u + 3 * v) + 0.25 * math.sin(23 * v)
    ring = 0.5 + 0.5 * math.cos(2 * math.pi * r)
    w = ring ** 3  # thin dark rings on a wide light band
    return tuple(round(l + (d - l) * w) for l, d in zip(LIGHT, DARK))


def png(width, height, pixel):
    rows = b"".join(b"\0" + bytes(c for x in range(width) for c in pixel(x, y)) for y in range(height))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)  # 8-bit RGB
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b"")


if __name__ == "__main__":
    out = pathlib.Path(__file__).resolve().parent / "ch04_wood.png"
    out.write_bytes(png(SIZE, SIZE, wood))
    print(out)
