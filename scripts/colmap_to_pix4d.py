#!/usr/bin/env python3
"""Write a PIX4Dmapper project layout of a COLMAP text model whose frame is a CRS less an offset (a `synth`
scene: its city/transform.json is such a translation): the calibrated cameras, PROJECT_offset.xyz,
PROJECT_wkt.prj and the sparse points as the densified cloud in LAS 1.2 (point format 2, in the CRS, with
colour). A way to check citylangsplat's PIX4Dmapper reading and `georef --from frame` end to end, written from
Pix4D's and ASPRS's definitions independently of the C++ readers.

    python3 scripts/colmap_to_pix4d.py SCENE/sparse/0 SCENE/images OFFSET_X OFFSET_Y OFFSET_Z CRS OUT [DX DY DZ]

OFFSET is the true offset (the model's frame = CRS - OFFSET); DX DY DZ (default 0) are added to the offset
written into PROJECT_offset.xyz and to the cloud, as a project georeferenced by a drone's GPS is metres off
(everything it places in the CRS is off by the same amount). CRS goes into
PROJECT_wkt.prj as given (e.g. EPSG:25832). The photos are linked into OUT/images.
"""
import math
import os
import struct
import sys

from colmap_text import quat_to_matrix, rows


def main(argv):
    if len(argv) not in (8, 11):
        sys.exit(__doc__)
    model, images, crs, out = argv[1], argv[2], argv[6], argv[7]
    offset = [float(v) for v in argv[3:6]]
    error = [float(v) for v in argv[8:11]] if len(argv) == 11 else [0.0, 0.0, 0.0]
    cameras = {}
    for r in rows(os.path.join(model, "cameras.txt")):
        if r[1] not in ("PINHOLE", "SIMPLE_PINHOLE"):
            sys.exit(f"camera {r[0]}: {r[1]} is not taken (PINHOLE or SIMPLE_PINHOLE)")
        p = [float(v) for v in r[4:]]
        f, cx, cy = (p[0], p[2], p[3]) if r[1] == "PINHOLE" else (p[0], p[1], p[2])
        cameras[r[0]] = (int(r[2]), int(r[3]), f, cx, cy)
    params = os.path.join(out, "1_initial", "params")
    clouds = os.path.join(out, "2_densification", "point_cloud")
    os.makedirs(params, exist_ok=True)
    os.makedirs(clouds, exist_ok=True)
    lines = ["fileName imageWidth imageHeight", "camera matrix K [3x3]", "radial distortion [3x1]",
             "tangential distortion [2x1]", "camera position t [3x1]", "camera rotation R [3x3]",
             "camera model m = K [R|-Rt] X", ""]
    image_rows = list(rows(os.path.join(model, "images.txt")))
    for r in image_rows[::2]:  # the second line of each image holds its 2D points
        q, t, cam, name = [float(v) for v in r[1:5]], [float(v) for v in r[5:8]], r[8], r[9]
        R = quat_to_matrix(*q)
        C = [-sum(R[k][i] * t[k] for k in range(3)) for i in range(3)]  # -R^T t
        w, h, f, cx, cy = cameras[cam]
        lines += [f"{name} {w} {h}", f"{f!r} 0 {cx!r}", f"0 {f!r} {cy!r}", "0 0 1", "0 0 0", "0 0",
                  " ".join(repr(c) for c in C)] + [" ".join(repr(v) for v in row) for row in R]
    project = os.path.basename(os.path.normpath(out))
    with open(os.path.join(params, f"{project}_calibrated_camera_parameters.txt"), "w") as f:
        f.write("\n".join(lines) + "\n")
    with open(os.path.join(params, f"{project}_offset.xyz"), "w") as f:
        f.write(" ".join(f"{o + e:.3f}" for o, e in zip(offset, error)) + "\n")
    with open(os.path.join(params, f"{project}_wkt.prj"), "w") as f:
        f.write(crs + "\n")

    # LAS 1.2, point format 2 (26 bytes: X Y Z int32, intensity, flags, class, angle, user, source, R G B
    # uint16), 1 mm steps about a header offset near the points (ASPRS LAS 1.2, tables 3 and 6).
    points = [([float(v) for v in r[1:4]], [int(v) for v in r[4:7]]) for r in rows(os.path.join(model, "points3D.txt"))]
    # The cloud in the CRS as the project believes it: with the same error as its offset.
    xyz = [[p[k] + offset[k] + error[k] for k in range(3)] for p, _ in points]
    base = [math.floor(min(p[k] for p in xyz)) for k in range(3)]
    scale = 0.001
    header = bytearray(227)
    header[0:4] = b"LASF"
    header[24], header[25] = 1, 2
    header[26:58] = b"citylangsplat colmap_to_pix4d".ljust(32, b"\0")
    struct.pack_into("<HIIBHI", header, 94, 227, 227, 0, 2, 26, len(xyz))
    struct.pack_into("<3d3d", header, 131, scale, scale, scale, *base)
    lo = [min(p[k] for p in xyz) for k in range(3)]
    hi = [max(p[k] for p in xyz) for k in range(3)]
    struct.pack_into("<6d", header, 179, hi[0], lo[0], hi[1], lo[1], hi[2], lo[2])
    body = bytearray()
    for p, (_, rgb) in zip(xyz, points):
        body += struct.pack("<3iHBBbBH3H", *(round((p[k] - base[k]) / scale) for k in range(3)), 0, 0x09, 1, 0, 0, 0,
                            *(257 * c for c in rgb))
    with open(os.path.join(clouds, f"{project}_group1_densified_point_cloud.las"), "wb") as f:
        f.write(bytes(header) + bytes(body))
    link = os.path.join(out, "images")
    if not os.path.exists(link):
        os.symlink(os.path.abspath(images), link)
    print(f"wrote {out}: {len(image_rows) // 2} cameras, {len(xyz)} points, offset {offset} + {error}")


if __name__ == "__main__":
    main(sys.argv)
