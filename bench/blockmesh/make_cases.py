#!/usr/bin/python3
"""Writes the eg2d case files of bench/blockmesh from one description of each
geometry's blocks, the description its blockMeshDict gives: the same vertices,
blocks, node counts and gradings, so that eg2d's sides carry blockMesh's own
boundary nodes (compare.py checks them against blockMesh's points).

  bench/blockmesh/make_cases.py      (rewrites pitzDaily/pitz-daily.toml,
                                      bfs/backward-facing-step-tmr.toml and
                                      bfs/system/blockMeshDict)

blockMesh's grading of an edge: sections (length fraction, cell fraction,
expansion ratio e = last cell / first cell); in a section of m cells the
cells grow geometrically by r = e^(1/(m-1)), so the node k of m sits at
(r^k - 1)/(r^m - 1) of the section: with s = k/m, (e^(m s/(m-1)) - 1)/(e^(m/(m-1)) - 1).
A section is one piece of the eg2d side, its share the cells' fraction.
"""
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def fraction(m, e):
    if abs(e - 1) < 1e-15:
        return "s"
    p = m / (m - 1)
    return f"({e!r}^({p!r}*s) - 1)/({e!r}^{p!r} - 1)"


def sections(grading, n):
    """blockMesh's sections of n cells: [(length fraction, cells, e)] (a
    section's cells are round(n * fraction), the last one the rest, as
    blockMesh's lineDivide counts them)."""
    if not isinstance(grading, list):
        return [(1.0, n, grading)]
    lt = sum(g[0] for g in grading)
    ct = sum(g[1] for g in grading)
    out, used = [], 0
    for k, (l, c, e) in enumerate(grading):
        m = n - used if k == len(grading) - 1 else int(n * c / ct + 0.5)
        out.append((l / lt, m, e))
        used += m
    return out


def side(key, p, q, grading, n):
    """A block's side from vertex p to q graded as blockMesh grades the edge."""
    secs = sections(grading, n)
    lines, start = [], 0.0
    for l, m, e in secs:
        a, b = start, start + l
        f = f"({a!r} + {b - a!r}*{fraction(m, e)})" if len(secs) > 1 else fraction(m, e)
        x = f"{p[0]!r} + {q[0] - p[0]!r}*{f}" if q[0] != p[0] else f"{p[0]!r}"
        y = f"{p[1]!r} + {q[1] - p[1]!r}*{f}" if q[1] != p[1] else f"{p[1]!r}"
        if len(secs) == 1:
            lines += [f"[blocks.sides.{key}]", f'x = "{x}"', f'y = "{y}"']
        else:
            lines += [f"[[blocks.sides.{key}]]", f"share = {m / n!r}", f'x = "{x}"', f'y = "{y}"']
        start = b
    return lines


def end_cells(p, q, grading, n):
    """The first and the last cell of blockMesh's graded edge p->q."""
    secs = sections(grading, n)
    length = ((q[0] - p[0]) ** 2 + (q[1] - p[1]) ** 2) ** 0.5

    def first(l, m, e):
        r = e ** (1 / (m - 1)) if m > 1 else 1.0
        return l * length / m if abs(r - 1) < 1e-15 else l * length * (r - 1) / (r ** m - 1)
    return first(*secs[0]), first(*secs[-1]) * secs[-1][2]


def node_fractions(grading, n):
    """The n + 1 nodes of blockMesh's graded edge as fractions of its length."""
    out, start = [0.0], 0.0
    for l, m, e in sections(grading, n):
        r = e ** (1 / (m - 1)) if m > 1 else 1.0
        for k in range(1, m + 1):
            out.append(start + l * (k / m if abs(r - 1) < 1e-15 else (r ** k - 1) / (r ** m - 1)))
        start += l
    return out


def wall_spacing(v, hexa, ni, nj, g, walls):
    """The block's wall_spacing: each wall side's first cell as blockMesh makes
    it, from the two edges that leave the wall's ends, interpolated along the
    wall at its nodes' fractions (blockMesh interpolates a block's inside from
    its edges so): one height where the two agree, else one per node."""
    a, b, c, d = hexa
    (gbot, gtop), (glef, grig) = g
    lef, rig = end_cells(v[a], v[d], glef, nj), end_cells(v[b], v[c], grig, nj)
    bot, top = end_cells(v[a], v[b], gbot, ni), end_cells(v[d], v[c], gtop, ni)
    ends = {"bottom": (lef[0], rig[0], gbot, ni), "top": (lef[1], rig[1], gtop, ni),
            "left": (bot[0], top[0], glef, nj), "right": (bot[1], top[1], grig, nj)}
    items = []
    for s in walls:
        h0, h1, grading, n = ends[s]
        if abs(h1 - h0) <= 1e-9 * max(h0, h1):
            items.append(f"{s} = {h0:.6g}")
        else:
            items.append(f"{s} = [" + ", ".join(f"{h0 + (h1 - h0) * t:.6g}" for t in node_fractions(grading, n)) + "]")
    return "wall_spacing = { " + ", ".join(items) + " }"


