#!/usr/bin/env python3
"""Writes resources/surfaces/default-organ.off: a closed, smooth, pear-shaped stand-in for a uterus.

It is the surface the workstation opens by default until the statistical shape model supplies the mean organ.
Dimensions follow a published multiparous example (about 79 x 43 x 35 mm, length x width x AP; docs/references.md
[NayabMultiparous]): a corpus that narrows through the isthmus into a cylindrical cervix (about 30 mm long).
Units: mm; the long axis is +z from the external os (z = 0) to the fundus.
Usage: python3 tools/make_placeholder_organ.py resources/surfaces/default-organ.off
"""
import math
import sys

LENGTH = 79.0        # mm, external os to fundus
WIDTH = 43.0         # mm, corpus width (left-right, x)
DEPTH = 35.0         # mm, corpus antero-posterior depth (y)
CERVIX_RADIUS = 13.0  # mm
CERVIX_LENGTH = 30.0  # mm
RINGS = 48           # rings between the poles
SEGMENTS = 64        # vertices per ring


def half_width(t):
    """Half-width profile along the axis, t in [0, 1] from os to fundus; 0 at both poles."""
    z = t * LENGTH
    corpus_start = CERVIX_LENGTH / LENGTH
    if t <= corpus_start:
        # cervix: a rounded cylinder that closes at the external os
        s = min(1.0, z / 6.0)
        return CERVIX_RADIUS * math.sqrt(s * (2.0 - s))
    # corpus: smooth step from the cervix radius to the corpus half-width, then a rounded fundus
    u = (t - corpus_start) / (1.0 - corpus_start)
    grow = 0.5 - 0.5 * math.cos(math.pi * min(1.0, u / 0.55))
    body = CERVIX_RADIUS + (WIDTH / 2.0 - CERVIX_RADIUS) * grow
    cap = math.sqrt(max(0.0, 1.0 - max(0.0, (u - 0.55) / 0.45) ** 2))
    return body * cap


def main(path):
    points = [(0.0, 0.0, 0.0)]
    for i in range(1, RINGS):
        t = i / RINGS
        # denser rings near the poles keep triangles well shaped
        t = 0.5 - 0.5 * math.cos(math.pi * t)
        r = half_width(t)
        ratio = 1.0 if t * LENGTH <= CERVIX_LENGTH else 1.0 - (1.0 - DEPTH / WIDTH) * min(
            1.0, (t * LENGTH - CERVIX_LENGTH) / 15.0)
        for j in range(SEGMENTS):
            a = 2.0 * math.pi * j / SEGMENTS
            points.append((r * math.cos(a), r * ratio * math.sin(a), t * LENGTH))
    points.append((0.0, 0.0, LENGTH))
    tris = []
    ring = lambda i, j: 1 + (i - 1) * SEGMENTS + (j % SEGMENTS)
    for j in range(SEGMENTS):  # os cap, outward normal towards -z
        tris.append((0, ring(1, j + 1), ring(1, j)))
    for i in range(1, RINGS - 1):
        for j in range(SEGMENTS):
            a, b, c, d = ring(i, j), ring(i, j + 1), ring(i + 1, j + 1), ring(i + 1, j)
            tris.append((a, b, c))
            tris.append((a, c, d))
    top = len(points) - 1
    for j in range(SEGMENTS):
        tris.append((top, ring(RINGS - 1, j), ring(RINGS - 1, j + 1)))
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(points), len(tris)))
        for p in points:
            f.write("%.4f %.4f %.4f\n" % p)
        for t in tris:
            f.write("3 %d %d %d\n" % t)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "resources/surfaces/default-organ.off")
