#!/usr/bin/env python3
"""Sagittal sections of OBJ surfaces as a PNG, without dependencies (docs pictures of the pathology stage).

Usage: section-png.py OUT.png X0 PANEL [PANEL ...]
PANEL: OBJ[:color][,OBJ[:color]...]  colors: black, red, blue. Each panel cuts its surfaces with the plane x = X0 (mm,
organ frame: x points to the patient's right) and draws y horizontally, z upwards; panels sit side by side at one scale.
Surfaces come from `hysteroscene-cli convert REGION.vtp REGION.obj`.
"""
import struct
import sys
import zlib

COLORS = {'black': (0, 0, 0), 'red': (220, 30, 30), 'blue': (30, 60, 220)}
SCALE = 8.0  # pixels per mm
MARGIN = 20


def read_obj(path):
    points, faces = [], []
    with open(path) as f:
        for line in f:
            p = line.split()
            if not p:
                continue
            if p[0] == 'v':
                points.append(tuple(float(c) for c in p[1:4]))
            elif p[0] == 'f':
                faces.append([int(q.split('/')[0]) - 1 for q in p[1:4]])
    return points, faces


def section(points, faces, x0):
    segments = []
    for f in faces:
        cut = []
        for a, b in ((f[0], f[1]), (f[1], f[2]), (f[2], f[0])):
            da, db = points[a][0] - x0, points[b][0] - x0
            if (da < 0) != (db < 0):
                t = da / (da - db)
                cut.append((points[a][1] + t * (points[b][1] - points[a][1]),
                            points[a][2] + t * (points[b][2] - points[a][2])))
        if len(cut) == 2:
            segments.append(cut)
    return segments


def write_png(path, width, height, pixels):
    rows = b''.join(b'\x00' + bytes(pixels[y * width * 3:(y + 1) * width * 3]) for y in range(height))

    def chunk(kind, data):
        return struct.pack('>I', len(data)) + kind + data + struct.pack('>I', zlib.crc32(kind + data) & 0xffffffff)

    with open(path, 'wb') as f:
        f.write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', width, height, 8, 2, 0, 0, 0)) +
                chunk(b'IDAT', zlib.compress(rows)) + chunk(b'IEND', b''))


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    out, x0 = sys.argv[1], float(sys.argv[2])
    panels = []
    for spec in sys.argv[3:]:
        lines = []
        for item in spec.split(','):
            path, color = (item.split(':') + ['black'])[:2]
            lines += [(s, COLORS[color]) for s in section(*read_obj(path), x0)]
        panels.append(lines)
    ys = [p[0] for lines in panels for s, _ in lines for p in s]
    zs = [p[1] for lines in panels for s, _ in lines for p in s]
    if not ys:
        sys.exit('the plane x = %g misses every surface' % x0)
    y0, z0 = min(ys), min(zs)
    pw, h = int((max(ys) - y0) * SCALE) + 2 * MARGIN, int((max(zs) - z0) * SCALE) + 2 * MARGIN
    width = pw * len(panels)
    pixels = bytearray([255]) * (width * h * 3)
    for i, lines in enumerate(panels):
        for (a, b), color in lines:
            xa, za = i * pw + MARGIN + (a[0] - y0) * SCALE, h - MARGIN - (a[1] - z0) * SCALE
            xb, zb = i * pw + MARGIN + (b[0] - y0) * SCALE, h - MARGIN - (b[1] - z0) * SCALE
            n = int(max(abs(xb - xa), abs(zb - za))) + 1
            for k in range(n + 1):
                x, z = int(xa + (xb - xa) * k / n), int(za + (zb - za) * k / n)
                for dx in (0, 1):
                    for dz in (0, 1):
                        if 0 <= x + dx < width and 0 <= z + dz < h:
                            o = ((z + dz) * width + x + dx) * 3
                            pixels[o:o + 3] = bytes(color)
    write_png(out, width, h, pixels)


if __name__ == '__main__':
    main()
