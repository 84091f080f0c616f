#!/usr/bin/env python3
"""Checks a merged model against its tiles without the merge's own code: every Gaussian of the PLY
lies in the cell of the tile its "tile" property names and in no other cell (tiles.json), the counts
agree with merge.json, and each tile kept exactly its Gaussians inside its cell (the tile's own PLY
read again). Exit 1 with the first disagreement."""
import argparse
import json
import os
import struct
import sys

TYPES = {"float": "f", "float32": "f", "int": "i", "int32": "i", "uint": "I", "uchar": "B", "double": "d"}


def read_ply(path):
    with open(path, "rb") as f:
        names, fmt, n = [], "<", 0
        while True:
            line = f.readline().decode("ascii").strip()
            if line.startswith("element vertex"):
                n = int(line.split()[2])
            elif line.startswith("property"):
                _, t, name = line.split()
                names.append(name)
                fmt += TYPES[t]
            elif line == "end_header":
                break
        size = struct.calcsize(fmt)
        data = f.read(size * n)
    rows = [struct.unpack_from(fmt, data, i * size) for i in range(n)]
    return names, rows


def inside(cell, x, y):
    lo = [-float("inf") if v is None else v for v in cell[:2]]
    hi = [float("inf") if v is None else v for v in cell[2:]]
    return lo[0] <= x < hi[0] and lo[1] <= y < hi[1]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--tiles", required=True)
    ap.add_argument("--merged", required=True)
    ap.add_argument("--method", default="citylangsplat")
    a = ap.parse_args()
    plan = json.load(open(os.path.join(a.tiles, "tiles.json")))
    report = json.load(open(os.path.join(a.merged, "merge.json")))["methods"][a.method]
    names, rows = read_ply(os.path.join(a.merged, "language", a.method, "point_cloud.ply"))
    ix, iy, it = names.index("x"), names.index("y"), names.index("tile")
    cells = [t["cell"] for t in plan["tiles"]]
    per_tile = [0] * len(cells)
    for r in rows:
        x, y, t = r[ix], r[iy], r[it]
        owners = [k for k, c in enumerate(cells) if inside(c, x, y)]
        if owners != [t]:
            sys.exit(f"Gaussian at ({x}, {y}) of tile {t} lies in the cells {owners}")
        per_tile[t] += 1
    if len(rows) != report["gaussians"]:
        sys.exit(f"merged PLY has {len(rows)} Gaussians, merge.json says {report['gaussians']}")
    for k, t in enumerate(plan["tiles"]):
        tn, trows = read_ply(os.path.join(a.tiles, t["name"], "citylangsplat", "language", a.method, "point_cloud.ply"))
        expected = sum(1 for r in trows if inside(t["cell"], r[tn.index("x")], r[tn.index("y")]))
        if per_tile[k] != expected or report["tiles"][k]["kept"] != expected:
            sys.exit(f"{t['name']}: kept {per_tile[k]} (merge.json {report['tiles'][k]['kept']}), its cell holds {expected}")
    print(f"{len(rows)} Gaussians, each in its own tile's cell and no other; per tile {per_tile}")


if __name__ == "__main__":
    main()
