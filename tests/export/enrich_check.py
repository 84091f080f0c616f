#!/usr/bin/python3
"""`citylangsplat enrich` on a trained run, checked by others than the writer:

1. The official CityJSON 2.0.2 schemas (data/schemas/cityjson-2.0, from cityjson/specs) accept the
   document, and the Extension file schema accepts our Extension (python3-jsonschema, Debian's; cjval,
   the official validator, is a Rust program outside Debian). What the schemas cannot say, checked as
   cjval does: vertex indices in range, parents/children both ways, one semantics value per surface,
   a semantic surface's parent/children both ways, every "+" member declared by the Extension.
2. Our attributes against the Extension's own definitions (observation on CityObjects, surfaceMembers
   on semantic surfaces, run at the root).
3. The geometry is the city model's: the polygons' area (exterior minus holes, from the CityJSON rings)
   equals the triangles' area of the label maps' mesh (labels/city_mesh.ply, written from the same
   city model by the raycast stage) within 0.1 %; every bldg:Window gml:id of the CityGML file is a
   Window semantic surface (parsed here with ElementTree).
4. The counts are the label maps': each enriched surface's +clsViews and +clsPixels equal what
   object.npy of every view holds (read here) for it and the openings in it.
5. The scores mean something: the windows' mean score for the query "window" is higher than the walls'.
8. `--out X.jsonl`: CityJSONSeq whose header and features pass the CityJSON and CityJSONFeature schemas
   and, joined back into one document here, equal the CityJSON output's objects on the same coordinates.
7. `changes` on the same run (its city model is the one the photos show): the document (with any
   proposals) passes checks 1 and 2, and nothing is proposed: the exact model lacks no opening.
6. Bad input: no run there, an --out that is no .json, and a city model other than the run's (citygml4j's
   LoD3 building for a run on FZK-Haus: --other-city) each fail with the path named, writing nothing.

    /usr/bin/python3 tests/export/enrich_check.py --binary build/citylangsplat --run RUN \\
        --city data/citygml/fzk-haus/fzk_haus_lod3_v2.gml --other-city data/citygml/citygml4j/lod3_building_v2.gml \\
        --schemas data/schemas --out /tmp/enrich
    /usr/bin/python3 tests/export/enrich_check.py --validate FILE.city.json[l] --schemas data/schemas   (checks 1-2 only)
Exit status: 0 pass, 1 fail.
"""
import argparse
import ast
import importlib.metadata
import json
import math
import os
import shutil
import struct
import subprocess
import sys
import xml.etree.ElementTree as ET

import jsonschema


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def validator_for(schema_dir, main):
    """A draft-07 validator of schema_dir/main that resolves the schemas' relative $refs among themselves."""
    store = {}
    for name in os.listdir(schema_dir):
        if name.endswith(".schema.json"):
            with open(os.path.join(schema_dir, name)) as f:
                s = json.load(f)
            store[s.get("$id", name)] = s
    with open(os.path.join(schema_dir, main)) as f:
        schema = json.load(f)
    resolver = jsonschema.RefResolver(base_uri=schema.get("$id", ""), referrer=schema, store=store)
    return jsonschema.Draft7Validator(schema, resolver=resolver)


def errors_of(validator, instance):
    return sorted(validator.iter_errors(instance), key=lambda e: list(e.absolute_path))


def polygon_area(rings, vertices, scale):
    """Exterior minus holes: Newell's normal of each ring (3D, any plane)."""
    total = 0.0
    for k, ring in enumerate(rings):
        n = [0.0, 0.0, 0.0]
        for i in range(len(ring)):
            a = [c * s for c, s in zip(vertices[ring[i]], scale)]
            b = [c * s for c, s in zip(vertices[ring[(i + 1) % len(ring)]], scale)]
            n[0] += (a[1] - b[1]) * (a[2] + b[2])
            n[1] += (a[2] - b[2]) * (a[0] + b[0])
            n[2] += (a[0] - b[0]) * (a[1] + b[1])
        area = 0.5 * math.sqrt(sum(x * x for x in n))
        total += area if k == 0 else -area
    return total


