#!/usr/bin/env python3
"""Prints what makes two tile sets or frame folders equal, one line per item, sorted:
for an .mbtiles file its metadata rows and a SHA-256 of each tile (z/x/y in XYZ rows);
for a folder every file below it (hidden ones too) with its SHA-256.
Two outputs are equal for the tests when these listings are identical."""
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


path = sys.argv[1]
print("\n".join(sorted(mbtiles(path) if path.endswith(".mbtiles") else folder(path))))
