#!/usr/bin/python3
"""`citylangsplat export` on a trained run, checked by others than the exporter:

1. Khronos' glTF-Validator (npm gltf-validator, run by node) reports no error, except the one it cannot
   help: its release (2.0.0-dev.3.10, 2024) predates KHR_gaussian_splatting and calls every
   `KHR_gaussian_splatting:` attribute name invalid (MESH_PRIMITIVE_INVALID_ATTRIBUTE; glTF-Validator
   issue #252, open). Those are counted and printed; any other error fails.
2. The splats read back from the GLB's bytes equal the model's PLY (read here, by the 3DGS PLY layout):
   positions, unit quaternions in (x, y, z, w), exp(scale), sigmoid(opacity), the SH coefficients.
3. The georeference, against the CityGML file itself: the splats whose level-1 feature ID is a
   bldg:Window, placed by the node's matrix and the origin in the asset's extras (glTF y up back to
   z up), lie within --tolerance metres of that window's polygons in the file's coordinates.
4. The property table's ids are the city model's: every Window row's id is a gml:id of a bldg:Window,
   its building the file's bldg:Building; the window splats score higher for the query "window".
6. `--format 3dtiles`: the tileset's box holds every splat centre (the PLY through the content's node
   matrix, glTF's y up turned to z up as 3D Tiles does), and its transform is a frame on the globe:
   orthogonal columns of length 1 within 0.1 % (a projection's scale), the up column pointing away from
   the Earth's centre, the origin 6,350-6,400 km from it.
5. `--compress spz`: the payload decoded by the SPZ decoder CesiumJS uses (npm @spz-loader/core, in
   glTF's LUF axes) equals the PLY within SPZ version 2's quantisation steps (positions 2^-bits,
   log-scales 1/16, quaternion and alpha 1/255, colour 1/(0.15 * 255) of the DC, SH 1/128 and buckets
   of 8/128 and 16/128),
   which catches a flipped axis or SH sign wherever a value exceeds its step.

    /usr/bin/python3 tests/export/gltf_check.py --binary build/citylangsplat --run RUN \\
        --city data/citygml/fzk-haus/fzk_haus_lod3_v2.gml --validator build/web/node_modules/gltf-validator \\
        --out /tmp/export
Exit status: 0 pass, 1 fail, 77 skipped (no node, or the npm packages are missing).
"""
import argparse
import json
import math
import os
import shutil
import struct
import subprocess
import sys
import xml.etree.ElementTree as ET

GML = "{http://www.opengis.net/gml}"
PLY_TYPES = {"float": "f", "float32": "f", "double": "d", "int": "i", "int32": "i", "uint": "I", "uchar": "B",
             "char": "b", "short": "h", "ushort": "H"}


def read_ply(path):
    """The vertex element of a binary little-endian PLY as {property: list}."""
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    count, props = 0, []
    for line in data[:end].decode().splitlines():
        w = line.split()
        if w[:2] == ["element", "vertex"]:
            count = int(w[2])
        elif w[0] == "property":
            props.append((w[2], PLY_TYPES[w[1]]))
    fmt = "<" + "".join(t for _, t in props)
    size = struct.calcsize(fmt)
    rows = [struct.unpack_from(fmt, data, end + i * size) for i in range(count)]
    return {name: [r[k] for r in rows] for k, (name, _) in enumerate(props)}


def read_glb(path):
    data = open(path, "rb").read()
    magic, version, length = struct.unpack_from("<III", data, 0)
    assert magic == 0x46546C67 and version == 2 and length == len(data), "not a GLB 2.0"
    json_len, _ = struct.unpack_from("<II", data, 12)
    doc = json.loads(data[20:20 + json_len])
    bin_len, _ = struct.unpack_from("<II", data, 20 + json_len)
    return doc, data[28 + json_len:28 + json_len + bin_len]


def accessor(doc, binary, index):
    acc = doc["accessors"][index]
    view = doc["bufferViews"][acc["bufferView"]]
    n = {"SCALAR": 1, "VEC3": 3, "VEC4": 4}[acc["type"]]
    fmt = {5126: "f", 5121: "B"}[acc["componentType"]]
    values = struct.unpack_from("<%d%s" % (acc["count"] * n, fmt), binary, view["byteOffset"])
    return [values[i * n:(i + 1) * n] for i in range(acc["count"])]


