#!/usr/bin/env python3
"""Writes seed inputs for bvh_fuzz into FOLDER: float soups (little-endian float32) of a few rays and boxes or
triangles at one scale or across many, from 1e-40 to 1e30, with zeros and subnormals. Deterministic."""
import random
import struct
import sys
from pathlib import Path


def soup(rng, rays, points, low, high):
    out = []
    for _ in range(rays):  # origin, direction, t_max
        out += [rng.uniform(-3, 3) * 10 ** rng.uniform(low, high) for _ in range(3)]
        out += [rng.uniform(-1, 1) for _ in range(3)] + [rng.choice([0.0, 1e30, rng.uniform(0, 10)])]
    for _ in range(points):
        out += [rng.choice([0.0, 1.0, rng.uniform(-1, 1)]) * 10 ** rng.uniform(low, high) for _ in range(3)]
    return struct.pack(f"<{len(out)}f", *out)


def main():
    folder = Path(sys.argv[1])
    folder.mkdir(parents=True, exist_ok=True)
    rng = random.Random(14)
    scales = [(-40, -40), (-30, -30), (-1, 1), (20, 20), (30, 30), (-30, 30), (-44, 1)]
    for i, (low, high) in enumerate(scales):
        (folder / f"seed{i}.soup").write_bytes(soup(rng, 8, 48, low, high))


if __name__ == "__main__":
    main()
