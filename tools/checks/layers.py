#!/usr/bin/env python3
"""Fails when a library source includes a header from a higher layer.

The layers of src/ (docs/DESIGN.md), lowest first. A file may include
headers of its own folder and of folders below it; eg2d.h (the public ids)
is open to all. In the spirit of Chromium's checkdeps: the order is written
once, here, and the build fails on the first arrow that runs upward.
"""
import pathlib
import re
import sys

LAYERS = ["base", "grid", "quality", "operator", "controls", "solvers",
          "generator", "geometry", "io", "api"]
# Folders under src/ that are not part of the library's layering: the CGNS
# plugin is its own module, built against libcgns, loaded with dlopen.
OUTSIDE = {"io/cgns_plugin"}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def layer_of(rel: pathlib.PurePosixPath):
    return rel.parts[0] if len(rel.parts) > 1 else None


def main(src: pathlib.Path) -> int:
    rank = {name: k for k, name in enumerate(LAYERS)}
    errors = []
    for path in sorted(src.rglob("*")):
        if path.suffix not in (".cpp", ".hpp", ".h") or not path.is_file():
            continue
        rel = pathlib.PurePosixPath(path.relative_to(src).as_posix())
        if any(str(rel).startswith(o + "/") for o in OUTSIDE):
            continue
        own = layer_of(rel)
        if own not in rank:
            errors.append(f"{rel}: folder '{own}' is in no layer (add it to LAYERS in {__file__})")
            continue
        for lineno, line in enumerate(path.read_text().splitlines(), 1):
            m = INCLUDE.match(line)
            if not m:
                continue
            target = pathlib.PurePosixPath(m.group(1))
            dep = layer_of(target)
            if dep is None:  # eg2d.h, or a header beside the file
                continue
            if dep not in rank:
                errors.append(f"{rel}:{lineno}: includes {target} from '{dep}', which is in no layer")
            elif rank[dep] > rank[own]:
                errors.append(f"{rel}:{lineno}: {own} (layer {rank[own]}) includes {target} "
                              f"from {dep} (layer {rank[dep]}), a higher layer")
    for e in errors:
        print(e)
    print(f"layers: {'FAILED, ' + str(len(errors)) + ' upward include(s)' if errors else 'ok'} "
          f"({' < '.join(LAYERS)})")
    return 1 if errors else 0


if __name__ == "__main__":
    root = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2] / "src"
    sys.exit(main(root))
