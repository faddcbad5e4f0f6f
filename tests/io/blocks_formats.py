#!/usr/bin/python3
"""A set of blocks written as one mesh, checked by readers eg2d did not write.

Usage: blocks_formats.py WRITE_BLOCK_SAMPLES OUTDIR cgns|no-cgns [CGNSCHECK]
Runs WRITE_BLOCK_SAMPLES OUTDIR (a backward-facing step in three blocks,
and a pair of blocks one turned by 90 degrees; write_block_samples.c), then:
  SU2: meshio reads the points (the joined nodes once) and the quads, every
    quad counter-clockwise, no edge in more than two quads, the boundary
    edges (those of one quad) exactly the markers' edges, each once, the
    markers wall, inlet and outlet with their edge counts;
  OpenFOAM: checkMesh says "Mesh OK.", one region (the joins are interior
    faces), upper-triangular order, its patch table wall, inlet, outlet and
    frontAndBack with their face counts, and a cell zone a block, named as
    the block, with the block's cells;
  Plot3D: the three zones read by OpenFOAM's plot3dToFoam (which merges
    the points zones share), then checkMesh: "Mesh OK.", one region, the
    cells, and the boundary faces less the joins';
  CGNS: cgnscheck reports no error (it checks each 1-to-1 transform against
    its ranges) and `cgnscheck -v` lists a zone a block, the boundary
    conditions less the joined sides, and each join from both zones with
    its transform ([1,2] on the step, [2,-1] and [-2,1] on the turned pair);
  VTK multiblock: VTK's vtkXMLMultiBlockDataReader reads step.vtm as three
    structured blocks named "upstream", "upper" and "lower" (the
    blocks' names, eg2d_blocks_set_name) of the blocks' sizes, every point
    the block's node (OUTDIR/step_nodes.txt, eg2d_get_coordinates) exactly,
    z = 0, the cell data of the vts format; each block file byte for byte
    the block's grid as eg2d_write writes a .vts, laid out as VTK's writer
    lays it out (step/step_K.vts); the joined nodes of neighbouring blocks
    the same points (block 0's IMAX and block 1's IMIN, block 1's JMIN and
    block 2's JMAX); one.vtm (a grid alone) one block, "block0".
The counts come from the blocks' sizes (OUTDIR/step.txt)."""
import os
import re
import shutil
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from solver_formats import check, checkmesh_env, failures, run_cgnscheck  # noqa: E402


def main():
    writer, out, with_cgns = sys.argv[1], sys.argv[2], sys.argv[3] == "cgns"
    cgnscheck = sys.argv[4] if len(sys.argv) > 4 else None
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    subprocess.run([writer, out] + ([] if with_cgns else ["no-cgns"]), check=True)
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
    env = checkmesh_env()
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
    # the blocks as cell zones named as the blocks, block by block
    section = log.split("Checking basic cellZone addressing...")[-1].split("\n\n")[0]
    zones = {k: int(v) for k, v in re.findall(r"^\s{4}(\w+)\s+(\d+)\s+\d+\s+\S+\s+\(", section, re.M)}
    sizes = [(25, 41), (81, 41), (81, 17)]
    want = {n: (ni - 1) * (nj - 1) for n, (ni, nj) in zip(["upstream", "upper", "lower"], sizes)}
    check("cell zones:       3" in log and zones == want, f"openfoam: checkMesh's cell zones and cells {zones} == {want}")
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
    if with_cgns and cgnscheck:
        check_cgns(out, cgnscheck)
    check_vtm(out)
    return 1 if failures else 0


def read_nodes(path):
    """Each block's nodes as an (nj, ni, 2) array, i fastest."""
    values = np.loadtxt(path)
    blocks, k = [], 0
    while k < len(values):
        ni, nj = int(values[k][0]), int(values[k][1])
        blocks.append(values[k + 1:k + 1 + ni * nj].reshape(nj, ni, 2))
        k += 1 + ni * nj
    return blocks