def toml(title, comment, verts, blocks, joins, patches, scale=1.0, walls=False):
    v = {k: (x * scale, y * scale) for k, (x, y) in verts.items()}
    out = [f"# {line}" if line else "#" for line in comment] + [
        f'title = "{title}"', 'system = "winslow"', "", "[output]", 'formats = ["openfoam", "vts"]', ""]
    for name, (a, b, c, d), (ni, nj), gx, gy in blocks:
        # hex (a b c d): bottom a->b, right b->c, top d->c, left a->d (blockMesh's
        # edgeGrading: x edges a-b, d-c; y edges a-d, b-c)
        gbot, gtop = (gx, gx) if not isinstance(gx, tuple) else gx
        glef, grig = (gy, gy) if not isinstance(gy, tuple) else gy
        out += ["[[blocks]]", f'name = "{name}"', f"size = [{ni + 1}, {nj + 1}]"]
        wall_sides = [s for s, t, _ in patches.get(name, []) if t == "wall"]
        if walls and wall_sides:  # the walls' first cells: for the graded wall layer on sets
            out.append(wall_spacing(v, (a, b, c, d), ni, nj, ((gbot, gtop), (glef, grig)), wall_sides))
        out += side("bottom", v[a], v[b], gbot, ni) + side("right", v[b], v[c], grig, nj)
        out += side("top", v[d], v[c], gtop, ni) + side("left", v[a], v[d], glef, nj)
        for s, t, pname in patches.get(name, []):
            out += ["[[blocks.patches]]", f'side = "{s}"', f'type = "{t}"', f'name = "{pname}"']
        out.append("")
    for (ba, sa), (bb, sb) in joins:
        out += ["[[joins]]", f'a = {{ block = "{ba}", side = "{sa}" }}', f'b = {{ block = "{bb}", side = "{sb}" }}', ""]
    return "\n".join(out)


# OpenFOAM-10's pitzDaily (pitzDaily/system/blockMeshDict, unchanged): mm.
negY = [(2, 4, 1), (1, 3, 0.3)]
posY = [(1, 4, 2), (2, 3, 4), (2, 4, 0.25)]
posYR = [(2, 1, 1), (1, 1, 0.25)]
pitz_verts = {0: (-20.6, 0), 1: (-20.6, 25.4), 2: (0, -25.4), 3: (0, 0), 4: (0, 25.4), 5: (206, -25.4),
              6: (206, 0), 7: (206, 25.4), 8: (290, -16.6), 9: (290, 0), 10: (290, 16.6)}
pitz_blocks = [  # name, hex (z = -0.5 face), cells, x grading, y grading ((left, right) if they differ)
    ("inlet", (0, 3, 4, 1), (18, 30), 0.5, posY),
    ("lower", (2, 5, 6, 3), (180, 27), 4, (negY, 1)),
    ("upper", (3, 6, 7, 4), (180, 30), 4, (posY, posYR)),
    ("lowerOut", (5, 8, 9, 6), (25, 27), 2.5, 1),
    ("upperOut", (6, 9, 10, 7), (25, 30), 2.5, posYR)]
pitz_joins = [(("inlet", "right"), ("upper", "left")), (("lower", "top"), ("upper", "bottom")),
              (("lower", "right"), ("lowerOut", "left")), (("upper", "right"), ("upperOut", "left")),
              (("lowerOut", "top"), ("upperOut", "bottom"))]
pitz_patches = {"inlet": [("left", "inflow", "inlet"), ("top", "wall", "upperWall"), ("bottom", "wall", "lowerWall")],
                "lower": [("left", "wall", "lowerWall"), ("bottom", "wall", "lowerWall")],
                "upper": [("top", "wall", "upperWall")],
                "lowerOut": [("bottom", "wall", "lowerWall"), ("right", "outflow", "outlet")],
                "upperOut": [("top", "wall", "upperWall"), ("right", "outflow", "outlet")]}

