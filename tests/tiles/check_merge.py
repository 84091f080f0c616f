#!/usr/bin/env python3
"""Checks a merged model against its tiles without the merge's own code: every Gaussian of the PLY
lies in the cell of the tile its "tile" property names and in no other cell (tiles.json), the counts
agree with merge.json, and each tile contributed exactly the Gaussians of its own PLY inside its cell,
every property equal. Exit 1 with the first disagreement."""
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
    per_tile = [[] for _ in cells]
    for r in rows:
        x, y, t = r[ix], r[iy], r[it]
        owners = [k for k, c in enumerate(cells) if inside(c, x, y)]
        if owners != [t]:
            sys.exit(f"Gaussian at ({x}, {y}) of tile {t} lies in the cells {owners}")
        per_tile[t].append(r)
    if len(rows) != report["gaussians"]:
        sys.exit(f"merged PLY has {len(rows)} Gaussians, merge.json says {report['gaussians']}")
    for k, t in enumerate(plan["tiles"]):
        tn, trows = read_ply(os.path.join(a.tiles, t["name"], "citylangsplat", "language", a.method, "point_cloud.ply"))
        # The merged rows carry the tile's own properties in its order, then "tile".
        columns = [names.index(n) for n in tn]
        kept = sorted(tuple(r[c] for c in columns) for r in per_tile[k])
        expected = sorted(r for r in trows if inside(t["cell"], r[tn.index("x")], r[tn.index("y")]))
        if kept != expected or report["tiles"][k]["kept"] != len(expected):
            sys.exit(f"{t['name']}: the merged model holds {len(kept)} of its Gaussians (merge.json "
                     f"{report['tiles'][k]['kept']}), its PLY has {len(expected)} in its cell, or they differ")
    per_tile = [len(p) for p in per_tile]
    print(f"{len(rows)} Gaussians, each in its own tile's cell and no other; per tile {per_tile}")


if __name__ == "__main__":
    main()
