#!/usr/bin/python3
"""Writes the case file of the NLR 7301 two-element airfoil (main element and
slotted flap, van den Berg & Oskam 1979) as a set of six blocks for the eg2d
command: bench/two-element-airfoil/README.md says what the library makes of it.

    make_case.py [--first-cell H] [--outflow X] [--n-far N] [--n-slot N] [--held]
                 [--legs D [--n-leg N] [--alpha A] [--beta B]] [-o CASE.toml]

The walls are the coordinates of nlr7301-main.dat and nlr7301-flap.dat, as
points of the case (splines through them, nodes by Vinokur's (1983)
distribution); the lines between the blocks are cubic Bezier curves written
as formulas in s; the far field a half circle of radius 10 chords about
(0.5, 0) closed by straight lines to the outflow at x = X.

Blocks (vertices: the main nose L, the cove's corner C, the cove's end D,
the main trailing edge T, the flap's nose F, the flap below D, E, the flap's
trailing edge G): "lower" under the main element from C round to L, "upper"
over it and its wake, "front" the fan from the slot's line C-F out to the
far field, "slot" between the cove C-D and the flap's nose F-E, "wake" from
the slot's end D-E between the main wake (with the cove's end D-T) and the
flap's upper surface and wake, "below_flap" under the flap and its wake.
Needs numpy (Debian's /usr/bin/python3)."""
import argparse
import os
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ap = argparse.ArgumentParser()
ap.add_argument("--first-cell", default="1e-4", help="first-cell height on both elements (chords)")
ap.add_argument("--outflow", type=float, default=10.5, help="x of the outflow (the main element's chord is 1)")
ap.add_argument("--n-far", type=int, default=65, help="nodes from the walls and wakes to the far field")
ap.add_argument("--n-slot", type=int, default=49, help="nodes across the slot")
ap.add_argument("--held", action="store_true",
                help="hold the slot's line, the slot's end, both wakes (and the legs) where the case puts them (eg2d_blocks_hold_join)")
ap.add_argument("--legs", default="0",
                help="start the slot's line and the lines from the cove's corner and the flap's nose this far off the walls (chords), "
                     "at the end of a line normal to them; auto: as far as --n-leg nodes growing by 1.2 from the first cell reach; 0: on the walls")
ap.add_argument("--alpha", type=float, default=30.0,
                help="with --legs: the line to the far field turns this far (degrees) from the cove's leg, away from the slot")
ap.add_argument("--alpha-flap", type=float, default=45.0,
                help="with --legs: the flap's stagnation line turns this far (degrees) from the flap's leg, away from the slot")
ap.add_argument("--beta", type=float, default=45.0,
                help="with --legs: the slot's line leaves each leg's end this far (degrees) from the leg's direction")
ap.add_argument("--reach", type=float, default=0.3,
                help="with --legs: the line to the far field and the flap's stagnation line keep their legs' ends' directions for about a third of this (chords)")
ap.add_argument("--n-leg", type=int, default=9, help="nodes along each such normal line")
ap.add_argument("--phia", type=float, default=215.0,
                help="where the line from the cove's corner meets the far field (degrees about (0.5, 0))")
ap.add_argument("--phib", type=float, default=250.0, help="where the flap's stagnation line meets the far field")
ap.add_argument("--phig", type=float,
                help="where the far field's circle ends below the flap (degrees; default: below its trailing edge)")
ap.add_argument("--ds-fte", type=float, default=0.001, help="spacing along the flap at its trailing edge")
ap.add_argument("--d-wake1", type=float, default=0.015,
                help="spacing along the main wake above the flap's trailing edge (the same as --ds-fte or so: the lines across the wakes' block then lean less)")
