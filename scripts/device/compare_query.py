#!/usr/bin/env python3
"""Compares two `citylangsplat query` outputs of one model (e.g. --device cpu and --device cuda).

  compare_query.py REFERENCE_DIR OTHER_DIR [--map-tol 1e-3] [--score-tol 1e-5]
Prints, and fails (exit 1) beyond the tolerances or on a NaN: the largest difference of every map
(maps/*/*.npy, float32; a map in only one of the two fails), of the per-Gaussian scores (score_*
properties of scores.ply) and the selection counts of query.json. Plain Python: the GPU machines have
no numpy.
"""
import argparse
import array
import glob
import json
import math
import os
import struct
import sys


def read_npy(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:6] != b"\x93NUMPY":
        sys.exit(f"compare_query: {path} is not a .npy file")
    major = data[6]
    size = 2 if major == 1 else 4
    header_len = int.from_bytes(data[8:8 + size], "little")
    header = data[8 + size:8 + size + header_len].decode("latin1")
    if "'<f4'" not in header or "'fortran_order': False" not in header:
        sys.exit(f"compare_query: {path}: expected little-endian float32 in C order, header {header.strip()}")
    values = array.array("f")
    values.frombytes(data[8 + size + header_len:])
    return header[header.index("'shape'"):].split(")")[0] + ")", values


PLY_TYPES = {"char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h", "ushort": "H",
             "uint16": "H", "int": "i", "int32": "i", "uint": "I", "uint32": "I", "float": "f", "float32": "f",
             "double": "d", "float64": "d"}


def largest_difference(a, b):
    """max |a_i - b_i|, NaN if either holds a NaN (plain max() would skip it)."""
    d = 0.0
    for x, y in zip(a, b):
        e = abs(x - y)
        if math.isnan(e):
            return math.nan
        d = max(d, e)
    return d


def within(d, tol):
    return d <= tol  # False for NaN


def read_json(path):
    with open(path) as f:
        return json.load(f)


def read_scores(path):
    """The score_* columns of a binary little-endian PLY's vertices (scalar properties only)."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    names, fmt, count = [], "<", 0
    for line in data[:end].decode("ascii").splitlines():
        parts = line.split()
        if parts[:1] == ["format"] and parts[1:2] != ["binary_little_endian"]:
            sys.exit(f"compare_query: {path}: format {' '.join(parts[1:])}, not binary_little_endian")
        if parts[:2] == ["element", "vertex"]:
            count = int(parts[2])
        elif parts[:1] == ["property"]:
            if parts[1] not in PLY_TYPES:
                sys.exit(f"compare_query: {path}: property {parts[-1]} of type {parts[1]} is not supported")
            names.append(parts[2])
            fmt += PLY_TYPES[parts[1]]
    size = struct.calcsize(fmt)
    rows = list(struct.iter_unpack(fmt, data[end:end + size * count]))
    return {n: [r[i] for r in rows] for i, n in enumerate(names) if n.startswith("score_")}


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("reference")
    p.add_argument("other")
    p.add_argument("--map-tol", type=float, default=1e-3)
    p.add_argument("--score-tol", type=float, default=1e-5)
    a = p.parse_args()
    failed = False
    def maps_of(d):
        return {os.path.relpath(f, d) for f in glob.glob(os.path.join(d, "maps", "*", "*.npy"))}
    maps, other_maps = maps_of(a.reference), maps_of(a.other)
    if not maps:
        sys.exit(f"compare_query: no maps under {a.reference}/maps")
    for rel in sorted(maps ^ other_maps):
        print(f"only in {a.reference if rel in maps else a.other}: {rel}")
        failed = True
    worst, compared = (0.0, ""), 0
    for rel in sorted(maps & other_maps):
        (shape_r, r), (shape_o, o) = read_npy(os.path.join(a.reference, rel)), read_npy(os.path.join(a.other, rel))
        if shape_r != shape_o:
            print(f"{rel}: shape {shape_r} against {shape_o}")
            failed = True
            continue
        d = largest_difference(r, o)
        compared += 1
        if math.isnan(d) or d > worst[0]:
            worst = (d, rel)
        if math.isnan(d):
            break
    print(f"maps: {compared} compared, largest difference {worst[0]:.3g} ({worst[1]})")
    failed |= not within(worst[0], a.map_tol)
    for d in (a.reference, a.other):
        for name in ("scores.ply", "query.json"):
            if not os.path.exists(os.path.join(d, name)):
                sys.exit(f"compare_query: {d} has no {name}: not a query output")
    sr, so = read_scores(os.path.join(a.reference, "scores.ply")), read_scores(os.path.join(a.other, "scores.ply"))
    if sorted(sr) != sorted(so) or any(len(sr[k]) != len(so[k]) for k in sr):
        print("scores.ply: the score properties or the Gaussian counts differ")
        failed = True
    else:
        diffs = [largest_difference(sr[k], so[k]) for k in sr]
        d = math.nan if any(math.isnan(x) for x in diffs) else max(diffs, default=0.0)
        print(f"scores: {len(sr)} texts x {len(next(iter(sr.values()), []))} Gaussians, largest difference {d:.3g}")
        failed |= not within(d, a.score_tol)
    qr, qo = (read_json(os.path.join(d, "query.json"))["queries"] for d in (a.reference, a.other))
    sel_r = [(q["text"], q["level"], q["selection"]["count"]) for q in qr]
    sel_o = [(q["text"], q["level"], q["selection"]["count"]) for q in qo]
    print(f"selections (text, level, count) {'equal' if sel_r == sel_o else 'differ'}: {sel_o}")
    failed |= sel_r != sel_o
    print("FAIL" if failed else "PASS")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
