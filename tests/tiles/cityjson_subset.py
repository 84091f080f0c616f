#!/usr/bin/env python3
"""The buildings of a CityJSON file whose footprint lies in a box, as a new CityJSON file: a small
district for the tiling test and bench (tests/tiles/slurm_tiles_test.sh, bench/tiles.sh). Written
here because no Debian package cuts CityJSON (cjio is not packaged); the vertex list is kept whole
(unreferenced vertices are valid CityJSON), only CityObjects are dropped."""
import argparse
import json
import sys


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("city", help="CityJSON file")
    ap.add_argument("--box", required=True, help="x0,y0,x1,y1 in the file's real coordinates")
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    x0, y0, x1, y1 = (float(v) for v in a.box.split(","))
    with open(a.city) as f:
        d = json.load(f)
    scale = d.get("transform", {}).get("scale", [1, 1, 1])
    shift = d.get("transform", {}).get("translate", [0, 0, 0])
    verts = d["vertices"]

    def indices(b, out):
        if isinstance(b, list):
            for x in b:
                indices(x, out)
        else:
            out.add(b)
        return out

    keep = {}
    for oid, o in d["CityObjects"].items():
        if o.get("type") not in ("Building", "BuildingPart") or o.get("parents"):
            continue
        idx = set()
        for g in o.get("geometry", []):
            indices(g["boundaries"], idx)
        for child in o.get("children", []):
            for g in d["CityObjects"][child].get("geometry", []):
                indices(g["boundaries"], idx)
        if not idx:
            continue
        xs = [verts[i][0] * scale[0] + shift[0] for i in idx]
        ys = [verts[i][1] * scale[1] + shift[1] for i in idx]
        if min(xs) >= x0 and max(xs) <= x1 and min(ys) >= y0 and max(ys) <= y1:
            keep[oid] = o
            for child in o.get("children", []):
                keep[child] = d["CityObjects"][child]
    if not keep:
        sys.exit(f"{a.city}: no building lies in the box {a.box}")
    d["CityObjects"] = keep
    with open(a.out, "w") as f:
        json.dump(d, f)
    print(f"{sum(1 for o in keep.values() if not o.get('parents'))} buildings -> {a.out}")


if __name__ == "__main__":
    main()