ap.add_argument("--n-upper", type=int, default=97, help="nodes along the main element's upper surface, nose to trailing edge")
ap.add_argument("--n-front", type=int, default=81, help="nodes along the main element's lower surface, from the slot's line to the nose")
ap.add_argument("--n-wake", type=int, default=49, help="nodes along each wake from the flap's trailing edge on, to the outflow")
ap.add_argument("--d-far", type=float, default=1.0, help="spacing at the far field (chords)")
ap.add_argument("--solver", help="[solver] method (the library's default: multigrid)")
ap.add_argument("--growth-limit", help="[controls] wall_growth_limit (the command's default: 1.2)")
ap.add_argument("-o", default=os.path.join(HERE, "two-element-airfoil.toml"))
args = ap.parse_args()

M = np.loadtxt(os.path.join(HERE, "nlr7301-main.dat"))
F = np.loadtxt(os.path.join(HERE, "nlr7301-flap.dat"))
ILE, IFL, IC, ID, IE = 120, 77, 232, 12, 22   # nose, flap nose, cove corner (of M); cove end (of the cove), E (of the flap's upper surface)
R, XC, XO = 10.0, 0.5, args.outflow
upper = M[:ILE + 1][::-1]          # L -> T
front = M[ILE:IC + 1][::-1]        # C -> L along the lower surface
cove = M[IC:]                      # C -> T
fup = F[:IFL + 1][::-1]            # F -> G over the flap
flo = F[IFL:]                      # F -> G under it
C, T, FL, G = M[IC], M[0], F[IFL], F[0]


def u(deg):
    r = np.radians(deg)
    return np.array([np.cos(r), np.sin(r)])


def angle(v):
    return np.degrees(np.arctan2(v[1], v[0]))


def circle(phi):
    return np.array([XC + R * np.cos(np.radians(phi)), R * np.sin(np.radians(phi))])


def bezier(P, t):
    t = np.asarray(t)[:, None]
    return (1 - t)**3 * P[0] + 3 * (1 - t)**2 * t * P[1] + 3 * (1 - t) * t**2 * P[2] + t**3 * P[3]


def split(P, s):
    P = [np.array(p) for p in P]
    a = [(1 - s) * P[i] + s * P[i + 1] for i in range(3)]
    b = [(1 - s) * a[i] + s * a[i + 1] for i in range(2)]
    c = (1 - s) * b[0] + s * b[1]
    return [P[0], a[0], b[0], c], [c, b[1], a[2], P[3]]


PHIA, PHIB = args.phia, args.phib
PHIG = (f"phig = {args.phig:g}          # where the far field's circle ends below the flap" if args.phig is not None
        else 'phig = "360 - acos((gx - xc)/R)*180/pi"   # and below the flap\'s')
A, B = circle(PHIA), circle(PHIB)
# The slot's line leaves the cove 45 degrees below it and the flap's nose 50
# degrees from its upper surface; the line to the far field from C and the
# flap's stagnation line leave 90 degrees further round.
cove_dir = angle(M[IC + 1] - M[IC])
slot0, slot1 = cove_dir - 45.0, angle(fup[1] - fup[0]) + 50.0
LEG_GROWTH = 1.2
LEG = (float(args.first_cell) * (LEG_GROWTH**(args.n_leg - 1) - 1) / (LEG_GROWTH - 1) if args.legs == "auto"
       else float(args.legs))