def check_vtm(out):
    import filecmp
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
    nodes = read_nodes(os.path.join(out, "step_nodes.txt"))

    def read(name, want, labels):
        reader = vtk.vtkXMLMultiBlockDataReader()
        reader.SetFileName(os.path.join(out, name))
        reader.Update()
        data = reader.GetOutput()
        n = data.GetNumberOfBlocks()
        check(n == len(want), f"vtm {name}: vtkXMLMultiBlockDataReader reads {n} blocks == {len(want)}")
        points = []
        for k in range(min(n, len(want))):
            grid, node = data.GetBlock(k), want[k]
            nj, ni = node.shape[:2]
            label = data.GetMetaData(k).Get(vtk.vtkCompositeDataSet.NAME())
            check(grid is not None and grid.IsA("vtkStructuredGrid") and label == labels[k]
                  and tuple(grid.GetDimensions()) == (ni, nj, 1),
                  f"vtm {name}: block {k} \"{label}\" a StructuredGrid of "
                  f"{tuple(grid.GetDimensions()) if grid else None} == {(ni, nj, 1)} points")
            p = vtk_to_numpy(grid.GetPoints().GetData()).reshape(nj, ni, 3)
            check(np.array_equal(p[:, :, :2], node) and not p[:, :, 2].any(),
                  f"vtm {name}: block {k}'s {ni * nj} points are its nodes exactly "
                  f"(largest difference {np.abs(p[:, :, :2] - node).max():.3g}), z = 0")
            cells = grid.GetCellData()
            sizes = {cells.GetArrayName(a): cells.GetArray(a).GetNumberOfTuples() for a in range(cells.GetNumberOfArrays())}
            check(sizes and set(sizes.values()) == {(ni - 1) * (nj - 1)},
                  f"vtm {name}: block {k} has {len(sizes)} cell arrays of {(ni - 1) * (nj - 1)} cells")
            points.append(p[:, :, :2])
        return points

    blocks = read("step.vtm", nodes, ["upstream", "upper", "lower"])
    for k in range(len(nodes)):
        same = filecmp.cmp(os.path.join(out, "step", f"step_{k}.vts"), os.path.join(out, f"step-{k}.vts"), shallow=False)
        check(same, f"vtm step: step/step_{k}.vts is block {k} as eg2d_write writes it (step-{k}.vts)")
    if len(blocks) == 3:
        for what, a, b in [("block 0's IMAX and block 1's IMIN", blocks[0][:, -1], blocks[1][:, 0]),
                           ("block 1's JMIN and block 2's JMAX", blocks[1][0, :], blocks[2][-1, :])]:
            check(a.shape == b.shape and np.array_equal(a, b),
                  f"vtm step: the {len(a)} joined nodes of {what} are the same points "
                  f"(largest difference {np.abs(a - b).max() if a.shape == b.shape else '?'})")
    read("one.vtm", nodes[:1], ["block0"])


def check_cgns(out, cgnscheck):
    for name, zones, bcs, conns in [
        ("step", ["upstream", "upper", "lower"],
         {"upstream": {"wall": "1:25,1:1", "wall_2": "1:25,41:41", "inlet": "1:1,1:41"},
          "upper": {"wall": "1:81,41:41", "outlet": "81:81,1:41"},
          "lower": {"wall": "1:81,1:1", "wall_2": "1:1,1:17", "outlet": "81:81,1:17"}},
         {("upstream", "join1"): ("25:25,1:41", "upper", "1:1,1:41", "1,2"),
          ("upper", "join1"): ("1:1,1:41", "upstream", "25:25,1:41", "1,2"),
          ("upper", "join2"): ("1:81,1:1", "lower", "1:81,17:17", "1,2"),
          ("lower", "join2"): ("1:81,17:17", "upper", "1:81,1:1", "1,2")}),
        ("turned", ["block0", "block1"], None,
         {("block0", "join1"): ("9:9,1:9", "block1", "9:1,1:1", "2,-1"),
          ("block1", "join1"): ("9:1,1:1", "block0", "9:9,1:9", "-2,1")})]:
        log = run_cgnscheck(out, name, cgnscheck)
        # Split the verbose listing by zone.
        parts = re.split(r'^checking zone "(\w+)"', log, flags=re.M)
        by_zone = {parts[k]: parts[k + 1] for k in range(1, len(parts) - 1, 2)}
        # the CGNS library lists zones by name, whatever order they were written in
        check(list(by_zone) == sorted(zones), f"cgns {name}: zones {list(by_zone)} == {sorted(zones)}")
        got_conns = {}
        got_bcs = {}
        for z, text in by_zone.items():
            for m in re.findall(r'checking 1to1 connectivity "(\w+)"\s+Range=\[([^\]]*)\].*?Donor Name=(\w+)'
                                r'\s+Donor Range=\[([^\]]*)\].*?Transform=\[([^\]]*)\]', text, re.S):
                got_conns[(z, m[0])] = m[1:]
            got_bcs[z] = {m[0]: m[1] for m in re.findall(r'checking BC "(\w+)".*?Range=\[([^\]]*)\]', text, re.S)}
        check(got_conns == conns, f"cgns {name}: 1-to-1 connections {got_conns} == {conns}")
        if bcs is not None:
            check(got_bcs == bcs, f"cgns {name}: boundary conditions {got_bcs} == {bcs}")


if __name__ == "__main__":
    sys.exit(main())
