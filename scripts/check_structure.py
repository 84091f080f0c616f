#!/usr/bin/env python3
"""The code against the structure docs/development.md describes (run by ctest as `structure`).

1. Layers: every module under src/ is in the table of docs/development.md ("## Layers"), and each of
   its #include lines names a header of its own module or of a module on a lower floor: no include
   runs up or sideways, so there is no cycle.
2. The two libraries: the table's "library" column agrees with CMakeLists.txt's CLS_TORCH_DIRS, and
   no module of `cls` includes LibTorch (<torch/...>, <ATen/...>, <c10/...>) or a module of
   `cls_torch`.
3. One layout: the paths of a run directory, a language model directory and a scene's extra files
   are spelled in src/core/run_layout.h only (a few other modules' own layouts are listed below, each
   with its reason).

Hand-written (a few regular expressions over the sources): no Debian package checks include layers
against a document. Exits 1 with one line per finding, 0 when the code agrees.
"""
import os
import re
import sys

# The checkout (argument 1: another one, e.g. an older commit's worktree to compare with).
ROOT = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SRC = os.path.join(ROOT, "src")
# The table of layers: this checkout's, or (for an older one that has none) this script's.
LAYERS_DOC = os.path.join(ROOT, "docs", "development.md")
if not os.path.exists(LAYERS_DOC):
    LAYERS_DOC = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "docs", "development.md")

# Path components of the run layout (RunLayout, LanguageModelFiles, SceneFiles).
LAYOUT_NAMES = (r"run\.json|language|labels|features|rgb|render|query|eval|changes|align|report|model\.json|"
                r"latents\.safetensors|autoencoder\.safetensors|autoencoder-langsplat\.safetensors|"
                r"city_objects\.json|stage\.json|started\.json|checkpoints|scene\.json|gt|points\.ply")
LAYOUT_LITERAL = re.compile(r'/\s*"(%s)"|"(%s)"\s*/|"(%s)/' % (LAYOUT_NAMES, LAYOUT_NAMES, LAYOUT_NAMES))
# Other layouts that share a name with the run's, each in the module that owns it.
LAYOUT_ALLOWED = {
    ("src/core/run_layout.h", None): "the run layout itself",
    ("src/render/render_job.cpp", "rgb"): "render's own output: the camera path's frames under path/rgb/",
    ("src/tiles/tile_tasks.cpp", "autoencoder.safetensors"): "the tiles directory's shared autoencoder",
}


def module_of(path):
    """src/models/clip/x.h -> models/clip; src/core/x.h -> core (models' subfolders are modules)."""
    parts = os.path.relpath(path, SRC).split(os.sep)
    if parts[0] == "models" and len(parts) > 2:
        return "models/" + parts[1]
    return parts[0]


def include_module(header, modules):
    parts = header.split("/")
    if parts[0] == "models" and len(parts) > 2 and "models/" + parts[1] in modules:
        return "models/" + parts[1]
    return parts[0] if parts[0] in modules else None


def read_layers():
    text = open(LAYERS_DOC, encoding="utf-8").read()
    section = text.split("## Layers", 1)[1].split("\n## ", 1)[0]
    layers = {}
    for floor, module, library in re.findall(r"^\|\s*(\d+)\s*\|\s*`([a-z_/]+)`\s*\|\s*`(\w+)`\s*\|", section, re.M):
        layers[module] = (int(floor), library)
    return layers


def torch_dirs():
    cmake = open(os.path.join(ROOT, "CMakeLists.txt"), encoding="utf-8").read()
    return set(re.search(r"set\(CLS_TORCH_DIRS ([^)]*)\)", cmake).group(1).split())


def sources():
    for root, _, files in os.walk(SRC):
        for f in sorted(files):
            if f.endswith((".h", ".cpp", ".cu", ".cuh", ".inc")):
                yield os.path.join(root, f)


def main():
    findings = []
    layers = read_layers()
    files = list(sources())
    modules = {module_of(p) for p in files}
    for m in sorted(modules - set(layers)):
        findings.append(f"docs/development.md: module {m} is not in the table of layers")
    for m in sorted(set(layers) - modules):
        findings.append(f"docs/development.md: the table lists {m}, which src/ does not have")
    torch = torch_dirs()
    for m, (_, library) in sorted(layers.items()):
        top = m.split("/")[0]
        expected = "citylangsplat" if m == "cli" else "cls_torch" if top in torch else "cls"
        if library != expected:
            findings.append(f"docs/development.md: {m} is in {expected} (CMakeLists.txt CLS_TORCH_DIRS), not {library}")

    for path in files:
        rel = os.path.relpath(path, ROOT)
        m = module_of(path)
        floor, library = layers.get(m, (None, None))
        for n, line in enumerate(open(path, encoding="utf-8", errors="replace"), 1):
            inc = re.match(r'\s*#\s*include\s*([<"])([^>"]+)[>"]', line)
            if inc:
                header = inc.group(2)
                if library == "cls" and inc.group(1) == "<" and re.match(r"(torch|ATen|c10)/", header):
                    findings.append(f"{rel}:{n}: {m} is in cls but includes LibTorch's <{header}>")
                target = include_module(header, modules) if inc.group(1) == '"' else None
                if target and target != m and floor is not None and target in layers:
                    if layers[target][0] >= floor:
                        findings.append(f"{rel}:{n}: {m} (floor {floor}) includes {header} of {target} "
                                        f"(floor {layers[target][0]}): includes must go down")
                    if library == "cls" and layers[target][1] != "cls":
                        findings.append(f"{rel}:{n}: {m} is in cls but includes {header} of {target} (cls_torch)")
                continue
            for match in LAYOUT_LITERAL.finditer(line):
                name = next(g for g in match.groups() if g)
                if (rel, None) in LAYOUT_ALLOWED or (rel, name) in LAYOUT_ALLOWED:
                    continue
                findings.append(f'{rel}:{n}: the layout name "{name}" is spelled outside src/core/run_layout.h')

    for f in findings:
        print(f)
    print(f"check_structure: {len(modules)} modules, {len(files)} files, {len(findings)} findings")
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