LEGS = LEG > 0
BETA, REACH = args.beta, args.reach
if LEGS:
    # The lines meet the walls only at 90 degrees: a normal line ("leg") from
    # the cove's corner and from the flap's nose, shared by the two blocks
    # beside it; at each leg's end the slot's line turns BETA degrees toward
    # the other leg's end and the line to the far field (the flap's
    # stagnation line) ALPHA degrees away from it.
    def normal(P, i):
        d = P[i + 1] - P[i - 1]
        return np.array([d[1], -d[0]]) / np.hypot(*d)
    nc, nf = normal(M, IC), normal(F, IFL)
    C1, F1 = C + LEG * nc, FL + LEG * nf
    Ls = np.linalg.norm(F1 - C1)

    def fork(n, toward, alpha):
        """The leg's direction n turned BETA degrees toward the point toward, and alpha away from it."""
        def rot(t):
            t = np.radians(t)
            return np.array([np.cos(t) * n[0] - np.sin(t) * n[1], np.sin(t) * n[0] + np.cos(t) * n[1]])
        side = 1.0 if np.cross(n, toward) > 0 else -1.0
        return rot(side * BETA), rot(-side * alpha)
    (sc, lc), (sf, st) = fork(nc, F1 - C1, args.alpha), fork(nf, C1 - F1, args.alpha_flap)
    lines = {"slot": [F1, F1 + Ls / 3 * sf, C1 + Ls / 3 * sc, C1],
             "lc": [C1, C1 + REACH * lc, A - 4.0 * u(PHIA), A],
             "stag": [F1, F1 + REACH * st, B - 4.0 * u(PHIB), B]}
    h, n = float(args.first_cell), args.n_leg
    q = np.linspace(1.0001, 2.0, 200001)   # the legs' nodes grow geometrically from the wall's first cell
    q = q[np.argmin(np.abs(h * (q**(n - 1) - 1) / (q - 1) - LEG))]
    HL = f"{h * q**(n - 2):.3g}"
else:
    Ls = np.linalg.norm(FL - C)
    lines = {"slot": [FL, FL + Ls / 3 * u(slot1), C + Ls / 3 * u(slot0), C],
             "lc": [C, C + 0.4 * u(slot0 - 90.0), A - 4.0 * u(PHIA), A],
             "stag": [FL, FL + 0.4 * u(slot1 + 90.0), B - 4.0 * u(PHIB), B]}
# The wakes leave along their trailing edges' bisectors and end level at the outflow.
te_m = (angle(upper[-1] - upper[-2]) + angle(M[-1] - M[-2])) / 2
te_f = (angle(fup[-1] - fup[-2]) + angle(flo[-1] - flo[-2])) / 2
W1, W2 = np.array([XO, -0.25]), np.array([XO, -0.5])
LW = XO - T[0]
wake_m = [T, T + min(1.0, 0.3 * LW) * u(te_m), W1 - np.array([0.3 * LW, 0]), W1]
lines["fwake"] = [G, G + min(0.6, 0.25 * LW) * u(te_f), W2 - np.array([0.3 * LW, 0]), W2]
# The main wake is two pieces, split where a line from G at 68 degrees meets it.
t = np.linspace(0, 0.3, 300001)
d = bezier(wake_m, t) - G
tw = t[np.argmin(np.abs(d[:, 0] * u(68.0)[1] - d[:, 1] * u(68.0)[0]))]
lines["wake1"], lines["wake2"] = split(wake_m, tw)
WP = lines["wake1"][3]
cove1, cove2 = cove[:ID + 1], cove[ID:]


def f(v):
    return repr(round(float(v), 6))


def bez(P, ends):
    def one(k):
        c = [ends[0][k], f(P[1][k]), f(P[2][k]), ends[1][k]]
        return f"(1-s)^3*{c[0]} + 3*(1-s)^2*s*{c[1]} + 3*(1-s)*s^2*{c[2]} + s^3*{c[3]}"
    return f'x = "{one(0)}"\ny = "{one(1)}"\n'


def pts(P):
    rows = [f"[{x:.5f}, {y:.5f}]" for x, y in P]
    return "points = [\n" + ",\n".join("  " + ", ".join(rows[i:i + 6]) for i in range(0, len(rows), 6)) + "]\n"


def dist(first, last):
    return f'distribution = {{ kind = "vinokur", first = "{first}", last = "{last}" }}\n'


def patch(side, kind, name, first=None, last=None):
    """A [[blocks.patches]] table: nodes first to last of the side (all by default)."""
    ends = "".join(f'{key} = "{value}"\n' for key, value in (("first", first), ("last", last)) if value)
    return f'[[blocks.patches]]\nside = "{side}"\n{ends}type = "{kind}"\nname = "{name}"\n'