def mesh_ply_area(path):
    """Sum of the triangles' areas of a binary little-endian PLY (vertex x y z float first)."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    sizes = {"float": 4, "int": 4, "uchar": 1, "uint": 4, "double": 8}
    elements, current = [], None
    for line in header:
        w = line.split()
        if w[0] == "element":
            current = {"name": w[1], "count": int(w[2]), "props": []}
            elements.append(current)
        elif w[0] == "property":
            current["props"].append(w[1:])
    pos = end
    vertices, area = [], 0.0
    for e in elements:
        for _ in range(e["count"]):
            values = []
            for p in e["props"]:
                if p[0] == "list":
                    n = data[pos]
                    pos += 1
                    values.append(struct.unpack_from("<%di" % n, data, pos))
                    pos += 4 * n
                else:
                    fmt = {"float": "<f", "int": "<i", "uchar": "<B", "uint": "<I", "double": "<d"}[p[0]]
                    values.append(struct.unpack_from(fmt, data, pos)[0])
                    pos += sizes[p[0]]
            if e["name"] == "vertex":
                vertices.append(values[:3])
            elif e["name"] == "face":
                a, b, c = (vertices[i] for i in values[0])
                u = [b[i] - a[i] for i in range(3)]
                v = [c[i] - a[i] for i in range(3)]
                x = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
                area += 0.5 * math.sqrt(sum(t * t for t in x))
    return area


def read_int32_npy(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:6] != b"\x93NUMPY":
        fail(path + ": not an npy file")
    header_len = struct.unpack_from("<H", data, 8)[0]
    header = ast.literal_eval(data[10:10 + header_len].decode("latin1"))
    if header["descr"] != "<i4":
        fail(path + ": not int32")
    n = 1
    for s in header["shape"]:
        n *= s
    return struct.unpack_from("<%di" % n, data, 10 + header_len)


def validate(doc, ext, schemas):
    """Checks 1 and 2; returns the CityObjects and vertices."""
    # 1. The official schemas, then what cjval checks beyond them.
    schema_dir = os.path.join(schemas, "cityjson-2.0")
    problems = [("CityJSON 2.0.2 schema", e) for e in errors_of(validator_for(schema_dir, "cityjson.schema.json"), doc)]
    problems += [("Extension schema", e) for e in errors_of(validator_for(schema_dir, "extension.schema.json"), ext)]
    for where, e in problems[:20]:
        print("  %s: %s at %s" % (where, e.message[:200], "/".join(map(str, e.absolute_path))))
    objects, vertices = doc["CityObjects"], doc["vertices"]
    declared_root = set(ext["extraRootProperties"])
    other = []
    for k in doc:
        if k.startswith("+") and k not in declared_root:
            other.append("root member %s is not declared by the Extension" % k)
    surfaces_checked = 0
    for oid, o in objects.items():
        for p in o.get("parents", []):
            if oid not in objects.get(p, {}).get("children", []):
                other.append("%s names parent %s, which does not name it as a child" % (oid, p))
        for c in o.get("children", []):
            if oid not in objects.get(c, {}).get("parents", []):
                other.append("%s names child %s, which does not name it as a parent" % (oid, c))
        declared = ext["extraAttributes"].get(o["type"], {})
        for k in o.get("attributes", {}):
            if k.startswith("+") and k not in declared:
                other.append("%s: attribute %s is not declared for %s by the Extension" % (oid, k, o["type"]))
        for g in o.get("geometry", []):
            for poly in g["boundaries"]:
                for ring in poly:
                    if len(ring) < 3 or any(not 0 <= v < len(vertices) for v in ring):
                        other.append("%s: a ring of %d vertices or an index out of range" % (oid, len(ring)))
            sem = g.get("semantics")
            if not sem:
                continue
            if len(sem["values"]) != len(g["boundaries"]):
                other.append("%s: %d semantics values for %d surfaces" % (oid, len(sem["values"]), len(g["boundaries"])))
            if any(v is not None and not 0 <= v < len(sem["surfaces"]) for v in sem["values"]):
                other.append("%s: a semantics value out of range" % oid)
            for i, s in enumerate(sem["surfaces"]):
                surfaces_checked += 1
                if "parent" in s and i not in sem["surfaces"][s["parent"]].get("children", []):
                    other.append("%s: surface %d's parent does not list it" % (oid, i))
                for c in s.get("children", []):
                    if sem["surfaces"][c].get("parent") != i:
                        other.append("%s: surface %d's child %d names another parent" % (oid, i, c))
                for k, v in s.items():
                    if isinstance(v, dict):
                        other.append("%s: surface %d member %s is an object (CityJSON: scalars only)" % (oid, i, k))
    for m in other[:20]:
        print("  " + m)
    print("CityJSON 2.0.2 schemas + Extension schema (jsonschema %s): %d errors; cjval's further checks: %d errors "
          "(%d CityObjects, %d semantic surfaces, %d vertices)"
          % (importlib.metadata.version("jsonschema"), len(problems), len(other),
             len(objects), surfaces_checked, len(vertices)))
    if problems or other:
        fail("the enriched CityJSON is not valid")

    # 2. Our members against the Extension's definitions.
    defs = ext["definitions"]
    def ours(name):
        return jsonschema.Draft7Validator({"$ref": "#/definitions/" + name, "definitions": defs})
    member_errors = errors_of(ours("run"), doc["+citylangsplat"])
    enriched_objects = enriched_surfaces = 0
    for oid, o in objects.items():
        if "+citylangsplat" in o.get("attributes", {}):
            member_errors += errors_of(ours("observation"), o["attributes"]["+citylangsplat"])
            enriched_objects += 1
        for g in o.get("geometry", []):
            for s in g.get("semantics", {}).get("surfaces", []):
                members = {k: v for k, v in s.items() if k.startswith("+")}
                if "+clsProposed" in members:
                    member_errors += errors_of(ours("proposalMembers"), members)
                elif members:
                    member_errors += errors_of(ours("surfaceMembers"), members)
                    enriched_surfaces += 1
    for e in member_errors[:10]:
        print("  Extension definitions: %s" % e.message[:200])
    print("Extension definitions: %d errors (%d CityObjects, %d semantic surfaces enriched)"
          % (len(member_errors), enriched_objects, enriched_surfaces))
    if member_errors or not enriched_objects or not enriched_surfaces:
        fail("the enriched members do not follow the Extension")

    return objects, vertices


def read_sequence(path, schemas):
    """A CityJSONSeq file: its first line against the CityJSON schema, every other line against the
    CityJSONFeature schema, then the features joined into one document (vertices appended, indices
    shifted), as cjio's `cat` would."""
    schema_dir = os.path.join(schemas, "cityjson-2.0")
    with open(path) as f:
        lines = [json.loads(line) for line in f if line.strip()]
    problems = errors_of(validator_for(schema_dir, "cityjson.schema.json"), lines[0])
    feature_schema = validator_for(schema_dir, "cityjsonfeature.schema.json")
    for line in lines[1:]:
        problems += errors_of(feature_schema, line)
    for e in problems[:20]:
        print("  %s at %s" % (e.message[:200], "/".join(map(str, e.absolute_path))))
    print("CityJSONSeq: header + %d features against the CityJSON and CityJSONFeature schemas: %d errors"
          % (len(lines) - 1, len(problems)))
    if problems or lines[0]["CityObjects"] or lines[0]["vertices"]:
        fail("%s is not a valid CityJSONSeq" % path)

    def shift(b, by):
        return [shift(x, by) for x in b] if isinstance(b, list) else b + by
    doc = dict(lines[0], CityObjects={}, vertices=[])
    for feature in lines[1:]:
        if feature["id"] not in feature["CityObjects"]:
            fail("feature %s does not hold its own object" % feature["id"])
        for oid, o in feature["CityObjects"].items():
            o = json.loads(json.dumps(o))
            for g in o.get("geometry", []):
                g["boundaries"] = shift(g["boundaries"], len(doc["vertices"]))
            doc["CityObjects"][oid] = o
        doc["vertices"] += feature["vertices"]
    return doc


