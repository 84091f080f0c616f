#!/usr/bin/python3
"""Writes a COLMAP text model (PINHOLE cameras) and its photos as an OPF 1.0 project (Pix4D's Open
Photogrammetry Format, the specification at github.com/Pix4D/opf-spec), for the test that `scene info`
and `train-rgb` take an OPF project whole. No complete public OPF project exists to test with: the
specification's examples are fragments of different projects (data/opf/README.md).

The OPF conventions, written here from the specification, independently of scene/opf.cpp:
- calibrated camera: `position` (the centre) and `orientation_deg` (omega, phi, kappa) with
  R = Rx(omega) Ry(phi) Rz(kappa) taking the image CS (x right, y up, z towards the viewer) to the world;
  COLMAP's R_w2c maps the world to (x right, y down, z forward), so R = R_w2c^T diag(1, -1, -1);
- perspective sensor: focal_length_px, principal_point_px from the image's top left corner;
- tie points: a glTF point cloud, here through a node matrix that swaps y and z (as the specification's
  example does), so the reader has to apply it.

    /usr/bin/python3 tests/scene/colmap_to_opf.py --colmap TXT_DIR --images IMAGES_DIR --out OPF_DIR
"""
import argparse
import json
import math
import os
import shutil
import struct
import sys


def quat_to_matrix(w, x, y, z):
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]


def omega_phi_kappa(r):
    """Angles (degrees) of r = Rx(omega) Ry(phi) Rz(kappa): r[0][2] = sin phi, r[1][2] = -sin omega cos phi,
    r[2][2] = cos omega cos phi, r[0][0] = cos phi cos kappa, r[0][1] = -cos phi sin kappa."""
    phi = math.asin(max(-1.0, min(1.0, r[0][2])))
    omega = math.atan2(-r[1][2], r[2][2])
    kappa = math.atan2(-r[0][1], r[0][0])
    return [math.degrees(a) for a in (omega, phi, kappa)]


