#!/usr/bin/env python3
"""Stand-in shared libraries: same soname, same dynamic symbols (name, version, type, binding, size),
no code: every function returns 0 (a null pointer, false, a failure code). Two uses in the GPU
build (scripts/device/README.md):

  elf_stubs.py from-dump SYMS OUTDIR
      SYMS holds `readelf -W --dyn-syms` of libraries elsewhere, each block headed `== path/NAME.so`:
      link-time stand-ins for the device's CUDA LibTorch, which this machine does not have.
  elf_stubs.py from-lib OUTDIR LIB...
      stand-ins for libraries of this machine that the device machine lacks and the GPU checks do not
      need (codecs and GIS formats behind OpenCV's image and video modules), so that what travels
      stays small. OpenCV registers GDAL when it first reads an image (GDALAllRegister); with the
      stub that does nothing, and a GDAL-only format then fails to open, as a missing codec does.
"""
import os
import re
import subprocess
import sys

SYMBOL = re.compile(r"^\s*\d+:\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)")


def parse_dynsyms(lines):
    """(name, version or None, default version?, type, binding, size) of each defined symbol."""
    out = []
    for line in lines:
        m = SYMBOL.match(line)
        if not m or m.group(6) == "UND" or m.group(3) in ("SECTION", "FILE"):
            continue
        size = int(m.group(2), 0)
        full = m.group(7)
        name, version, default = full, None, True
        if "@@" in full:
            name, version = full.split("@@", 1)
        elif "@" in full:
            name, version = full.split("@", 1)
            default = False
        if m.group(6) == "ABS":  # a version node's own symbol
            continue
        out.append((name, version, default, m.group(3), m.group(4), size))
    return out


def soname_of(path):
    text = subprocess.run(["readelf", "-dW", path], capture_output=True, text=True, check=True).stdout
    m = re.search(r"\(SONAME\)\s+Library soname: \[(.*)\]", text)
    return m.group(1) if m else os.path.basename(path)


def version_definitions(path):
    """Version nodes (name, parent) in DT_VERDEF order, the file's own (soname) node first."""
    text = subprocess.run(["readelf", "-VW", path], capture_output=True, text=True, check=True).stdout
    nodes, in_def = [], False
    for line in text.splitlines():
        if line.startswith("Version definition section"):
            in_def = True
            continue
        if line.startswith("Version needs section") or line.startswith("Version symbols section"):
            in_def = False
        if in_def:
            m = re.search(r"Flags: (\S+)\s+Index: \d+\s+Cnt: \d+\s+Name: (\S+)", line)
            if m and m.group(1) != "BASE":
                nodes.append(m.group(2))
    return nodes


def assembly(symbols):
    lines = []
    for i, (name, version, default, kind, bind, size) in enumerate(symbols):
        label = f'"{name}"' if version is None else f"__stub_{i}"
        if kind == "TLS":
            lines += ['.section .tbss,"awT",@nobits', f".type {label}, @tls_object"]
        elif kind in ("FUNC", "IFUNC"):
            lines += [".text", f".type {label}, @function"]
        else:
            t = "@gnu_unique_object" if bind == "UNIQUE" else "@object"
            lines += [".data", f".type {label}, {t}"]
        lines.append((".weak " if bind == "WEAK" else ".globl ") + label)
        if kind in ("FUNC", "IFUNC"):
            lines += [f"{label}: xorl %eax, %eax", "ret", f".size {label}, 3"]
        else:
            lines += [f"{label}: .zero {max(size, 1)}", f".size {label}, {size}"]
        if version is not None:
            lines.append(f'.symver {label}, "{name}{"@@" if default else "@"}{version}"')
    return "\n".join(lines) + "\n"


def build(soname, symbols, versions, outdir):
    base = os.path.join(outdir, soname)
    with open(base + ".s", "w") as f:
        f.write(assembly(symbols))
    cmd = ["gcc", "-shared", "-nostdlib", "-o", base, base + ".s", "-Wl,-soname," + soname]
    for v in sorted({s[1] for s in symbols if s[1]} - set(versions)):
        versions.append(v)
    if versions:
        with open(base + ".map", "w") as f:
            f.write("".join(f"{v} {{ {'local: __stub_*;' if k == 0 else ''} }};\n" for k, v in enumerate(versions)))
        cmd.append("-Wl,--version-script=" + base + ".map")
        cmd.append("-Wl,--undefined-version")
    subprocess.run(cmd, check=True)
    for ext in (".s", ".map"):
        if os.path.exists(base + ext):
            os.remove(base + ext)
    print(f"{soname}: {len(symbols)} symbols, {len(versions)} versions")


def main():
    if len(sys.argv) >= 4 and sys.argv[1] == "from-dump":
        blocks, current = {}, None
        with open(sys.argv[2]) as f:
            for line in f:
                if line.startswith("== "):
                    current = os.path.basename(line[3:].strip())
                    blocks[current] = []
                elif current:
                    blocks[current].append(line)
        os.makedirs(sys.argv[3], exist_ok=True)
        for soname, lines in blocks.items():
            build(soname, parse_dynsyms(lines), [], sys.argv[3])
    elif len(sys.argv) >= 4 and sys.argv[1] == "from-lib":
        os.makedirs(sys.argv[2], exist_ok=True)
        for lib in sys.argv[3:]:
            text = subprocess.run(["readelf", "-W", "--dyn-syms", lib], capture_output=True, text=True, check=True)
            build(soname_of(lib), parse_dynsyms(text.stdout.splitlines()), version_definitions(lib), sys.argv[2])
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
