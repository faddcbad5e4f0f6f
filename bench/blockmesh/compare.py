#!/usr/bin/python3
"""eg2d's sets of blocks against OpenFOAM's blockMesh on the same blocks and
node counts (issue 39): for each geometry of bench/blockmesh, blockMesh meshes
its system/blockMeshDict and eg2d its case file, checkMesh checks both, and
this script measures both polyMeshes the same way. Prints a Markdown table.

  bench/blockmesh/compare.py BUILD_DIR [--walls [--check]] [GEOMETRY...]   (default: pitzDaily bfs)

BUILD_DIR may also be the eg2d command itself.

--walls runs eg2d on the case files whose blocks give their walls blockMesh's
first cells (wall_spacing; *-walls.toml, make_cases.py writes them).

--check (with --walls; the ctest blockmesh_walls) exits 1 unless eg2d's
mesh of each geometry has what issue 39 asks against blockMesh's: no folds;
checkMesh's verdict OK but for the aspect ratio a wall layer must have;
non-orthogonality within 5 degrees of blockMesh's; skewness at most 4
(checkMesh's limit); the largest size ratio at most blockMesh's (to 0.1%:
both meshes share the boundary's spacing); the largest turn at an
interface below blockMesh's, or no larger than the turns nearby.

Needs blockMesh and checkMesh (Debian's openfoam package; WM_PROJECT_DIR is
set to /usr/share/openfoam when unset) and numpy.

The measures, from each block's nodes as a structured array: both generators
write cells block by block, i fastest (blockMesh in its dictionary's order,
eg2d in the case file's), so each block's nodes are rebuilt from its cells'
corners and the rebuilt cells are checked against the mesh's own before
anything is measured.
  size ratio     the largest ratio of two cells' areas across an internal face
  kink           the angle (degrees) between consecutive segments of a grid line;
                 at an interface, of the line that crosses it (the segment in
                 either block); "nearby", at the 1st to 3rd node into the blocks
                 on those same lines. Nodes where three or more blocks meet are
                 left out (no one line crosses there).
  folds          cells of non-positive area (the blocks are counterclockwise)
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
GEOMETRIES = {  # directory of the blockMeshDict, eg2d case file, the blocks' cells (ni, nj) in order
    "pitzDaily": ("pitzDaily", "pitzDaily/pitz-daily.toml", [(18, 30), (180, 27), (180, 30), (25, 27), (25, 30)]),
    "bfs": ("bfs", "bfs/backward-facing-step-tmr.toml", [(64, 64), (24, 64), (128, 64), (128, 48)]),
}
NEARBY = 3

SYSTEM = {  # what blockMesh and checkMesh need of a case's system/
    "controlDict": "application blockMesh; startFrom startTime; startTime 0; stopAt endTime; endTime 1;\n"
                   "deltaT 1; writeControl timeStep; writeInterval 1; writeFormat ascii; writePrecision 17;\n"
                   "writeCompression off; timeFormat general; timePrecision 6; runTimeModifiable false;\n",
    "fvSchemes": "ddtSchemes { default steadyState; } gradSchemes { default Gauss linear; }\n"
                 "divSchemes { default none; } laplacianSchemes { default Gauss linear corrected; }\n"
                 "interpolationSchemes { default linear; } snGradSchemes { default corrected; }\n",
    "fvSolution": "",
}


def foam_file(path, name):
    with open(path, "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary; object %s; }\n%s" % (name, SYSTEM[name]))


def run(cmd, cwd=None):
    return subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def check_mesh(case):
    out = run(["checkMesh", "-case", case]).stdout
    verdict = "OK" if "Mesh OK." in out else (re.search(r"Failed \d+ mesh checks", out) or [None])[0] or "no verdict"
    failed = [s.strip().lstrip("*") for s in re.findall(r"^\s*\*\*\*(.*)$", out, re.M)]
    if verdict != "OK":
        verdict += " (" + "; ".join(f.split(",")[0] for f in failed) + ")"
    nonorth = re.search(r"Mesh non-orthogonality Max: ([0-9.eE+-]+)", out)
    skew = re.search(r"Max skewness = ([0-9.eE+-]+)", out)
    return verdict, float(nonorth[1]) if nonorth else None, float(skew[1]) if skew else None


def foam_list(path):
    """The list of an ASCII polyMesh file: an array of numbers, or of faces."""
    text = open(path).read()
    text = text[text.index("}", text.index("FoamFile")) + 1:]
    text = re.sub(r"//.*", "", text)
    m = re.search(r"(\d+)\s*\(", text)
    n, body = int(m[1]), text[m.end():]
    if "faces" in os.path.basename(path):
        return [list(map(int, f.split())) for f in re.findall(r"\d+\s*\(([^)]*)\)", body)[:n]]
    if "points" in os.path.basename(path):
        return re.findall(r"\(([^)]*)\)", body)[:n]
    return np.array(body[:body.rindex(")")].split()[:n], dtype=int)


def read_poly_mesh(case):
    d = os.path.join(case, "constant", "polyMesh")
    pts = np.array([list(map(float, p.split())) for p in foam_list(os.path.join(d, "points"))])
    faces = foam_list(os.path.join(d, "faces"))
    owner, neighbour = foam_list(os.path.join(d, "owner")), foam_list(os.path.join(d, "neighbour"))
    return pts, faces, owner, neighbour


def block_nodes(pts, faces, owner, neighbour, sizes):
    """Each block's nodes (ni+1, nj+1, 2) rebuilt from its cells' corners on the
    low z plane, and the mesh's point index of each."""
    zlow = pts[:, 2] < 0.5 * (pts[:, 2].min() + pts[:, 2].max())
    ncells = owner.max() + 1
    corners = [set() for _ in range(ncells)]
    for f, face in enumerate(faces):
        low = {p for p in face if zlow[p]}
        corners[owner[f]] |= low
        if f < len(neighbour):
            corners[neighbour[f]] |= low
    if sum(n * m for n, m in sizes) != ncells:
        sys.exit("the blocks' cells (%d) are not the mesh's (%d)" % (sum(n * m for n, m in sizes), ncells))
    blocks, start = [], 0
    for ni, nj in sizes:
        cell = lambda i, j: corners[start + i + ni * j]
        ids = np.zeros((ni + 1, nj + 1), dtype=int)
        for i in range(ni + 1):
            for j in range(nj + 1):
                inside = [cell(a, b) for a in (i - 1, i) for b in (j - 1, j) if 0 <= a < ni and 0 <= b < nj]
                around = [cell(a, b) for a in range(i - 2, i + 2) for b in range(j - 2, j + 2)
                          if 0 <= a < ni and 0 <= b < nj and not (i - 1 <= a <= i and j - 1 <= b <= j)]
                left = set.intersection(*inside) - set().union(*around)
                if len(left) != 1:
                    sys.exit("cannot rebuild node (%d, %d) of a block of %dx%d cells" % (i, j, ni, nj))
                ids[i, j] = left.pop()
        for i in range(ni):  # the rebuilt cells are the mesh's
            for j in range(nj):
                if set(ids[i:i + 2, j:j + 2].ravel()) != cell(i, j):
                    sys.exit("cell (%d, %d) of a block is not the mesh's" % (i, j))
        blocks.append((ids, pts[ids][:, :, :2]))
        start += ni * nj
    return blocks


