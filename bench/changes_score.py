#!/usr/bin/python3
"""Scores `citylangsplat changes` against the openings a given city model lacks (bench/changes.sh).

Truth: the openings (CityGML bldg:Window / bldg:Door elements; CityJSON Window / Door semantic objects) of
the true model (`synth --city`, what the photos show) that the given model (the scene's city/ file) does
not have: CityGML by gml:id, CityJSON by the opening's polygons (a dropped opening's polygons take their
wall's semantics). Read here from the files, not from anything `changes` wrote.

A proposal (changes.json: a rectangle's four corners in the CRS) matches a true opening when the opening's
centroid lies within 0.5 m of the rectangle's plane and the intersection over union of the rectangle and
the opening's polygons projected onto that plane (rasterised at 2 cm) is at least 0.5; proposals and
openings are matched one to one, highest IoU first. Precision = matched proposals / proposals, recall =
matched openings / missing openings.

    python3 bench/changes_score.py --true-city TRUE --given-city GIVEN --changes RUN/changes/changes.json
With --scene (the synth scene: its COLMAP text model, city/transform.json and gt/labels), a missing
opening counts as visible when its centroid projects, in at least one view, onto a pixel whose
ground-truth label (rendered by synth from the true model) is a window or door: the recall over those
is the share of what the photos show.
Prints one JSON line: {"missing", "visible", "proposals", "matched", "precision", "recall",
"recall_visible", "ious"}.
"""
import argparse
import json
import math
import xml.etree.ElementTree as ET


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def dot(a, b):
    return sum(a[i] * b[i] for i in range(3))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def gml_openings(path):
    """{gml:id: [polygon exterior rings]} of every bldg:Window / bldg:Door (and CityGML 3 Window/DoorSurface)."""
    out = {}
    for el in ET.parse(path).iter():
        tag = el.tag.split("}")[-1]
        if tag not in ("Window", "Door", "WindowSurface", "DoorSurface"):
            continue
        oid = next((v for k, v in el.attrib.items() if k.endswith("}id")), None)
        rings = []
        for ring in el.iter():
            if ring.tag.split("}")[-1] != "LinearRing":
                continue
            values = []
            for node in ring.iter():
                name = node.tag.split("}")[-1]
                if name in ("posList", "pos", "coordinates") and node.text:
                    values += [float(x) for x in node.text.replace(",", " ").split()]
            pts = [values[i:i + 3] for i in range(0, len(values) - 2, 3)]
            if len(pts) >= 3:
                rings.append(pts)
        if oid and rings:
            out[oid] = rings
    return out


def cityjson_openings(path):
    """{key: [exterior rings]} per Window / Door semantic object; key = the sorted polygons' first vertices."""
    doc = json.load(open(path))
    scale, translate = doc["transform"]["scale"], doc["transform"]["translate"]
    verts = [[v[i] * scale[i] + translate[i] for i in range(3)] for v in doc["vertices"]]
    out = {}
    for oid, o in doc["CityObjects"].items():
        for g in o.get("geometry", []):
            sem = g.get("semantics")
            if not sem or g["type"] != "MultiSurface" and g["type"] != "CompositeSurface" and g["type"] != "Solid":
                continue
            polys = g["boundaries"] if g["type"] != "Solid" else [p for shell in g["boundaries"] for p in shell]
            values = sem["values"] if g["type"] != "Solid" else [v for shell in sem["values"] for v in shell]
            groups = {}
            for poly, v in zip(polys, values):
                if v is not None and sem["surfaces"][v]["type"] in ("Window", "Door"):
                    groups.setdefault(v, []).append([verts[i] for i in poly[0]])
            for rings in groups.values():
                key = json.dumps(sorted([[round(x, 3) for x in r[0]] for r in rings]))
                out[key] = rings
    return out


def openings(path):
    return cityjson_openings(path) if path.endswith(".json") else gml_openings(path)


def inside(pt, poly):
    x, y, hit = pt[0], pt[1], False
    for i in range(len(poly)):
        (x0, y0), (x1, y1) = poly[i], poly[(i + 1) % len(poly)]
        if (y0 > y) != (y1 > y) and x < x0 + (y - y0) * (x1 - x0) / (y1 - y0):
            hit = not hit
    return hit