# Driver & Seegmiller's (1985) step as NASA's Turbulence Modeling Resource
# gives it (case 2DBFS; repository TMBWG/turbmodels, commit
# c3966ddea2280b6e39b8ad1f90001f20b886f266: backstep_val.html, the layout
# Backstep_validation/Plots/backstep_bcs_noborder.png, the grids
# Backstep_grids/*.nmf and Backstep_grids/Plots/backstep5_3levdn.p3dbin read
# for the zones' corners and spacings). Lengths in step heights H: inlet
# x = -130, step at x = 0, outlet x = 50; the channel y = 1..9 upstream,
# y = 0..9 downstream. TMR's zones 1 (x -130..-4) and 2 (-4..0) are kept;
# its zones 3 (0..8) and 4 (8..50) span the step's face and the channel, a
# block face blockMesh cannot join in part, so here they are one block above
# the step's top (y = 1..9) and one beside it (y = 0..1), each graded as TMR's
# two (uniform over x = 0..8, then growing to the outlet). Node counts are
# TMR's level "3 levels down" (65x65, 25x65, 97x113, 33x113 nodes); the
# ratios are those of its spacings (first cell about 7e-4 H at the walls and
# on both sides of y = 1). TMR's symmetry stretch x = -130..-110 of both
# walls is part of the walls here (a block face has one patch).
wall = [(0.5, 0.5, 1000.0), (0.5, 0.5, 0.001)]   # y = 1..9: toward both walls
step = [(0.5, 0.5, 140.0), (0.5, 0.5, 1 / 140.0)]  # y = 0..1: toward the wall and the step's top
down = [(8, 96, 1), (42, 32, 73.6)]                 # x = 0..50: TMR's zones 3 and 4
bfs_verts = {0: (-130, 1), 1: (-4, 1), 2: (0, 1), 3: (50, 1), 4: (-130, 9), 5: (-4, 9), 6: (0, 9), 7: (50, 9),
             8: (0, 0), 9: (50, 0)}
bfs_blocks = [("zone1", (0, 1, 5, 4), (64, 64), 0.0367, wall),
              ("zone2", (1, 2, 6, 5), (24, 64), 0.234, wall),
              ("upper", (2, 3, 7, 6), (128, 64), down, wall),
              ("lower", (8, 9, 3, 2), (128, 48), down, step)]
bfs_joins = [(("zone1", "right"), ("zone2", "left")), (("zone2", "right"), ("upper", "left")),
             (("lower", "top"), ("upper", "bottom"))]
bfs_patches = {"zone1": [("left", "inflow", "inlet"), ("bottom", "wall", "lowerWall"), ("top", "wall", "upperWall")],
               "zone2": [("bottom", "wall", "lowerWall"), ("top", "wall", "upperWall")],
               "upper": [("top", "wall", "upperWall"), ("right", "outflow", "outlet")],
               "lower": [("left", "wall", "lowerWall"), ("bottom", "wall", "lowerWall"), ("right", "outflow", "outlet")]}


def grading_text(g):
    if isinstance(g, list):
        return "(" + " ".join(f"({a} {b} {c})" for a, b, c in g) + ")"
    return repr(g)