def strings(doc, binary, prop):
    values, offsets = (doc["bufferViews"][prop[k]] for k in ("values", "stringOffsets"))
    raw = binary[values["byteOffset"]:values["byteOffset"] + values["byteLength"]]
    o = struct.unpack_from("<%dI" % (offsets["byteLength"] // 4), binary, offsets["byteOffset"])
    return [raw[o[k]:o[k + 1]].decode() for k in range(len(o) - 1)]


def windows_of(city):
    """gml:id -> list of polygons (lists of xyz) of every bldg:Window, and the bldg:Building ids."""
    windows, buildings = {}, set()
    for e in ET.parse(city).iter():
        name = e.tag.rsplit("}", 1)[-1]
        if name == "Building" and e.get(GML + "id"):
            buildings.add(e.get(GML + "id"))
        if name == "Window" and e.get(GML + "id"):
            polygons = []
            for ring in e.iter():
                if ring.tag.rsplit("}", 1)[-1] not in ("LinearRing", "Ring"):
                    continue
                v = [float(x) for pos in ring.iter() if pos.tag in (GML + "posList", GML + "pos") for x in pos.text.split()]
                polygons.append([v[i:i + 3] for i in range(0, len(v), 3)])
            windows[e.get(GML + "id")] = polygons
    return windows, buildings


def distance_to_polygon_box(p, polygons):
    """Distance from p to the axis-aligned box of the polygons (a window is a planar rectangle)."""
    pts = [q for poly in polygons for q in poly]
    lo = [min(q[a] for q in pts) for a in range(3)]
    hi = [max(q[a] for q in pts) for a in range(3)]
    return math.sqrt(sum(max(lo[a] - p[a], 0, p[a] - hi[a]) ** 2 for a in range(3)))


# The decoder's Node entry believes it runs in a browser once process.type says "renderer" (its Node
# path needs a bundler); the wasm is inlined.
DECODE_SPZ = """
process.type = 'renderer';
const { loadSpz } = require(process.argv[1]);
const fs = require('fs');
const glb = fs.readFileSync(process.argv[2]);
const jl = glb.readUInt32LE(12);
const doc = JSON.parse(glb.subarray(20, 20 + jl).toString());
const bin = glb.subarray(28 + jl);
const ext = doc.meshes[0].primitives[0].extensions.KHR_gaussian_splatting.extensions.KHR_gaussian_splatting_compression_spz_2;
const view = doc.bufferViews[ext.bufferView];
loadSpz(new Uint8Array(bin.subarray(view.byteOffset, view.byteOffset + view.byteLength)),
        { unpackOptions: { coordinateSystem: 'LUF' } }).then((g) => {
  const out = {};
  for (const k of ['positions', 'scales', 'rotations', 'alphas', 'colors', 'sh']) out[k] = Array.from(g[k]);
  out.numPoints = g.numPoints; out.shDegree = g.shDegree;
  fs.writeFileSync(process.argv[3], JSON.stringify(out));
});
"""


def check_spz(args, ply, spz_loader):
    glb = os.path.join(args.out, "fzk_spz.glb")
    subprocess.run([args.binary, "export", args.run, "--compress", "spz", "--out", glb], check=True)
    decoded = os.path.join(args.out, "spz_decoded.json")
    subprocess.run(["node", "-e", DECODE_SPZ, os.path.abspath(spz_loader), glb, decoded], check=True)
    g = json.load(open(decoded))
    doc, _ = read_glb(glb)
    n, rest = len(ply["x"]), sum(1 for k in ply if k.startswith("f_rest_")) // 3
    extent = max(abs(v) for a in "xyz" for v in ply[a])
    bits = 12
    while bits > 0 and extent * 2 ** bits >= 2 ** 23 - 1:
        bits -= 1
    c0 = 0.28209479177387814
    worst = {"position": 0.0, "log-scale": 0.0, "rotation": 0.0, "alpha": 0.0, "colour": 0.0, "sh": 0.0}
    steps = {"position": 0.5 / 2 ** bits + 1e-4 * extent / 2 ** 10, "log-scale": 0.5 / 16 + 1e-5, "rotation": 1.5 / 127.5,
             "alpha": 0.5 / 255 + 1e-6, "colour": c0 * 0.5 / (0.15 * 255) + 2e-4, "sh": 0.0}
    # The decoder's colour is 0.5 + k * DC with its own constant k, 1.5e-4 off C0 * DC at the extremes: + 2e-4.
    tested_signs = 0
    for i in range(n):
        for a in range(3):
            worst["position"] = max(worst["position"], abs(g["positions"][3 * i + a] - ply["xyz"[a]][i]))
            worst["log-scale"] = max(worst["log-scale"], abs(math.log(g["scales"][3 * i + a]) - ply[f"scale_{a}"][i]))
            dc = 0.5 + c0 * ply[f"f_dc_{a}"][i]
            if 0 < dc < 1:  # the byte clamps outside
                worst["colour"] = max(worst["colour"], abs(g["colors"][3 * i + a] - dc))
        q = [ply[f"rot_{k}"][i] for k in (1, 2, 3, 0)]
        norm = math.sqrt(sum(c * c for c in q)) * (1 if q[3] >= 0 else -1)
        worst["rotation"] = max(worst["rotation"], max(abs(g["rotations"][4 * i + k] - q[k] / norm) for k in range(3)))
        worst["alpha"] = max(worst["alpha"], abs(g["alphas"][i] - 1 / (1 + math.exp(-ply["opacity"][i]))))
        for k in range(rest):
            step = (0.5 + (4 if k < 3 else 8)) / 128 + 1e-6  # 8 bits, then the nearest bucket centre
            for c in range(3):
                v = ply[f"f_rest_{c * rest + k}"][i]
                if abs(v) < 1 - step:  # SPZ clamps to [-1, 1]
                    worst["sh"] = max(worst["sh"], abs(g["sh"][(i * rest + k) * 3 + c] - v) - step)
                    tested_signs += abs(v) > step
    ok = all(worst[k] <= steps[k] for k in worst)
    print(f"SPZ: {os.path.getsize(glb)} bytes ({g['numPoints']} points, SH degree {g['shDegree']}, {bits} fractional bits), "
          f"decoded by @spz-loader/core; largest differences to the PLY: " +
          ", ".join(f"{k} {worst[k]:.2e} (step {steps[k]:.2e})" if k != "sh" else f"sh {worst[k]:+.2e} beyond its step"
                    for k in worst) + f"; {tested_signs} SH values larger than their step")
    required = doc.get("extensionsRequired", [])
    failures = []
    if g["numPoints"] != n or not ok:
        failures.append("the SPZ payload does not decode to the PLY within its quantisation")
    if "KHR_gaussian_splatting_compression_spz_2" not in required or "KHR_gaussian_splatting" not in required:
        failures.append(f"extensionsRequired {required} lacks the two extensions CesiumJS looks for")
    return failures


def check_tileset(args, ply):
    out = os.path.join(args.out, "tiles")
    subprocess.run([args.binary, "export", args.run, "--format", "3dtiles", "--out", out], check=True)
    tileset = json.load(open(os.path.join(out, "tileset.json")))
    root = tileset["root"]
    doc, _ = read_glb(os.path.join(out, root["content"]["uri"]))
    m, box, t = doc["nodes"][0]["matrix"], root["boundingVolume"]["box"], root["transform"]
    outside = 0
    for i in range(len(ply["x"])):
        p = [ply["x"][i], ply["y"][i], ply["z"][i], 1]
        g = [sum(m[4 * c + r] * p[c] for c in range(4)) for r in range(3)]
        local = [g[0], -g[2], g[1]]  # y up -> z up
        outside += any(abs(local[a] - box[a]) > box[3 + 4 * a] + 1e-6 for a in range(3))
    cols = [t[4 * c:4 * c + 3] for c in range(3)]
    dot = lambda a, b: sum(x * y for x, y in zip(a, b))
    lengths = [math.sqrt(dot(c, c)) for c in cols]
    skew = max(abs(dot(cols[a], cols[b])) / (lengths[a] * lengths[b]) for a, b in ((0, 1), (0, 2), (1, 2)))
    centre = t[12:15]
    radius = math.sqrt(dot(centre, centre))
    up = dot(cols[2], centre) / (lengths[2] * radius)
    print(f"3D Tiles: {outside} of {len(ply['x'])} splat centres outside the root box; transform columns of length "
          f"{', '.join(f'{v:.5f}' for v in lengths)}, largest cosine between two {skew:.1e}, up . radial {up:.6f}, "
          f"origin {radius / 1000:.1f} km from the Earth's centre")
    failures = []
    if outside or max(abs(v - 1) for v in lengths) > 1e-3 or skew > 1e-3 or up < 0.999 or not 6.35e6 < radius < 6.4e6:
        failures.append("the tileset's box or transform is wrong")
    return failures


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--binary", required=True)
    p.add_argument("--run", required=True, help="a `run` output with a CityLangSplat language model")
    p.add_argument("--city", required=True, help="the CityGML file of the run")
    p.add_argument("--node-modules", required=True, help="npm's node_modules with gltf-validator and @spz-loader/core")
    # Provenance gives a splat its window when its centre lies within 2 % of the view's depth of the
    # window's surface: 0.3-0.5 m at the sample run's 15-25 m.
    p.add_argument("--tolerance", type=float, default=0.5, help="metres from a window's box (default 0.5)")
    p.add_argument("--share", type=float, default=0.9, help="share of window splats within it (default 0.9)")
    p.add_argument("--out", required=True)
    args = p.parse_args()
    validator = os.path.join(args.node_modules, "gltf-validator")
    spz_loader = os.path.join(args.node_modules, "@spz-loader", "core")
    if not shutil.which("node") or not all(os.path.exists(os.path.join(d, "package.json")) for d in (validator, spz_loader)):
        print("SKIP: node, gltf-validator or @spz-loader/core is missing (scripts/install_web.sh)")
        return 77
    os.makedirs(args.out, exist_ok=True)
    glb = os.path.join(args.out, "fzk.glb")
    subprocess.run([args.binary, "export", args.run, "window", "--out", glb], check=True)
    failures = []

    # 1. Khronos' validator.
    script = ("const v = require(process.argv[1]); const fs = require('fs');"
              "v.validateBytes(new Uint8Array(fs.readFileSync(process.argv[2])))"
              ".then((r) => console.log(JSON.stringify(r.issues)));")
    issues = json.loads(subprocess.run(["node", "-e", script, os.path.abspath(validator), glb], check=True,
                                       capture_output=True, text=True).stdout)
    errors = [m for m in issues["messages"] if m["severity"] == 0]
    known = [m for m in errors if m["code"] == "MESH_PRIMITIVE_INVALID_ATTRIBUTE"
             and m["pointer"].rsplit("/", 1)[-1].startswith("KHR_gaussian_splatting:")]
    others = [m for m in errors if m not in known]
    print(f"glTF-Validator: {issues['numErrors']} errors, {issues['numWarnings']} warnings, {issues['numInfos']} infos, "
          f"{issues['numHints']} hints; {len(known)} errors are KHR_gaussian_splatting attribute names it predates "
          f"(glTF-Validator #252); {len(others)} other errors")
    for m in issues["messages"]:
        if m["severity"] <= 1 and m not in known:
            print(f"  {m['code']} {m['pointer']}: {m['message']}")
    if others:
        failures.append(f"{len(others)} validator errors besides the extension's attribute names")

    # 2. The splats against the PLY.
    doc, binary = read_glb(glb)
    prim = doc["meshes"][0]["primitives"][0]
    attr = lambda name: accessor(doc, binary, prim["attributes"][name])
    ply = read_ply(os.path.join(args.run, "language", "citylangsplat", "point_cloud.ply"))
    n = len(ply["x"])
    pos, rot, scale, opacity = (attr("POSITION"), attr("KHR_gaussian_splatting:ROTATION"),
                                attr("KHR_gaussian_splatting:SCALE"), attr("KHR_gaussian_splatting:OPACITY"))
    dc = attr("KHR_gaussian_splatting:SH_DEGREE_0_COEF_0")
    rest = sum(1 for k in ply if k.startswith("f_rest_")) // 3
    worst = 0.0
    for i in range(n):
        q = [ply[f"rot_{k}"][i] for k in range(4)]
        qn = math.sqrt(sum(c * c for c in q))
        expected = ([ply[a][i] for a in "xyz"], [q[1] / qn, q[2] / qn, q[3] / qn, q[0] / qn],
                    [math.exp(ply[f"scale_{k}"][i]) for k in range(3)], [1 / (1 + math.exp(-ply["opacity"][i]))],
                    [ply[f"f_dc_{c}"][i] for c in range(3)])
        got = (pos[i], rot[i], scale[i], opacity[i], dc[i])
        for e, g in zip(expected, got):
            worst = max(worst, max(abs(a - b) / max(1.0, abs(a)) for a, b in zip(e, g)))
    for k in range(rest):  # f_rest is channel-major: coefficient k of channel c at c * rest + k
        degree = 1 if k < 3 else (2 if k < 8 else 3)
        coef = attr(f"KHR_gaussian_splatting:SH_DEGREE_{degree}_COEF_{k - (0, 3, 8)[degree - 1]}")
        for i in range(n):
            worst = max(worst, max(abs(coef[i][c] - ply[f"f_rest_{c * rest + k}"][i]) for c in range(3)))
    print(f"{n} splats, SH degree {int(math.sqrt(rest + 1)) - 1}: largest relative difference to the PLY {worst:.2e}")
    if worst > 1e-6:
        failures.append(f"the GLB's splats differ from the PLY by {worst}")

    # 3. and 4. The window splats in the city model's coordinates, and the table's ids.
    windows, buildings = windows_of(args.city)
    meta = doc["extensions"]["EXT_structural_metadata"]
    table = meta["propertyTables"][0]["properties"]
    ids, classes, owners = (strings(doc, binary, table[k]) for k in ("id", "class", "building"))
    window_rows = {r for r, c in enumerate(classes) if c == "window"}
    not_in_file = [ids[r] for r in window_rows if ids[r] not in windows]
    bad_owner = {owners[r] for r in window_rows} - buildings
    print(f"property table: {len(ids)} city objects, {len(window_rows)} windows "
          f"({len(window_rows) - len(not_in_file)} are bldg:Window gml:ids of {os.path.basename(args.city)}), "
          f"buildings {sorted({owners[r] for r in window_rows})}")
    if not window_rows or not_in_file or bad_owner:
        failures.append(f"window rows whose id is no bldg:Window: {not_in_file[:5]}; buildings not in the file: {bad_owner}")

    extras = doc["asset"]["extras"]["citylangsplat"]
    m = doc["nodes"][0]["matrix"]
    origin = extras["origin"]
    level1 = [int(f[0]) for f in attr("_FEATURE_ID_0")]
    score = [s[0] for s in attr("_SCORE_0")]
    near, total, dists = 0, 0, []
    for i in range(n):
        r = level1[i]
        if r not in window_rows:
            continue
        g = [sum(m[4 * c + row] * (list(pos[i]) + [1])[c] for c in range(4)) for row in range(3)]
        crs = [g[0] + origin[0], -g[2] + origin[1], g[1] + origin[2]]  # glTF (E, U, -N) back to (E, N, U)
        d = distance_to_polygon_box(crs, windows[ids[r]])
        dists.append(d)
        near += d <= args.tolerance
        total += 1
    dists.sort()
    share = near / max(total, 1)
    print(f"georeference: {near} of {total} window splats ({100 * share:.1f}%) within {args.tolerance} m of their "
          f"window in {extras['crs'] or 'the file'} coordinates (median {dists[len(dists) // 2] if dists else float('nan'):.3f} m), "
          f"origin {origin}")
    if total == 0 or share < args.share:
        failures.append(f"{100 * share:.1f}% of the window splats lie within {args.tolerance} m of their window")
    on = [score[i] for i in range(n) if level1[i] in window_rows]
    off = [score[i] for i in range(n) if level1[i] not in window_rows]
    mean = lambda v: sum(v) / max(len(v), 1)
    print(f"query 'window': mean score {mean(on):.3f} on window splats, {mean(off):.3f} on the others")
    if not on or mean(on) <= mean(off):
        failures.append("window splats do not score higher for 'window'")

    failures += check_spz(args, ply, spz_loader)
    failures += check_tileset(args, ply)

    for f in failures:
        print(f"FAIL: {f}")
    if not failures:
        print("PASS")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
