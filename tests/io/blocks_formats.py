#!/usr/bin/python3
"""A set of blocks written as one mesh, checked by readers eg2d did not write.

Usage: blocks_formats.py WRITE_BLOCK_SAMPLES OUTDIR
Runs WRITE_BLOCK_SAMPLES OUTDIR (a backward-facing step in three blocks;
write_block_samples.c), then:
  SU2: meshio reads the points (the joined nodes once) and the quads, every
    quad counter-clockwise, no edge in more than two quads, the boundary
    edges (those of one quad) exactly the markers' edges, each once, the
    markers wall, inlet and outlet with their edge counts;
  OpenFOAM: checkMesh says "Mesh OK.", one region (the joins are interior
    faces), upper-triangular order, its patch table wall, inlet, outlet and
    frontAndBack with their face counts;
  Plot3D: the three zones read by OpenFOAM's plot3dToFoam (which merges
    the points zones share), then checkMesh: "Mesh OK.", one region, the
    cells, and the boundary faces less the joins'.
The counts come from the blocks' sizes (OUTDIR/step.txt)."""
import os
import re
import shutil
import subprocess
import sys

import numpy as np

failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def main():
    writer, out = sys.argv[1], sys.argv[2]
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    subprocess.run([writer, out], check=True)
    with open(os.path.join(out, "step.txt")) as f:
        cells, points, wall, inlet, outlet = map(int, f.read().split())
    patches = {"wall": wall, "inlet": inlet, "outlet": outlet}

    import meshio
    path = os.path.join(out, "step.su2")
    mesh = meshio.read(path)
    check(mesh.points.shape[0] == points, f"su2: meshio reads {mesh.points.shape[0]} points == {points}")
    quads = np.concatenate([c.data for c in mesh.cells if c.type == "quad"])
    check(len(quads) == cells, f"su2: {len(quads)} quads == {cells}")
    x, y = mesh.points[quads, 0], mesh.points[quads, 1]
    area = 0.5 * (x * np.roll(y, -1, axis=1) - np.roll(x, -1, axis=1) * y).sum(axis=1)
    check(area.min() > 0, f"su2: every quad counter-clockwise, smallest area {area.min():.3e}")
    count = {}
    for q in quads:
        for k in range(4):
            e = tuple(sorted((int(q[k]), int(q[(k + 1) % 4]))))
            count[e] = count.get(e, 0) + 1
    boundary = {e for e, n in count.items() if n == 1}
    check(max(count.values()) == 2, "su2: no edge has more than two quads")
    with open(path) as f:
        text = f.read()
    names = re.findall(r"^MARKER_TAG=\s*(\S+)", text, re.M)
    sizes = [int(s) for s in re.findall(r"^MARKER_ELEMS=\s*(\d+)", text, re.M)]
    check(dict(zip(names, sizes)) == patches and len(names) == 3, f"su2: markers {dict(zip(names, sizes))} == {patches}")
    lines = [c.data for c in mesh.cells if c.type == "line"]
    marked = [tuple(sorted((int(a), int(b)))) for a, b in np.concatenate(lines)]
    check(len(marked) == len(set(marked)) and set(marked) == boundary,
          f"su2: {len(marked)} marker edges, each once, are the {len(boundary)} boundary edges")

    checkmesh = shutil.which("checkMesh") or "/usr/bin/checkMesh"
    env = dict(os.environ)
    if "WM_PROJECT_DIR" not in env and os.path.isdir("/usr/share/openfoam/etc"):
        env["WM_PROJECT_DIR"] = "/usr/share/openfoam"
    case = os.path.join(out, "step_foam")
    p = subprocess.run([checkmesh, "-case", case], capture_output=True, text=True, env=env)
    log = p.stdout + p.stderr
    with open(os.path.join(out, "step_checkMesh.log"), "w") as f:
        f.write(log)
    m = re.search(r"^\s*cells:\s+(\d+)", log, re.M)
    check(p.returncode == 0 and "\nMesh OK." in log and m and int(m.group(1)) == cells,
          f"openfoam: checkMesh exit {p.returncode}, \"Mesh OK.\", {m.group(1) if m else '?'} cells == {cells}")
    check("Upper triangular ordering OK." in log and "Number of regions: 1 (OK)." in log,
          "openfoam: upper-triangular faces, one region (the joins are interior)")
    table = {k: int(v) for k, v in re.findall(r"^\s{4}(\w+)\s+(\d+)\s+\d+\s+ok", log, re.M)}
    want = dict(patches, frontAndBack=2 * cells)
    check(table == want, f"openfoam: checkMesh's patches and face counts {table} == {want}")
    non_orth = re.search(r"Mesh non-orthogonality Max: (\S+)", log)
    skew = re.search(r"Max skewness = (\S+)", log)
    print(f"     checkMesh: non-orthogonality max {non_orth.group(1) if non_orth else '?'}, "
          f"skewness max {skew.group(1) if skew else '?'}")

    # The blocks as the zones of a one-cell-thick Plot3D file, through
    # OpenFOAM's plot3dToFoam (which merges the points the zones share).
    p3 = os.path.join(out, "step_p3d")
    os.makedirs(os.path.join(p3, "constant"))
    shutil.copytree(os.path.join(case, "system"), os.path.join(p3, "system"))
    p = subprocess.run([os.path.join(os.path.dirname(checkmesh), "plot3dToFoam"), "-case", p3, "-noBlank",
                        os.path.join(out, "step.p3d")], capture_output=True, text=True, env=env)
    check(p.returncode == 0, f"plot3d: plot3dToFoam reads the three zones, exit {p.returncode}")
    log = subprocess.run([checkmesh, "-case", p3], capture_output=True, text=True, env=env).stdout
    m = re.search(r"^\s*cells:\s+(\d+)", log, re.M)
    f = re.search(r"^\s+defaultFaces\s+(\d+)", log, re.M)
    faces = 2 * cells + wall + inlet + outlet
    check("\nMesh OK." in log and "Number of regions: 1 (OK)." in log and m and int(m.group(1)) == cells
          and f and int(f.group(1)) == faces,
          f"plot3d: checkMesh \"Mesh OK.\", one region, {cells} cells, {faces} boundary faces (the joins merged)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