def turn(a, b):
    """Angle (degrees) between segment vectors a and b (arrays of 2-vectors)."""
    c = np.einsum("...k,...k", a, b) / (np.linalg.norm(a, axis=-1) * np.linalg.norm(b, axis=-1))
    return np.degrees(np.arccos(np.clip(c, -1, 1)))


def cell_areas(x):
    d1, d2 = x[1:, 1:] - x[:-1, :-1], x[:-1, 1:] - x[1:, :-1]
    return 0.5 * (d1[..., 0] * d2[..., 1] - d1[..., 1] * d2[..., 0])


def measures(pts, faces, owner, neighbour, sizes):
    blocks = block_nodes(pts, faces, owner, neighbour, sizes)
    areas = np.concatenate([cell_areas(x).T.ravel() for _, x in blocks])  # cell order: i fastest
    folds = int((areas <= 0).sum())
    a, b = np.abs(areas[owner[:len(neighbour)]]), np.abs(areas[neighbour])
    ratio = float(np.max(np.maximum(a / b, b / a)))
    # where each point sits on a block's side (not at its corners): the line into the block
    ends = {}
    for k, (ids, x) in enumerate(blocks):
        ni, nj = ids.shape[0] - 1, ids.shape[1] - 1
        for i in range(ni + 1):
            for j in range(nj + 1):
                on_i, on_j = i in (0, ni), j in (0, nj)
                if on_i == on_j:
                    ends.setdefault(ids[i, j], []).append(None)  # a corner, or not on a side
                    continue
                if on_i:  # the line of constant j, into the block from i = 0 or ni
                    line = x[::1 if i == 0 else -1, j][:NEARBY + 2]
                else:
                    line = x[i, ::1 if j == 0 else -1][:NEARBY + 2]
                ends.setdefault(ids[i, j], []).append(line)
    kink, nearby = 0.0, 0.0
    for lines in ends.values():
        if len(lines) != 2 or any(line is None for line in lines):
            continue
        la, lb = lines
        kink = max(kink, float(turn(la[0] - la[1], lb[1] - lb[0])))
        for line in (la, lb):
            seg = np.diff(line, axis=0)
            nearby = max(nearby, float(turn(seg[:-1], seg[1:]).max()))
    return {"folds": folds, "ratio": ratio, "kink": kink, "nearby": nearby, "blocks": blocks}


