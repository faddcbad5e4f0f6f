#!/usr/bin/python3
"""The solver-ready files eg2d writes, checked by readers eg2d did not write.

Usage: solver_formats.py WRITE_SOLVER_SAMPLES OUTDIR cgns|no-cgns [CGNSCHECK]
Runs WRITE_SOLVER_SAMPLES OUTDIR (a NACA 0012 C-grid 65x17 with a wake of 16,
an O-grid 65x17 and a single block 21x13 with the user's patches; see
write_solver_samples.c), then for each grid:
  SU2: meshio reads it; its quads all turn counter-clockwise, the points are
    the nodes less the cut's duplicates, and the boundary edges that the
    quads leave (edges of one quad, found here) are exactly the markers'
    edges, each in one marker, with the markers' names and sizes as the
    topology's patches have them;
  OpenFOAM: checkMesh (Debian's openfoam) says "Mesh OK.", with the cell
    count and the patches and their face counts (its own patch table);
  CGNS: cgnscheck reports no error and `cgnscheck -v` lists the boundary
    conditions with their ranges and the cut's 1-to-1 connections.
Expected counts come from the topology alone: ni, nj and the wake."""
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


def expected_patches(name, ni, nj, wake):
    """Patch name -> number of boundary edges, and the number of points."""
    if name == "c":
        return {"wall": ni - 1 - 2 * wake, "outflow": 2 * (nj - 1), "farfield": ni - 1}, ni * nj - (wake + 1)
    if name == "o":
        return {"wall": ni - 1, "farfield": ni - 1}, (ni - 1) * nj
    return {"bottom": ni - 1, "outlet": nj - 1, "top": 10, "lid": ni - 1 - 10, "inlet": nj - 1}, ni * nj


def check_su2(d, name, ni, nj, wake):
    import meshio
    path = os.path.join(d, name + ".su2")
    mesh = meshio.read(path)
    patches, npoints = expected_patches(name, ni, nj, wake)
    check(mesh.points.shape[0] == npoints, f"su2 {name}: meshio reads {mesh.points.shape[0]} points == {npoints}")
    quads = np.concatenate([c.data for c in mesh.cells if c.type == "quad"])
    check(len(quads) == (ni - 1) * (nj - 1), f"su2 {name}: {len(quads)} quads == {(ni - 1) * (nj - 1)}")
    p = mesh.points[:, :2]
    x, y = p[quads, 0], p[quads, 1]
    area = 0.5 * (x * np.roll(y, -1, axis=1) - np.roll(x, -1, axis=1) * y).sum(axis=1)
    check(area.min() > 0, f"su2 {name}: every quad counter-clockwise, smallest area {area.min():.3e}")
    # Boundary edges: the quads' edges that only one quad has.
    count = {}
    for q in quads:
        for k in range(4):
            e = tuple(sorted((int(q[k]), int(q[(k + 1) % 4]))))
            count[e] = count.get(e, 0) + 1
    boundary = {e for e, n in count.items() if n == 1}
    check(max(count.values()) == 2, f"su2 {name}: no edge has more than two quads")
    # Markers: meshio keeps their edges with integer tags (in file order);
    # the names are the MARKER_TAG lines.
    with open(path) as f:
        text = f.read()
    names = re.findall(r"^MARKER_TAG=\s*(\S+)", text, re.M)
    sizes = [int(s) for s in re.findall(r"^MARKER_ELEMS=\s*(\d+)", text, re.M)]
    check(sorted(names) == sorted(patches) and len(names) == len(set(names)),
          f"su2 {name}: markers {names} are the patches {sorted(patches)}")
    lines = [(c.data, t) for c, t in zip(mesh.cells, mesh.cell_data["su2:tag"]) if c.type == "line"]
    edges = np.concatenate([l for l, _ in lines]) if lines else np.zeros((0, 2), int)
    tags = np.concatenate([t for _, t in lines]) if lines else np.zeros(0, int)
    marked = [tuple(sorted((int(a), int(b)))) for a, b in edges]
    check(len(marked) == len(set(marked)) and set(marked) == boundary,
          f"su2 {name}: {len(marked)} marker edges, each once, are the {len(boundary)} boundary edges")
    for k, (n, s) in enumerate(zip(names, sizes)):
        got = int((tags == np.unique(tags)[k]).sum()) if len(tags) else 0
        check(s == patches.get(n) and got == s, f"su2 {name}: marker {n}: {got} edges read, {s} declared, "
                                                f"{patches.get(n)} expected")