def block_mesh_dict(verts, blocks, patches):
    """The blockMeshDict of a 2-D description (one cell deep, z = 0..1)."""
    keys = sorted(verts)
    idx = {k: n for n, k in enumerate(keys)}
    vs = [f"    ({verts[k][0]} {verts[k][1]} 0)" for k in keys] + [f"    ({verts[k][0]} {verts[k][1]} 1)" for k in keys]
    nv = len(keys)
    bl, faces = [], {}
    for name, (a, b, c, d), (ni, nj), gx, gy in blocks:
        h = [idx[a], idx[b], idx[c], idx[d]]
        bl.append(f"    hex ({' '.join(map(str, h + [k + nv for k in h]))}) {name} ({ni} {nj} 1)\n"
                  f"    simpleGrading ({grading_text(gx)} {grading_text(gy)} 1)")
        sides = {"bottom": (h[0], h[1]), "right": (h[1], h[2]), "top": (h[2], h[3]), "left": (h[3], h[0])}
        for s, t, pname in patches.get(name, []):
            p, q = sides[s]
            faces.setdefault((pname, t), []).append(f"            ({p} {q} {q + nv} {p + nv})")
        faces.setdefault(("frontAndBack", "empty"), []).append(
            f"            ({h[0]} {h[3]} {h[2]} {h[1]})\n            ({h[0] + nv} {h[1] + nv} {h[2] + nv} {h[3] + nv})")
    bnd = []
    for (pname, t), fs in faces.items():
        ft = {"wall": "wall", "empty": "empty"}.get(t, "patch")
        bnd.append(f"    {pname}\n    {{\n        type {ft};\n        faces\n        (\n" + "\n".join(fs) +
                   "\n        );\n    }")
    head = ("/*  Driver & Seegmiller's (1985) backward-facing step in TMR's proportions, in\n"
            "    four blocks: written by bench/blockmesh/make_cases.py (see it for the\n"
            "    sources); bench/blockmesh/compare.py meshes it with blockMesh and\n"
            "    bfs/backward-facing-step-tmr.toml with eg2d. Lengths in step heights. */\n"
            "FoamFile\n{\n    version     2.0;\n    format      ascii;\n    class       dictionary;\n"
            "    object      blockMeshDict;\n}\n\nconvertToMeters 1;\n\n")
    return (head + "vertices\n(\n" + "\n".join(vs) + "\n);\n\nblocks\n(\n" + "\n\n".join(bl) +
            "\n);\n\nedges\n(\n);\n\nboundary\n(\n" + "\n".join(bnd) + "\n);\n")


PITZ_COMMENT = [
    "OpenFOAM-10's pitzDaily, Pitz and Daily's (1983) step, as eg2d's set of blocks:",
    "the blocks, node counts and node distributions of its blockMeshDict",
    "(pitzDaily/system/blockMeshDict; OpenFOAM/OpenFOAM-10, commit",
    "2c6a80318abbb7d61ca37a619bd43aa6db667f36), lengths in metres. Each side is",
    "blockMesh's graded edge: geometric cells, last/first = the expansion ratio,",
    "multi-graded edges as pieces (share = the section's cells).",
    "Written by bench/blockmesh/make_cases.py; compared by compare.py."]
BFS_COMMENT = [
    "Driver and Seegmiller's (1985) backward-facing step in the proportions of",
    "NASA's Turbulence Modeling Resource (case 2DBFS), in four blocks with the",
    "node counts and gradings of bfs/system/blockMeshDict (lengths in step",
    "heights; the sources are in bench/blockmesh/make_cases.py, which writes",
    "this file). Each side is blockMesh's graded edge: geometric cells,",
    "last/first = the expansion ratio, multi-graded edges as pieces."]

if __name__ == "__main__":
    # pitzDaily's blocks are the tutorial's; its outlet blocks' contraction makes their
    # bottom and top edges slanted (graded by length, as blockMesh grades them)
    files = {"pitzDaily/pitz-daily.toml": toml("pitzDaily (OpenFOAM-10's blocks and node counts)", PITZ_COMMENT,
                                               pitz_verts, pitz_blocks, pitz_joins, pitz_patches, scale=0.001) + "\n",
             "bfs/backward-facing-step-tmr.toml": toml(
                 "Backward-facing step, Driver & Seegmiller's proportions (NASA TMR 2DBFS)", BFS_COMMENT,
                 bfs_verts, bfs_blocks, bfs_joins, bfs_patches) + "\n",
             "bfs/system/blockMeshDict": block_mesh_dict(bfs_verts, bfs_blocks, bfs_patches)}
    # the same with each block's walls given blockMesh's first cells (compare.py --walls)
    for name, (title, comment, verts, blocks, joins, patches, scale) in {
            "pitzDaily/pitz-daily-walls.toml": ("pitzDaily, first cells at the walls", PITZ_COMMENT, pitz_verts,
                                                pitz_blocks, pitz_joins, pitz_patches, 0.001),
            "bfs/backward-facing-step-tmr-walls.toml": ("Backward-facing step (TMR 2DBFS), first cells at the walls",
                                                        BFS_COMMENT, bfs_verts, bfs_blocks, bfs_joins, bfs_patches,
                                                        1.0)}.items():
        files[name] = toml(title, comment + ["The walls' first cells are blockMesh's (wall_spacing of each block)."],
                           verts, blocks, joins, patches, scale, walls=True) + "\n"
    for name, text in files.items():
        with open(os.path.join(HERE, name), "w") as f:
            f.write(text)