def arc(start, end):
    """The far field's circle from angle start to angle end (degrees about (xc, 0))."""
    phi = f"({start} + ({end} - {start})*s)*pi/180"
    return f'x = "xc + R*cos({phi})"\ny = "R*sin({phi})"\n'


Cn, FLn, An, Bn, WPn = ("cx", "cy"), ("fx", "fy"), ("ax", "ay"), ("bx", "by"), ("wpx", "wpy")
W1n, W2n, Tn, Gn = ("xo", "yw1"), ("xo", "yw2"), ("tx", "ty"), ("gx", "gy")
L = lines

def far_field(side, start, end, arc_intervals, x0, y, line_intervals):
    """The circle from angle start to end, then the straight far field from (x0, y) to the outflow."""
    return (f'[[blocks.sides.{side}]]\n{arc(start, end)}share = "({arc_intervals})/(ni - 1)"\n'
            f'[[blocks.sides.{side}]]\nx = "{x0} + (xo - {x0})*s"\ny = "{y}"\n'
            f'share = "({line_intervals})/(ni - 1)"\n{dist("d_ff", "d_wo")}')


def main_wake(side):
    """The main wake as the last two pieces of a side: the same nodes in both blocks it joins."""
    return (f'[[blocks.sides.{side}]]\nshare = "(n_wake1 - 1)/(ni - 1)"\n'
            f"{dist('ds_te', 'd_wake1')}{bez(L['wake1'], (Tn, WPn))}"
            f'[[blocks.sides.{side}]]\nshare = "(n_wake - 1)/(ni - 1)"\n'
            f"{dist('d_wake1', 'd_wo')}{bez(L['wake2'], (WPn, W1n))}")

stag_main = 'x = "lx + (xc - R - lx)*s"\ny = "ly*(1 - s)"\n'


def heights(wall, wake):
    """A side's first cells node by node with legs: h on its wall's nodes, then
    along a wake growing geometrically to d_wake at the outflow, so that the
    rows beside the wake open up downstream as the outflow's (the side's
    joined nodes grade the lines that leave them as its wall's do)."""
    h = float(args.first_cell)
    q = (D_WAKE / h)**(1.0 / (wake - 1))
    v = [h] * wall + [h * q**k for k in range(1, wake)]
    return "[" + ", ".join(f"{x:.4g}" for x in v) + "]"


N_WAKE1, D_WAKE = 41, 0.004   # the case's n_wake1 and d_wake (below)
N_MAIN_WAKE = N_WAKE1 + args.n_wake - 1   # n_wake1 + n_wake - 1: the main wake's nodes, its trailing edge's included
if LEGS:
    WS_UPPER = f"wall_spacing = {{ bottom = {heights(args.n_upper, N_MAIN_WAKE)} }}"
    WS_WAKE = f"wall_spacing = {{ bottom = {heights(49, args.n_wake)}, top = {heights(9, N_MAIN_WAKE)} }}"
    WS_FLAP = f"wall_spacing = {{ top = {heights(65, args.n_wake)} }}"
else:
    WS_UPPER, WS_WAKE, WS_FLAP = (f"wall_spacing = {{{{ {k} }}}}".replace("{{", "{").replace("}}", "}")
                                  for k in ('bottom = "h"', 'bottom = "h", top = "h"', 'top = "h"'))


def leg(side, wall, end, a, b, count):
    """A piece of a side: the straight leg from the point named wall to the one named end."""
    return (f'[[blocks.sides.{side}]]\nshare = "({count} - 1)/(nj - 1)"\n'
            f'points = [["{wall[0]}", "{wall[1]}"], ["{end[0]}", "{end[1]}"]]\n{dist(a, b)}')