def lines(path):
    return [l.split() for l in open(path) if l.strip() and not l.startswith("#")]


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--colmap", required=True, help="COLMAP text model (cameras.txt, images.txt, points3D.txt)")
    p.add_argument("--images", required=True)
    p.add_argument("--out", required=True)
    args = p.parse_args()
    os.makedirs(os.path.join(args.out, "images"), exist_ok=True)
    os.makedirs(os.path.join(args.out, "tracks"), exist_ok=True)

    cams = {}
    for c in lines(os.path.join(args.colmap, "cameras.txt")):
        if c[1] != "PINHOLE" or abs(float(c[4]) - float(c[5])) > 1e-9:
            sys.exit(f"colmap_to_opf: camera {c[0]} is {c[1]} with fx {c[4]}, fy {c[5]}: only PINHOLE with fx = fy")
        cams[c[0]] = {"size": [int(c[2]), int(c[3])], "f": float(c[4]), "pp": [float(c[6]), float(c[7])]}
    rows = lines(os.path.join(args.colmap, "images.txt"))
    images = [r for r in rows if len(r) == 10 and r[9].lower().endswith((".png", ".jpg", ".jpeg"))]

    sensors, calibrated_sensors, cameras, captures, calibrated = [], [], [], [], []
    for cam_id, c in cams.items():
        sensors.append({"id": int(cam_id), "image_size_px": c["size"]})
        calibrated_sensors.append({"id": int(cam_id), "internals": {
            "type": "perspective", "focal_length_px": c["f"], "principal_point_px": c["pp"],
            "radial_distortion": [0, 0, 0], "tangential_distortion": [0, 0]}})
    for k, r in enumerate(images):
        qw, qx, qy, qz, tx, ty, tz = (float(v) for v in r[1:8])
        rw2c = quat_to_matrix(qw, qx, qy, qz)
        centre = [-sum(rw2c[j][i] * t for j, t in enumerate((tx, ty, tz))) for i in range(3)]
        # R = R_w2c^T diag(1, -1, -1): element (i, col) = R_w2c[col][i] * (1, -1, -1)[col]
        r_opf = [[rw2c[col][i] * (1, -1, -1)[col] for col in range(3)] for i in range(3)]
        shutil.copyfile(os.path.join(args.images, r[9]), os.path.join(args.out, "images", r[9]))
        cameras.append({"id": k + 1, "uri": "images/" + r[9]})
        captures.append({"id": k + 1, "time": "2026-11-28T00:00:00Z", "rig_model_id": 1,
                         "cameras": [{"id": k + 1, "sensor_id": int(r[8])}]})
        calibrated.append({"id": k + 1, "sensor_id": int(r[8]), "position": centre,
                           "orientation_deg": omega_phi_kappa(r_opf)})

    rows = lines(os.path.join(args.colmap, "points3D.txt"))
    points = [[float(v) for v in r[1:4]] for r in rows]
    # Stored through a node matrix that maps (a, b, c) -> (a, -c, b): store (x, z, -y); then the colours
    # (COLOR_0, RGBA bytes: glTF aligns vertex attributes to 4 bytes).
    stored = b"".join(struct.pack("<3f", x, z, -y) for x, y, z in points)
    colours = b"".join(struct.pack("<4B", int(r[4]), int(r[5]), int(r[6]), 255) for r in rows)
    open(os.path.join(args.out, "tracks", "positions.bin"), "wb").write(stored + colours)

    def write(name, doc):
        with open(os.path.join(args.out, name), "w") as f:
            json.dump(doc, f, indent=1)

    write("camera_list.json", {"format": "application/opf-camera-list+json", "version": "1.0", "cameras": cameras})
    write("input_cameras.json", {"format": "application/opf-input-cameras+json", "version": "1.0",
                                 "sensors": sensors, "captures": captures})
    write("calibrated_cameras.json", {"format": "application/opf-calibrated-cameras+json", "version": "1.0",
                                      "sensors": calibrated_sensors, "cameras": calibrated})
    write("tracks/sparse.gltf", {
        "asset": {"version": "2.0"},
        "buffers": [{"uri": "positions.bin", "byteLength": len(stored) + len(colours)}],
        "bufferViews": [{"buffer": 0, "byteLength": len(stored)},
                        {"buffer": 0, "byteOffset": len(stored), "byteLength": len(colours)}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": len(points), "type": "VEC3"},
                      {"bufferView": 1, "componentType": 5121, "normalized": True, "count": len(points), "type": "VEC4"}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "COLOR_0": 1}, "mode": 0}]}],
        "nodes": [{"mesh": 0, "matrix": [1, 0, 0, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1]}],
        "scene": 0, "scenes": [{"nodes": [0]}]})

    # The synthetic scene's frame is a local one: an engineering CRS, as the specification's arbitrary example.
    write("scene_reference_frame.json", {
        "format": "application/opf-scene-reference-frame+json", "version": "1.0",
        "crs": {"definition": 'ENGINEERINGCRS["scene",ENGINEERINGDATUM["scene origin"],CS[Cartesian,3],'
                              'AXIS["x",east,ORDER[1]],AXIS["y",north,ORDER[2]],AXIS["z",up,ORDER[3]],LENGTHUNIT["metre",1.0]]'},
        "base_to_canonical": {"scale": [1, 1, 1], "shift": [0, 0, 0], "swap_xy": False}})

    def item(kind, resources):
        return {"id": kind, "type": kind, "resources": resources, "sources": []}

    write("project.opf", {"version": "1.0", "format": "application/opf-project+json", "name": "colmap_to_opf",
                          "items": [item("camera_list", [{"uri": "camera_list.json", "format": "application/opf-camera-list+json"}]),
                                    item("input_cameras", [{"uri": "input_cameras.json", "format": "application/opf-input-cameras+json"}]),
                                    item("calibration", [{"uri": "calibrated_cameras.json", "format": "application/opf-calibrated-cameras+json"},
                                                         {"uri": "tracks/sparse.gltf", "format": "model/gltf+json"},
                                                         {"uri": "tracks/positions.bin", "format": "application/gltf-buffer+bin"}]),
                                    item("scene_reference_frame", [{"uri": "scene_reference_frame.json",
                                                                    "format": "application/opf-scene-reference-frame+json"}])]})
    print(f"colmap_to_opf: {len(calibrated)} cameras, {len(points)} tie points -> {args.out}")


if __name__ == "__main__":
    main()