def checkmesh_env():
    # Debian's openfoam puts the programs in /usr/bin; they find their etc/
    # through WM_PROJECT_DIR (without it: "Could not find mandatory etc
    # entry 'controlDict'").
    env = dict(os.environ)
    if "WM_PROJECT_DIR" not in env and os.path.isdir("/usr/share/openfoam/etc"):
        env["WM_PROJECT_DIR"] = "/usr/share/openfoam"
    return env


def check_openfoam(d, name, ni, nj, wake, checkmesh):
    case = os.path.join(d, name + "_foam")
    p = subprocess.run([checkmesh, "-case", case], capture_output=True, text=True, env=checkmesh_env())
    out = p.stdout + p.stderr
    with open(os.path.join(d, name + "_checkMesh.log"), "w") as f:
        f.write(out)
    cells = (ni - 1) * (nj - 1)
    m = re.search(r"^\s*cells:\s+(\d+)", out, re.M)
    check(p.returncode == 0 and "\nMesh OK." in out and m and int(m.group(1)) == cells,
          f"openfoam {name}: checkMesh exit {p.returncode}, \"Mesh OK.\", {m.group(1) if m else '?'} cells == {cells}")
    check("Upper triangular ordering OK." in out and "Number of regions: 1 (OK)." in out
          and "Mesh has 2 solution (non-empty) directions" in out,
          f"openfoam {name}: upper-triangular faces, one region, 2-D (empty front and back)")
    patches, _ = expected_patches(name, ni, nj, wake)
    patches = dict(patches, frontAndBack=2 * cells)
    table = dict(re.findall(r"^\s{4}(\w+)\s+(\d+)\s+\d+\s+ok", out, re.M))
    check({k: int(v) for k, v in table.items()} == patches,
          f"openfoam {name}: checkMesh's patches and face counts {table} == {patches}")
    with open(os.path.join(case, "constant/polyMesh/boundary")) as f:
        boundary = f.read()
    walls = re.findall(r"(\w+)\s*\{\s*type\s+wall;", boundary)
    want = {"c": ["wall"], "o": ["wall"], "single": ["bottom", "lid"]}[name]
    check(walls == want, f"openfoam {name}: wall patches {walls} == {want}")


def check_plot3d(d, name, ni, nj, wake, checkmesh):
    """The extruded ASCII Plot3D through plot3dToFoam (which merges coincident
    points, so a cut becomes internal), then checkMesh."""
    case = os.path.join(d, name + "_p3d")
    os.makedirs(os.path.join(case, "constant"))
    shutil.copytree(os.path.join(d, name + "_foam", "system"), os.path.join(case, "system"))
    env = checkmesh_env()
    p = subprocess.run([os.path.join(os.path.dirname(checkmesh), "plot3dToFoam"), "-case", case, "-singleBlock",
                        "-noBlank", os.path.join(d, name + ".p3d")], capture_output=True, text=True, env=env)
    check(p.returncode == 0, f"plot3d {name}: plot3dToFoam exit {p.returncode}")
    out = subprocess.run([checkmesh, "-case", case], capture_output=True, text=True, env=env).stdout
    cells = (ni - 1) * (nj - 1)
    patches, _ = expected_patches(name, ni, nj, wake)
    faces = 2 * cells + sum(patches.values())
    m = re.search(r"^\s*cells:\s+(\d+)", out, re.M)
    f = re.search(r"^\s+defaultFaces\s+(\d+)", out, re.M)
    check("\nMesh OK." in out and m and int(m.group(1)) == cells and f and int(f.group(1)) == faces
          and re.search(r"bounding box \(.*\) \(\S+ \S+ 0\.5\)", out),
          f"plot3d {name}: checkMesh \"Mesh OK.\", {cells} cells, {faces} boundary faces (the cut merged), span 0.5")


