#!/usr/bin/python3
"""Reads back every file eg2d writes with readers eg2d did not write.

Usage: readback.py WRITE_SAMPLES OUTDIR cgns|no-cgns [CGNSCHECK]
(no-cgns: the library was built without the CGNS plugin).
Runs WRITE_SAMPLES OUTDIR (a converged test-domain grid in every format, plus the
reference coordinates and per-cell quality printed by the test program),
then: VTK's vtkXMLStructuredGridReader (.vts, points and cell data) and
vtkMultiBlockPLOT3DReader (every Plot3D variant), cgnscheck and (when VTK
has it) vtkCGNSReader for the CGNS file, Python parses of the GMV and
Matlab files, and Python's xml parser for the SVG pictures.
Coordinates must agree to 1e-12 (4-byte-real Plot3D: 1e-6 relative)."""
import os
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

TOL = 1e-12
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def load_reference(d):
    with open(os.path.join(d, "reference.txt")) as f:
        ni, nj = map(int, f.readline().split())
        xy = np.loadtxt(f)
    quality = {}
    with open(os.path.join(d, "quality.txt")) as f:
        for line in f:
            name, *values = line.split()
            quality[name] = np.array(values, dtype=float)
    return ni, nj, xy[:, 0], xy[:, 1], quality


def points_error(points, x, y):
    p = vtk_to_numpy(points.GetData())
    return max(np.abs(p[:, 0] - x).max(), np.abs(p[:, 1] - y).max(), np.abs(p[:, 2]).max())


def check_vts(d, ni, nj, x, y, quality):
    r = vtk.vtkXMLStructuredGridReader()
    r.SetFileName(os.path.join(d, "grid.vts"))
    r.Update()
    g = r.GetOutput()
    check(g.GetDimensions() == (ni, nj, 1), f"vts: dimensions {g.GetDimensions()} == ({ni}, {nj}, 1)")
    e = points_error(g.GetPoints(), x, y)
    check(e <= TOL, f"vts: vtkXMLStructuredGridReader coordinates, max error {e:.3e} <= {TOL}")
    cd = g.GetCellData()
    for name, ref in quality.items():
        a = cd.GetArray(name)
        if a is None:
            check(False, f"vts: cell data {name} present")
            continue
        v = vtk_to_numpy(a)
        e = np.abs(v - ref).max() / max(1.0, np.abs(ref).max())
        check(len(v) == (ni - 1) * (nj - 1) and e <= TOL, f"vts: cell data {name}, {len(v)} values, rel. error {e:.3e}")


def check_scaled_jacobian(d, quality):
    """The library's per-cell scaled Jacobian equals VTK's vtkMeshQuality (Verdict's) on the .vts."""
    r = vtk.vtkXMLStructuredGridReader()
    r.SetFileName(os.path.join(d, "grid.vts"))
    q = vtk.vtkMeshQuality()
    q.SetInputConnection(r.GetOutputPort())
    q.SetQuadQualityMeasureToScaledJacobian()
    q.Update()
    v = vtk_to_numpy(q.GetOutput().GetCellData().GetArray("Quality"))
    ref = quality.get("scaled_jacobian")
    if ref is None:
        check(False, "quality.txt has scaled_jacobian")
        return
    e = np.abs(v - ref).max()
    check(len(v) == len(ref) and e <= TOL and ref.min() > 0,
          f"vtkMeshQuality scaled Jacobian == EG2D_QUALITY_SCALED_JACOBIAN per cell, max error {e:.3e}, "
          f"smallest {ref.min():.4f}")


PLOT3D = [
    # file, binary, multi, 2d, byte count, big endian, double
    ("grid.x", True, False, True, True, False, True),
    ("grid_3d.x", True, False, False, True, False, True),
    ("grid_multi.x", True, True, True, True, False, True),
    ("grid_3d_multi.x", True, True, False, True, False, True),
    ("grid_be.x", True, False, True, True, True, True),
    ("grid_3d_multi_be.x", True, True, False, True, True, True),
    ("grid_single.x", True, False, True, True, False, False),
    ("grid_stream.x", True, False, True, False, False, True),
    ("grid_ascii.x", False, False, True, False, False, True),
    ("grid_ascii_3d.x", False, False, False, False, False, True),
    ("grid_ascii_multi.x", False, True, True, False, False, True),
    ("grid_ascii_3d_multi.x", False, True, False, False, False, True),
]


def check_plot3d(d, ni, nj, x, y):
    for name, binary, multi, two_d, byte_count, big, double in PLOT3D:
        r = vtk.vtkMultiBlockPLOT3DReader()
        r.SetXYZFileName(os.path.join(d, name))
        r.AutoDetectFormatOff()
        r.SetBinaryFile(binary)
        r.SetMultiGrid(multi)
        r.SetTwoDimensionalGeometry(two_d)
        r.SetHasByteCount(byte_count)
        r.SetByteOrderToBigEndian() if big else r.SetByteOrderToLittleEndian()
        r.SetDoublePrecision(double)
        r.SetIBlanking(False)
        r.Update()
        out = r.GetOutput()
        g = out.GetBlock(0) if out.GetNumberOfBlocks() > 0 else None
        if g is None or g.GetPoints() is None:
            check(False, f"plot3d {name}: vtkMultiBlockPLOT3DReader read a grid")
            continue
        tol = TOL if double else 1e-6 * max(np.abs(x).max(), np.abs(y).max())
        e = points_error(g.GetPoints(), x, y)
        check(g.GetDimensions() == (ni, nj, 1) and e <= tol,
              f"plot3d {name}: vtkMultiBlockPLOT3DReader dims {g.GetDimensions()}, max error {e:.3e} <= {tol:.0e}")


