#!/usr/bin/env python3
"""Cf = tau_w / (0.5 rho U^2) on the patch "plate" of an OpenFOAM case at a given x,
linear between the two face centres around it, from the wallShearStress field
(kinematic, U = 1) that the function object wrote at a time.

    cf.py CASE TIME [X]        prints Cf
    cf.py CASE TIME --profile  prints x Cf per face
"""
import re
import sys


def strip_comments(text):
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    return re.sub(r"//[^\n]*", "", text)


def list_body(text, start=0):
    """The first 'N ( ... )' list at or after start: (N, body)."""
    m = re.compile(r"(\d+)\s*\(").search(text, start)
    n = int(m.group(1))
    depth, i = 1, m.end()
    while depth:
        c = text[i]
        depth += (c == "(") - (c == ")")
        i += 1
    return n, text[m.end():i - 1]


def read_mesh_patch(case, patch):
    mesh = case + "/constant/polyMesh/"
    pts_n, body = list_body(strip_comments(open(mesh + "points").read()))
    pts = [tuple(map(float, t.split())) for t in re.findall(r"\(([^()]*)\)", body)]
    assert len(pts) == pts_n
    fac_n, body = list_body(strip_comments(open(mesh + "faces").read()))
    faces = [tuple(map(int, t.split())) for t in re.findall(r"\d+\(([^()]*)\)", body)]
    assert len(faces) == fac_n
    bnd = strip_comments(open(mesh + "boundary").read())
    m = re.search(r"\b" + patch + r"\s*\{([^}]*)\}", bnd)
    nf = int(re.search(r"nFaces\s+(\d+)", m.group(1)).group(1))
    sf = int(re.search(r"startFace\s+(\d+)", m.group(1)).group(1))
    xc = []
    for f in faces[sf:sf + nf]:
        xc.append(sum(pts[k][0] for k in f) / len(f))
    return xc


def read_tau(case, time, patch):
    text = strip_comments(open("%s/%s/wallShearStress" % (case, time)).read())
    bf = text.index("boundaryField")
    m = re.compile(r"\b" + patch + r"\s*\{").search(text, bf)
    seg = text[m.end():]
    v = re.search(r"value\s+(uniform|nonuniform)", seg)
    if v.group(1) == "uniform":
        raise SystemExit("cf.py: uniform wallShearStress on %s" % patch)
    n, body = list_body(seg, v.end())
    tau = [tuple(map(float, t.split())) for t in re.findall(r"\(([^()]*)\)", body)]
    assert len(tau) == n
    return tau


def main():
    case, time = sys.argv[1], sys.argv[2]
    xc = read_mesh_patch(case, "plate")
    tau = read_tau(case, time, "plate")
    cf = [-2.0 * t[0] for t in tau]          # tau_w = -tau_x on a wall below the flow; 0.5 U^2 = 0.5
    order = sorted(range(len(xc)), key=lambda k: xc[k])
    xs, cs = [xc[k] for k in order], [cf[k] for k in order]
    if len(sys.argv) > 3 and sys.argv[3] == "--profile":
        for a, b in zip(xs, cs):
            print("%.9g %.9g" % (a, b))
        return
    x = float(sys.argv[3]) if len(sys.argv) > 3 else 0.97
    for k in range(len(xs) - 1):
        if xs[k] <= x <= xs[k + 1]:
            w = (x - xs[k]) / (xs[k + 1] - xs[k])
            print("%.7g" % ((1 - w) * cs[k] + w * cs[k + 1]))
            return
    raise SystemExit("cf.py: x = %g is not between the plate's face centres" % x)


main()