def run_cgnscheck(d, name, cgnscheck):
    """`cgnscheck -v` of d/name.cgns (its log kept beside it), checked to
    report no error; returns the log."""
    p = subprocess.run([cgnscheck, "-v", os.path.join(d, name + ".cgns")], capture_output=True, text=True)
    out = p.stdout + p.stderr
    with open(os.path.join(d, name + "_cgnscheck.log"), "w") as f:
        f.write(out)
    # cgnscheck exits 0 even when it reports errors (READERS.md): count them.
    errors = [l for l in out.splitlines() if "ERROR" in l.upper()]
    check(p.returncode == 0 and not errors and "checking complete" in out,
          f"cgns {name}: cgnscheck exit {p.returncode}, {len(errors)} errors {errors[:3]}")
    return out


def cgns_check(d, name, ni, nj, wake, cgnscheck):
    out = run_cgnscheck(d, name, cgnscheck)
    # The boundary conditions and the cut's connections as cgnscheck -v read
    # them, against ranges worked out here from the topology (1-based).
    bcs = {m[0]: (m[1], m[2]) for m in re.findall(
        r'checking BC "([^"]+)"\s+BC Type=(\w+).*?Range=\[([^\]]*)\]', out, re.S)}
    conns = {m[0]: m[1:] for m in re.findall(
        r'checking 1to1 connectivity "([^"]+)"\s+Range=\[([^\]]*)\].*?Donor Range=\[([^\]]*)\]'
        r'.*?Transform=\[([^\]]*)\]', out, re.S)}
    w = wake
    if name == "c":
        want_bc = {"wall": ("BCWall", f"{w + 1}:{ni - w},1:1"), "outflow": ("BCOutflow", f"{ni}:{ni},1:{nj}"),
                   "outflow_2": ("BCOutflow", f"1:1,1:{nj}"), "farfield": ("BCFarfield", f"1:{ni},{nj}:{nj}")}
        want_conn = {"wake_lower": (f"1:{w + 1},1:1", f"{ni}:{ni - w},1:1", "-1,-2"),
                     "wake_upper": (f"{ni - w}:{ni},1:1", f"{w + 1}:1,1:1", "-1,-2")}
    elif name == "o":
        want_bc = {"wall": ("BCWall", f"1:{ni},1:1"), "farfield": ("BCFarfield", f"1:{ni},{nj}:{nj}")}
        want_conn = {"cut_imin": (f"1:1,1:{nj}", f"{ni}:{ni},1:{nj}", "1,2"),
                     "cut_imax": (f"{ni}:{ni},1:{nj}", f"1:1,1:{nj}", "1,2")}
    else:
        want_bc = {"bottom": ("BCWall", f"1:{ni},1:1"), "outlet": ("BCOutflow", f"{ni}:{ni},1:{nj}"),
                   "top": ("BCSymmetryPlane", f"1:11,{nj}:{nj}"), "lid": ("BCWall", f"11:{ni},{nj}:{nj}"),
                   "inlet": ("BCInflow", f"1:1,1:{nj}")}
        want_conn = {}
    check(bcs == want_bc, f"cgns {name}: boundary conditions {bcs} == {want_bc}")
    check(conns == want_conn, f"cgns {name}: 1-to-1 connections {conns} == {want_conn}")


def read_p3d(path):
    """x, y as (nj, ni) arrays of the k = 0 plane of an ASCII 3-D Plot3D file."""
    with open(path) as f:
        t = f.read().split()
    ni, nj, nk = map(int, t[:3])
    v = np.array(t[3:], dtype=float).reshape(3, nk, nj, ni)
    return ni, nj, v[0, 0], v[1, 0]