def check_cgns(d, ni, nj, x, y, cgnscheck):
    path = os.path.join(d, "grid.cgns")
    p = subprocess.run([cgnscheck, path], capture_output=True, text=True)
    errors = [l for l in (p.stdout + p.stderr).splitlines() if "ERROR" in l.upper()]
    check(p.returncode == 0 and not errors and "checking complete" in p.stdout,
          f"cgns: cgnscheck exit {p.returncode}, {len(errors)} errors")
    if hasattr(vtk, "vtkCGNSReader"):
        r = vtk.vtkCGNSReader()
        r.SetFileName(path)
        r.Update()
        it = r.GetOutput().NewIterator()
        it.InitTraversal()
        g = it.GetCurrentDataObject()
        e = points_error(g.GetPoints(), x, y)
        check(e <= TOL, f"cgns: vtkCGNSReader coordinates, max error {e:.3e}")


def check_gmv(d, ni, nj, x, y, quality):
    with open(os.path.join(d, "grid.gmv")) as f:
        t = f.read().split()
    check(t[:2] == ["gmvinput", "ascii"] and t[2] == "nodes" and int(t[3]) == ni * nj, "gmv: header, node count")
    n = ni * nj
    xyz = np.array(t[4:4 + 3 * n], dtype=float).reshape(3, n)
    e = max(np.abs(xyz[0] - x).max(), np.abs(xyz[1] - y).max(), np.abs(xyz[2]).max())
    check(e <= TOL, f"gmv: coordinates, max error {e:.3e}")
    p = 4 + 3 * n
    nc = (ni - 1) * (nj - 1)
    check(t[p] == "cells" and int(t[p + 1]) == nc, "gmv: cells header")
    p += 2
    ok = True
    for j in range(nj - 1):
        for i in range(ni - 1):
            a = i + ni * j + 1
            ok &= t[p:p + 6] == ["quad", "4", str(a), str(a + 1), str(a + 1 + ni), str(a + ni)]
            p += 6
    check(ok, "gmv: every quad has its four 1-based corners counter-clockwise in (i, j)")
    check(t[p] == "variable", "gmv: variable section")
    p += 1
    seen = 0
    while t[p] != "endvars":
        name, where = t[p], t[p + 1]
        v = np.array(t[p + 2:p + 2 + nc], dtype=float)
        ok = where == "0" and name in quality and np.abs(v - quality[name]).max() <= TOL * max(1, np.abs(v).max())
        check(ok, f"gmv: cell variable {name}")
        seen += 1
        p += 2 + nc
    check(seen == len(quality) and t[p + 1:] == ["endgmv"], f"gmv: {seen} variables, endvars, endgmv")


def check_matlab(d, ni, nj, x, y):
    with open(os.path.join(d, "grid.m")) as f:
        text = f.read()
    for name, ref in (("xl", x), ("yl", y)):
        m = re.search(name + r" = \[(.*?)\];", text, re.S)
        rows = [r.split() for r in m.group(1).split(";") if r.strip()] if m else []
        a = np.array(rows, dtype=float) if rows else np.zeros((0, 0))
        # Matlab's xl(i, j) is node (i-1, j-1): rows i, columns j.
        ok = a.shape == (ni, nj) and np.abs(a - ref.reshape(nj, ni).T).max() <= TOL
        check(ok, f"matlab: {name} is a {a.shape} matrix equal to the reference")
    check(f"m = {ni};" in text and f"n = {nj};" in text and text.count("plot(") == 6, "matlab: sizes and plot calls")


def check_svg(d, ni, nj):
    ns = "{http://www.w3.org/2000/svg}"
    for name, coloured in (("grid.svg", True), ("grid_plain.svg", False)):
        root = ET.parse(os.path.join(d, name)).getroot()
        lines = root.findall(f".//{ns}polyline")
        boundary = [l for l in lines if l.get("class") == "boundary"]
        polys = root.findall(f".//{ns}polygon")
        check(root.tag == ns + "svg" and len(lines) == (ni - 2) + (nj - 2) + 4 and len(boundary) == 4,
              f"svg {name}: well-formed, {len(lines)} grid lines of which {len(boundary)} boundary")
        for l in boundary[:1]:
            pts = l.get("points").split()
            check(len(pts) == ni, f"svg {name}: JMIN boundary has {len(pts)} points")
        check(len(polys) == ((ni - 1) * (nj - 1) if coloured else 0), f"svg {name}: {len(polys)} coloured cells")


def main():
    exe, d = sys.argv[1], sys.argv[2]
    with_cgns = sys.argv[3] == "cgns"
    cgnscheck = sys.argv[4] if len(sys.argv) > 4 else shutil.which("cgnscheck")
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    subprocess.run([exe, d] + ([] if with_cgns else ["no-cgns"]), check=True)
    ni, nj, x, y, quality = load_reference(d)
    check_vts(d, ni, nj, x, y, quality)
    check_scaled_jacobian(d, quality)
    check_plot3d(d, ni, nj, x, y)
    if with_cgns:
        check_cgns(d, ni, nj, x, y, cgnscheck)
    else:
        print("skip cgns: built without the CGNS plugin")
    check_gmv(d, ni, nj, x, y, quality)
    check_matlab(d, ni, nj, x, y)
    check_svg(d, ni, nj)
    leftovers = [f for f in os.listdir(d) if ".eg2d-tmp-" in f]
    check(not leftovers, f"no temporary files left behind ({leftovers})")
    print(f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
