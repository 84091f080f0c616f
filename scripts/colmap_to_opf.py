#!/usr/bin/env python3
"""Write an OPF 1.0 project (Pix4D's Open Photogrammetry Format) of a COLMAP text model with PINHOLE or
SIMPLE_PINHOLE cameras (square pixels): a way to check citylangsplat's OPF reader end to end on a scene
whose COLMAP form it reads too (e.g. a `synth` scene: `scene convert` it to text first). Written from the
specification's definitions, independently of the C++ reader: omega-phi-kappa R = Rx(o) Ry(p) Rz(k) from
the image CS (x right, y up, z backward) to the world, tie points as an OPF-glTF point cloud with a node
matrix holding their centroid.

    python3 scripts/colmap_to_opf.py SCENE_DIR/sparse/0 SCENE_DIR   # writes SCENE_DIR/project.opf and its files
"""
import json
import math
import os
import struct
import sys

from colmap_text import quat_to_matrix, rows


def main(model, out):
    cameras = {}
    for r in rows(os.path.join(model, "cameras.txt")):
        cam_id, kind, w, h, p = int(r[0]), r[1], int(r[2]), int(r[3]), [float(v) for v in r[4:]]
        if kind == "SIMPLE_PINHOLE":
            p = [p[0], p[0], p[1], p[2]]
        elif kind != "PINHOLE" or abs(p[0] - p[1]) > 1e-9 * p[0]:
            sys.exit(f"camera {cam_id}: {kind} with fx {p[0]} fy {p[1]}: only square-pixel pinholes")
        cameras[cam_id] = (w, h, p)
    lines = list(rows(os.path.join(model, "images.txt")))
    images = lines[0::2] if all(len(l) >= 10 for l in lines[0::2]) else lines  # every other line: its 2D points
    cam_list, calibrated, sensors = [], [], {}
    for r in images:
        if len(r) < 10:
            continue
        image_id, q, t, cam_id, name = int(r[0]), [float(v) for v in r[1:5]], [float(v) for v in r[5:8]], int(r[8]), r[9]
        w, h, p = cameras[cam_id]
        sensors[cam_id] = (w, h, p)
        rcv = quat_to_matrix(*q)                      # world -> camera, computer vision axes
        c = [-sum(rcv[k][i] * t[k] for k in range(3)) for i in range(3)]   # -R^T t
        # R (image CS -> world) = Rcv^T diag(1, -1, -1)
        R = [[rcv[0][i] * (1 if j == 0 else 0) + rcv[1][i] * (-1 if j == 1 else 0) + rcv[2][i] * (-1 if j == 2 else 0)
              for j in range(3)] for i in range(3)]
        phi = math.asin(max(-1.0, min(1.0, R[0][2])))
        omega = math.atan2(-R[1][2], R[2][2])
        kappa = math.atan2(-R[0][1], R[0][0])
        cam_list.append({"id": image_id, "uri": "../images/" + name})  # relative to the camera list
        calibrated.append({"id": image_id, "sensor_id": cam_id, "position": c,
                           "orientation_deg": [math.degrees(omega), math.degrees(phi), math.degrees(kappa)]})
    points = [([float(v) for v in r[1:4]], [int(v) for v in r[4:7]]) for r in rows(os.path.join(model, "points3D.txt"))]
    centre = [sum(p[0][k] for p in points) / max(1, len(points)) for k in range(3)]
    os.makedirs(os.path.join(out, "opf"), exist_ok=True)
    with open(os.path.join(out, "opf", "positions.bin"), "wb") as f:
        for xyz, _ in points:
            f.write(struct.pack("<3f", *[xyz[k] - centre[k] for k in range(3)]))
    with open(os.path.join(out, "opf", "colors.bin"), "wb") as f:
        for _, rgb in points:
            f.write(struct.pack("<3B", *rgb))
    n = len(points)
    gltf = {"asset": {"version": "2.0", "extensions": {"OPF_asset_version": {"version": "1.0"}}},
            "buffers": [{"uri": "positions.bin", "byteLength": 12 * n}, {"uri": "colors.bin", "byteLength": 3 * n}],
            "bufferViews": [{"buffer": 0, "byteLength": 12 * n}, {"buffer": 1, "byteLength": 3 * n}],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": n, "type": "VEC3"},
                          {"bufferView": 1, "componentType": 5121, "normalized": True, "count": n, "type": "VEC3"}],
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "COLOR_0": 1}, "mode": 0}]}],
            "nodes": [{"mesh": 0, "matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, centre[0], centre[1], centre[2], 1]}],
            "scene": 0, "scenes": [{"nodes": [0]}]}
    files = {
        "opf/camera_list.json": {"format": "application/opf-camera-list+json", "version": "1.0", "cameras": cam_list},
        "opf/input_cameras.json": {"format": "application/opf-input-cameras+json", "version": "1.0", "captures": [],
                                   "sensors": [{"id": i, "image_size_px": [w, h]} for i, (w, h, _) in sensors.items()]},
        "opf/calibrated_cameras.json": {
            "format": "application/opf-calibrated-cameras+json", "version": "1.0", "cameras": calibrated,
            "sensors": [{"id": i, "internals": {"type": "perspective", "focal_length_px": p[0], "principal_point_px": [p[2], p[3]],
                                                "radial_distortion": [0, 0, 0], "tangential_distortion": [0, 0]}}
                        for i, (_, _, p) in sensors.items()]},
        "opf/sparse.gltf": gltf,
        "opf/scene_reference_frame.json": {"format": "application/opf-scene-reference-frame+json", "version": "1.0",
                                           "base_to_canonical": {"scale": [1, 1, 1], "shift": [0, 0, 0], "swap_xy": False}},
    }
    for path, content in files.items():
        with open(os.path.join(out, path), "w") as f:
            json.dump(content, f, indent=1)

    def item(kind, *resources):
        return {"id": kind, "type": kind, "sources": [], "resources": [{"uri": u, "format": f} for u, f in resources]}
    project = {"version": "1.0", "format": "application/opf-project+json", "name": os.path.basename(os.path.abspath(out)),
               "generator": {"name": "citylangsplat scripts/colmap_to_opf.py", "version": "1"},
               "items": [item("camera_list", ("opf/camera_list.json", "application/opf-camera-list+json")),
                         item("input_cameras", ("opf/input_cameras.json", "application/opf-input-cameras+json")),
                         item("calibration", ("opf/calibrated_cameras.json", "application/opf-calibrated-cameras+json"),
                              ("opf/sparse.gltf", "model/gltf+json")),
                         item("scene_reference_frame",
                              ("opf/scene_reference_frame.json", "application/opf-scene-reference-frame+json"))]}
    with open(os.path.join(out, "project.opf"), "w") as f:
        json.dump(project, f, indent=1)
    print(f"wrote {os.path.join(out, 'project.opf')}: {len(calibrated)} cameras, {n} tie points")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