def check_report(d, name, ni, nj, wake):
    """The JSON report against numbers worked out here from the Plot3D file
    and the SU2 file (read by meshio)."""
    import json
    import meshio
    with open(os.path.join(d, name + ".report.json")) as f:
        r = json.load(f)
    _, npoints = expected_patches(name, ni, nj, wake)
    cells = (ni - 1) * (nj - 1)
    check((r["ni"], r["nj"], r["cells"], r["points"], r["folded_cells"]) == (ni, nj, cells, npoints, 0),
          f"report {name}: sizes {r['ni']}x{r['nj']}, {r['cells']} cells, {r['points']} points, no folds")
    check(r["run"]["iterations"] > 0 and r["run"]["residual"] < 1e-3 and r["run"]["seconds"] >= 0,
          f"report {name}: run {r['run']}")
    m = meshio.read(os.path.join(d, name + ".su2"))
    q = np.concatenate([c.data for c in m.cells if c.type == "quad"])
    x, y = m.points[q, 0], m.points[q, 1]
    area = 0.5 * (x * np.roll(y, -1, axis=1) - np.roll(x, -1, axis=1) * y).sum(axis=1)
    check(abs(r["area_min"] - area.min()) <= 1e-12 * abs(area).max(),
          f"report {name}: smallest area {r['area_min']:.6e} == meshio's quads {area.min():.6e}")
    _, _, X, Y = read_p3d(os.path.join(d, name + ".p3d"))
    # The wall's inner nodes: JMIN between the trailing edges (C), all of JMIN but the TE (O).
    if name == "single":
        nodes, rows = range(1, ni - 1), max(2, (nj - 1) // 3)  # "bottom" (the lid is on JMAX: checked by count)
    else:
        nodes, rows = (range(wake + 1, ni - 1 - wake) if name == "c" else range(1, ni - 1)), max(2, (nj - 1) // 3)
    # Corners (the wall turning by more than 45 degrees at an inner node) and
    # the nodes beside them are left out: the wall has no normal there.
    first, last = nodes[0] - 1, nodes[-1] + 1

    def corner(q):
        if q <= first or q >= last:
            return False
        u = (X[0, q] - X[0, q - 1], Y[0, q] - Y[0, q - 1])
        v = (X[0, q + 1] - X[0, q], Y[0, q + 1] - Y[0, q])
        return abs(np.arctan2(u[0] * v[1] - u[1] * v[0], u[0] * v[0] + u[1] * v[1])) > np.pi / 4
    i = np.array([q for q in nodes if not (corner(q - 1) or corner(q) or corner(q + 1))])
    t = np.stack([X[0, i + 1] - X[0, i - 1], Y[0, i + 1] - Y[0, i - 1]])
    dvec = np.stack([X[1, i] - X[0, i], Y[1, i] - Y[0, i]])
    h = np.abs(t[0] * dvec[1] - t[1] * dvec[0]) / np.hypot(*t)
    sp = np.hypot(np.diff(X[:rows + 1, i], axis=0), np.diff(Y[:rows + 1, i], axis=0))
    growth = (sp[1:] / sp[:-1]).max()
    w = r["wall"]
    if name == "single":
        check(w["nodes"] == (ni - 2) + (ni - 1 - 10 - 1), f"report single: {w['nodes']} inner wall nodes (bottom, lid)")
        return
    close = lambda a, b: abs(a - b) <= 1e-9 * abs(b)
    check(w["nodes"] == len(i) and close(w["first_cell_height"]["min"], h.min())
          and close(w["first_cell_height"]["max"], h.max()) and close(w["growth_max"], growth),
          f"report {name}: {w['nodes']} wall nodes, first cell {w['first_cell_height']['min']:.6e}.."
          f"{w['first_cell_height']['max']:.6e}, growth {w['growth_max']:.6f} == {len(i)}, {h.min():.6e}.."
          f"{h.max():.6e}, {growth:.6f} from the Plot3D file")
    with open(os.path.join(d, name + ".report.txt")) as f:
        text = f.read()
    check("folded cells    0\n" in text and f"{cells} cells" in text and "wall            wall: JMIN" in text,
          f"report {name}: the text report's folds, cells and wall")


def main():
    exe, d = sys.argv[1], sys.argv[2]
    with_cgns = sys.argv[3] == "cgns"
    cgnscheck = sys.argv[4] if len(sys.argv) > 4 else shutil.which("cgnscheck")
    checkmesh = shutil.which("checkMesh")
    check(checkmesh is not None, "checkMesh on PATH (Debian's openfoam, installed by .ci/install-deps)")
    if checkmesh is None:
        return 1
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    subprocess.run([exe, d] + ([] if with_cgns else ["no-cgns"]), check=True)
    for name in ("c", "o", "single"):
        with open(os.path.join(d, name + ".txt")) as f:
            ni, nj, topology, wake = map(int, f.read().split())
        check_su2(d, name, ni, nj, wake)
        check_openfoam(d, name, ni, nj, wake, checkmesh)
        check_plot3d(d, name, ni, nj, wake, checkmesh)
        check_report(d, name, ni, nj, wake)
        if with_cgns:
            cgns_check(d, name, ni, nj, wake, cgnscheck)
    leftovers = [f for f in os.listdir(d) if ".eg2d-tmp-" in f]
    check(not leftovers, f"no temporary files left behind ({leftovers})")
    print(f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