def boundary_difference(first, second):
    """The largest distance between two meshes' nodes on the domain's boundary
    (a block's side that is no join: its nodes belong to that block alone; a
    join's nodes are the set's to move), relative to the block's size."""
    count = {}
    for ids, _ in first:
        for p in set(ids.ravel()):
            count[p] = count.get(p, 0) + 1
    worst = 0.0
    for (ids, xa), (_, xb) in zip(first, second):
        span = np.ptp(xa.reshape(-1, 2), axis=0).max()
        for edge in (np.s_[0, :], np.s_[-1, :], np.s_[:, 0], np.s_[:, -1]):
            alone = np.array([count[p] == 1 for p in ids[edge]])
            if alone.any():
                worst = max(worst, np.abs(xa[edge][alone] - xb[edge][alone]).max() / span)
    return worst


def mesh_blockmesh(dict_dir, work):
    case = os.path.join(work, "blockMesh")
    os.makedirs(os.path.join(case, "system"))
    shutil.copy(os.path.join(dict_dir, "system", "blockMeshDict"), os.path.join(case, "system"))
    for name in SYSTEM:
        foam_file(os.path.join(case, "system", name), name)
    r = run(["blockMesh", "-case", case])
    if r.returncode:
        sys.exit("blockMesh failed on %s:\n%s" % (dict_dir, r.stdout[-2000:]))
    return case


def mesh_eg2d(build, toml, work):
    out = os.path.join(work, "eg2d")
    tool = build if os.path.isfile(build) else os.path.join(build, "tools", "eg2d", "eg2d")  # the command, or a build
    r = run([tool, "run", toml, "-o", out])
    m = re.search(r"quality: (\d+) folded cells", r.stdout)
    folds = int(m[1]) if m else None
    # exit 4 with the files written: a wall layer grows faster than 1.2
    # (said in its output); the mesh is measured all the same
    if r.returncode and not (r.returncode == 4 and "(the files are written)" in r.stdout):
        last = (r.stdout.strip().splitlines() or ["exit %d" % r.returncode])[-1]
        return None, folds, re.sub(r"^eg2d: " + re.escape(toml) + r"(:\d+:\d+)?: ", "", last)  # not the path
    case = [os.path.join(out, d) for d in os.listdir(out) if d.endswith("_foam")][0]
    for name in SYSTEM:  # eg2d writes its own; blockMesh's case gets the same as this script's
        foam_file(os.path.join(case, "system", name), name)
    return case, folds, None