def resolved(doc):
    """The document's objects with every vertex index replaced by its coordinates."""
    def coords(b):
        return [coords(x) for x in b] if isinstance(b, list) else doc["vertices"][b]
    objects = json.loads(json.dumps(doc["CityObjects"]))
    for o in objects.values():
        for g in o.get("geometry", []):
            g["boundaries"] = coords(g["boundaries"])
    return objects


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--validate", help="only checks 1 and 2 of this enriched file (its Extension beside it)")
    ap.add_argument("--binary")
    ap.add_argument("--run")
    ap.add_argument("--city", help="the CityGML file the run was made from")
    ap.add_argument("--other-city", help="a city model that is not the run's")
    ap.add_argument("--schemas", required=True, help="data/schemas")
    ap.add_argument("--out")
    a = ap.parse_args()
    if a.validate:
        if a.validate.endswith(".jsonl"):
            doc = read_sequence(a.validate, a.schemas)
        else:
            with open(a.validate) as f:
                doc = json.load(f)
        with open(os.path.join(os.path.dirname(os.path.abspath(a.validate)), "citylangsplat.ext.json")) as f:
            validate(doc, json.load(f), a.schemas)
        print("PASS")
        return
    if not all((a.binary, a.run, a.city, a.other_city, a.out)):
        ap.error("--binary, --run, --city, --other-city and --out are needed without --validate")

    shutil.rmtree(a.out, ignore_errors=True)
    os.makedirs(a.out)
    out = os.path.join(a.out, "enriched.city.json")
    cmd = [a.binary, "enrich", a.run, "window", "--out", out]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        fail("%s exited %d: %s" % (" ".join(cmd), r.returncode, r.stderr))
    print(r.stderr.strip().splitlines()[-1])
    with open(out) as f:
        doc = json.load(f)
    with open(os.path.join(a.out, "citylangsplat.ext.json")) as f:
        ext = json.load(f)

    objects, vertices = validate(doc, ext, a.schemas)

    # 3. The geometry against the label maps' mesh and the CityGML file.
    scale = doc["transform"]["scale"]
    area = sum(polygon_area(poly, vertices, scale)
               for o in objects.values() for g in o.get("geometry", []) for poly in g["boundaries"])
    labels = os.path.join(a.run, "labels")
    mesh_area = mesh_ply_area(os.path.join(labels, "city_mesh.ply"))
    rel = abs(area - mesh_area) / mesh_area
    print("geometry: %.3f m2 of polygons (exterior minus holes) against %.3f m2 of the label maps' triangles: %.2e relative"
          % (area, mesh_area, rel))
    if rel > 1e-3:
        fail("the polygons do not cover the city model's surface")
    gml_windows = set()
    for el in ET.parse(a.city).iter():
        if el.tag.endswith("}Window"):
            gml_windows.update(v for k, v in el.attrib.items() if k.endswith("}id"))
    with open(os.path.join(labels, "objects.json")) as f:
        table = json.load(f)["objects"]
    window_surfaces = [s for o in objects.values() for g in o.get("geometry", [])
                       for s in g.get("semantics", {}).get("surfaces", []) if s["type"] == "Window"]
    print("windows: %d Window surfaces, %d bldg:Window in %s" % (len(window_surfaces), len(gml_windows), os.path.basename(a.city)))
    if len(window_surfaces) != len(gml_windows):
        fail("the Window surfaces are not the file's windows")

    # 4. The counts against object.npy: each row of the table with its openings.
    rows_of = {}
    for row in table:
        chain, r = [], row["index"]
        while r >= 0:
            chain.append(r)
            r = table[r]["parent"]
        for c in chain:
            rows_of.setdefault(c, set()).add(row["index"])
    views, pixels = {}, {}
    for entry in sorted(os.listdir(labels)):
        npy = os.path.join(labels, entry, "object.npy")
        if not os.path.exists(npy):
            continue
        counts = {}
        for v in read_int32_npy(npy):
            if v >= 0:
                counts[v] = counts.get(v, 0) + 1
        for obj in rows_of:
            n = sum(counts.get(i, 0) for i in rows_of[obj])
            if n:
                views[obj] = views.get(obj, 0) + 1
                pixels[obj] = pixels.get(obj, 0) + n
    # CityJSON's semantic surfaces carry no gml:id: compare the multiset of (views, pixels) per class.
    with open(os.path.join(labels, "objects.json")) as f:
        class_names = json.load(f)["classes"]
    mismatch = []
    for cls_name, type_name in (("window", "Window"), ("wall", "WallSurface"), ("roof", "RoofSurface")):
        class_id = [i for i, name in enumerate(class_names) if name == cls_name]
        expected = sorted((views.get(r["index"], 0), pixels.get(r["index"], 0)) for r in table if r["class"] in class_id)
        got = sorted((s["+clsViews"], s["+clsPixels"]) for o in objects.values() for g in o.get("geometry", [])
                     for s in g.get("semantics", {}).get("surfaces", []) if s["type"] == type_name)
        if expected != got:
            mismatch.append("%s: %s against object.npy's %s" % (type_name, got[:5], expected[:5]))
    building = next(o for o in objects.values() if o["type"] == "Building")["attributes"]["+citylangsplat"]
    b_row = next(r["index"] for r in table if r["level"] == 3 and r["parent"] < 0)
    if (building["views"], building["pixels"]) != (views.get(b_row, 0), pixels.get(b_row, 0)):
        mismatch.append("building: %s against object.npy's %s" % ((building["views"], building["pixels"]),
                                                                    (views.get(b_row, 0), pixels.get(b_row, 0))))
    print("views and pixels of every window, wall, roof and the building equal object.npy's counts: %s"
          % ("yes" if not mismatch else "no"))
    for m in mismatch:
        print("  " + m)
    if mismatch:
        fail("the counts are not the label maps'")

    # 5. The query's scores.
    def mean(values):
        return sum(values) / len(values) if values else float("nan")
    win = mean([s["+clsQuery_window"] for s in window_surfaces if "+clsQuery_window" in s])
    walls = mean([s["+clsQuery_window"] for o in objects.values() for g in o.get("geometry", [])
                  for s in g.get("semantics", {}).get("surfaces", []) if s["type"] == "WallSurface" and "+clsQuery_window" in s])
    best = sum(1 for s in window_surfaces if s.get("+clsBestClass") == "window")
    print("query 'window': mean %.3f on Window surfaces, %.3f on WallSurfaces; %d of %d windows' best class is window"
          % (win, walls, best, len(window_surfaces)))
    if not win > walls:
        fail("the windows do not answer 'window' better than the walls")

    # 7. `changes` on the same run.
    changes_out = os.path.join(a.out, "changes", "enriched.city.json")
    r = subprocess.run([a.binary, "changes", a.run, "--out", changes_out], capture_output=True, text=True)
    if r.returncode != 0:
        fail("changes exited %d: %s" % (r.returncode, r.stderr))
    print(r.stderr.strip().splitlines()[-1])
    with open(changes_out) as f:
        changed = json.load(f)
    with open(os.path.join(a.out, "changes", "citylangsplat.ext.json")) as f:
        validate(changed, json.load(f), a.schemas)
    with open(os.path.join(a.out, "changes", "changes.json")) as f:
        proposals = json.load(f)["proposals"]
    if proposals:
        fail("changes proposes %d openings on the exact model: %s" % (len(proposals), proposals[:2]))

    # 8. The same as CityJSONSeq: each line valid, and joined back the same objects on the same coordinates.
    seq_out = os.path.join(a.out, "seq", "enriched.city.jsonl")
    r = subprocess.run([a.binary, "enrich", a.run, "window", "--out", seq_out], capture_output=True, text=True)
    if r.returncode != 0:
        fail("enrich --out %s exited %d: %s" % (seq_out, r.returncode, r.stderr))
    joined = read_sequence(seq_out, a.schemas)
    validate(joined, ext, a.schemas)
    same = resolved(joined) == resolved(doc) and joined["transform"] == doc["transform"]
    print("CityJSONSeq joined back: the document's %d CityObjects on the same coordinates: %s"
          % (len(doc["CityObjects"]), "yes" if same else "no"))
    if not same:
        fail("the CityJSONSeq output is not the document")

    # 6. Bad input.
    bad_out = os.path.join(a.out, "bad")
    for args, status, named in (([os.path.join(a.out, "no_run")], 2, os.path.join(a.out, "no_run")),
                                ([a.run, "--out", os.path.join(bad_out, "x.txt")], 2, "x.txt"),
                                ([a.run, "--city", a.other_city, "--out", os.path.join(bad_out, "x.json")], 1, a.other_city)):
        r = subprocess.run([a.binary, "enrich"] + args, capture_output=True, text=True)
        message = r.stderr.strip().splitlines()[-1] if r.stderr.strip() else ""
        print("enrich %s: exit %d, %s" % (" ".join(args[1:]) or args[0], r.returncode, message[:160]))
        if r.returncode != status or named not in r.stderr or os.path.exists(bad_out):
            fail("expected exit %d naming %s and nothing written" % (status, named))
    print("PASS")


if __name__ == "__main__":
    main()
