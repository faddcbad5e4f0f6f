#!/usr/bin/env python3
"""Fails when a library source includes a header its layer may not use.

The layers of src/ and what each may include are the table of
docs/DESIGN.md ("## Layers": layer number, folder, what it holds, may use),
read here, so the document and the check are one list. A file may include
headers of its own folder and of the layers its row names ("everything
below", "all of 0-5", "nothing", or names); eg2d.h (the public ids) is open
to all. In the spirit of Chromium's checkdeps: the build fails on the first
arrow the table does not allow.

Usage: layers.py [SRC [DESIGN_MD]]   (default: this tree's src/ and docs/DESIGN.md)
"""
import pathlib
import re
import sys

# Folders under src/ that are not part of the library's layering: the CGNS
# plugin is its own module, built against libcgns, loaded with dlopen.
OUTSIDE = {"io/cgns_plugin"}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
ROW = re.compile(r"^\|\s*(\d+)\s*\|\s*`src/(\w+)/`\s*\|.*\|\s*([^|]+?)\s*\|\s*$")


def read_layers(design: pathlib.Path):
    """[(name, rank)], {name: set of the layers it may include} from DESIGN.md's table."""
    rows = []
    for line in design.read_text().splitlines():
        m = ROW.match(line)
        if m:
            rows.append((int(m.group(1)), m.group(2), m.group(3)))
    rows.sort()
    names = [name for _, name, _ in rows]
    allowed = {}
    for rank, name, uses in rows:
        if uses == "nothing":
            allowed[name] = set()
        elif uses == "everything below":
            allowed[name] = set(names[:rank])
        elif uses.startswith("all of "):
            lo, hi = (int(t) for t in uses[len("all of "):].split("-"))
            allowed[name] = set(names[lo:hi + 1])
        else:
            allowed[name] = {u.strip() for u in uses.split(",")}
        for dep in allowed[name]:
            if dep not in names or names.index(dep) >= rank:
                raise SystemExit(f"{design}: layer {name} may use '{dep}', which is not a layer below it")
    return names, allowed


def layer_of(rel: pathlib.PurePosixPath):
    return rel.parts[0] if len(rel.parts) > 1 else None


def main(src: pathlib.Path, design: pathlib.Path) -> int:
    names, allowed = read_layers(design)
    rank = {name: k for k, name in enumerate(names)}
    errors = []
    for path in sorted(src.rglob("*")):
        if path.suffix not in (".cpp", ".hpp", ".h") or not path.is_file():
            continue
        rel = pathlib.PurePosixPath(path.relative_to(src).as_posix())
        if any(str(rel).startswith(o + "/") for o in OUTSIDE):
            continue
        own = layer_of(rel)
        if own not in rank:
            errors.append(f"{rel}: folder '{own}' is in no layer (add it to the table of {design})")
            continue
        for lineno, line in enumerate(path.read_text().splitlines(), 1):
            m = INCLUDE.match(line)
            if not m:
                continue
            target = pathlib.PurePosixPath(m.group(1))
            dep = layer_of(target)
            if dep is None or dep == own:  # eg2d.h, a header beside the file, its own layer
                continue
            if dep not in rank:
                errors.append(f"{rel}:{lineno}: includes {target} from '{dep}', which is in no layer")
            elif rank[dep] > rank[own]:
                errors.append(f"{rel}:{lineno}: {own} (layer {rank[own]}) includes {target} "
                              f"from {dep} (layer {rank[dep]}), a higher layer")
            elif dep not in allowed[own]:
                errors.append(f"{rel}:{lineno}: {own} includes {target} from {dep}, which its row of "
                              f"{design.name} does not allow (may use: {', '.join(sorted(allowed[own])) or 'nothing'})")
    for e in errors:
        print(e)
    print(f"layers: {'FAILED, ' + str(len(errors)) + ' include(s) not allowed' if errors else 'ok'} "
          f"({' < '.join(names)})")
    return 1 if errors else 0


if __name__ == "__main__":
    root = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2] / "src"
    design = pathlib.Path(sys.argv[2]) if len(sys.argv) > 2 else root.parent / "docs" / "DESIGN.md"
    sys.exit(main(root, design))