C1n, F1n = ("c1x", "c1y"), ("f1x", "f1y")
if LEGS:
    lower_left = (leg("left", Cn, C1n, "hs", "hl", "n_leg")
                  + f'[[blocks.sides.left]]\nshare = "(n_lc - 1)/(nj - 1)"\n{dist("hl", "d_far")}{bez(L["lc"], (C1n, An))}')
    front_size, front_bottom = '"n_sl", "n_lc"', f"[blocks.sides.bottom]\n{dist('hl', 'hl')}{bez(L['slot'], (F1n, C1n))}"
    front_right = f"[blocks.sides.right]\n{dist('hl', 'd_far')}{bez(L['lc'], (C1n, An))}"
    front_left = f"[blocks.sides.left]\n{dist('hl', 'd_far')}{bez(L['stag'], (F1n, Bn))}"
    slot_left = (leg("left", FLn, F1n, "hs", "hl", "n_leg")
                 + f'[[blocks.sides.left]]\nshare = "(n_sl - 1)/(nj - 1)"\n{dist("hl", "hl")}{bez(L["slot"], (F1n, C1n))}'
                 + leg("left", C1n, Cn, "hl", "hs", "n_leg"))
    flap_left = (f'[[blocks.sides.left]]\nshare = "(n_lc - 1)/(nj - 1)"\nreverse = true\n{dist("hl", "d_far")}{bez(L["stag"], (F1n, Bn))}'
                 + leg("left", F1n, FLn, "hl", "hs", "n_leg"))
    side_joins = f"""[[joins]]   # the line from the cove to the far field
a = "front.right"
b = {{ block = "lower", side = "left", first = "n_leg - 1", last = "n_n - 1" }}

[[joins]]   # the slot's line, from the flap's nose to the cove
a = "front.bottom"
b = {{ block = "slot", side = "left", first = "n_leg - 1", last = "n_s - n_leg" }}

[[joins]]   # the flap's stagnation line
a = "front.left"
b = {{ block = "below_flap", side = "left", first = "n_lc - 1", last = 0 }}

[[joins]]   # the line normal to the cove's corner
a = {{ block = "lower", side = "left", first = 0, last = "n_leg - 1" }}
b = {{ block = "slot", side = "left", first = "n_s - 1", last = "n_s - n_leg" }}

[[joins]]   # the line normal to the flap's nose
a = {{ block = "below_flap", side = "left", first = "n_n - 1", last = "n_lc - 1" }}
b = {{ block = "slot", side = "left", first = 0, last = "n_leg - 1" }}
"""
    leg_constants = f"""n_leg = {args.n_leg}         # nodes along the lines normal to the cove's corner and the flap's nose
n_lc = "n_n - n_leg + 1"   # nodes from their ends out to the far field
n_sl = "n_s - 2*n_leg + 2"   # nodes along the slot's line between them
hl = {HL}        # spacing at the normal lines' ends
c1x = {C1[0]:.8f}        # the end of the line normal to the cove's corner
c1y = {C1[1]:.8f}
f1x = {F1[0]:.8f}        # and of the one normal to the flap's nose
f1y = {F1[1]:.8f}
"""
else:
    lower_left = f"[blocks.sides.left]\n{dist('hs', 'd_far')}{bez(L['lc'], (Cn, An))}"
    front_size, front_bottom = '"n_s", "n_n"', f"[blocks.sides.bottom]\n{dist('hs', 'hs')}{bez(L['slot'], (FLn, Cn))}"
    front_right = f"[blocks.sides.right]\n{dist('hs', 'd_far')}{bez(L['lc'], (Cn, An))}"
    front_left = f"[blocks.sides.left]\n{dist('hs', 'd_far')}{bez(L['stag'], (FLn, Bn))}"
    slot_left = f"[blocks.sides.left]\n{dist('hs', 'hs')}{bez(L['slot'], (FLn, Cn))}"
    flap_left = f"[blocks.sides.left]\nreverse = true\n{dist('hs', 'd_far')}{bez(L['stag'], (FLn, Bn))}"
    side_joins = """[[joins]]   # the line from the cove to the far field
a = "lower.left"
b = "front.right"

[[joins]]   # the slot's line, from the flap's nose to the cove
a = "front.bottom"
b = "slot.left"

[[joins]]   # the flap's stagnation line
a = "front.left"
b = { block = "below_flap", side = "left", first = "n_n - 1", last = 0 }
"""
    leg_constants = ""