def iou(corners, rings, step=0.02):
    c0 = corners[0]
    w, h = math.dist(corners[0], corners[1]), math.dist(corners[0], corners[3])
    u = [x / w for x in sub(corners[1], c0)]
    v = [x / h for x in sub(corners[3], c0)]
    n = cross(u, v)
    pts = [p for r in rings for p in r]
    centroid = [sum(p[i] for p in pts) / len(pts) for i in range(3)]
    if abs(dot(sub(centroid, c0), n)) > 0.5:
        return 0.0
    flat = [[(dot(sub(p, c0), u), dot(sub(p, c0), v)) for p in r] for r in rings]
    fu = [q[0] for r in flat for q in r]
    fv = [q[1] for r in flat for q in r]
    if max(fu) < 0 or min(fu) > w or max(fv) < 0 or min(fv) > h:
        return 0.0
    u0, u1, v0, v1 = min(0, min(fu)), max(w, max(fu)), min(0, min(fv)), max(h, max(fv))
    both = either = 0
    boxes = [(min(q[0] for q in r), max(q[0] for q in r), min(q[1] for q in r), max(q[1] for q in r)) for r in flat]
    y = v0 + step / 2
    while y < v1:
        x = u0 + step / 2
        while x < u1:
            a = 0 <= x <= w and 0 <= y <= h
            b = any(bx[0] <= x <= bx[1] and bx[2] <= y <= bx[3] and inside((x, y), r) for bx, r in zip(boxes, flat))
            both += a and b
            either += a or b
            x += step
        y += step
    return both / either if either else 0.0


def visible_openings(scene, missing):
    """The keys of the missing openings that some view's ground-truth labels show (see the docstring)."""
    from PIL import Image  # python3-pil, as the browser tests
    t = json.load(open(f"{scene}/city/transform.json"))["matrix"]
    cams = {}
    for line in open(f"{scene}/sparse/0/cameras.txt"):
        w = line.split()
        if w and not w[0].startswith("#"):
            cams[w[0]] = [float(x) for x in w[4:8]]  # PINHOLE fx fy cx cy
    lines = [l.split() for l in open(f"{scene}/sparse/0/images.txt") if l.strip() and not l.startswith("#")]
    legend = json.load(open(f"{scene}/gt/legend.json"))
    opening_labels = {c["id"] + 1 for c in legend if c["name"] in ("window", "door")}
    views = []
    for f in lines[0::2]:
        qw, qx, qy, qz, tx, ty, tz = map(float, f[1:8])
        R = [[1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qz * qw), 2 * (qx * qz + qy * qw)],
             [2 * (qx * qy + qz * qw), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qx * qw)],
             [2 * (qx * qz - qy * qw), 2 * (qy * qz + qx * qw), 1 - 2 * (qx * qx + qy * qy)]]
        label = Image.open(f"{scene}/gt/labels/{f[9].rsplit('.', 1)[0]}.png")
        views.append((R, (tx, ty, tz), cams[f[8]], label))
    seen = set()
    for key, rings in missing.items():
        pts = [p for r in rings for p in r]
        c = [sum(p[i] for p in pts) / len(pts) for i in range(3)]
        x = [sum(t[r][k] * c[k] for k in range(3)) + t[r][3] for r in range(3)]
        for R, tv, (fx, fy, cx, cy), label in views:
            p = [sum(R[r][k] * x[k] for k in range(3)) + tv[r] for r in range(3)]
            if p[2] <= 0:
                continue
            u, v = int(fx * p[0] / p[2] + cx), int(fy * p[1] / p[2] + cy)
            if 0 <= u < label.width and 0 <= v < label.height and label.getpixel((u, v)) in opening_labels:
                seen.add(key)
                break
    return seen


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--true-city", required=True)
    ap.add_argument("--given-city", required=True)
    ap.add_argument("--changes", required=True)
    ap.add_argument("--min-iou", type=float, default=0.5)
    ap.add_argument("--scene", help="the synth scene, for the openings the photos show")
    a = ap.parse_args()
    true, given = openings(a.true_city), openings(a.given_city)
    missing = {k: r for k, r in true.items() if k not in given}
    proposals = json.load(open(a.changes))["proposals"]
    pairs = []
    for i, p in enumerate(proposals):
        for k, rings in missing.items():
            s = iou(p["corners"], rings)
            if s >= a.min_iou:
                pairs.append((s, i, k))
    pairs.sort(reverse=True)
    used_p, used_t, ious = set(), set(), []
    for s, i, k in pairs:
        if i in used_p or k in used_t:
            continue
        used_p.add(i)
        used_t.add(k)
        ious.append(round(s, 3))
    n = len(ious)
    out = {"true_openings": len(true), "missing": len(missing), "proposals": len(proposals), "matched": n,
           "precision": n / len(proposals) if proposals else None,
           "recall": n / len(missing) if missing else None, "ious": ious}
    if a.scene:
        visible = visible_openings(a.scene, missing)
        found = sum(1 for k in used_t if k in visible)
        out.update({"visible": len(visible), "matched_visible": found,
                    "recall_visible": found / len(visible) if visible else None})
    print(json.dumps(out))


if __name__ == "__main__":
    main()
