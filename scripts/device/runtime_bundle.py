#!/usr/bin/env python3
"""The shared libraries that programs built here need on the device machine and that it lacks.

  runtime_bundle.py OUTDIR DEVICE_SONAMES ELF...
Walks DT_NEEDED from the given programs and libraries (which travel themselves). A library is left
out when the device has its soname (DEVICE_SONAMES: `ldconfig -p` of the device machine) or when it
is the device's LibTorch or CUDA; codec and GIS libraries that only OpenCV's video and exotic image
formats use become stubs (elf_stubs.py: functions return 0); every other one is copied, and its own
needs walked.
"""
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import elf_stubs  # noqa: E402

FROM_DEVICE = re.compile(r"^lib(torch|c10|cudart|nvrtc|cuda|cublas|cusparse|cufft|curand|cupti|nvToolsExt)")
STUB = re.compile(r"^lib(gdal|gdcm|av(codec|format|util|device|filter)|sw(scale|resample)|gst|"
                  r"dc1394|OpenNI|gphoto|raw1394|hdf5|tesseract|lept|vtk|opencv_dnn|x26|codec2|aom|dav1d|vpx|"
                  r"rsvg|poppler|jxl|heif|openjp2|spatialite|proj|geos|netcdf|cfitsio|xerces|arpack|blosc|"
                  r"armadillo|odbc|mysql|mariadb|pq|kml|qhull|fyba|ogdi)")


def needed(path):
    text = subprocess.run(["readelf", "-dW", path], capture_output=True, text=True, check=True).stdout
    return re.findall(r"\(NEEDED\)\s+Shared library: \[(.*)\]", text)


def local_paths():
    text = subprocess.run(["ldconfig", "-p"], capture_output=True, text=True, check=True).stdout
    paths = {}
    for line in text.splitlines():
        m = re.match(r"\s+(\S+) \(libc6,x86-64.*\) => (\S+)", line)
        if m and m.group(1) not in paths:
            paths[m.group(1)] = m.group(2)
    return paths


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    out, device_file, roots = sys.argv[1], sys.argv[2], sys.argv[3:]
    with open(device_file) as f:
        device = {m.group(1) for m in (re.match(r"\s+(\S+) \(", l) for l in f) if m}
    os.makedirs(out, exist_ok=True)
    paths = local_paths()
    own = {os.path.basename(r) for r in roots}  # the build's own libraries travel with it
    seen, todo, stubs, copied = set(own), list(roots), [], []
    while todo:
        for soname in needed(todo.pop()):
            if soname in seen or soname in device or FROM_DEVICE.match(soname):
                continue
            seen.add(soname)
            if soname not in paths:
                sys.exit(f"runtime_bundle: {soname} is neither on this machine nor on the device")
            if STUB.match(soname):
                stubs.append(paths[soname])
            else:
                shutil.copy(paths[soname], os.path.join(out, soname))  # follows the symlink
                copied.append(soname)
                todo.append(paths[soname])
    for lib in stubs:
        text = subprocess.run(["readelf", "-W", "--dyn-syms", lib], capture_output=True, text=True, check=True)
        elf_stubs.build(elf_stubs.soname_of(lib), elf_stubs.parse_dynsyms(text.stdout.splitlines()),
                        elf_stubs.version_definitions(lib), out)
    print(f"runtime_bundle: {len(copied)} libraries copied, {len(stubs)} stubs: {' '.join(sorted(copied))}")


if __name__ == "__main__":
    main()