exitl = 'x = "ex + (dx - ex)*s"\ny = "ey + (dy - ey)*s"\n'
d_wo = '"d_far"' if XO > 5 else "0.05"
HEADER = f"""# The NLR 7301 two-element airfoil: a supercritical main element and its
# slotted flap (van den Berg & Oskam 1979; coordinates in nlr7301-main.dat and
# nlr7301-flap.dat), chord 1, as six blocks solved as one grid (written by
# bench/two-element-airfoil/make_case.py --first-cell {args.first_cell} --outflow {XO:g}
# --n-far {args.n_far} --n-slot {args.n_slot}). Not yet a working example: this
# version of eg2d does not mesh it (bench/two-element-airfoil/README.md).
title = "Two-element airfoil (NLR 7301 with flap, six blocks)"
system = "winslow"

"""
if LEGS:
    given = " ".join(f"--{k.replace('_', '-')} {v}" for k, v in vars(args).items()
                     if k not in ("o", "held") and v is not None and v != ap.get_default(k))
    HEADER = f"""# The NLR 7301 two-element airfoil: a supercritical main element and its
# slotted flap (van den Berg & Oskam 1979), chord 1, as six blocks solved as
# one grid, wall-resolved on both elements (first cell {args.first_cell} chord) with a
# wake from each trailing edge. The lines between the blocks are placed and
# held (blockMesh's way), and meet the walls at 90 degrees. Written by
# bench/two-element-airfoil/make_case.py{" --held" if args.held else ""} {given}
# (its README says why this layout).
title = "Two-element airfoil (NLR 7301 with flap, six blocks)"
system = "winslow"

"""
if args.solver:
    HEADER += f'[solver]\nmethod = "{args.solver}"\n\n'
if args.growth_limit:
    HEADER += f"[controls]\nwall_growth_limit = {args.growth_limit}   # the layers' growth where their lines meet held ones\n\n"