def fmt(v, spec):
    return "—" if v is None else format(v, spec)


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    build, args = sys.argv[1], sys.argv[2:]
    walls, checking = "--walls" in args, "--check" in args
    names = [a for a in args if a not in ("--walls", "--check")] or list(GEOMETRIES)
    failures = []
    os.environ.setdefault("WM_PROJECT_DIR", "/usr/share/openfoam")
    print("| geometry | generator | cells | checkMesh | non-orthogonality max (deg) | skewness max "
          "| neighbour size ratio max | interface kink max (deg) | interior kink nearby max (deg) | folds |")
    print("|---|---|---:|---|---:|---:|---:|---:|---:|---:|")
    notes = []
    for name in names:
        dict_dir, toml, sizes = GEOMETRIES[name]
        if walls:
            toml = toml.replace(".toml", "-walls.toml")
        with tempfile.TemporaryDirectory() as work:
            rows = {}
            bm = mesh_blockmesh(os.path.join(HERE, dict_dir), work)
            rows["blockMesh"] = (bm, measures(*read_poly_mesh(bm), sizes))
            eg, folds, failure = mesh_eg2d(build, os.path.join(HERE, toml), work)
            if eg:
                rows["eg2d"] = (eg, measures(*read_poly_mesh(eg), sizes))
                notes.append("%s: eg2d's nodes on the domain's boundary are blockMesh's to %.1e of a block's size"
                             % (name, boundary_difference(rows["blockMesh"][1]["blocks"], rows["eg2d"][1]["blocks"])))
            for gen in ("blockMesh", "eg2d"):
                if gen not in rows:
                    print("| %s | %s | — | not written: %s | — | — | — | — | — | %s |" %
                          (name, gen, failure, fmt(folds, "d")))
                    continue
                case, m = rows[gen]
                verdict, nonorth, skew = check_mesh(case)
                rows[gen] = (case, m, verdict, nonorth, skew)
                print("| %s | %s | %d | %s | %s | %s | %.3g | %.3g | %.3g | %d |" %
                      (name, gen, sum(a * b for a, b in sizes), verdict, fmt(nonorth, ".3g"), fmt(skew, ".3g"),
                       m["ratio"], m["kink"], m["nearby"], m["folds"]))
            if checking:
                failures += judged(name, rows)
    print()
    for n in notes:
        print("- " + n)
    if checking and failures:
        sys.exit("\n".join("compare.py --check: " + f for f in failures))


def judged(name, rows):
    """What eg2d's mesh of a geometry misses of issue 39's bounds against blockMesh's (--check)."""
    if "eg2d" not in rows or len(rows["eg2d"]) < 5:
        return ["%s: eg2d wrote no mesh" % name]
    _, b, _, b_nonorth, _ = rows["blockMesh"]
    _, e, verdict, nonorth, skew = rows["eg2d"]
    out = []
    if e["folds"]:
        out.append("%s: %d folded cells" % (name, e["folds"]))
    if verdict not in ("OK", "Failed 1 mesh checks (High aspect ratio cells found)"):
        out.append("%s: checkMesh: %s" % (name, verdict))
    if nonorth is None or not nonorth <= b_nonorth + 5.0:
        out.append("%s: non-orthogonality %s against blockMesh's %.3g + 5" % (name, nonorth, b_nonorth))
    if skew is None or not skew <= 4.0:
        out.append("%s: skewness %s over checkMesh's 4" % (name, skew))
    if not e["ratio"] <= b["ratio"] * 1.001:
        out.append("%s: size ratio %.4g against blockMesh's %.4g" % (name, e["ratio"], b["ratio"]))
    if not (e["kink"] < b["kink"] or e["kink"] <= e["nearby"]):
        out.append("%s: interface turn %.3g, blockMesh's %.3g, nearby %.3g" % (name, e["kink"], b["kink"], e["nearby"]))
    return out


if __name__ == "__main__":
    main()
