#!/usr/bin/env python3
"""Writes sky.hdr, the course's own HDR environment: an analytic sky with a sun, 128 x 64 in
latitude-longitude (row 0 looks up, +y; column u at phi = 2 pi u from +x toward +z), as chapter 06 reads it.

  sky above the horizon: a blue that lightens toward the horizon, L = zenith + (horizon - zenith) (1 - cos t)^3;
  ground below it:       a dim brown, constant;
  sun:                   a disk of angular radius 2.5 degrees at elevation 35 degrees, radiance 3000,
                         each pixel its covered fraction (8 x 8 points per pixel).

The sun carries about four fifths of the light: the sharp case where drawing directions by the map's
brightness pays. Run `python3 make_sky.py` here to write sky.hdr again (the same bytes: no randomness).
"""
import math

WIDTH, HEIGHT = 128, 64
ZENITH = (0.18, 0.32, 0.80)
HORIZON = (0.85, 0.90, 1.00)
GROUND = (0.12, 0.10, 0.08)
SUN_RADIANCE = (3000.0, 2800.0, 2500.0)
SUN_ELEVATION, SUN_AZIMUTH, SUN_RADIUS = math.radians(35), math.radians(250), math.radians(2.5)
SUPERSAMPLES = 8


def direction(u, v):
    theta, phi = math.pi * v, 2 * math.pi * u
    return (math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi))


SUN = direction(SUN_AZIMUTH / (2 * math.pi), 0.5 - SUN_ELEVATION / math.pi)
COS_SUN_RADIUS = math.cos(SUN_RADIUS)


def sky(d):
    if d[1] < 0:
        return GROUND
    t = (1 - d[1]) ** 3
    return tuple(z + (h - z) * t for z, h in zip(ZENITH, HORIZON))


def pixel(x, y):
    covered = 0
    for a in range(SUPERSAMPLES):
        for b in range(SUPERSAMPLES):
            d = direction((x + (a + 0.5) / SUPERSAMPLES) / WIDTH, (y + (b + 0.5) / SUPERSAMPLES) / HEIGHT)
            covered += sum(p * q for p, q in zip(d, SUN)) >= COS_SUN_RADIUS
    fraction = covered / SUPERSAMPLES ** 2
    base = sky(direction((x + 0.5) / WIDTH, (y + 0.5) / HEIGHT))
    return tuple(c * (1 - fraction) + s * fraction for c, s in zip(base, SUN_RADIANCE))


def rgbe(rgb):
    v = max(rgb)
    if v < 1e-32:
        return bytes(4)
    mantissa, exponent = math.frexp(v)
    scale = mantissa * 256 / v
    return bytes([int(c * scale) for c in rgb] + [exponent + 128])


def main():
    # Flat (not run-length encoded) scanlines: a reader tells them apart by the first pixel, whose bytes are
    # not the run-length marker 2 2.
    data = bytearray(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (HEIGHT, WIDTH))
    for y in range(HEIGHT):
        for x in range(WIDTH):
            data += rgbe(pixel(x, y))
    with open("sky.hdr", "wb") as f:
        f.write(data)


if __name__ == "__main__":
    main()