s = HEADER + f'''[constants]
h = {args.first_cell}            # first-cell height on both elements' walls (chords)
hs = "h"            # spacing at the walls of the lines that leave them
n_n = {args.n_far}            # nodes from the walls and wakes out to the far field
n_s = {args.n_slot}            # nodes across the slot (and between the two wakes)
n_front = {args.n_front}        # main element: its lower surface, from the slot's line to the nose
n_upper = {args.n_upper}        # main element: its upper surface, nose to trailing edge
n_nose = 25         # the slot: along the cove and the flap's nose, from the slot's line to the slot's end
n_cove = 9          # main element: the cove from the slot's end to the trailing edge
n_wake1 = {N_WAKE1}        # main wake: from the trailing edge to above the flap's trailing edge
n_aft = "n_cove + n_wake1 - 1"   # flap: its upper surface from the slot's end to its trailing edge
n_flap = 65         # flap: its lower surface
{leg_constants}n_wake = {args.n_wake}         # each wake from the flap's trailing edge on, to the outflow
ds_le = 0.001       # spacing along the walls at the main element's nose,
ds_te = 0.0015      # at its trailing edge,
ds_c = 0.002        # at the cove's corner where the slot's line starts,
ds_fle = 0.001      # at the flap's nose,
ds_d = 0.002        # at the cove's end, where the slot ends,
ds_e = 0.002        # on the flap below it,
ds_fte = {args.ds_fte:g}      # and at the flap's trailing edge
d_far = {args.d_far!r}         # spacing at the far field
d_wo = {d_wo}         # spacing along the wakes and the far field at the outflow
d_ff = 0.01         # spacing along the far field below the flap where its wake's columns begin
d_wake = {D_WAKE:g}      # spacing across the wakes at the outflow
d_wake1 = {args.d_wake1:g}     # spacing along the main wake above the flap's trailing edge
R = 10              # the far field: a half circle of radius R about (xc, 0), then straight to x = xo
xc = 0.5
xo = {XO!r}
phia = {PHIA:g}          # where the line from the cove meets the far field (degrees about (xc, 0))
phib = {PHIB:g}          # where the flap's stagnation line meets it
ax = "xc + R*cos(phia*pi/180)"
ay = "R*sin(phia*pi/180)"
bx = "xc + R*cos(phib*pi/180)"
by = "R*sin(phib*pi/180)"
lx = -0.00004       # the main element's nose
ly = -0.00042
cx = 0.85143        # the cove's corner (a point of the main element's lower surface)
cy = 0.01477
tx = 0.94360        # the main element's trailing edge
ty = 0.01454
fx = 0.89359        # the flap's nose
fy = -0.02558
dx = {cove1[-1][0]:.5f}        # the cove's end, short of the trailing edge
dy = {cove1[-1][1]:.5f}
ex = {fup[IE][0]:.5f}        # the flap's upper surface below it
ey = {fup[IE][1]:.5f}
gx = 1.20490        # the flap's trailing edge
gy = -0.10267
wpx = {float(WP[0])!r}   # the main wake above the flap's trailing edge
wpy = {float(WP[1])!r}
yw1 = -0.25         # the main wake at the outflow
yw2 = -0.5          # the flap's wake at the outflow
phit = "acos((tx - xc)/R)*180/pi"         # the far field above the main trailing edge
{PHIG}
yt = "R*sin(phit*pi/180)"
yg = "R*sin(phig*pi/180)"
xg = "xc + R*cos(phig*pi/180)"

[output]
formats = ["su2", "openfoam", "cgns", "vtm", "svg"]

# Below the main element's lower surface, from the cove's corner to the
# nose, out to the far field between the line from the cove and the main
# element's stagnation line.
[[blocks]]
name = "lower"
size = ["n_front", "n_n"]
wall_spacing = {{ bottom = "h" }}
[blocks.sides.bottom]
curve = "spline"
{dist('ds_c', 'ds_le')}{pts(front)}
[blocks.sides.right]
{stag_main}{dist('hs', 'd_far')}
[blocks.sides.top]
{arc('phia', '180')}{lower_left}
{patch('bottom', 'wall', 'main')}{patch('top', 'inflow', 'inflow')}
# Above the main element: its upper surface and wake, out to the far field.
[[blocks]]
name = "upper"
size = ["n_upper + n_wake1 + n_wake - 2", "n_n"]
{WS_UPPER}
[[blocks.sides.bottom]]
curve = "spline"
share = "(n_upper - 1)/(ni - 1)"
{dist('ds_le', 'ds_te')}{pts(upper)}
{main_wake('bottom')}[blocks.sides.right]
x = "xo"
y = "yw1 + (yt - yw1)*s"
{dist('d_wake', 'd_far')}
{far_field('top', '180', 'phit', 'n_upper - 1', 'tx', 'yt', 'n_wake1 + n_wake - 2')}[blocks.sides.left]
{stag_main}{dist('hs', 'd_far')}
{patch('bottom', 'wall', 'main', last='n_upper - 1')}{patch('top', 'inflow', 'inflow', last='n_upper - 1')}{patch('top', 'farfield', 'farfield', first='n_upper - 1')}{patch('right', 'outflow', 'outflow')}
# Below the cove and in front of the flap: from the slot's line out to the
# far field, between the line from the cove and the flap's stagnation line.
[[blocks]]
name = "front"
size = [{front_size}]
{front_bottom}
{front_right}
[blocks.sides.top]
{arc('phib', 'phia')}{front_left}
{patch('top', 'inflow', 'inflow')}
# The slot: between the cove above and the flap's nose below, from the
# slot's line to the slot's end (a line across it short of the main trailing edge).
[[blocks]]
name = "slot"
size = ["n_nose", "n_s"]
wall_spacing = {{ bottom = "h", top = "h" }}
[blocks.sides.bottom]
curve = "spline"
{dist('ds_fle', 'ds_e')}{pts(fup[:IE + 1])}
[blocks.sides.right]
{exitl}{dist('hs', 'hs')}
[blocks.sides.top]
curve = "spline"
{dist('ds_c', 'ds_d')}{pts(cove1)}
{slot_left}
{patch('bottom', 'wall', 'flap')}{patch('top', 'wall', 'main')}
# Behind the slot: the flap's upper surface and its wake below, the end of
# the cove and the main wake above.
[[blocks]]
name = "wake"
size = ["n_aft + n_wake - 1", "n_s"]
{WS_WAKE}
[[blocks.sides.bottom]]
curve = "spline"
share = "(n_aft - 1)/(ni - 1)"
{dist('ds_e', 'ds_fte')}{pts(fup[IE:])}
[[blocks.sides.bottom]]
share = "(n_wake - 1)/(ni - 1)"
{dist('ds_fte', 'd_wo')}{bez(L['fwake'], (Gn, W2n))}
[blocks.sides.right]
x = "xo"
y = "yw2 + (yw1 - yw2)*s"
{dist('d_wake', 'd_wake')}
[[blocks.sides.top]]
curve = "spline"
share = "(n_cove - 1)/(ni - 1)"
{dist('ds_d', 'ds_te')}{pts(cove2)}
{main_wake('top')}[blocks.sides.left]
{exitl}{dist('hs', 'hs')}
{patch('bottom', 'wall', 'flap', last='n_aft - 1')}{patch('top', 'wall', 'main', last='n_cove - 1')}{patch('right', 'outflow', 'outflow')}
# Below the flap: its lower surface and wake, out to the far field.
[[blocks]]
name = "below_flap"
size = ["n_flap + n_wake - 1", "n_n"]
{WS_FLAP}
{far_field('bottom', 'phib', 'phig', 'n_flap - 1', 'xg', 'yg', 'n_wake - 1')}[blocks.sides.right]
x = "xo"
y = "yg + (yw2 - yg)*s"
{dist('d_far', 'd_wake')}
[[blocks.sides.top]]
curve = "spline"
share = "(n_flap - 1)/(ni - 1)"
{dist('ds_fle', 'ds_fte')}{pts(flo)}
[[blocks.sides.top]]
share = "(n_wake - 1)/(ni - 1)"
{dist('ds_fte', 'd_wo')}{bez(L['fwake'], (Gn, W2n))}
{flap_left}
{patch('top', 'wall', 'flap', last='n_flap - 1')}{patch('bottom', 'inflow', 'inflow', last='n_flap - 1')}{patch('bottom', 'farfield', 'farfield', first='n_flap - 1')}{patch('right', 'outflow', 'outflow')}
# The joins, node to node.
[[joins]]   # the main element's stagnation line
a = "lower.right"
b = "upper.left"

{side_joins}
[[joins]]   # the slot's end
a = "slot.right"
b = "wake.left"

[[joins]]   # the main wake
a = {{ block = "upper", side = "bottom", first = "n_upper - 1", last = "n_upper + n_wake1 + n_wake - 3" }}
b = {{ block = "wake", side = "top", first = "n_cove - 1", last = "n_cove + n_wake1 + n_wake - 3" }}

[[joins]]   # the flap's wake
a = {{ block = "below_flap", side = "top", first = "n_flap - 1", last = "n_flap + n_wake - 2" }}
b = {{ block = "wake", side = "bottom", first = "n_aft - 1", last = "n_aft + n_wake - 2" }}

'''
if args.held:  # the placed lines held (held = true after their [[joins]] line); with legs, every line
    placed = ("slot's line", "slot's end", "main wake", "flap's wake") + (
        ("normal to", "stagnation line", "from the cove") if LEGS else ())
    s = "\n".join(line + ("\nheld = true" if line.startswith("[[joins]]") and any(t in line for t in placed) else "")
                   for line in s.split("\n"))
with open(args.o, 'w') as out:
    out.write(s)
print('wrote', args.o)
