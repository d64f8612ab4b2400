#!/usr/bin/env python3
"""Prints what makes two tile sets or frame folders equal, one line per item, sorted:
for an .mbtiles file its metadata rows and a SHA-256 of each tile (z/x/y in XYZ rows);
for a folder every file below it (hidden ones too) with its SHA-256.
Two outputs are equal for the tests when these listings are identical.

tile_hashes.py --pixels A.png B.png says whether two 8-bit PNGs hold the same pixels (the
decoded, unfiltered rows) and where the first differing pixel is: the Slurm test's diagnosis
of a tile whose bytes differ."""
import hashlib
import os
import sqlite3
import sys


def mbtiles(path):
    db = sqlite3.connect(f"file:{path}?mode=ro", uri=True)
    lines = [f"meta {name}={value}" for name, value in db.execute("SELECT name, value FROM metadata")]
    for z, x, row, data in db.execute("SELECT zoom_level, tile_column, tile_row, tile_data FROM tiles"):
        y = (1 << z) - 1 - row
        lines.append(f"tile {z}/{x}/{y} {hashlib.sha256(data).hexdigest()}")
    return lines


def folder(path):
    lines = []
    for root, _, files in os.walk(path):
        for name in files:
            full = os.path.join(root, name)
            with open(full, "rb") as f:
                lines.append(f"file {os.path.relpath(full, path)} {hashlib.sha256(f.read()).hexdigest()}")
    return lines


def png_rows(path):
    """The unfiltered rows of an 8-bit, non-interlaced PNG: (width, bytes per pixel, rows)."""
    import struct
    import zlib
    data = open(path, "rb").read()
    pos, idat, width, height, bpp = 8, b"", 0, 0, 1
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            width, height = struct.unpack(">II", body[:8])
            bpp = {0: 1, 2: 3, 4: 2, 6: 4}[body[9]]
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    global last_filtered
    last_filtered = zlib.decompress(idat)
    raw, stride, rows, prior = last_filtered, width * bpp, [], bytearray(width * bpp)
    for y in range(height):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b = prior[i]
            c = prior[i - bpp] if i >= bpp else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + ((a + b) >> 1)) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        prior = line
    return width, bpp, rows


if sys.argv[1] == "--pixels":
    wa, ba, ra = png_rows(sys.argv[2])
    fa = last_filtered
    wb, bb, rb = png_rows(sys.argv[3])
    fb = last_filtered
    # Which stage of the encoder differs: the rows' filters (the filtered bytes deflate reads) or
    # only the deflate stream.
    if fa == fb:
        print("the same filtered rows (the deflate streams differ);", end=" ")
    else:
        stride = wa * ba + 1
        types = lambda f: "".join(str(f[y * stride]) for y in range(min(len(f) // stride, 8)))
        print(f"different filtered rows (filter types of the first rows {types(fa)} vs {types(fb)});", end=" ")
    if (wa, ba, len(ra)) != (wb, bb, len(rb)):
        print(f"different shapes ({wa}x{len(ra)}x{ba} and {wb}x{len(rb)}x{bb})")
    elif ra == rb:
        print("the same pixels (only the PNG encoding differs)")
    else:
        diffs = [(y, i // ba) for y in range(len(ra)) for i in range(wa * ba) if ra[y][i] != rb[y][i]]
        y, x = diffs[0]
        print(f"{len(diffs)} differing samples, the first at pixel ({x}, {y}): "
              f"{list(ra[y][x * ba:(x + 1) * ba])} vs {list(rb[y][x * ba:(x + 1) * ba])}")
    sys.exit(0)

path = sys.argv[1]
print("\n".join(sorted(mbtiles(path) if path.endswith(".mbtiles") else folder(path))))
