"""Tests of the eg2d command: examples, demo, messages of bad case files, exit codes,
progress and Ctrl-C. Run by ctest with /usr/bin/python3:

    cli_test.py TOOL EXAMPLES_DIR [unittest arguments, e.g. ErrorMessages]
    cli_test.py TOOL EXAMPLES_DIR --example NAME SIZE   (one example at a small size; SIZE
                                                          "blocks": a set of blocks at its own sizes)
"""
import math
import json
import os
import re
import resource
import shutil
import signal
import stat
import struct
import subprocess
import sys
import tempfile
import textwrap
import time
import unittest
import xml.etree.ElementTree as ET

TOOL = EXAMPLES = None


def run(*args, cwd=None):
    p = subprocess.run([TOOL, *args], capture_output=True, text=True, cwd=cwd, timeout=600)
    return p.returncode, p.stdout, p.stderr


def features():
    """{"solvers": {"psor": True, "lsor": False, ...}, ...} from eg2d --version."""
    code, out, _ = run("--version")
    assert code == 0
    table = {}
    for line in out.splitlines()[1:]:
        what, rest = line.split(":", 1)
        have, _, lack = rest.partition("not in this build:")
        table[what] = {**{n: True for n in have.split()}, **{n: False for n in lack.split()}}
    return table


def case_from_example(directory, example, *replacements):
    """examples/EXAMPLE.toml with each (old, new) text replaced, written to DIRECTORY/case.toml; its path."""
    with open(os.path.join(EXAMPLES, example + ".toml")) as f:
        text = f.read()
    for old, new in replacements:
        text = text.replace(old, new)
    path = os.path.join(directory, "case.toml")
    with open(path, "w") as f:
        f.write(text)
    return path


def check_mesh(test, case):
    """OpenFOAM's checkMesh (where installed) on a case directory: no failed
    check but the aspect ratio a y+ 1 layer must have, no negative volume,
    non-orthogonality at most 70 degrees, skewness at most 4."""
    checkmesh = shutil_which("checkMesh")
    if not checkmesh:
        return
    env = dict(os.environ)
    env.setdefault("WM_PROJECT_DIR", "/usr/share/openfoam")
    out = subprocess.run([checkmesh, "-case", case], capture_output=True, text=True, env=env).stdout
    failed = re.search(r"Failed (\d+) mesh checks", out)
    if failed:
        test.assertEqual(failed.group(1), "1", case)
        test.assertIn("High aspect ratio cells found", out, case)
    else:
        test.assertIn("Mesh OK.", out, case)
    nonorth = float(re.search(r"Mesh non-orthogonality Max: ([0-9.eE+-]+)", out).group(1))
    skew = float(re.search(r"Max skewness = ([0-9.eE+-]+)", out).group(1))
    test.assertLessEqual(nonorth, 70.0, case)
    test.assertLessEqual(skew, 4.0, case)
    test.assertNotIn("negative", out.lower().replace("negative volumes: 0", ""), case)


def check_cgns_file(test, path, bcs):
    """cgnscheck (where installed) finds no errors in the file, and it checks
    each boundary condition named."""
    cgnscheck = shutil_which("cgnscheck")
    if not cgnscheck:
        return
    p = subprocess.run([cgnscheck, "-v", path], capture_output=True, text=True)
    out = p.stdout + p.stderr
    test.assertEqual([l for l in out.splitlines() if "ERROR" in l.upper()], [], path)
    test.assertIn("checking complete", out, path)
    for bc in bcs:
        test.assertIn(f'checking BC "{bc}"', out, path)


def check_svg(test, path):
    """The picture is well-formed XML with an <svg> root holding drawing elements."""
    root = ET.parse(path).getroot()
    test.assertEqual(root.tag, "{http://www.w3.org/2000/svg}svg")
    test.assertGreater(len(list(root.iter())), 4)


class Example(unittest.TestCase):
    """One example case file, run at a small size (set by main())."""
    name = size = None

    def test_runs(self):
        case = os.path.join(EXAMPLES, self.name + ".toml")
        with tempfile.TemporaryDirectory() as out:
            # a set of blocks (SIZE "blocks") runs at its blocks' own sizes
            code, stdout, stderr = run("run", case, "-o", out, *(() if self.size == "blocks" else ("--size", self.size)))
            self.assertEqual(code, 0, stdout + stderr)
            with open(case) as f:
                text = f.read()
            checks_folds = "fold_check = false" not in text
            # solve = false: the start grid alone (the gallery's pictures of TFI and Hermite TFI)
            self.assertRegex(stdout, r"not solved \(solve = false\)" if "solve = false" in text
                             else r"converged in \d+ iterations")
            if checks_folds:  # (a case that turns the check off says why in its comment)
                self.assertIn("quality: 0 folded cells", stdout)
            written = re.findall(r"^wrote (.*)$", stdout, re.M)
            self.assertTrue(written)
            for path in written:
                self.assertTrue(os.path.getsize(path) > 0, path)
                if path.endswith(".svg"):
                    check_svg(self, path)
                # the solver formats read back by readers eg2d did not write
                if os.path.isdir(os.path.join(path, "constant", "polyMesh")):
                    check_mesh(self, path)
                if path.endswith(".cgns"):
                    check_cgns_file(self, path, ())
                    if shutil_which("cgnscheck"):  # the walls carry their boundary condition
                        p = subprocess.run([shutil_which("cgnscheck"), "-v", path], capture_output=True, text=True)
                        self.assertIn("BC Type=BCWall", p.stdout + p.stderr, path)
            # (a VTK multiblock's .vts files are written in its directory)
            self.assertEqual(sorted(os.listdir(out)),
                             sorted({os.path.relpath(p, out).split(os.sep)[0] for p in written}))


class ErrorMessages(unittest.TestCase):
    """A bad case file gives one precise message naming the file, line, column and key."""

    GOOD_SIDES = textwrap.dedent("""
        [sides.bottom]
        x = "s"
        y = "0"
        [sides.right]
        x = "1"
        y = "s"
        [sides.top]
        x = "s"
        y = "1"
        [sides.left]
        x = "0"
        y = "s"
        """)

    def check(self, text, code, message, extra_files=None):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "case.toml")
            with open(path, "w") as f:
                f.write(textwrap.dedent(text).lstrip("\n"))
            for name, content in (extra_files or {}).items():
                with open(os.path.join(d, name), "w") as f:
                    f.write(content)
            got, stdout, stderr = run("run", path, "-o", os.path.join(d, "out"))
            self.assertEqual(stderr, "eg2d: " + message.replace("CASE", path) + "\n")
            self.assertEqual(got, code)
            self.assertFalse(os.path.exists(os.path.join(d, "out")), "a failed run wrote files")

    def test_unknown_key(self):
        self.check('size = [9, 9]\nsovler = "psor"\n' + self.GOOD_SIDES, 3,
                   "CASE:2:1: key 'sovler': unknown key (expected one of: title, size, topology, system, "
                   "initial, solve, constants, solver, sides, controls, output, patches, interior_lines, blocks, joins, "
                   "variational_area, variational_spacing, variational_orthogonality, variational_smoothness, "
                   "variational_orthogonality_form, hermite_spacing, "
                   "hermite_sides, hermite_height_jmin, hermite_height_imax, hermite_height_jmax, "
                   "hermite_height_imin, march_distance, march_first_height, march_growth, march_smoothing, "
                   "march_area_smoothing, march_end_imin, march_end_imax, airfoil_farfield, airfoil_le_spacing, "
                   "airfoil_te_spacing, airfoil_wake_nodes, airfoil_trailing_edge, airfoil_o_te_base)")

    def test_unknown_key_in_a_side(self):
        self.check('size = [9, 9]\n' + self.GOOD_SIDES + 'z = "1"\n', 3,
                   "CASE:15:1: key 'sides.left.z': unknown key (expected one of: x, y, points, file, naca, "
                   "airfoil, curve, closed_te, distribution, reverse, share, sliding)")

    def test_wrong_type(self):
        self.check('size = [9, 9]\n[solver]\ntolerance = true\n' + self.GOOD_SIDES, 3,
                   "CASE:3:13: key 'solver.tolerance': expected a number, found a boolean")

    def test_wrong_type_size(self):
        self.check('size = 9\n' + self.GOOD_SIDES, 3,
                   "CASE:1:8: key 'size': expected an array, found an integer")

    def test_missing_side(self):
        text = 'size = [9, 9]\n' + self.GOOD_SIDES.replace('[sides.left]\nx = "0"\ny = "s"\n', "")
        self.check(text, 3, "CASE:3:1: key 'sides.left': missing (a single-block case needs the sides "
                            "bottom, right, top, left)")

    def test_bad_formula(self):
        text = 'size = [9, 9]\n' + self.GOOD_SIDES.replace('y = "1"', 'y = "0.75 + 0.25*sin(pi*(0.5 + 2*s)"')
        self.check(text, 3, "CASE:11:5: key 'sides.top.y': bad formula \"0.75 + 0.25*sin(pi*(0.5 + 2*s)\": "
                            "Missing parenthesis")

    def test_unknown_name_in_formula(self):
        text = 'size = [9, 9]\n' + self.GOOD_SIDES.replace('y = "1"', 'y = "1 + t"')
        self.check(text, 3, "CASE:11:5: key 'sides.top.y': bad formula \"1 + t\": Unexpected token \"t\" "
                            "found at position 4.")

    def test_formula_not_finite(self):
        text = 'size = [9, 9]\n' + self.GOOD_SIDES.replace('y = "1"', 'y = "1/(s - 0.5)"')
        self.check(text, 3, "CASE:11:5: key 'sides.top.y': formula \"1/(s - 0.5)\" gives inf at s = 0.5")

    def test_corner_mismatch_from_the_library(self):
        text = 'size = [9, 9]\n' + self.GOOD_SIDES.replace('x = "1"', 'x = "1.25"')
        self.check(text, 4, "CASE:6:1: key 'sides.right': eg2d_set_side: corner JMIN/IMAX: (1, 0) vs (1.25, 0)")

    def test_solver_parameter_out_of_range_from_the_library(self):
        if not features()["solvers"]["af"]:
            self.skipTest("this build has no AF solver")
        self.check('size = [9, 9]\n[solver]\nmethod = "af"\naf_steps = 2\n' + self.GOOD_SIDES, 4,
                   "CASE:4:12: key 'solver.af_steps': eg2d_set_parameter: af_steps = 2: must be in [4, 1000] "
                   "(or 0 for automatic)")

    def test_distribution_errors(self):
        if not features()["geometry"]["curves"]:
            self.skipTest("this build has no curves")
        left = '[sides.left]\npoints = [[0, 0], [0, 0.2], [0, 1]]\ndistribution = '
        base = 'size = [5, 5]\n' + self.GOOD_SIDES.replace('[sides.left]\nx = "0"\ny = "s"\n', "")
        self.check(base + left + '{ kind = "tanh3" }\n', 3,
                   "CASE:14:25: key 'sides.left.distribution.kind': \"tanh3\" is not one of: uniform, exponential, "
                   "tanh, tanh2, vinokur")
        self.check(base + left + '{ kind = "vinokur", first = 0.9, last = 0.5 }\n', 4,
                   "CASE:14:16: key 'sides.left.distribution': eg2d_curve_points: Vinokur spacings 0.9 + 0.5 leave "
                   "no room on length 1 with 5 points")
        self.check(base + left + '{ kind = "tanh", beta = 2 }\n', 3,
                   "CASE:14:33: key 'sides.left.distribution.beta': unknown key (expected one of: kind, delta, "
                   "first_spacing)")
        self.check(base + left + '{ kind = "tanh", delta = 2, first_spacing = 0.1 }\n', 3,
                   "CASE:14:60: key 'sides.left.distribution.first_spacing': give delta or first_spacing, not both")
        self.check(base + left + '{ kind = "exponential" }\n', 3,
                   "CASE:14:16: key 'sides.left.distribution.beta': missing: give beta or first_spacing")
        self.check(base + left + '{ kind = "tanh", first_spacing = 0.5 }\n', 4,
                   "CASE:14:49: key 'sides.left.distribution.first_spacing': eg2d_distribution_parameter: "
                   "first_spacing = 0.5: not reachable with n = 5: over tanh delta in (0, 700] the first spacing "
                   "stays within [1.97891e-228, 0.25] (it clusters at s = 0: its first spacing is below the uniform "
                   "1/(n-1))")

    def test_multigrid_parameters(self):
        if not features()["solvers"]["multigrid"]:
            self.skipTest("this build has no multigrid")
        self.check('size = [9, 9]\n[solver]\nmethod = "multigrid"\nmg_cycle = 3\n' + self.GOOD_SIDES, 4,
                   "CASE:4:12: key 'solver.mg_cycle': eg2d_set_parameter: mg_cycle = 3: must be in [1, 2]")
        self.check('size = [9, 9]\n[solver]\nmethod = "multigrid"\nmg_fmg = "no"\n' + self.GOOD_SIDES, 3,
                   "CASE:4:10: key 'solver.mg_fmg': bad formula \"no\": Unexpected token \"no\" found at position 0.")

    def test_prints_what_ran(self):
        """The command says which solver ran on how many levels, and every change of strategy."""
        with tempfile.TemporaryDirectory() as d:
            for size, levels, note in (("[65, 65]", "solver multigrid, 5 grid levels (5 at the end)", None),
                                       ("[4, 4]", "solver multigrid",
                                        "note, iteration 1: multigrid: the 4x4 grid has no coarse level")):
                path = os.path.join(d, "case.toml")
                with open(path, "w") as f:
                    f.write("size = " + size + '\n[solver]\nmethod = "multigrid"\n' +
                            self.GOOD_SIDES.replace('y = "1"', 'y = "1 + 0.3 * s * (1 - s)"'))
                code, stdout, stderr = run("run", path, "-o", os.path.join(d, "out"))
                self.assertEqual(code, 0, stdout + stderr)
                self.assertIn(levels + "\n", stdout)
                if note:
                    self.assertIn(note, stdout)
                else:
                    self.assertNotIn("note,", stdout)

    def test_toml_syntax(self):
        self.check('size = [9, 9\n', 3, "CASE:1:14: TOML syntax error: Error while parsing array: encountered end-of-file")

    def test_bad_choice(self):
        self.check('size = [9, 9]\nsystem = "poisson"\n' + self.GOOD_SIDES, 3,
                   "CASE:2:10: key 'system': \"poisson\" is not one of: laplace, winslow, variational")

    def test_point_count(self):
        text = 'size = [4, 3]\n' + self.GOOD_SIDES.replace('[sides.left]\nx = "0"\ny = "s"',
                                                          '[sides.left]\npoints = [[0, 0], [0, 1]]')
        self.check(text, 3, "CASE:13:10: key 'sides.left.points': 2 points given, but this side needs 3 (size 3)")

    def test_point_file_bad_line(self):
        text = 'size = [3, 3]\n' + self.GOOD_SIDES.replace('[sides.left]\nx = "0"\ny = "s"',
                                                          '[sides.left]\nfile = "left.txt"')
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "case.toml")
            with open(path, "w") as f:
                f.write(textwrap.dedent(text).lstrip("\n"))
            with open(os.path.join(d, "left.txt"), "w") as f:
                f.write("# x y\n0 0\n0 0.5 7\n0 1\n")
            code, _, stderr = run("run", path, "-o", os.path.join(d, "out"))
            self.assertEqual(stderr, f"eg2d: {path}:13:8: key 'sides.left.file': eg2d_read_points: {d}/left.txt:3: "
                                     "\"0 0.5 7\": unexpected \"7\" after the two numbers x y\n")
            self.assertEqual(code, 8)
            os.remove(os.path.join(d, "left.txt"))
            code, _, stderr = run("run", path, "-o", os.path.join(d, "out"))
            self.assertEqual(stderr, f"eg2d: {path}:13:8: key 'sides.left.file': eg2d_read_points: {d}/left.txt: "
                                     "cannot open: No such file or directory\n")
            self.assertEqual(code, 8)

    def test_pieces_that_do_not_meet(self):
        text = 'size = [9, 9]\n' + self.GOOD_SIDES.replace(
            '[sides.bottom]\nx = "s"\ny = "0"',
            '[[sides.bottom]]\nx = "0.5*s"\ny = "0"\n[[sides.bottom]]\n'
            '        x = "0.6 + 0.4*s"\ny = "0"')
        self.check(text, 3, "CASE:6:1: key 'sides.bottom[1]': starts at (0.6, 0) but the previous piece ends "
                            "at (0.5, 0)")

    def test_not_available_in_this_build(self):
        solvers = features()["solvers"]
        missing = [n for n, have in solvers.items() if not have]
        for name in missing:
            self.check(f'size = [9, 9]\n[solver]\nmethod = "{name}"\n' + self.GOOD_SIDES, 9,
                       f"CASE:3:10: key 'solver.method': \"{name}\" is not available in this build of eg2d")
        if not features()["geometry"]["curves"]:
            self.check('size = [9, 9]\n' + self.GOOD_SIDES.replace('y = "1"', 'y = "1"\ndistribution = "uniform"'), 9,
                       "CASE:12:16: key 'sides.top.distribution': is not available in this build of eg2d")
        self.check('size = [9, 9]\n[solver]\nmethod = "sor"\n' + self.GOOD_SIDES, 3,
                   "CASE:3:10: key 'solver.method': \"sor\" is not one of: psor, lsor, af, nested, multigrid")


class Sides(unittest.TestCase):
    """Inline points, a point file, pieces and constants give the same grid as formulas."""

    FORMULAS = textwrap.dedent("""
        size = [5, 5]
        [solver]
        tolerance = 1e-12
        [sides.bottom]
        x = "s"
        y = "0"
        [sides.right]
        x = "1 + 2*s - 2*s^2"
        y = "s"
        [sides.top]
        x = "s"
        y = "1 - 2*s + 2*s^2"
        [sides.left]
        x = "0"
        y = "s"
        """)
    POINTS = textwrap.dedent("""
        size = [5, 5]
        [constants]
        half = 0.5
        [solver]
        tolerance = 1e-12
        [[sides.bottom]]
        x = "half*s"
        y = "0"
        [[sides.bottom]]
        points = [[0.5, 0], [0.75, 0], [1, 0]]
        [sides.right]
        file = "right.txt"
        [sides.top]
        points = [[0, 1], [0.25, 0.625], [0.5, 0.5], [0.75, 0.625], [1, 1]]
        [sides.left]
        x = "0"
        y = "s"
        """)

    def test_points_files_and_pieces(self):
        with tempfile.TemporaryDirectory() as d:
            for name, text in (("formulas.toml", self.FORMULAS), ("points.toml", self.POINTS)):
                with open(os.path.join(d, name), "w") as f:
                    f.write(text)
            with open(os.path.join(d, "right.txt"), "w") as f:
                f.write("# the swan's right side, x = 1 + 2y - 2y^2\n1 0\n1.375, 0.25\n\n1.5 0.5\n1.375 0.75\n1 1\n")
            a = run("run", os.path.join(d, "formulas.toml"), "-o", d, "--quiet")
            b = run("run", os.path.join(d, "points.toml"), "-o", d, "--quiet")
            self.assertEqual(a[0], 0, a)
            self.assertEqual(b[0], 0, b)
            strip = lambda s: re.sub(r", [0-9.]+ s$", "", s.split("\n", 1)[1], flags=re.M).replace("formulas", "points")
            self.assertEqual(strip(a[1]), strip(b[1]))
            self.assertRegex(a[1], r"converged in \d+ iterations")


    def test_curve_with_a_distribution(self):
        """points + curve + distribution: nodes by arc length along the polyline (read back from Plot3D)."""
        if not features()["geometry"]["curves"]:
            self.skipTest("this build has no curves")
        text = self.FORMULAS.replace('[sides.left]\nx = "0"\ny = "s"',
                                     '[sides.left]\npoints = [[0, 0], [0, 0.2], [0, 1]]\ncurve = "polyline"\n'
                                     'distribution = "uniform"') + '[output]\nformats = ["plot3d"]\n'
        with tempfile.TemporaryDirectory() as d:
            with open(os.path.join(d, "c.toml"), "w") as f:
                f.write(text)
            code, out, err = run("run", os.path.join(d, "c.toml"), "-o", d, "--quiet")
            self.assertEqual(code, 0, out + err)
            with open(os.path.join(d, "c.xyz"), "rb") as f:
                data = f.read()
            self.assertEqual(struct.unpack("<iiii", data[:16]), (8, 5, 5, 8))
            xy = struct.unpack("<50d", data[20:20 + 400])
            left_y = [xy[25 + 5 * j] for j in range(5)]
            self.assertEqual(left_y, [0.0, 0.25, 0.5, 0.75, 1.0])


    def test_sliding_side(self):
        """sliding = true: the top's nodes slide along it until the grid lines meet it at 90 degrees."""
        if not features()["geometry"]["curves"]:
            self.skipTest("this build has no curves")
        ortho = r"top (\d+\.\d+)/(\d+\.\d+)"
        with tempfile.TemporaryDirectory() as d:
            with open(os.path.join(EXAMPLES, "swan.toml")) as f:
                text = f.read().replace("# method: the library's default, FAS multigrid", 'method = "psor"')  # point SOR, as when this was measured
            with open(os.path.join(d, "fixed.toml"), "w") as f:
                f.write(text)
            with open(os.path.join(d, "sliding.toml"), "w") as f:
                f.write(text.replace('y = "1 - 2*s + 2*s^2"', 'y = "1 - 2*s + 2*s^2"\nsliding = true'))
            fixed = run("run", os.path.join(d, "fixed.toml"), "-o", d, "--size", "33x33", "--quiet")
            sliding = run("run", os.path.join(d, "sliding.toml"), "-o", d, "--size", "33x33", "--quiet")
            self.assertEqual(sliding[0], 0, sliding)
            fmax, fmean = map(float, re.search(ortho, fixed[1]).groups())
            smax, smean = map(float, re.search(ortho, sliding[1]).groups())
            self.assertGreater(fmean, 20)   # 26.75 deg with fixed nodes
            self.assertLess(smean, 1)       # 0.23 deg sliding
            self.assertLess(smax, 5)        # 4.43 deg (next to the corners, which stay fixed)


class RunFiles(unittest.TestCase):
    """first_spacing in place of a stretching parameter; the run's history and control functions as files."""

    CASE = 'size = [13, 9]\n' + ErrorMessages.GOOD_SIDES.replace(
        'y = "1"', 'y = "1 + 0.3 * s * (1 - s)"') + textwrap.dedent("""
        [solver]
        method = "lsor"
        tolerance = 1e-10
        [controls.source_arrays]
        P = "0.5"
        Q = "-0.25"
        [output]
        formats = ["plot3d", "history", "history-svg", "controls"]
        """)

    def run_case(self, d, text=None, out="out"):
        path = os.path.join(d, "case.toml")
        with open(path, "w") as f:
            f.write(text or self.CASE)
        return run("run", path, "-o", os.path.join(d, out), "--quiet")

    def read_csv(self, path):
        with open(path) as f:
            lines = f.read().splitlines()
        return lines[0], [line.split(",") for line in lines[1:]]

    def test_history_and_controls(self):
        with tempfile.TemporaryDirectory() as d:
            code, out, err = self.run_case(d)
            self.assertEqual(code, 0, out + err)
            iterations, residual = re.search(r"converged in (\d+) iterations, residual (\S+),", out).groups()
            header, rows = self.read_csv(os.path.join(d, "out", "case.history.csv"))
            self.assertEqual(header, "iteration,residual")
            self.assertEqual([int(r[0]) for r in rows], list(range(1, int(iterations) + 1)))  # one row per iteration
            self.assertEqual("%.3e" % float(rows[-1][1]), residual)                           # the reported residual
            self.assertLessEqual(float(rows[-1][1]), 1e-10)
            check_svg(self, os.path.join(d, "out", "case.history.svg"))
            with open(os.path.join(d, "out", "case.history.svg")) as f:
                self.assertIn("case: %s iterations, residual %s" % (iterations, residual), f.read())
            header, rows = self.read_csv(os.path.join(d, "out", "case.controls.csv"))
            self.assertEqual(header, "i,j,x,y,P,Q")
            self.assertEqual(len(rows), 13 * 9)                                               # ni*nj nodes
            self.assertEqual([(int(r[0]), int(r[1])) for r in rows], [(i, j) for j in range(9) for i in range(13)])
            for r in rows:
                i, j, P, Q = int(r[0]), int(r[1]), float(r[4]), float(r[5])
                inner = 0 < i < 12 and 0 < j < 8
                self.assertAlmostEqual(P, 0.5 if inner else 0, places=12)
                self.assertAlmostEqual(Q, -0.25 if inner else 0, places=12)
            # x, y are the grid's nodes (the Plot3D file's)
            with open(os.path.join(d, "out", "case.xyz"), "rb") as f:
                xy = struct.unpack("<%dd" % (2 * 13 * 9), f.read()[20:20 + 16 * 13 * 9])
            self.assertEqual([float(r[2]) for r in rows], list(xy[:13 * 9]))
            self.assertEqual([float(r[3]) for r in rows], list(xy[13 * 9:]))
            self.assertEqual(sorted(os.listdir(os.path.join(d, "out"))),
                             ["case.controls.csv", "case.history.csv", "case.history.svg", "case.xyz"])

    def test_png(self):
        # the whole grid as a picture, 800 pixels on its longer side (the domain is
        # 1 x 1.075: taller), drawn by cairo; a build without it says so
        with tempfile.TemporaryDirectory() as d:
            code, out, err = self.run_case(d, self.CASE.replace('"controls"]', '"controls", "png"]'))
            if features()["formats"]["png"]:
                self.assertEqual(code, 0, out + err)
                size, pixels = png_size(self, os.path.join(d, "out", "case.png"))
                self.assertEqual(size[1], 800)
                self.assertLess(abs(size[0] - 800 / 1.075), 40)
                if pixels:  # the walls' red (a single block's sides by default) and the white between lines
                    colours = set(pixels.getdata())
                    self.assertIn((0xc0, 0x10, 0x10), colours)
                    self.assertIn((255, 255, 255), colours)
            else:
                self.assertEqual(code, 9, out + err)
                self.assertIn('"png" is not available in this build', err)

    def test_failed_run_writes_no_history(self):
        with tempfile.TemporaryDirectory() as d:
            code, out, err = self.run_case(d, self.CASE.replace("tolerance = 1e-10", "tolerance = 1e-10\nmax_iterations = 2"))
            self.assertEqual(code, 5, out + err)
            self.assertFalse(os.path.exists(os.path.join(d, "out")))

    def test_the_set_rules_hold_for_the_run_files(self):
        # a link's target is replaced (the link kept); a FIFO without a reader
        # fails the set, which leaves every older file as it was
        with tempfile.TemporaryDirectory() as d:
            os.mkdir(os.path.join(d, "out"))
            target = os.path.join(d, "kept.csv")
            with open(target, "w") as f:
                f.write("old")
            os.symlink(target, os.path.join(d, "out", "case.history.csv"))
            code, out, err = self.run_case(d)
            self.assertEqual(code, 0, out + err)
            self.assertTrue(os.path.islink(os.path.join(d, "out", "case.history.csv")))
            with open(target) as f:
                self.assertTrue(f.read().startswith("iteration,residual\n"))
            for name in ("case.xyz", "case.history.svg"):
                with open(os.path.join(d, "out", name), "w") as f:
                    f.write("old")
            os.remove(os.path.join(d, "out", "case.controls.csv"))
            os.mkfifo(os.path.join(d, "out", "case.controls.csv"))
            code, out, err = self.run_case(d)
            self.assertEqual(code, 8, out + err)
            self.assertIn("case.controls.csv: a FIFO with no reader: not written", err)
            for name in ("case.xyz", "case.history.svg"):
                with open(os.path.join(d, "out", name)) as f:
                    self.assertEqual(f.read(), "old")
            self.assertEqual(sorted(os.listdir(os.path.join(d, "out"))),
                             ["case.controls.csv", "case.history.csv", "case.history.svg", "case.xyz"])

    def test_first_spacing(self):
        """first_spacing gives the parameter: the first interval of the side is that long (Plot3D read back)."""
        if not features()["geometry"]["curves"]:
            self.skipTest("this build has no curves")
        for kind in ('kind = "exponential"', 'kind = "tanh"', 'kind = "tanh2", c = 1'):
            text = self.CASE.replace('[sides.left]\nx = "0"\ny = "s"',
                                     '[sides.left]\nx = "0"\ny = "2*s"\ndistribution = { %s, first_spacing = 0.01 }'
                                     % kind).replace('x = "1"\ny = "s"', 'x = "1"\ny = "2*s"').replace(
                                     'y = "1 + 0.3 * s * (1 - s)"', 'y = "2 + 0.3 * s * (1 - s)"')
            with tempfile.TemporaryDirectory() as d:
                code, out, err = self.run_case(d, text)
                self.assertEqual(code, 0, out + err)
                with open(os.path.join(d, "out", "case.xyz"), "rb") as f:
                    xy = struct.unpack("<%dd" % (2 * 13 * 9), f.read()[20:20 + 16 * 13 * 9])
                left_y = [xy[13 * 9 + 13 * j] for j in range(9)]
                self.assertAlmostEqual(left_y[1] - left_y[0], 0.01, delta=1e-12, msg=kind)
                self.assertGreater(left_y[8] - left_y[7], 0.01)


class Controls(unittest.TestCase):
    """The [controls] keys reach the library: each changes the grid, and bad values are reported at their key."""

    def summary(self, text, d, name):
        path = os.path.join(d, name + ".toml")
        with open(path, "w") as f:
            f.write(text)
        code, out, err = run("run", path, "-o", d, "--quiet", "--size", "17x17")
        self.assertEqual(code, 0, out + err)
        return re.search(r"cell area (\S+) to (\S+),", out).groups()

    def test_each_control_changes_the_grid(self):
        if not features()["controls"].get("source_arrays"):
            self.skipTest("this build has no controls")
        with open(os.path.join(EXAMPLES, "channel-1.toml")) as f:
            with_sources = f.read()
        arrays = with_sources[with_sources.index("[controls.source_arrays]"):with_sources.index("[sides.bottom]")]
        with open(os.path.join(EXAMPLES, "dome.toml")) as f:
            plain = f.read()
        a = plain.index("[sides.bottom]")
        plain = plain[:a] + '[constants]\nn = "ni - 1"\nm = "nj - 1"\n' + plain[a:]
        a = plain.index("[sides.bottom]")
        with tempfile.TemporaryDirectory() as d:
            base = self.summary(plain, d, "plain")
            for name, extra in [
                    ("arrays", arrays),
                    ("line", '[[controls.line_source]]\ndirection = "eta"\nline = 0\namplitude = 10\ndecay = 0.3\n'),
                    ("point", '[[controls.point_source]]\nxi = 8\neta = 8\namplitude = 10\ndecay = 0.3\n'),
                    ("weight", '[controls]\nweight = "1 + 4*exp(-((i - 8)^2 + (j - 8)^2)/8)"\n'),
                    ("grid", '[controls.parameter_grid]\ni = { kind = "line", a = 0.5 }\n'),
                    ("wall", '[controls]\northogonality = "wall"\nwall_spacing = { bottom = 0.01 }\nwall_growth_limit = 10\n')]:
                self.assertNotEqual(self.summary(plain[:a] + extra + plain[a:], d, name), base, name)

    def test_short_wall_layer_exits_4(self):
        """A wall layer too short for its first cell: the command says so with the nj that would do, and
        exits 4 with the files written; with that nj it exits 0 and prints the layer's figures."""
        case = ('title = "channel"\nsize = [%d, %d]\n[controls]\northogonality = "wall"\n'
                'wall_spacing = { bottom = 1e-6 }\n[output]\nformats = ["report"]\n' + ErrorMessages.GOOD_SIDES)
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "short.toml")
            with open(path, "w") as f:
                f.write(case % (9, 17))
            code, out, err = run("run", path, "-o", d, "--quiet")
            self.assertEqual(code, 4, out + err)
            m = re.search(r"the wall layer at bottom grows by (\S+) within 30 cells, more than 1.2: nj >= (\d+) would "
                          r"meet it \(the files are written\)", err)
            self.assertIsNotNone(m, err)
            self.assertTrue(os.path.exists(os.path.join(d, "short.report.txt")))
            with open(path, "w") as f:
                f.write(case % (9, int(m.group(2))))
            code, out, err = run("run", path, "-o", d, "--quiet")
            self.assertEqual(code, 0, out + err)
            m = re.search(r"wall layer bottom: first cell (\S+) \(median; \S+ to \S+, asked 1.0000e-06\), growth (\S+)",
                          out)
            self.assertIsNotNone(m, out)
            self.assertAlmostEqual(float(m.group(1)), 1e-6, delta=1e-9)
            self.assertLessEqual(float(m.group(2)), 1.2)

    def test_bad_control_values(self):
        if not features()["controls"].get("source_arrays"):
            self.skipTest("this build has no controls")
        t = ErrorMessages()
        t.check('size = [9, 9]\n[controls.source_arrays]\nP = "i +"\n' + ErrorMessages.GOOD_SIDES, 3,
                "CASE:3:5: key 'controls.source_arrays.P': bad formula \"i +\": Unexpected end of expression at position 4")
        t.check('size = [9, 9]\n[[controls.line_source]]\ndirection = "zeta"\nline = 0\namplitude = 1\ndecay = 1\n'
                + ErrorMessages.GOOD_SIDES, 3,
                "CASE:3:13: key 'controls.line_source[0].direction': \"zeta\" is not one of: xi, eta")
        t.check('size = [9, 9]\n[controls]\nwall_spacing = { top = -1 }\n' + ErrorMessages.GOOD_SIDES, 3,
                "CASE:3:24: key 'controls.wall_spacing.top': must be >= 0 (0 = orthogonality only)")
        # heights node by node: a bad one named by its index, a wrong count by the library
        t.check('size = [9, 9]\n[controls]\nwall_spacing = { top = [1e-3, 0, 1e-3] }\n' + ErrorMessages.GOOD_SIDES, 3,
                "CASE:3:31: key 'controls.wall_spacing.top[1]': must be a finite number > 0")
        t.check('size = [9, 9]\n[controls]\nwall_spacing = { top = [1e-3, 2e-3, 1e-3] }\n' + ErrorMessages.GOOD_SIDES, 4,
                "CASE:3:24: key 'controls.wall_spacing.top': eg2d_set_wall_spacing_nodes: n = 3: side JMAX has 9 nodes")
        t.check('size = [9, 9]\n[[controls.line_source]]\ndirection = "xi"\nline = 20\namplitude = 1\ndecay = 1\n'
                + ErrorMessages.GOOD_SIDES, 4, "CASE:2:1: key 'controls.line_source[0]': eg2d_add_line_source: line = 20: "
                "must be in [0, 8] (xi index units)")


class CommandLine(unittest.TestCase):
    def test_help_documents_exit_codes_and_an_example(self):
        code, out, _ = run("--help")
        self.assertEqual(code, 0)
        for line in ("  3    bad case file", "  9    the case asks for a feature not available in this build",
                     "  130  interrupted by Ctrl-C", "eg2d demo -o demo-out"):
            self.assertIn(line, out)

    def test_usage_errors(self):
        for args, message in [(["frobnicate"], "unknown command \"frobnicate\""),
                              (["run"], "run needs a case file"),
                              (["demo", "--size", "2x9"], "--size expects NIxNJ with 3 <= NI, NJ <= 100000, found \"2x9\""),
                              (["demo", "--bogus"], "unknown option --bogus"),
                              (["demo", "nosuch"], "no demo named \"nosuch\"")]:
            code, _, err = run(*args)
            self.assertEqual(code, 2, args)
            self.assertTrue(err.startswith("eg2d: " + message), err)

    def test_missing_case_file(self):
        code, _, err = run("run", "/nonexistent/case.toml")
        self.assertEqual(code, 8)
        self.assertEqual(err, "eg2d: /nonexistent/case.toml: cannot read the case file: No such file or directory\n")

    def test_not_converged_writes_nothing(self):
        with tempfile.TemporaryDirectory() as d:
            path = case_from_example(d, "swan", ("max_iterations = 20000", "max_iterations = 5"),
                                     ("# method: the library's default, FAS multigrid", 'method = "psor"'))
            code, out, err = run("run", path, "-o", os.path.join(d, "out"), "--size", "17x17")
            self.assertEqual(code, 5, out + err)
            self.assertIn("(no files written)", err)
            self.assertFalse(os.path.exists(os.path.join(d, "out")))


    def test_folded_grid_exit_7(self):
        # Laplace (Amsden-Hirt) folds the antenna at its reflex corners; Winslow does not
        with tempfile.TemporaryDirectory() as d:
            path = case_from_example(d, "antenna", ('system = "winslow"', 'system = "laplace"'))
            code, out, err = run("run", path, "-o", os.path.join(d, "out"), "--quiet")
            self.assertEqual(code, 7, out + err)
            self.assertRegex(err, r"^eg2d: .*: eg2d_solve: the converged grid has \d+ folded cells; .*\(no files written\)\n$")
            self.assertRegex(out, r"quality: [1-9]\d* folded cells")
            self.assertFalse(os.path.exists(os.path.join(d, "out")))

    def test_start_grid_only(self):
        # solve = false writes the start grid as it is, checked for folds like a solved one:
        # linear TFI folds the antenna at its reflex corners (102 cells at 33 x 33)
        with tempfile.TemporaryDirectory() as d:
            path = case_from_example(d, "antenna", ('system = "winslow"', 'solve = false'))
            code, out, err = run("run", path, "-o", os.path.join(d, "out"), "--quiet", "--size", "33x33")
            self.assertEqual(code, 7, out + err)
            self.assertRegex(out, r"tfi start grid, not solved \(solve = false\)\nquality: 102 folded cells")
            self.assertNotIn("converged", out)
            self.assertRegex(err, r"^eg2d: .*: the start grid has 102 folded cells \(solve = false; no files written\)\n$")
            self.assertFalse(os.path.exists(os.path.join(d, "out")))
            path = case_from_example(d, "antenna", ('system = "winslow"', 'solve = false'),
                                     ("[solver]", "[solver]\nfold_check = false"))
            code, out, err = run("run", path, "-o", os.path.join(d, "out"), "--quiet", "--size", "33x33")
            self.assertEqual(code, 0, out + err)
            self.assertRegex(out, r"wrote .*case\.svg")
            path = case_from_example(d, "swan", ('system = "winslow"', 'solve = 1'))
            code, out, err = run("run", path, "-o", os.path.join(d, "out"))
            self.assertEqual(code, 3, out + err)
            self.assertIn("key 'solve': expected a boolean", err)

    def test_diverged_exit_6(self):
        # point SOR over-relaxed far beyond Winslow's stability
        with tempfile.TemporaryDirectory() as d:
            path = case_from_example(d, "swan", ("# method: the library's default, FAS multigrid",
                                                 'method = "psor"\nrelaxation = 1.99'))
            code, out, err = run("run", path, "-o", os.path.join(d, "out"), "--quiet", "--size", "17x17")
            self.assertEqual(code, 6, out + err)
            self.assertRegex(err, r"^eg2d: .*: eg2d_solve: psor diverged at iteration \d+: .*\(no files written\)\n$")
            self.assertFalse(os.path.exists(os.path.join(d, "out")))

    def test_unwritable_output_exit_8(self):
        with tempfile.TemporaryDirectory() as d:
            blocker = os.path.join(d, "file")
            open(blocker, "w").close()
            code, out, err = run("demo", "-o", os.path.join(blocker, "out"), "--quiet", "--size", "9x9")
            self.assertEqual(code, 8, out + err)
            # checked before the solve: nothing is printed after the case's first line
            self.assertEqual(err, f"eg2d: {blocker}: is not a directory, so {blocker}/out cannot be made "
                                  "(checked before solving)\n")
            self.assertNotIn("converged", out)

    def existing_output_set(self, d, svg_fifo=False):
        """d/out holding an older swan.{xyz,vts,svg}: swan.xyz a symbolic link to d/kept.xyz, swan.vts a
        plain file of mode 0640, swan.svg a file with a second hard link (or a FIFO with no reader).
        Returns the out directory and a function that asserts all of it is as it was."""
        out = os.path.join(d, "out")
        os.mkdir(out)
        kept = os.path.join(d, "kept.xyz")
        with open(kept, "w") as f:
            f.write("old xyz")
        os.symlink(kept, os.path.join(out, "swan.xyz"))
        with open(os.path.join(out, "swan.vts"), "w") as f:
            f.write("old swan.vts")
        os.chmod(os.path.join(out, "swan.vts"), 0o640)
        if svg_fifo:
            os.mkfifo(os.path.join(out, "swan.svg"))
        else:
            with open(os.path.join(out, "swan.svg"), "w") as f:
                f.write("old swan.svg")
            os.link(os.path.join(out, "swan.svg"), os.path.join(d, "other-name.svg"))

        def unchanged():
            self.assertEqual(sorted(os.listdir(out)), ["swan.svg", "swan.vts", "swan.xyz"])  # no stage left
            self.assertEqual(os.readlink(os.path.join(out, "swan.xyz")), kept)
            with open(kept, "rb") as f:
                self.assertEqual(f.read(), b"old xyz")
            with open(os.path.join(out, "swan.vts")) as f:
                self.assertEqual(f.read(), "old swan.vts")
            self.assertEqual(os.stat(os.path.join(out, "swan.vts")).st_mode & 0o777, 0o640)
            if svg_fifo:
                self.assertTrue(stat.S_ISFIFO(os.lstat(os.path.join(out, "swan.svg")).st_mode))
            else:
                with open(os.path.join(d, "other-name.svg")) as f:
                    self.assertEqual(f.read(), "old swan.svg")
                self.assertEqual(os.stat(os.path.join(out, "swan.svg")).st_ino,
                                 os.stat(os.path.join(d, "other-name.svg")).st_ino)
        return out, unchanged

    def test_output_set_respects_what_is_at_the_paths(self):
        # a symbolic link stays a link with its target rewritten; a file keeps
        # its permission bits; a second hard link still sees the new bytes
        with tempfile.TemporaryDirectory() as d:
            out, _ = self.existing_output_set(d)
            target = os.path.join(d, "kept.xyz")
            code, stdout, stderr = run("demo", "-o", out, "--quiet", "--size", "9x9")
            self.assertEqual(code, 0, stdout + stderr)
            self.assertTrue(os.path.islink(os.path.join(out, "swan.xyz")))
            self.assertEqual(os.readlink(os.path.join(out, "swan.xyz")), target)
            # single-grid 2-D Plot3D: the (ni, nj) record and the x, y record, each between markers
            self.assertEqual(os.path.getsize(target), (4 + 4 * 2 + 4) + (4 + 8 * 2 * 81 + 4))
            with open(target, "rb") as f:
                self.assertEqual(struct.unpack("<4i", f.read(16)), (8, 9, 9, 8))
            self.assertEqual(os.stat(os.path.join(out, "swan.vts")).st_mode & 0o777, 0o640)
            check_svg(self, os.path.join(d, "other-name.svg"))
            self.assertEqual(os.stat(os.path.join(out, "swan.svg")).st_ino,
                             os.stat(os.path.join(d, "other-name.svg")).st_ino)
            self.assertEqual([n for n in os.listdir(out) if n.startswith(".eg2d-set")], [])

    def test_failed_run_leaves_the_output_set_unchanged(self):
        # not converged: nothing is written, and no path changes type, mode, links or content
        with tempfile.TemporaryDirectory() as d:
            out, unchanged = self.existing_output_set(d)
            path = os.path.join(d, "swan.toml")
            with open(os.path.join(EXAMPLES, "swan.toml")) as f:
                text = f.read().replace("max_iterations = 20000", "max_iterations = 5").replace(
                    "# method: the library's default, FAS multigrid", 'method = "psor"')
            with open(path, "w") as f:
                f.write(text)
            code, stdout, stderr = run("run", path, "-o", out, "--quiet", "--size", "17x17")
            self.assertEqual(code, 5, stdout + stderr)
            self.assertIn("(no files written)", stderr)
            unchanged()

    def test_fifo_without_a_reader_fails_the_set_unchanged(self):
        # the FIFO (the set's last file) is written first: its failure comes before the link's
        # target or any other file of the set is touched
        with tempfile.TemporaryDirectory() as d:
            out, unchanged = self.existing_output_set(d, svg_fifo=True)
            code, stdout, stderr = run("demo", "-o", out, "--quiet", "--size", "9x9")
            self.assertEqual(code, 8, stdout + stderr)
            self.assertIn(f"{out}/swan.svg: a FIFO with no reader: not written", stderr)
            unchanged()

    def test_fifo_with_a_reader_is_streamed_into(self):
        # the reader is open before the run; the grid (1320 bytes) fits in the pipe's buffer
        with tempfile.TemporaryDirectory() as d:
            fifo = os.path.join(d, "swan.xyz")
            os.mkfifo(fifo)
            reader = os.open(fifo, os.O_RDONLY | os.O_NONBLOCK)
            try:
                code, stdout, stderr = run("demo", "-o", d, "--quiet", "--size", "9x9")
                got = os.read(reader, 1 << 16)
            finally:
                os.close(reader)
            self.assertEqual(code, 0, stdout + stderr)
            self.assertTrue(stat.S_ISFIFO(os.lstat(fifo).st_mode))
            self.assertEqual(len(got), (4 + 4 * 2 + 4) + (4 + 8 * 2 * 81 + 4))

    def test_output_path_that_is_a_directory_is_refused_before_solving(self):
        with tempfile.TemporaryDirectory() as d:
            os.mkdir(os.path.join(d, "swan.vts"))
            with open(os.path.join(d, "swan.xyz"), "w") as f:
                f.write("old")
            code, out, err = run("demo", "-o", d, "--quiet", "--size", "9x9")
            self.assertEqual(code, 8, out + err)
            self.assertEqual(err, f"eg2d: {d}/swan.vts: a directory, not replaced by an output file "
                                  "(checked before solving)\n")
            self.assertNotIn("converged", out)
            with open(os.path.join(d, "swan.xyz")) as f:
                self.assertEqual(f.read(), "old")
            self.assertTrue(os.path.isdir(os.path.join(d, "swan.vts")))

    def test_failed_write_leaves_the_old_set(self):
        # swan.vts is a FIFO nobody reads: its write fails, and the old
        # .xyz and .svg beside it are left as they were (the set is one unit)
        with tempfile.TemporaryDirectory() as d:
            for name in ("swan.xyz", "swan.svg"):
                with open(os.path.join(d, name), "w") as f:
                    f.write("old")
            os.mkfifo(os.path.join(d, "swan.vts"))
            code, out, err = run("demo", "-o", d, "--quiet", "--size", "9x9")
            self.assertEqual(code, 8, out + err)
            self.assertIn("swan.vts", err)
            for name in ("swan.xyz", "swan.svg"):
                with open(os.path.join(d, name)) as f:
                    self.assertEqual(f.read(), "old")
            self.assertTrue(stat.S_ISFIFO(os.lstat(os.path.join(d, "swan.vts")).st_mode))
            self.assertEqual(sorted(os.listdir(d)), ["swan.svg", "swan.vts", "swan.xyz"])

    def test_absent_plugin_refused_before_solving(self):
        with tempfile.TemporaryDirectory() as d:
            case = case_from_example(d, "swan", ('formats = ["plot3d", "vts", "svg"]', 'formats = ["plot3d", "cgns"]'))
            p = subprocess.run([TOOL, "run", case, "-o", os.path.join(d, "out"), "--quiet"], capture_output=True,
                               text=True, timeout=600, env={**os.environ, "EG2D_PLUGIN_DIR": "/nonexistent"})
            self.assertEqual(p.returncode, 9, p.stdout + p.stderr)
            self.assertIn("(checked before solving; no files written)", p.stderr)
            self.assertNotIn("converged", p.stdout)
            self.assertFalse(os.path.exists(os.path.join(d, "out")))

    def test_out_of_memory_exit_10(self):
        with open(TOOL, "rb") as f:
            binary = f.read()
            if b"__asan_init" in binary or b"__tsan_init" in binary:
                self.skipTest("a sanitizer's allocator aborts instead of failing an allocation")
        limit = lambda: resource.setrlimit(resource.RLIMIT_AS, (2 << 30, resource.RLIM_INFINITY))
        with tempfile.TemporaryDirectory() as d:
            p = subprocess.run([TOOL, "demo", "--size", "46340x46340", "-o", d, "--quiet"], capture_output=True,
                               text=True, timeout=600, preexec_fn=limit)
            self.assertEqual(p.returncode, 10, p.stdout + p.stderr)
            self.assertEqual(p.stderr, "eg2d: out of memory: the grid is too large for this machine "
                                       "(eg2d_create: cannot allocate 2147395600 nodes)\n")
            self.assertEqual(os.listdir(d), [])

    def test_directory_as_case_file(self):
        with tempfile.TemporaryDirectory() as d:
            code, out, err = run("run", d, "-o", os.path.join(d, "out"))
            self.assertEqual(code, 8, out + err)
            self.assertEqual(err, f"eg2d: {d}: a directory, not a case file\n")


class Demo(unittest.TestCase):
    def test_default_demo_writes_a_picture(self):
        with tempfile.TemporaryDirectory() as d:
            code, out, err = run("demo", "-o", os.path.join(d, "demo-out"), "--quiet")
            self.assertEqual(code, 0, out + err)
            self.assertTrue(out.startswith("Swan (the elliptic-grid course notes, A4): 65 x 65 single-block grid"))
            files = sorted(os.listdir(os.path.join(d, "demo-out")))
            self.assertIn("swan.svg", files)
            check_svg(self, os.path.join(d, "demo-out", "swan.svg"))
            self.assertEqual(files, ["swan.svg", "swan.vts", "swan.xyz"])
            # 2D Plot3D, Fortran unformatted: [8] ni nj [8], [16 ni nj] x y [16 ni nj]
            with open(os.path.join(d, "demo-out", "swan.xyz"), "rb") as f:
                data = f.read()
            self.assertEqual(len(data), 4 + 8 + 4 + 4 + 16 * 65 * 65 + 4)
            self.assertEqual(struct.unpack("<iiii", data[:16]), (8, 65, 65, 8))
            x = struct.unpack("<%dd" % (65 * 65), data[20:20 + 8 * 65 * 65])
            self.assertEqual((min(x), max(x)), (0.0, 1.5))  # the swan's right side bulges to x = 1.5

    def test_picture_coloured_by_quality(self):
        """[output] svg_quality colours every cell: one polygon per cell."""
        with tempfile.TemporaryDirectory() as d:
            code, out, err = run("demo", "antenna", "-o", d, "--size", "21x11", "--quiet")
            self.assertEqual(code, 0, out + err)
            root = ET.parse(os.path.join(d, "antenna.svg")).getroot()
            self.assertEqual(len(list(root.iter("{http://www.w3.org/2000/svg}polygon"))), 20 * 10)

    def test_list_is_the_examples(self):
        code, out, _ = run("demo", "--list")
        self.assertEqual(code, 0)
        listed = [line.split()[0] for line in out.splitlines()]
        examples = sorted(f[:-5] for f in os.listdir(EXAMPLES) if f.endswith(".toml"))
        self.assertEqual(listed, examples)
        self.assertRegex(out, r"(?m)^swan +Swan \(the elliptic-grid course notes, A4\) \(default\)$")

    def test_demo_text_is_the_example_file(self):
        # the embedded demo runs the same case as the file: same first line and counts
        with tempfile.TemporaryDirectory() as d:
            a = run("demo", "valley", "-o", d, "--size", "17x17", "--quiet")
            b = run("run", os.path.join(EXAMPLES, "valley.toml"), "-o", d, "--size", "17x17", "--quiet")
            self.assertEqual(a[0], 0)
            strip = lambda s: re.sub(r", [0-9.]+ s$", "", s, flags=re.M)
            self.assertEqual(strip(a[1]), strip(b[1]))


class Progress(unittest.TestCase):
    def test_terminal_progress_rewrites_one_line(self):
        """On a terminal the progress line is rewritten in place (carriage returns, no new lines)."""
        import pty
        master, slave = pty.openpty()
        with tempfile.TemporaryDirectory() as d:
            p = subprocess.Popen([TOOL, "demo", "-o", d, "--size", "9x9"], stdout=slave, stderr=subprocess.PIPE)
            os.close(slave)
            chunks = []
            while True:
                try:
                    chunk = os.read(master, 4096)
                except OSError:  # the terminal closed: the program ended
                    break
                if not chunk:
                    break
                chunks.append(chunk)
            p.wait(timeout=60)
            os.close(master)
        text = b"".join(chunks).decode()
        self.assertEqual(p.returncode, 0)
        self.assertRegex(text, r"\r  iteration +1  residual \d\.\d{3}e[-+]\d\d  rate -/iteration ")
        self.assertNotRegex(text, r"\n  iteration")
        self.assertIn("converged in", text)

    def test_plain_progress_lines_and_ctrl_c(self):
        """Not a terminal: plain lines. SIGINT after the first line stops the run, writes nothing, exit 130;
        SIGTERM likewise, exit 143."""
        for sig, code in ((signal.SIGINT, 130), (signal.SIGTERM, 143)):
            self.stopped_by(sig, code)

    def stopped_by(self, sig, code):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "big.toml")
            with open(os.path.join(EXAMPLES, "swan.toml")) as f:
                text = f.read().replace("tolerance = 1e-10", "tolerance = 1e-15").replace(
                    "max_iterations = 20000", "max_iterations = 100000000").replace("# method: the library's default, FAS multigrid", 'method = "psor"')
            with open(path, "w") as f:
                f.write(text)
            out_dir = os.path.join(d, "out")
            p = subprocess.Popen([TOOL, "run", path, "-o", out_dir, "--size", "801x801"],
                                 stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            header = p.stdout.readline()
            first = p.stdout.readline()
            p.send_signal(sig)
            rest, err = p.communicate(timeout=120)
            self.assertTrue(header.startswith("Swan (the elliptic-grid course notes, A4): 801 x 801"), header)
            self.assertRegex(first, r"^  iteration 1  residual \d\.\d{3}e[-+]\d\d  rate -/iteration\n$")
            self.assertEqual(p.returncode, code, rest + err)
            self.assertRegex(rest, r"(?m)^interrupted by %s at iteration \d+, residual .*: no files written$" % sig.name)
            self.assertFalse(os.path.exists(out_dir))


class Patches(unittest.TestCase):
    """[[patches]] name and type stretches of the sides; the solver formats carry them."""

    CASE = 'size = [9, 5]\n' + ErrorMessages.GOOD_SIDES + textwrap.dedent("""
        [[patches]]
        side = "left"
        type = "inflow"
        name = "inlet"
        [[patches]]
        side = "bottom"
        first = 2
        last = 6
        type = "symmetry"
        name = "axis"
        [output]
        formats = ["su2", "openfoam"]
        span = 0.25
        """)

    def run_case(self, text, d):
        path = os.path.join(d, "case.toml")
        with open(path, "w") as f:
            f.write(text)
        return run("run", path, "-o", os.path.join(d, "out"), "--quiet")

    def test_patches_reach_the_files(self):
        with tempfile.TemporaryDirectory() as d:
            code, out, err = self.run_case(self.CASE, d)
            self.assertEqual(code, 0, err)
            with open(os.path.join(d, "out", "case.su2")) as f:
                su2 = f.read()
            markers = re.findall(r"MARKER_TAG= (\S+)\nMARKER_ELEMS= (\d+)", su2)
            # bottom's default "jmin" keeps the edges either side of "axis"
            self.assertEqual(markers, [("jmin", "4"), ("axis", "4"), ("imax", "4"), ("jmax", "8"), ("inlet", "4")])
            with open(os.path.join(d, "out", "case_foam", "constant", "polyMesh", "boundary")) as f:
                boundary = f.read()
            self.assertEqual(re.findall(r"^    (\w+)\n    \{\n        type +(\w+);", boundary, re.M),
                             [("jmin", "wall"), ("axis", "symmetry"), ("imax", "wall"), ("jmax", "wall"),
                              ("inlet", "patch"), ("frontAndBack", "empty")])
            self.assertEqual(self.points_z(os.path.join(d, "out", "case_foam")), {0.0, 0.25})

    def test_bad_patches(self):
        with tempfile.TemporaryDirectory() as d:
            text = self.CASE.replace('side = "left"', 'side = "west"')
            code, _, err = self.run_case(text, d)
            self.assertEqual(code, 3)
            self.assertIn("key 'patches[0].side': \"west\" is not one of: bottom, right, top, left", err)
            text = self.CASE.replace("last = 6", "last = 9")
            code, _, err = self.run_case(text, d)
            self.assertEqual(code, 3)
            self.assertIn("first = 2, last = 9: need whole numbers 0 <= first < last <= 8 (side bottom has 9 nodes)",
                          err)
            # the library's own check, located at the table
            text = self.CASE.replace('side = "left"', 'side = "bottom"')
            code, _, err = self.run_case(text, d)
            self.assertNotEqual(code, 0)
            self.assertIn("patches[1]", err)
            self.assertIn("eg2d_set_patch: side JMIN nodes [2, 6] overlap patch \"inlet\" [0, 8]", err)

    def points_z(self, case):
        with open(os.path.join(case, "constant", "polyMesh", "points")) as f:
            return {float(m) for m in re.findall(r"^\(\S+ \S+ (\S+)\)$", f.read(), re.M)}

    def test_existing_case_is_updated_in_place(self):
        # the second run replaces the mesh and keeps the case's own files; no stage is left
        with tempfile.TemporaryDirectory() as d:
            code, _, err = self.run_case(self.CASE, d)
            self.assertEqual(code, 0, err)
            case = os.path.join(d, "out", "case_foam")
            with open(os.path.join(case, "system", "controlDict"), "w") as f:
                f.write("the user's controlDict")
            os.mkdir(os.path.join(case, "0"))
            open(os.path.join(case, "0", "U"), "w").close()
            code, _, err = self.run_case(self.CASE.replace("span = 0.25", "span = 0.5"), d)
            self.assertEqual(code, 0, err)
            self.assertEqual(self.points_z(case), {0.0, 0.5})
            with open(os.path.join(case, "system", "controlDict")) as f:
                self.assertEqual(f.read(), "the user's controlDict")
            self.assertTrue(os.path.exists(os.path.join(case, "0", "U")))
            self.assertEqual(sorted(os.listdir(os.path.join(d, "out"))), ["case.su2", "case_foam"])

    def test_case_path_that_is_a_file_is_refused_before_solving(self):
        with tempfile.TemporaryDirectory() as d:
            os.mkdir(os.path.join(d, "out"))
            blocker = os.path.join(d, "out", "case_foam")
            with open(blocker, "w") as f:
                f.write("old")
            code, out, err = self.run_case(self.CASE, d)
            self.assertEqual(code, 8, out + err)
            self.assertEqual(err, f"eg2d: {blocker}: not a directory, so no case can be written there "
                                  "(checked before solving)\n")
            with open(blocker) as f:
                self.assertEqual(f.read(), "old")

    def test_failed_set_leaves_no_staged_case(self):
        # case.su2 is a FIFO nobody reads: the set fails after the case was staged,
        # and the staged case directory goes with the stage
        with tempfile.TemporaryDirectory() as d:
            os.mkdir(os.path.join(d, "out"))
            os.mkfifo(os.path.join(d, "out", "case.su2"))
            code, out, err = self.run_case(self.CASE, d)
            self.assertEqual(code, 8, out + err)
            self.assertIn("case.su2", err)
            self.assertEqual(os.listdir(os.path.join(d, "out")), ["case.su2"])



def naca0012_selig(path, n=81, scale=1, at=(0, 0)):
    """The standard NACA 0012 (open trailing edge, 0.00252 chords) as a Selig file,
    of chord SCALE with its leading edge AT."""
    xs = [0.5 * (1 - math.cos(math.pi * k / (n - 1))) for k in range(n)]
    t = lambda x: 0.6 * (0.2969 * math.sqrt(x) - 0.1260 * x - 0.3516 * x**2 + 0.2843 * x**3 - 0.1015 * x**4)
    with open(path, "w") as f:
        f.write("NACA 0012 open\n")
        for x, y in [(x, t(x)) for x in reversed(xs)] + [(x, -t(x)) for x in xs[1:]]:
            f.write(f"{at[0] + scale * x:.8f} {at[1] + scale * y:.8f}\n")


def naca4_selig(path, m, p, t, base=None, n=81):
    """NACA MPTT's standard section (its trailing edge open, 0.0021 t/0.12 chords
    thick) as a Selig file, or with its thickness raised in proportion to x so
    that its base is BASE chords thick; the ends' y returned."""
    xs = [0.5 * (1 - math.cos(math.pi * k / (n - 1))) for k in range(n)]
    yt = lambda x: 5 * t * (0.2969 * math.sqrt(x) - 0.1260 * x - 0.3516 * x**2 + 0.2843 * x**3 - 0.1015 * x**4)
    extra = 0 if base is None else base / 2 - yt(1)
    def camber(x):  # the camber line's height and slope
        if m == 0:
            return 0, 0
        q = p if x < p else 1 - p
        return m / q**2 * ((2 * p * x - x * x) if x < p else (1 - 2 * p + 2 * p * x - x * x)), 2 * m / q**2 * (p - x)
    def point(x, side):
        c, slope = camber(x)
        h, a = yt(x) + extra * x, math.atan(slope)
        return x - side * h * math.sin(a), c + side * h * math.cos(a)
    points = [(round(x, 8), round(y, 8)) for x, y in
              [point(x, 1) for x in reversed(xs)] + [point(x, -1) for x in xs[1:]]]  # as written
    with open(path, "w") as f:
        f.write(f"NACA {m * 100:.0f}{p * 10:.0f}{t * 100:02.0f}{'' if base is None else f' base {base}'}\n")
        for x, y in points:
            f.write(f"{x:.8f} {y:.8f}\n")
    return points[0], points[-1]


def svg_view(path):
    """An eg2d airfoil picture: (its window in the plane as xmin, ymin, xmax, ymax,
    from the viewBox with y negated back; its width and height in pixels;
    {class: [[(x, y), ...], ...]} its polylines in the plane)."""
    root = ET.parse(path).getroot()
    vx, vy, vw, vh = (float(v) for v in root.get("viewBox").split())
    lines = {}
    for p in root.iter("{http://www.w3.org/2000/svg}polyline"):
        pts = [tuple(float(v) for v in xy.split(",")) for xy in p.get("points").split()]
        lines.setdefault(p.get("class"), []).append([(x, -y) for x, y in pts])
    return (vx, -(vy + vh), vx + vw, -vy), (int(root.get("width")), int(root.get("height"))), lines


def png_size(test, path):
    """The width and height of a PNG file, read by PIL (Debian's python3-pil), or by
    file(1) where PIL is missing; the pixels too with PIL (else None)."""
    try:
        from PIL import Image
    except ImportError:
        out = subprocess.run(["file", path], capture_output=True, text=True).stdout
        m = re.search(r"PNG image data, (\d+) x (\d+)", out)
        test.assertTrue(m, out)
        return (int(m.group(1)), int(m.group(2))), None
    with Image.open(path) as im:
        test.assertEqual(im.format, "PNG")
        im.load()
        return im.size, im.convert("RGB")


def vts_points(path):
    root = ET.parse(path).getroot()
    text = root.find(".//{*}Points/{*}DataArray").text.split()
    return [(float(text[k]), float(text[k + 1])) for k in range(0, len(text), 3)]


class InteriorLines(unittest.TestCase):
    """[[interior_lines]]: the row is held on its curve by TFI and the solve."""

    LINE = textwrap.dedent("""
        [[interior_lines]]
        direction = "eta"
        index = 10
        curve = { x = "s", y = "10/32 + 0.05*sin(pi*s)" }
        """)

    def test_row_held(self):
        with tempfile.TemporaryDirectory() as d:
            path = case_from_example(d, "valley", ("size = [65, 65]", "size = [33, 33]"),
                                     ('formats = ["plot3d", "svg"]', 'formats = ["plot3d-ascii"]'))
            with open(path, "a") as f:
                f.write(self.LINE)
            code, out, err = run("run", path, "-o", os.path.join(d, "out"))
            self.assertEqual(code, 0, err)
            with open(os.path.join(d, "out", "case.p3d")) as f:
                numbers = f.read().split()
            ni, nj = int(numbers[0]), int(numbers[1])
            xyz = [float(v) for v in numbers[2:]]
            x, y = xyz[:ni * nj], xyz[ni * nj:]
            for i in range(1, ni - 1):
                s = i / (ni - 1)
                self.assertAlmostEqual(x[i + ni * 10], s, places=12)
                self.assertAlmostEqual(y[i + ni * 10], 10 / 32 + 0.05 * math.sin(math.pi * s), places=12)

    def test_bad_line(self):
        with tempfile.TemporaryDirectory() as d:
            path = case_from_example(d, "valley", ("size = [65, 65]", "size = [33, 33]"))
            with open(path, "a") as f:
                f.write(self.LINE.replace("index = 10", "index = 40"))
            code, _, err = run("run", path, "-o", os.path.join(d, "out"))
            self.assertEqual(code, 3)
            self.assertIn("key 'interior_lines[0].index': index = 40: an interior row in [1, 31]", err)


class Airfoil(unittest.TestCase):
    """eg2d airfoil: the issue's command at the sizes it names (the hybrid
    layer; a C-grid 385x97 takes about 0.5 s), the family property, the
    solver formats read back by checkMesh, meshio and cgnscheck where
    installed, open trailing edges, and the command line's errors."""

    def airfoil(self, d, *args):
        code, out, err = run("airfoil", *args, "-o", d, "--quiet")
        self.assertEqual(code, 0, out + err)
        return out

    def report(self, d, name):
        import json
        with open(os.path.join(d, name + ".report.json")) as f:
            return json.load(f)

    def test_c_grid_family(self):
        import math
        with tempfile.TemporaryDirectory() as d:
            self.airfoil(d, "0012", "--topology", "c", "--size", "385x97", "--yplus", "1", "--reynolds", "6e6",
                         "--levels", "3", "--format", "plot3d3d,cgns,su2,openfoam,vts")
            for size in ("385x97", "193x49", "97x25"):
                for ext in ("-3d.xyz", ".cgns", ".su2", ".vts", ".report.txt", ".report.json"):
                    self.assertTrue(os.path.isfile(os.path.join(d, f"naca0012-{size}{ext}")), size + ext)
                self.assertTrue(os.path.isdir(os.path.join(d, f"naca0012-{size}_foam", "constant", "polyMesh")))
            # y+ 1 at Re 6e6 by the flat-plate estimate eg2d.h states
            cf = (2 * math.log10(6e6) - 0.65) ** -2.3
            h = 1 / (6e6 * math.sqrt(cf / 2))
            r = self.report(d, "naca0012-385x97")
            self.assertEqual(r["folded_cells"], 0)
            self.assertLess(abs(r["wall"]["first_cell_height"]["min"] / h - 1), 0.05)
            self.assertLess(abs(r["wall"]["first_cell_height"]["max"] / h - 1), 0.05)
            self.assertLessEqual(r["wall"]["angle_deviation_deg"]["max"], 1.0)
            # the family: each coarser grid is every other node of the next
            fine = vts_points(os.path.join(d, "naca0012-385x97.vts"))
            mid = vts_points(os.path.join(d, "naca0012-193x49.vts"))
            self.assertEqual(mid, [fine[i + 385 * j] for j in range(0, 97, 2) for i in range(0, 385, 2)])
            # the far field at least 100 chords from the section
            body = [fine[i] for i in range(80, 305)]
            outer = [fine[i + 385 * 96] for i in range(385)]
            self.assertGreaterEqual(min(math.dist(p, q) for p in outer for q in body[::8]), 100 - 1e-6)
            for size, (ni, nj, w) in {"385x97": (385, 97, 80), "193x49": (193, 49, 40), "97x25": (97, 25, 20)}.items():
                self.check_su2(os.path.join(d, f"naca0012-{size}"), ni, nj, w)
                self.check_cgns(os.path.join(d, f"naca0012-{size}"), True)
            for size in ("385x97", "193x49", "97x25"):  # every level
                self.check_mesh(os.path.join(d, f"naca0012-{size}_foam"))

    def check_su2(self, name, ni, nj, w):
        """meshio reads NAME.su2 (where installed) with its markers, every boundary
        edge in one; W the C-grid's cut nodes a side (0: an O-grid)."""
        try:
            import meshio
        except ImportError:
            return
        mesh = meshio.read(name + ".su2")
        with open(name + ".su2") as f:
            tags = sorted(re.findall(r"^MARKER_TAG=\s*(\S+)", f.read(), re.M))
        lines = sum(len(c.data) for c in mesh.cells if c.type == "line")
        if w:
            self.assertEqual(mesh.points.shape[0], ni * nj - (w + 1))  # the cut's nodes merged, trailing edge included
            self.assertEqual(tags, ["farfield", "outflow", "wall"])
            self.assertEqual(lines, (ni - 1 - 2 * w) + (ni - 1) + 2 * (nj - 1))
        else:
            self.assertEqual(mesh.points.shape[0], (ni - 1) * nj)  # the periodic cut merged
            self.assertEqual(tags, ["farfield", "wall"])
            self.assertEqual(lines, 2 * (ni - 1))

    def check_cgns(self, name, cgrid):
        """cgnscheck (where installed) finds no errors in NAME.cgns, and it holds
        the boundary conditions and the cut's 1-to-1 connection."""
        check_cgns_file(self, name + ".cgns", ("wall", "farfield", "outflow") if cgrid else ("wall", "farfield"))
        if not shutil_which("cgnscheck"):
            return
        p = subprocess.run([shutil_which("cgnscheck"), "-v", name + ".cgns"], capture_output=True, text=True)
        out = p.stdout + p.stderr
        for cut in ("wake_lower", "wake_upper") if cgrid else ("cut_imin", "cut_imax"):
            self.assertIn(f'checking 1to1 connectivity "{cut}"', out)

    def check_mesh(self, case):
        check_mesh(self, case)

    def test_o_grid_and_open_trailing_edges(self):
        import math
        with tempfile.TemporaryDirectory() as d:
            self.airfoil(d, "0012", "--topology", "o", "--size", "257x129", "--yplus", "1", "--reynolds", "6e6",
                         "--levels", "2", "--format", "su2,vts,openfoam")
            r = self.report(d, "naca0012-257x129")
            self.assertEqual(r["folded_cells"], 0)
            cf = (2 * math.log10(6e6) - 0.65) ** -2.3
            h = 1 / (6e6 * math.sqrt(cf / 2))
            self.assertLess(abs(r["wall"]["first_cell_height"]["min"] / h - 1), 0.05)
            self.assertLess(abs(r["wall"]["first_cell_height"]["max"] / h - 1), 0.05)
            self.assertLessEqual(r["wall"]["angle_deviation_deg"]["max"], 1.0)
            self.assertTrue(os.path.isfile(os.path.join(d, "naca0012-129x65.su2")))
            fine = vts_points(os.path.join(d, "naca0012-257x129.vts"))  # the far field 100 chords out or more
            outer, body = fine[257 * 128:], fine[:257]
            self.assertGreaterEqual(min(math.dist(p, q) for p in outer for q in body[::4]), 100 - 1e-6)
            # the standard section's open trailing edge kept blunt: checkMesh passes on both levels
            for size in ("257x129", "129x65"):
                self.check_mesh(os.path.join(d, f"naca0012-{size}_foam"))
            selig = os.path.join(d, "open.dat")
            naca0012_selig(selig)
            out = self.airfoil(d, selig, "--topology", "o", "--size", "257x129", "--first-cell", "1e-5",
                               "--format", "vts")
            r = self.report(d, "open-257x129")
            self.assertEqual(r["folded_cells"], 0)  # the blunt base kept: two convex corners
            self.airfoil(d, selig, "--topology", "c", "--size", "385x97", "--first-cell", "1e-5", "--format", "vts")
            self.assertEqual(self.report(d, "open-385x97")["folded_cells"], 0)  # the base kept on C-grids too

    def test_tmr_comparison(self):
        """A C-grid of one of the TMR family's sizes (113x33, its coarsest) is compared
        with the published figures in NAME-NIxNJ.tmr.txt, and printed; its own figures are
        the grid's (the counts of the airfoil's and the wake's points, the first cell as
        asked, the far field); another size (97x25) has no comparison."""
        with tempfile.TemporaryDirectory() as d:
            code, text, err = run("airfoil", "0012", "--topology", "c", "--size", "113x33", "--first-cell", "8e-6",
                                  "--farfield", "500", "--te", "sharpen", "-o", d)
            self.assertEqual(code, 4, text + err)  # 32 rows to 500 chords grow by more than 1.2: said, written
            with open(os.path.join(d, "naca0012-113x33.tmr.txt")) as f:
                tmr = f.read()
            self.assertIn(tmr, text)
            self.assertIn("its level 7 of 7 (64 times coarser than 7169x2049)", tmr)
            rows = {line[:40].strip(): line[40:].split() for line in tmr.splitlines()[2:]}
            self.assertEqual(rows["points on the airfoil"], ["65", "65"])
            self.assertEqual(rows["points on each side of the wake"], ["25", "25"])
            published, low, _, high = rows["first cell, chords"]
            self.assertAlmostEqual(float(published), 1e-7 * (1.02 ** 64 - 1) / 0.02, delta=1e-7)
            self.assertLess(abs(float(low) / 8e-6 - 1), 0.01)
            self.assertLess(abs(float(high) / 8e-6 - 1), 0.01)
            self.assertLess(abs(float(rows["far field, chords"][2]) / 500 - 1), 0.01)
            code, text, err = run("airfoil", "0012", "--topology", "c", "--size", "97x25", "--first-cell", "1e-4",
                                  "--farfield", "20", "-o", d)
            self.assertIn(code, (0, 4), text + err)  # 4: 24 rows grow by more than 1.2, said, written
            self.assertTrue(os.path.exists(os.path.join(d, "naca0012-97x25.report.txt")))
            self.assertFalse(os.path.exists(os.path.join(d, "naca0012-97x25.tmr.txt")))
            self.assertNotIn("TMR", text)

    @unittest.skipUnless(sys.platform.startswith("linux"), "glibc's tunables")
    def test_huge_pages_rerun(self):
        """From 2^18 nodes, or with EG2D_HUGE_PAGES=1, eg2d airfoil runs itself again with
        glibc's transparent huge pages (GLIBC_TUNABLES=glibc.malloc.hugetlb=1) and says so
        once; the files are those of a run without (EG2D_HUGE_PAGES=0); a GLIBC_TUNABLES
        that names hugetlb is the user's choice and is left alone."""
        base = {k: v for k, v in os.environ.items() if k not in ("GLIBC_TUNABLES", "EG2D_HUGE_PAGES")}
        note = "note: running again with GLIBC_TUNABLES=glibc.malloc.hugetlb=1"
        with tempfile.TemporaryDirectory() as d:
            def airfoil(out, **env):
                p = subprocess.run([TOOL, "airfoil", "0012", "--topology", "c", "--size", "97x25", "--first-cell",
                                    "1e-4", "--farfield", "20", "-o", os.path.join(d, out)],
                                   capture_output=True, text=True, timeout=600, env={**base, **env})
                self.assertIn(p.returncode, (0, 4), p.stdout + p.stderr)  # 4: 24 rows grow by more than 1.2
                with open(os.path.join(d, out, "naca0012-97x25.xyz"), "rb") as f:
                    return p.stdout, f.read(), p.stderr
            text, on, err = airfoil("on", EG2D_HUGE_PAGES="1")
            self.assertEqual(text.count(note), 1, text)
            self.assertNotIn("could not run again", text + err)
            self.assertEqual(text.count("naca0012 C-grid 97x25"), 1, text)  # the run itself once, after the note
            text, off, _ = airfoil("off", EG2D_HUGE_PAGES="0")
            self.assertNotIn("running again", text)
            self.assertEqual(on, off)
            text, _, _ = airfoil("user", EG2D_HUGE_PAGES="1", GLIBC_TUNABLES="glibc.malloc.hugetlb=0")
            self.assertNotIn("running again", text)
            text, _, _ = airfoil("small")  # 2425 nodes: not asked
            self.assertNotIn("running again", text)

    def test_selig_blunt_bases(self):
        """Selig files with an open trailing edge (NACA 4412, 0.0025 chords) and a
        blunt base (NACA 0012 thickened to a 1% base) on both topologies: the base
        kept as wall, the run saying so, and every level passing the issue's
        checks (first cells from --first-cell here, at sizes a test can afford)."""
        with tempfile.TemporaryDirectory() as d:
            for name, shape in (("open4412", (0.04, 0.4, 0.12)), ("flatback", (0, 0.4, 0.12, 0.01))):
                corners = naca4_selig(os.path.join(d, name + ".dat"), *shape)
                for topo, ni, nj in (("c", 257, 65), ("o", 129, 65)):
                    out = os.path.join(d, topo)
                    code, text, err = run("airfoil", os.path.join(d, name + ".dat"), "--topology", topo, "--size",
                                          f"{ni}x{nj}", "--first-cell", "1e-4", "--farfield", "20", "--levels", "2",
                                          "--format", "cgns,su2,openfoam,vts", "-o", out)
                    self.assertEqual(code, 0, text + err)  # 0: the first 30 cells grow by 1.2 at most
                    gap = math.dist(*corners)
                    self.assertIn(f"note: the open trailing edge ({gap:.3g} chords thick) kept as a blunt base", text)
                    r = self.report(out, f"{name}-{ni}x{nj}")
                    self.assertEqual(r["folded_cells"], 0)
                    for k in ("min", "max"):
                        self.assertLess(abs(r["wall"]["first_cell_height"][k] / 1e-4 - 1), 0.05)
                    self.assertLessEqual(r["wall"]["angle_deviation_deg"]["max"], 1.0)
                    grid = vts_points(os.path.join(out, f"{name}-{ni}x{nj}.vts"))
                    w = int(re.search(r"JMIN (\d+)\.\.", r["wall"]["stretches"][0]).group(1))
                    wall = grid[w:ni - w] if topo == "c" else grid[:ni]
                    for corner in corners:  # the base kept: the file's ends are wall nodes
                        self.assertLess(min(math.dist(corner, q) for q in wall), 1e-7, (name, topo))
                    if topo == "c":  # the cut leaves the base's midpoint along the base's normal
                        cut = (grid[w - 1][0] - grid[w][0], grid[w - 1][1] - grid[w][1])
                        base = (corners[1][0] - corners[0][0], corners[1][1] - corners[0][1])
                        self.assertLess(abs(cut[0] * base[0] + cut[1] * base[1]) / (math.hypot(*cut) * gap), 1e-9)
                    outer = grid[ni * (nj - 1):]
                    self.assertGreaterEqual(min(math.dist(p, q) for p in outer for q in wall[::2]), 20 - 1e-6)
                    for level, (li, lj) in enumerate(((ni, nj), ((ni + 1) // 2, (nj + 1) // 2))):
                        base_name = os.path.join(out, f"{name}-{li}x{lj}")
                        self.check_mesh(base_name + "_foam")
                        self.check_su2(base_name, li, lj, w >> level)
                        self.check_cgns(base_name, topo == "c")
            # sharpened on request, and the run says so: one node at the trailing edge
            code, text, err = run("airfoil", os.path.join(d, "open4412.dat"), "--size", "129x33", "--first-cell",
                                  "1e-4", "--farfield", "10", "--te", "sharpen", "--format", "vts", "-o", d)
            self.assertIn("note: the open trailing edge (0.00252 chords thick) sharpened", text)
            # what the file gave: the cambered nose lies a little before x = 0
            self.assertRegex(text, r"open4412\.dat: chord 1\.000\d+ from the leading edge \(-0\.000\d+, 0\.00\d+\) to "
                                   r"the trailing edge \(1, 0\)")
            grid = vts_points(os.path.join(d, "open4412-129x33.vts"))
            r = self.report(d, "open4412-129x33")
            w = int(re.search(r"JMIN (\d+)\.\.", r["wall"]["stretches"][0]).group(1))
            self.assertEqual(grid[w], grid[128 - w])
            self.assertGreater(math.dist(grid[w], grid[w + 1]), 1e-3)  # no base: the next node is on a surface

    VIEWS = ("domain", "airfoil", "le", "te")

    def check_views(self, d, name, le, te, ni, nj):
        """The four pictures of grid NAME in D frame what they say, from the section's
        leading edge LE and trailing edge TE; what lies outside a window is left out."""
        chord = math.dist(le, te)
        inside = lambda p, w, margin=0: w[0] - margin <= p[0] <= w[2] + margin and w[1] - margin <= p[1] <= w[3] + margin
        windows, shown, has_png = {}, {}, features()["formats"]["png"]
        for view in self.VIEWS:
            path = os.path.join(d, f"{name}-{view}.svg")
            window, size, lines = svg_view(path)
            windows[view] = window
            points = [p for kind in lines.values() for line in kind for p in line]
            shown[view] = len(points)
            # clipped: every point drawn is in the window (to the printed digits)
            eps = 1e-3 * (window[2] - window[0])
            self.assertEqual([p for p in points if not inside(p, window, eps)], [], view)
            self.assertTrue(lines.get("wall"), view)  # the section is in every view
            self.assertTrue(lines.get("grid"), view)
            self.assertLess(os.path.getsize(path), 200_000, view)
            if view != "domain":
                self.assertEqual(size, (800, 600), view)
            if has_png:
                png, pixels = png_size(self, os.path.join(d, f"{name}-{view}.png"))
                self.assertEqual(png, size, view)  # the size the SVG states
                if pixels:  # drawn: the wall's colour in the middle half, where the section is
                    red = [(x, y) for x in range(png[0] // 4, 3 * png[0] // 4) for y in range(png[1] // 4, 3 * png[1] // 4)
                           if pixels.getpixel((x, y))[0] > 150 > pixels.getpixel((x, y))[1]]
                    self.assertTrue(red, view)
        width = lambda w: w[2] - w[0]
        for p in (le, te):
            self.assertTrue(inside(p, windows["airfoil"]))
            self.assertTrue(inside(p, windows["domain"]))
        self.assertLess(width(windows["airfoil"]), 2 * chord)
        self.assertGreater(width(windows["domain"]), 100 * chord)
        for view, p, other in (("le", le, te), ("te", te, le)):
            w = windows[view]
            self.assertTrue(inside(p, w), view)
            self.assertFalse(inside(other, w), view)
            self.assertLess(width(w), 0.1 * chord, view)
            self.assertLess(math.dist(p, ((w[0] + w[2]) / 2, (w[1] + w[3]) / 2)), 0.01 * chord, view)
            # culled: far fewer points than the grid's lines have (2 ni nj)
            self.assertLess(shown[view], 0.05 * 2 * ni * nj, view)
        self.assertLess(shown["domain"], 0.25 * 2 * ni * nj)

    def test_views(self):
        with tempfile.TemporaryDirectory() as d:
            formats = "svg,png" if features()["formats"]["png"] else "svg"
            self.airfoil(d, "0012", "--topology", "c", "--size", "385x97", "--yplus", "1", "--reynolds", "6e6",
                         "--levels", "2", "--format", formats)
            self.check_views(d, "naca0012-385x97", (0, 0), (1, 0), 385, 97)
            self.check_views(d, "naca0012-193x49", (0, 0), (1, 0), 193, 49)
            # a section of chord 2 elsewhere, with a blunt base: framed from the grid alone
            selig = os.path.join(d, "moved.dat")
            naca0012_selig(selig, scale=2, at=(3, 1))
            self.airfoil(d, selig, "--topology", "o", "--size", "257x129", "--first-cell", "1e-5", "--format", formats)
            self.check_views(d, "moved-257x129", (3, 1), (5, 1), 257, 129)

    def test_docs_pictures_are_current(self):
        # docs/airfoil.md's pictures are what its command draws now
        docs = os.path.join(EXAMPLES, os.pardir, "docs", "airfoil")
        with tempfile.TemporaryDirectory() as d:
            self.airfoil(d, "0012", "--topology", "c", "--size", "385x97", "--yplus", "1", "--reynolds", "6e6",
                         "--levels", "3", "--format", "svg")
            for view in self.VIEWS:
                name = f"naca0012-385x97-{view}.svg"
                with open(os.path.join(d, name)) as new, open(os.path.join(docs, name)) as old:
                    self.assertTrue(new.read() == old.read(), f"docs/airfoil/{name} is not what eg2d draws now: "
                                    "make it again with docs/airfoil.md's command and --format svg")

    def test_command_line(self):
        with tempfile.TemporaryDirectory() as d:
            code, _, err = run("airfoil", "0012", "--size", "250x100", "--first-cell", "1e-5", "--levels", "2", "-o", d)
            self.assertEqual(code, 2)
            self.assertIn("--levels 2 needs NI-1 and NJ-1 divisible by 2", err)
            self.assertIn("250x100 allows at most 1", err)
            code, _, err = run("airfoil", "0012", "--size", "97x25", "--yplus", "1", "-o", d)
            self.assertEqual(code, 2)
            self.assertIn("--yplus needs --reynolds, and --reynolds --yplus", err)
            code, _, err = run("airfoil", "0012", "--size", "97x25", "--first-cell", "1e-5", "--growth", "10",
                               "--format", "png", "-o", d)
            if features()["formats"]["png"]:
                # 4: 22 faces of this coarse grid past checkMesh's non-orthogonality 70 (84.5), said, written
                self.assertEqual(code, 4, err)
                self.assertIn("97x25 has 22 face(s) past checkMesh's limits", err)
                self.assertTrue(os.path.isfile(os.path.join(d, "naca0012-97x25-le.png")))
            else:  # a build without cairo names what it lacks
                self.assertEqual(code, 9)
                self.assertIn("--format png is not in this build: it needs cairo", err)
            code, out, _ = run("airfoil", "--help")
            self.assertEqual(code, 0)
            self.assertIn("--levels", out)


class AirfoilOutputSet(unittest.TestCase):
    """eg2d airfoil writes its family (every level, format, report, picture and
    TMR comparison) as one set: what would fail after the solve is refused
    before it, and a failure or a signal part-way leaves the output directory
    exactly as it was (no .eg2d-set-* stage, no new file), with a message
    naming the cause and a non-zero exit."""

    ARGS = ("0012", "--size", "97x25", "--first-cell", "1e-4", "--farfield", "20", "--levels", "2")

    def old_directory(self, d):
        """d/out with an older family's grid and report; returns it and a snapshot function."""
        out = os.path.join(d, "out")
        os.mkdir(out)
        for name in ("naca0012-97x25.xyz", "naca0012-49x13.report.json"):
            with open(os.path.join(out, name), "w") as f:
                f.write("old " + name)
        return out

    def snapshot(self, out):
        """{name: (file type, bytes)} of every entry of out."""
        snap = {}
        for name in os.listdir(out):
            st = os.lstat(os.path.join(out, name))
            data = None
            if stat.S_ISREG(st.st_mode):
                with open(os.path.join(out, name), "rb") as f:
                    data = f.read()
            snap[name] = (stat.S_IFMT(st.st_mode), data)
        return snap

    def test_fifo_without_a_reader(self):
        # the report of the finest level (written by the library, amended by
        # the command) and a TMR comparison (the command's own text, which a
        # plain stream would have hung on) as FIFOs nobody reads
        for args, fifo in ((self.ARGS, "naca0012-97x25.report.txt"),
                           (("0012", "--size", "113x33", "--first-cell", "8e-6", "--farfield", "500",
                             "--te", "sharpen"), "naca0012-113x33.tmr.txt")):
            with tempfile.TemporaryDirectory() as d:
                out = self.old_directory(d)
                os.mkfifo(os.path.join(out, fifo))
                before = self.snapshot(out)
                p = subprocess.run([TOOL, "airfoil", *args, "-o", out, "--quiet"], capture_output=True, text=True,
                                   timeout=120)
                self.assertEqual(p.returncode, 8, p.stdout + p.stderr)
                self.assertEqual(p.stderr, f"eg2d: {out}/{fifo}: a FIFO with no reader: not written\n")
                self.assertEqual(self.snapshot(out), before)

    def test_missing_cgns_plugin_refused_before_solving(self):
        with tempfile.TemporaryDirectory() as d:
            out = self.old_directory(d)
            before = self.snapshot(out)
            for target in (out, os.path.join(d, "new")):
                p = subprocess.run([TOOL, "airfoil", *self.ARGS, "--format", "plot3d,cgns", "-o", target],
                                   capture_output=True, text=True, timeout=120,
                                   env={**os.environ, "EG2D_PLUGIN_DIR": "/nonexistent"})
                self.assertEqual(p.returncode, 9, p.stdout + p.stderr)
                self.assertRegex(p.stderr, r"(?s)^eg2d: airfoil: --format cgns: .*\(checked before solving; no files "
                                           r"written\)\n$")
                self.assertNotIn("iteration", p.stdout)  # nothing was solved
            self.assertEqual(self.snapshot(out), before)
            self.assertFalse(os.path.exists(os.path.join(d, "new")))

    def test_full_disk(self):
        # the file-size limit (EFBIG) as a full disk: the finest grid's files
        # fail part-way through the set, which is dropped whole; an output
        # directory the command made is removed again
        def limit():
            signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
            resource.setrlimit(resource.RLIMIT_FSIZE, (64 << 10, 64 << 10))
        with tempfile.TemporaryDirectory() as d:
            out = self.old_directory(d)
            before = self.snapshot(out)
            for target in (out, os.path.join(d, "new", "deeper")):
                p = subprocess.run([TOOL, "airfoil", "0012", "--size", "385x97", "--first-cell", "1e-5", "--levels",
                                    "2", "--format", "vts,plot3d", "-o", target, "--quiet"], capture_output=True,
                                   text=True, timeout=120, preexec_fn=limit)
                self.assertEqual(p.returncode, 8, p.stdout + p.stderr)
                self.assertRegex(p.stderr, r"^eg2d: naca0012-385x97\.vts: eg2d_write: .*/\.eg2d-set-\w+/"
                                           r"naca0012-385x97\.vts: .*File too large")
            self.assertEqual(self.snapshot(out), before)
            self.assertFalse(os.path.exists(os.path.join(d, "new")))

    def test_sigterm_during_the_solve(self):
        # 1793x513 takes about a second after its first iteration is printed
        with tempfile.TemporaryDirectory() as d:
            out = self.old_directory(d)
            before = self.snapshot(out)
            p = subprocess.Popen([TOOL, "airfoil", "0012", "--size", "1793x513", "--first-cell", "1e-6", "--levels",
                                  "3", "--format", "plot3d,vts,svg", "-o", out], stdout=subprocess.PIPE,
                                 stderr=subprocess.PIPE, text=True, env={**os.environ, "EG2D_HUGE_PAGES": "0"})
            while not p.stdout.readline().startswith("  iteration"):
                self.assertIsNone(p.poll())
            p.send_signal(signal.SIGTERM)
            rest, err = p.communicate(timeout=120)
            self.assertEqual(p.returncode, 143, rest + err)
            # by the solve's check, or the set's if the signal came as the files were staged
            self.assertRegex(err, r"^eg2d: (airfoil: )?interrupted by SIGTERM: no files written\n$")
            self.assertNotIn("level 0", rest)
            self.assertEqual(self.snapshot(out), before)

    def test_sigterm_while_writing(self):
        # the set is staged whole, then the finest grid streamed into a FIFO
        # whose reader holds it there; SIGTERM then: the stream is finished
        # (it cannot be taken back), and nothing else of the set is written
        with tempfile.TemporaryDirectory() as d:
            out = self.old_directory(d)
            fifo = os.path.join(out, "naca0012-385x97.xyz")
            os.mkfifo(fifo)
            before = self.snapshot(out)
            reader = os.open(fifo, os.O_RDONLY | os.O_NONBLOCK)
            try:
                p = subprocess.Popen([TOOL, "airfoil", "0012", "--size", "385x97", "--first-cell", "1e-5",
                                      "--levels", "2", "--format", "plot3d,svg", "-o", out, "--quiet"],
                                     stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
                first = b""
                while not first:  # the pipe (64 kB) fills: the command is blocked in its write
                    self.assertIsNone(p.poll())
                    try:
                        first = os.read(reader, 1)
                    except BlockingIOError:
                        time.sleep(0.02)
                self.assertTrue([n for n in os.listdir(out) if n.startswith(".eg2d-set-")])  # the stage, whole
                p.send_signal(signal.SIGTERM)
                got = len(first)
                while p.poll() is None or got < 597544:
                    try:
                        chunk = os.read(reader, 1 << 16)
                    except BlockingIOError:
                        time.sleep(0.02)
                        continue
                    if not chunk:
                        break
                    got += len(chunk)
            finally:
                os.close(reader)
            rest, err = p.communicate(timeout=120)
            self.assertEqual(p.returncode, 143, rest + err)
            self.assertEqual(err, f"eg2d: interrupted by SIGTERM: only {fifo} written (in place), no other file\n")
            self.assertEqual(got, 597544)  # 385x97 Plot3D: the stream went whole
            self.assertEqual(self.snapshot(out), before)

    CHANNEL = ("channel", "--lower", "s;0", "--upper", "s;1", "--size", "33x17", "--first-cell", "1e-2", "--levels", "2")

    def test_channel_writes_the_same_set(self):
        # eg2d channel's family goes through the same set: a FIFO nobody reads
        # among its paths fails it whole; without it, the family is written
        with tempfile.TemporaryDirectory() as d:
            out = os.path.join(d, "out")
            os.mkdir(out)
            with open(os.path.join(out, "channel-33x17.xyz"), "w") as f:
                f.write("old")
            os.mkfifo(os.path.join(out, "channel-17x9.report.json"))
            before = self.snapshot(out)
            code, stdout, err = run(*self.CHANNEL, "-o", out, "--quiet")
            self.assertEqual(code, 8, stdout + err)
            self.assertEqual(err, f"eg2d: {out}/channel-17x9.report.json: a FIFO with no reader: not written\n")
            self.assertEqual(self.snapshot(out), before)
            os.remove(os.path.join(out, "channel-17x9.report.json"))
            code, stdout, err = run(*self.CHANNEL, "-o", out, "--quiet")
            self.assertEqual(code, 4, stdout + err)  # 16 rows grow by more than 1.2: said, written
            self.assertEqual(sorted(os.listdir(out)), sorted(f"channel-{s}.{e}" for s in ("33x17", "17x9")
                                                            for e in ("xyz", "report.txt", "report.json")))

    def test_empty_output_directory_refused(self):
        for command in (["airfoil", *self.ARGS], list(self.CHANNEL)):
            with tempfile.TemporaryDirectory() as d:
                code, out, err = run(*command, "-o", "", cwd=d)
                self.assertEqual(code, 2, out + err)
                self.assertEqual(err, f"eg2d: {command[0]}: -o \"\": an empty output directory name (it would be the "
                                      f"filesystem root; -o . is the current directory) (eg2d {command[0]} --help "
                                      "shows the usage)\n")
                self.assertEqual(os.listdir(d), [])


class Channel(unittest.TestCase):
    """eg2d channel: a channel between two walls given as expressions or point
    files, or round a centreline; its patches in SU2, OpenFOAM and CGNS (read
    back by checkMesh and cgnscheck where installed), the first cell from y+,
    the wall layer's exit 4 and the errors that write nothing."""

    STRAIGHT = ("--lower", "4*s;0", "--upper", "4*s;1")

    def channel(self, d, *args, code=0):
        got, out, err = run("channel", *args, "-o", d, "--quiet")
        self.assertEqual(got, code, out + err)
        return out, err

    def report(self, path):
        import json
        with open(path + ".report.json") as f:
            return json.load(f)

    def su2_markers(self, path):
        with open(path) as f:
            return dict((tag, int(n)) for tag, n in re.findall(r"MARKER_TAG= (\S+)\nMARKER_ELEMS= (\d+)", f.read()))

    def foam_patches(self, case):
        """{name: (type, nFaces)} of the case's constant/polyMesh/boundary."""
        with open(os.path.join(case, "constant", "polyMesh", "boundary")) as f:
            text = f.read()
        return {name: (kind, int(n)) for name, kind, n in
                re.findall(r"^    (\w+)\n    \{\n        type\s+(\w+);.*?nFaces\s+(\d+);", text, re.M | re.S)}

    def wall_lines(self, out):
        """{wall: (first cell median, growth)} of the printed wall layer summary."""
        return {name: (float(first), float(growth)) for name, first, growth in
                re.findall(r"^wall layer (\w+): first cell (\S+) \(median;.*\), growth (\S+) over 30 cells", out, re.M)}

    def test_straight_channel_in_solver_formats(self):
        """Two levels of a straight channel from expressions: the four patches with
        their edge counts in SU2 and OpenFOAM, cgnscheck's BCs, checkMesh OK."""
        with tempfile.TemporaryDirectory() as d:
            self.channel(d, *self.STRAIGHT, "--size", "129x65", "--first-cell", "1e-3", "--levels", "2",
                         "--format", "openfoam,su2,cgns")
            for ni, nj in ((129, 65), (65, 33)):
                base = os.path.join(d, f"channel-{ni}x{nj}")
                self.assertEqual(self.su2_markers(base + ".su2"),
                                 {"lower_wall": ni - 1, "upper_wall": ni - 1, "inlet": nj - 1, "outlet": nj - 1})
                self.check_su2_meshio(base + ".su2", ni, nj)
                self.assertEqual(self.foam_patches(base + "_foam"),
                                 {"lower_wall": ("wall", ni - 1), "upper_wall": ("wall", ni - 1),
                                  "inlet": ("patch", nj - 1), "outlet": ("patch", nj - 1),
                                  "frontAndBack": ("empty", 2 * (ni - 1) * (nj - 1))})
                self.assertEqual(self.report(base)["folded_cells"], 0)
                self.check_cgns(base + ".cgns", {"lower_wall": "BCWall", "upper_wall": "BCWall",
                                                 "inlet": "BCInflow", "outlet": "BCOutflow"})
                Airfoil.check_mesh(self, base + "_foam")
                if shutil_which("checkMesh"):  # this straight channel's cells are rectangles
                    env = dict(os.environ)
                    env.setdefault("WM_PROJECT_DIR", "/usr/share/openfoam")
                    out = subprocess.run(["checkMesh", "-case", base + "_foam"], capture_output=True, text=True,
                                         env=env).stdout
                    self.assertIn("Mesh OK.", out)
                    self.assertIn("Total volume = 4.", out)

    def test_vtk_multiblock_of_each_level(self):
        """vtm: each level's NAME.vtm with its block file in NAME/, staged and put in place with it."""
        with tempfile.TemporaryDirectory() as d:
            self.channel(d, *self.STRAIGHT, "--size", "129x65", "--first-cell", "1e-3", "--levels", "2", "--format", "vtm")
            for ni, nj in ((129, 65), (65, 33)):
                name = f"channel-{ni}x{nj}"
                self.assertEqual(os.listdir(os.path.join(d, name)), [name + "_0.vts"])
                with open(os.path.join(d, name + ".vtm")) as f:
                    self.assertIn(f'<DataSet index="0" name="block0" file="{name}/{name}_0.vts"/>', f.read())
                with open(os.path.join(d, name, name + "_0.vts")) as f:
                    self.assertIn(f'WholeExtent="0 {ni - 1} 0 {nj - 1} 0 0"', f.read())
            self.assertFalse([n for n in os.listdir(d) if n.startswith(".eg2d-set-")])  # no stage left

    def check_su2_meshio(self, path, ni, nj):
        """meshio reads PATH (where installed): ni nj points, the quadrilaterals, every boundary edge once."""
        try:
            import meshio
        except ImportError:
            return
        mesh = meshio.read(path)
        self.assertEqual(mesh.points.shape[0], ni * nj)
        self.assertEqual(sum(len(c.data) for c in mesh.cells if c.type == "quad"), (ni - 1) * (nj - 1))
        self.assertEqual(sum(len(c.data) for c in mesh.cells if c.type == "line"), 2 * (ni - 1) + 2 * (nj - 1))

    def check_cgns(self, path, bcs):
        """cgnscheck (where installed) finds no error in PATH, and each BC of bcs with its type."""
        cgnscheck = shutil_which("cgnscheck")
        if not cgnscheck:
            return
        p = subprocess.run([cgnscheck, "-v", path], capture_output=True, text=True)
        out = p.stdout + p.stderr
        self.assertEqual([l for l in out.splitlines() if "ERROR" in l.upper()], [])
        self.assertIn("checking complete", out)
        for name, kind in bcs.items():
            self.assertRegex(out, f'checking BC "{name}"\n    BC Type={kind}\n')

    def diffuser_walls(self, d):
        """A planar diffuser from 1 to 3 wide over x in [0, 10], symmetric about y = 0.5:
        two point files (200 segments each; a cosine ramp from x = 2 to 8); their paths
        and the lower wall's length."""
        paths, length = [], 0.0
        for name, sign in (("lower.dat", -1), ("upper.dat", 1)):
            points = []
            for k in range(201):
                x = 10 * k / 200
                t = min(max((x - 2) / 6, 0), 1)
                points.append((x, 0.5 + sign * (1.5 - 0.5 * math.cos(math.pi * t))))
            with open(os.path.join(d, name), "w") as f:
                f.write("# x y\n" + "".join(f"{x!r} {y!r}\n" for x, y in points))
            paths.append(os.path.join(d, name))
            if sign < 0:
                length = sum(math.dist(p, q) for p, q in zip(points, points[1:]))
        return paths[0], paths[1], length

    def test_diffuser_from_point_files_at_yplus_1(self):
        """257x129 at y+ 1, Re 1e6 on the lower wall's length: the first cell within 1% of
        the flat-plate estimate eg2d.h states, the layer's growth at most 1.2 on both walls."""
        with tempfile.TemporaryDirectory() as d:
            lower, upper, length = self.diffuser_walls(d)
            out, _ = self.channel(d, "--lower", lower, "--upper", upper, "--size", "257x129", "--yplus", "1",
                                  "--reynolds", "1e6", "--format", "vts")
            cf = (2 * math.log10(1e6) - 0.65) ** -2.3
            h = length / (1e6 * math.sqrt(cf / 2))
            walls = self.wall_lines(out)
            self.assertEqual(sorted(walls), ["lower_wall", "upper_wall"])
            for name, (first, growth) in walls.items():
                self.assertLess(abs(first / h - 1), 0.01, name)
                self.assertLessEqual(growth, 1.2, name)
            r = self.report(os.path.join(d, "channel-257x129"))
            self.assertEqual(r["folded_cells"], 0)
            self.assertLess(abs(r["wall"]["first_cell_height"]["min"] / h - 1), 0.01)
            self.assertLess(abs(r["wall"]["first_cell_height"]["max"] / h - 1), 0.01)
            self.assertLessEqual(r["wall"]["growth_max"], 1.2)
            # the walls' ends are the files' ends: the inlet from (0, -0.5) to (0, 1.5), the outlet 3 wide
            p = vts_points(os.path.join(d, "channel-257x129.vts"))
            for (x, y), want in ((p[0], (0, -0.5)), (p[256], (10, -1.5)), (p[257 * 128], (0, 1.5)),
                                 (p[-1], (10, 2.5))):
                self.assertLess(math.dist((x, y), want), 1e-9)

    def test_centreline_width_and_spacings(self):
        """Walls half the width either side of the centreline; --inlet-spacing and
        --outlet-spacing are the first and last spacings along the walls; the coarser level
        is every other node of the finer; --symmetry-upper names the upper patch symmetry."""
        with tempfile.TemporaryDirectory() as d:
            self.channel(d, "--centreline", "4*s;0", "--width", "1 + s", "--size", "65x33", "--first-cell", "1e-2",
                         "--growth", "10", "--inlet-spacing", "0.01", "--outlet-spacing", "0.2", "--levels", "2",
                         "--format", "vts,su2")
            p = vts_points(os.path.join(d, "channel-65x33.vts"))
            lower, upper = p[:65], p[65 * 32:]
            for (xl, yl), (xu, yu) in zip(lower, upper):
                self.assertAlmostEqual(xl, xu, delta=1e-12)
                self.assertAlmostEqual(yl, -0.5 * (1 + xl / 4), delta=1e-12)
                self.assertAlmostEqual(yu, 0.5 * (1 + xu / 4), delta=1e-12)
            self.assertAlmostEqual(lower[1][0] - lower[0][0], 0.01, delta=1e-9)
            self.assertAlmostEqual(lower[64][0] - lower[63][0], 0.2, delta=1e-9)
            coarse = vts_points(os.path.join(d, "channel-33x17.vts"))
            self.assertEqual(coarse, [p[i + 65 * j] for j in range(0, 33, 2) for i in range(0, 65, 2)])
            out, _ = self.channel(d, *self.STRAIGHT, "--size", "65x33", "--first-cell", "1e-2", "--symmetry-upper",
                                  "--format", "su2")
            self.assertEqual(self.su2_markers(os.path.join(d, "channel-65x33.su2")),
                             {"lower_wall": 64, "symmetry": 64, "inlet": 32, "outlet": 32})
            self.assertEqual(sorted(self.wall_lines(out)), ["lower_wall"])

    def test_spline_through_point_files(self):
        """--spline joins a point file's 11 points by a spline: the wall's nodes lie closer to the
        smooth curve the points were taken from than the straight segments' do."""
        def wall(x, sign):
            return 0.5 + sign * (1 - 0.5 * math.cos(math.pi * x / 10))
        with tempfile.TemporaryDirectory() as d:
            for name, sign in (("lo.dat", -1), ("up.dat", 1)):
                with open(os.path.join(d, name), "w") as f:
                    f.write("".join(f"{x} {wall(x, sign)!r}\n" for x in range(11)))
            deviation = {}
            for flag in ("--spline", "--quiet"):
                self.channel(d, "--lower", os.path.join(d, "lo.dat"), "--upper", os.path.join(d, "up.dat"), flag,
                             "--size", "129x65", "--first-cell", "1e-3", "--format", "vts")
                lower = vts_points(os.path.join(d, "channel-129x65.vts"))[:129]
                deviation[flag] = max(abs(y - wall(x, -1)) for x, y in lower)
            self.assertLess(deviation["--spline"], 0.5 * deviation["--quiet"], deviation)

    def test_short_wall_layer_exits_4(self):
        """NJ too small for the first cell: exit 4, the files written, the NJ that would do
        named; with that NJ the command exits 0 and the layer grows by at most 1.2."""
        with tempfile.TemporaryDirectory() as d:
            _, err = self.channel(d, *self.STRAIGHT, "--size", "65x17", "--first-cell", "1e-4", "--format", "su2",
                                  code=4)
            m = re.search(r"the wall layer at lower_wall grows by (\S+) within 30 cells, more than 1.2: nj >= (\d+) "
                          r"would meet it \(the files are written\)", err)
            self.assertIsNotNone(m, err)
            self.assertGreater(float(m.group(1)), 1.2)
            self.assertTrue(os.path.isfile(os.path.join(d, "channel-65x17.su2")))
            nj = int(m.group(2))
            self.assertGreater(nj, 17)
            out, err = self.channel(d, *self.STRAIGHT, "--size", f"65x{nj}", "--first-cell", "1e-4", "--format", "su2")
            for name, (first, growth) in self.wall_lines(out).items():
                self.assertAlmostEqual(first, 1e-4, delta=1e-8)
                self.assertLessEqual(growth, 1.2)

    def failure(self, code, message, *args):
        """The command fails with CODE and exactly MESSAGE (D: the directory), writing nothing."""
        with tempfile.TemporaryDirectory() as d:
            out_dir = os.path.join(d, "out")
            got, out, err = run("channel", *[a.replace("D/", d + "/") for a in args], "--size", "65x33",
                                "--first-cell", "1e-3", "-o", out_dir)
            self.assertEqual(err, "eg2d: " + message.replace("D/", d + "/") + "\n")
            self.assertEqual(got, code)
            self.assertFalse(os.path.exists(out_dir), "a failed run wrote files")

    def test_bad_expression_exits_3(self):
        self.failure(3, 'channel: --upper: bad formula "1+": Unexpected end of expression at position 3',
                     "--lower", "4*s;0", "--upper", "4*s;1+")
        self.failure(3, 'channel: --lower: bad formula "sinh(s": Missing parenthesis',
                     "--lower", "4*s;sinh(s", "--upper", "4*s;1")
        self.failure(3, 'channel: --width: "0.3 - s" is -0.0125 at s = 0.3125, not positive',
                     "--centreline", "4*s;0", "--width", "0.3 - s")

    def test_unreadable_file_and_bad_walls(self):
        self.failure(8, "channel: --lower: eg2d_read_points: D/none.dat: cannot open: No such file or directory",
                     "--lower", "D/none.dat", "--upper", "4*s;1")
        self.failure(4, "channel: the lower wall and the upper wall cross between (2, 0) and (2.0625, 0)",
                     "--lower", "4*s;0", "--upper", "4*s;1-2*s")
        self.failure(4, "channel: the walls run opposite ways: the lower wall runs from (0, 0) to (4, 0), the upper "
                        "from (4, 1) to (0, 1); give both from the inlet to the outlet",
                     "--lower", "4*s;0", "--upper", "4-4*s;1")
        self.failure(4, "channel: the upper wall lies to the right of the lower wall (looking from the inlet to the "
                        "outlet): the lower wall runs from (0, 1) to (4, 1), the upper from (0, 0) to (4, 0); swap "
                        "--lower and --upper", "--lower", "4*s;1", "--upper", "4*s;0")
        self.failure(2, "channel: give --lower and --upper, or --centreline and --width, not both (eg2d channel "
                        "--help shows the usage)", "--lower", "4*s;0", "--upper", "4*s;1", "--width", "1")

    def test_docs_pictures_are_current(self):
        # docs/channel.md's pictures are what its command draws now
        docs = os.path.join(EXAMPLES, os.pardir, "docs", "channel")
        with tempfile.TemporaryDirectory() as d:
            self.channel(d, "--centreline", "4*s;0.5*sin(pi*s)", "--width", "1 + 0.5*s", "--size", "129x65",
                         "--first-cell", "1e-3", "--inlet-spacing", "0.01", "--outlet-spacing", "0.05", "--format", "svg")
            for view in ("domain", "inlet-corner"):
                name = f"channel-129x65-{view}.svg"
                with open(os.path.join(d, name)) as new, open(os.path.join(docs, name)) as old:
                    self.assertTrue(new.read() == old.read(), f"docs/channel/{name} is not what eg2d draws now: "
                                    "make it again with docs/channel.md's command")

    def test_help(self):
        code, out, _ = run("channel", "--help")
        self.assertEqual(code, 0)
        for option in ("--lower", "--centreline", "--yplus", "--levels", "--symmetry-upper", "Exit codes"):
            self.assertIn(option, out)
        code, out, _ = run("--help")
        self.assertIn("eg2d channel --lower WALL --upper WALL", out)


AIRFOILS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data", "airfoils")


def closed_section_points(kind, n=100):
    """A closed (sharp) trailing-edge section, Selig's order: NACA 4-digit
    "MPTT" or 5-digit "230TT" with the closed thickness (-0.1036 x^4;
    Abbott & von Doenhoff 1959), or "joukowski" (the circle through 1
    centred at -0.08 + 0.08i under z + 1/z: a cusped edge)."""
    if kind == "joukowski":
        cx, cy = -0.08, 0.08
        r, a0 = math.hypot(1 - cx, cy), math.atan2(-cy, 1 - cx)
        pts = []
        for k in range(2 * n + 1):
            zx, zy = cx + r * math.cos(a0 + math.pi * k / n), cy + r * math.sin(a0 + math.pi * k / n)
            q = zx * zx + zy * zy
            pts.append((zx + zx / q, zy - zy / q))
        pts[0] = pts[-1] = (2.0, 0.0)
        return pts
    t = int(kind[-2:]) / 100
    yt = lambda x: 5 * t * (0.2969 * math.sqrt(x) - 0.1260 * x - 0.3516 * x**2 + 0.2843 * x**3 - 0.1036 * x**4)
    if len(kind) == 5:  # 230TT: the camber line of maximum at 0.15 chords (m = 0.2025, k1 = 15.957)
        m, k1 = 0.2025, 15.957
        camber = lambda x: ((k1 / 6 * (x**3 - 3 * m * x * x + m * m * (3 - m) * x),
                             k1 / 6 * (3 * x * x - 6 * m * x + m * m * (3 - m))) if x < m
                            else (k1 * m**3 / 6 * (1 - x), -k1 * m**3 / 6))
    else:
        m, p = int(kind[0]) / 100, int(kind[1]) / 10
        camber = lambda x: ((0.0, 0.0) if m == 0 else
                            (m / p**2 * (2 * p * x - x * x), 2 * m / p**2 * (p - x)) if x < p else
                            (m / (1 - p)**2 * (1 - 2 * p + 2 * p * x - x * x), 2 * m / (1 - p)**2 * (p - x)))
    xs = [0.5 * (1 - math.cos(math.pi * k / n)) for k in range(n + 1)]
    def point(x, side):
        c, slope = camber(x)
        a = math.atan(slope)
        return x - side * yt(x) * math.sin(a), c + side * yt(x) * math.cos(a)
    return [point(x, 1) for x in reversed(xs)] + [point(x, -1) for x in xs[1:]]


def write_points(path, name, pts):
    with open(path, "w") as f:
        f.write(name + "\n")
        for x, y in pts:
            f.write(f"{x:.8f} {y:.8f}\n")


def read_points(path):
    with open(path) as f:
        return [tuple(float(v) for v in line.split()) for line in f.readlines()[1:] if line.strip()]


class SharpTrailingEdge(unittest.TestCase):
    """O-grids round a closed (sharp) trailing edge: cut back to a base 5e-5
    chords thick they pass OpenFOAM's checkMesh (aspect ratio aside) on
    sections of eight families at 257x129, y+ 1, Re 6e6; kept sharp
    (--te-base 0) the command names the faces past checkMesh's limits and
    exits 4; a file's direction and start point do not change the grid."""

    def sections(self, d):
        files = {}
        for kind in ("0012", "4412", "23012", "joukowski"):
            files[kind] = os.path.join(d, f"closed{kind}.dat")
            write_points(files[kind], f"closed {kind}", closed_section_points(kind))
        for name in ("sd7003", "s1223", "rae2822", "clarky"):
            files[name] = os.path.join(AIRFOILS, name + ".dat")
        return files

    def test_o_grids_pass_checkmesh(self):
        cf = (2 * math.log10(6e6) - 0.65) ** -2.3
        h = 1 / (6e6 * math.sqrt(cf / 2))
        with tempfile.TemporaryDirectory() as d:
            for kind, path in self.sections(d).items():
                code, out, err = run("airfoil", path, "--topology", "o", "--size", "257x129", "--yplus", "1",
                                     "--reynolds", "6e6", "--format", "openfoam", "-o", d)
                self.assertEqual(code, 0, kind + out + err)
                self.assertIn("sharp trailing edge cut back to a base 5e-05 chords thick", out, kind)
                self.assertRegex(out, r"solver check .*skewness max [0-9.]+ \(limit 4\)\n", kind)
                stem = os.path.splitext(os.path.basename(path))[0]
                with open(os.path.join(d, stem + "-257x129.report.json")) as f:
                    r = json.load(f)
                self.assertEqual(r["folded_cells"], 0, kind)
                # the first cell as asked (in the file's lengths: the Joukowski section's chord is 4)
                self.assertLess(abs(r["wall"]["first_cell_height"]["min"] / h - 1), 0.02, kind)
                self.assertLess(abs(r["wall"]["first_cell_height"]["max"] / h - 1), 0.02, kind)
                self.assertLessEqual(r["wall"]["growth_max"], 1.2, kind)
                Airfoil.check_mesh(self, os.path.join(d, stem + "-257x129_foam"))

    def test_sharp_edge_kept_is_named_and_exits_4(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "closed0012.dat")
            write_points(path, "closed 0012", closed_section_points("0012"))
            code, out, err = run("airfoil", path, "--topology", "o", "--size", "257x129", "--yplus", "1",
                                 "--reynolds", "6e6", "--te-base", "0", "-o", d)
            self.assertEqual(code, 4, out + err)
            self.assertIn("trailing edge kept sharp (--te-base 0)", out)
            # the two columns beside the edge's line: cells (0, j) and (255, j)
            m = re.search(r"solver check .*skewness max ([0-9.]+) \(limit 4\): (\d+) face\(s\) past, "
                          r"the worst of cell \((\d+), (\d+)\)", out)
            self.assertIsNotNone(m, out)
            self.assertGreater(float(m.group(1)), 4)
            self.assertIn(int(m.group(3)), (0, 255))
            self.assertIn("257x129 has %s face(s) past checkMesh's limits" % m.group(2), err)
            self.assertIn("(the files are written)", err)
            self.assertTrue(os.path.isfile(os.path.join(d, "closed0012-257x129.xyz")))
            # the reports say it too: the text report's line as printed, the JSON's figures
            line = re.search(r"^solver check .*\n", out, re.M).group(0)
            with open(os.path.join(d, "closed0012-257x129.report.txt")) as f:
                self.assertTrue(f.read().endswith(line))
            with open(os.path.join(d, "closed0012-257x129.report.json")) as f:
                check = json.load(f)["solver_check"]
            self.assertEqual(check["faces_past"], int(m.group(2)))
            self.assertEqual(check["worst"]["cell"], [int(m.group(3)), int(m.group(4))])
            self.assertEqual("%.3g" % check["skewness_max"], m.group(1))  # printed to 3 digits
            self.assertGreater(check["worst"]["skewness"], 4)
            self.assertEqual((check["nonorthogonality_limit_deg"], check["skewness_limit"]), (70, 4))
            # the standard open section's blunt base: nothing past, exit 0
            code, out, err = run("airfoil", "0012", "--topology", "o", "--size", "129x65", "--first-cell", "1e-5",
                                 "--growth", "1.3", "-o", d)
            self.assertEqual(code, 0, out + err)
            self.assertRegex(out, r"solver check .*\(limit 4\)\n")
            with open(os.path.join(d, "naca0012-129x65.report.json")) as f:
                check = json.load(f)["solver_check"]
            self.assertEqual((check["faces_past"], check["worst"]), (0, None))
            self.assertLessEqual(check["skewness_max"], 4)

    def test_direction_and_start_point(self):
        """Reversed files (clockwise) and files starting at the leading edge give
        the grid of Selig's order, point for point, on O- and C-grids, sharp and blunt."""
        with tempfile.TemporaryDirectory() as d:
            sharp = read_points(os.path.join(AIRFOILS, "sd7003.dat"))
            blunt_file = os.path.join(d, "blunt.dat")
            naca4_selig(blunt_file, 0.04, 0.4, 0.12)
            blunt = read_points(blunt_file)
            for name, pts in (("sharp", sharp), ("blunt", blunt)):
                le = min(range(len(pts)), key=lambda k: pts[k][0])
                loop = pts[:-1] if pts[0] == pts[-1] else pts
                variants = {"selig": pts, "reversed": pts[::-1],
                            "from_le": loop[le:] + loop[:le + 1] if pts[0] == pts[-1] else pts[le:] + pts[:le + 1],
                            "from_le_reversed": (loop[le:] + loop[:le + 1])[::-1]}
                for topo, size in (("o", "129x65"), ("c", "161x49")):
                    grids = {}
                    for v, p in variants.items():
                        path = os.path.join(d, f"{name}_{v}.dat")
                        write_points(path, f"{name} {v}", p)
                        out = os.path.join(d, f"{name}_{v}_{topo}")
                        code, text, err = run("airfoil", path, "--topology", topo, "--size", size, "--first-cell",
                                              "1e-5", "--farfield", "20", "--format", "plot3d-ascii", "-o", out)
                        self.assertIn(code, (0, 4), text + err)  # 4: a coarse grid's growth or faces, said
                        with open(os.path.join(out, f"{name}_{v}-{size}.p3d")) as f:
                            grids[v] = [float(t) for t in f.read().split()]
                    for v in variants:
                        self.assertEqual(len(grids[v]), len(grids["selig"]), (name, topo, v))
                        self.assertLess(max(abs(a - b) for a, b in zip(grids[v], grids["selig"])), 1e-9,
                                        (name, topo, v))


def tables():
    """{section title: [row dict by column name]} of `eg2d --tables`, the library's tables."""
    code, out, _ = run("--tables")
    assert code == 0
    result, title, header = {}, None, None
    for line in out.splitlines():
        if line.startswith("## "):
            title, header = line[3:], None
            result[title] = []
        elif line.startswith("|") and not line.startswith("|---"):
            cells = [c.strip().strip("`") for c in line.strip("|").split("|")]
            if header is None:
                header = cells
            else:
                result[title].append(dict(zip(header, cells)))
    return result


class CaseParameters(unittest.TestCase):
    """A case file sets every parameter of the library's table, by its key in its table, and chooses
    every initial grid of the library's list: walked from `eg2d --tables`, so a new parameter or
    initialiser is covered without a line here."""

    SIDES = ErrorMessages.GOOD_SIDES

    def run_case(self, d, top="", sections=None, initial="tfi"):
        sections = dict(sections or {})
        sections.setdefault("output", "")
        sections["output"] += '\nformats = ["report-json"]\n'
        text = f'size = [9, 9]\ninitial = "{initial}"\nsolve = false\n{top}\n{self.SIDES}'
        for name, body in sections.items():
            text += f"\n[{name}]\n{body}\n"
        path = os.path.join(d, "case.toml")
        with open(path, "w") as f:
            f.write(text)
        out = os.path.join(d, "out")
        shutil.rmtree(out, ignore_errors=True)
        code, stdout, stderr = run("run", path, "-o", out)
        report = None
        if code == 0:
            with open(os.path.join(out, "case.report.json")) as f:
                report = json.load(f)
        return code, stderr, report

    @staticmethod
    def value_inside(row):
        """A value other than the default, inside the parameter's range."""
        rng, default = row["range"], float(row["default"])
        lo, hi = (float(t) for t in rng[1:-1].split(","))
        open_lo, open_hi = rng[0] == "(", rng[-1] == ")"
        if row["kind"].startswith("on/off"):
            return 1 - default
        top = min(hi, lo + 4)
        if row["kind"].startswith("integer"):
            candidates = [lo + 1, lo + 2, lo] if open_lo else [lo, lo + 1, lo + 2]
        else:
            candidates = [lo + 0.37 * (top - lo), lo + 0.61 * (top - lo)]
        for v in candidates:
            if v != default and (v > lo if open_lo else v >= lo) and (v < hi if open_hi else v <= hi):
                return v
        raise AssertionError(f"no value inside {rng} other than {default} for {row['key']}")

    def place(self, row, value):
        key = row["key"]
        if row["table"] == "top":
            return f"{key} = {value!r}\n", {}
        return "", {row["table"]: f"{key} = {value!r}"}

    def test_every_parameter_reaches_the_library(self):
        rows = tables()["Parameters"]
        self.assertGreaterEqual(len(rows), 48)
        with tempfile.TemporaryDirectory() as d:
            for row in rows:
                with self.subTest(key=row["key"]):
                    if row["key"] == "svg_quality":  # a case file names the per-cell metric
                        top, sections, expected = "", {"output": 'svg_quality = "skewness"'}, 10.0
                    else:
                        expected = self.value_inside(row)
                        top, sections = self.place(row, expected)
                    code, stderr, report = self.run_case(d, top, sections)
                    self.assertEqual(code, 0, stderr)
                    self.assertEqual(report["parameters"][row["key"]], expected)
                    self.assertEqual(set(report["parameters"]), {r["key"] for r in rows})

    def test_every_parameter_is_refused_outside_its_range_naming_its_key(self):
        with tempfile.TemporaryDirectory() as d:
            for row in tables()["Parameters"]:
                lo, hi = (float(t) for t in row["range"][1:-1].split(","))
                if row["key"] == "svg_quality" or hi >= 1e29:
                    continue
                with self.subTest(key=row["key"]):
                    top, sections = self.place(row, hi + (hi - lo) + 1)
                    code, stderr, _ = self.run_case(d, top, sections)
                    self.assertEqual(code, 4, stderr)
                    self.assertIn(f"eg2d_set_parameter: {row['key']} = ", stderr)
                    self.assertIn("must be in", stderr)

    def test_the_header_says_what_the_table_says(self):
        """Where eg2d.h's parameter table gives a range or a default, it is the library's."""
        with open(os.path.join(EXAMPLES, "..", "include", "eg2d.h")) as f:
            header = f.read()
        rows = {int(r["id"]): r for r in tables()["Parameters"]}
        num = r"(-?\d+(?:\.\d+)?(?:e[+-]?\d+)?)"
        checked = 0
        for name, ident, comment in re.findall(r"#define (EG2D_PARAM_\w+)\s+(\d+)\s*/\*(.*?)\*/", header, re.S):
            comment, row = " ".join(comment.split()), rows[int(ident)]
            with self.subTest(name=name):
                m = re.match(r"([\[(])" + num + r", " + num + r"([\])])", comment)
                if m:
                    lo, hi = (float(t) for t in row["range"][1:-1].split(","))
                    self.assertEqual((m.group(1), float(m.group(2)), float(m.group(3)), m.group(4)),
                                     (row["range"][0], lo, hi, row["range"][-1]), comment)
                    checked += 1
                d = re.search(r"default " + num, comment) or re.search(r"(?:^|, )" + num + r" \(default\)", comment)
                if d:
                    self.assertEqual(float(d.group(1)), float(row["default"]), comment)
                if "auto (default" in comment:
                    self.assertEqual(float(row["default"]), 0.0, comment)
                    self.assertIn("automatic", row["kind"], comment)
        self.assertGreaterEqual(checked, 30)

    def test_every_initializer(self):
        names = [r["name"] for r in tables()["Initial grids"]]
        self.assertIn("hyperbolic", names)
        with tempfile.TemporaryDirectory() as d:
            for name in names:
                with self.subTest(initial=name):
                    code, stderr, report = self.run_case(d, initial=name)
                    self.assertEqual(code, 0, stderr)
                    self.assertEqual(report["folded_cells"], 0)


class BlockSets(unittest.TestCase):
    """Case files of several blocks ([[blocks]], [[joins]]): the step example
    run, its merged mesh read by checkMesh and counted in the SU2 file, each
    block's own file; bad sets refused naming the key."""

    STEP = "backward-facing-step"
    # the step's blocks: upstream 25x41, upper 81x41, lower 81x17
    CELLS = 24 * 40 + 80 * 40 + 80 * 16
    POINTS = 25 * 41 + 81 * 41 + 81 * 17 - 41 - 81
    PATCHES = {"wall": 2 * 24 + 2 * 80 + 16, "inlet": 40, "outlet": 40 + 16}

    # An O-grid as one block joined to itself: an ellipse in a circle, the
    # block's left and right sides the same radial line, joined.
    RING = textwrap.dedent('''\
        title = "ring"
        system = "winslow"
        [output]
        formats = ["openfoam", "cgns", "su2"]
        [[blocks]]
        name = "ring"
        size = [65, 33]
        [blocks.sides.bottom]
        x = "cos(2*pi*s)"
        y = "0.6*sin(2*pi*s)"
        [blocks.sides.top]
        x = "3*cos(2*pi*s)"
        y = "3*sin(2*pi*s)"
        [blocks.sides.left]
        x = "1 + 2*s"
        y = "0"
        [blocks.sides.right]
        x = "1 + 2*s"
        y = "0"
        [[blocks.patches]]
        side = "bottom"
        type = "wall"
        name = "body"
        [[blocks.patches]]
        side = "top"
        type = "farfield"
        name = "outer"
        [[joins]]
        a = "ring.left"
        b = "ring.right"
        ''')

    def test_block_joined_to_itself(self):
        """The ring's cut is interior: one mesh of 64 x 32 cells and 64 x 33
        points (the cut's nodes once), two patches, checkMesh OK, and its CGNS
        zone connected to itself (two 1-to-1 records, cgnscheck clean)."""
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "ring.toml")
            with open(path, "w") as f:
                f.write(self.RING)
            out = os.path.join(d, "out")
            code, stdout, stderr = run("run", path, "-o", out)
            self.assertEqual(code, 0, stdout + stderr)
            with open(os.path.join(out, "ring.su2")) as f:
                su2 = f.read()
            self.assertIn("NELEM= 2048\n", su2)
            self.assertIn("NPOIN= 2112\n", su2)
            self.assertEqual(re.findall(r"MARKER_TAG= (\S+)", su2), ["body", "outer"])
            check_mesh(self, os.path.join(out, "ring_foam"))
            check_cgns_file(self, os.path.join(out, "ring.cgns"), ["body", "outer"])

    def test_held_join(self):
        """held = true keeps a join's nodes where the sides put them: the ring's
        cut, held, is the radial line y = 0 after the run; free, it moves (the
        ring's inner ellipse sheared, so that y = 0 is no line of symmetry)."""
        ring = self.RING.replace('x = "cos(2*pi*s)"', 'x = "cos(2*pi*s) + 0.4*sin(2*pi*s)"')  # a sheared ellipse
        for held in (False, True):
            text = ring + ("held = true\n" if held else "")
            with tempfile.TemporaryDirectory() as d:
                path = os.path.join(d, "ring.toml")
                with open(path, "w") as f:
                    f.write(text.replace('formats = ["openfoam", "cgns", "su2"]', 'formats = ["plot3d-ascii"]'))
                out = os.path.join(d, "out")
                code, stdout, stderr = run("run", path, "-o", out)
                self.assertEqual(code, 0, stdout + stderr)
                with open(os.path.join(out, "ring.p3d")) as f:  # one grid: its size, x, y
                    values = f.read().split()
                ni, nj = int(values[0]), int(values[1])
                y = [float(v) for v in values[2 + ni * nj:2 + 2 * ni * nj]]
                cut = max(abs(y[ni * j]) for j in range(nj))  # node (0, j): the cut's
                if held:
                    self.assertEqual(cut, 0.0)
                else:
                    self.assertGreater(cut, 1e-3)

    WAKES = {("upper", "bottom"), ("wake", "bottom"), ("wake", "top"), ("below_flap", "top")}

    def test_two_element_airfoil(self):
        """examples/two-element-airfoil.toml: the NLR 7301 main element and
        slotted flap (van den Berg & Oskam 1979) in six blocks, wall-resolved
        on both elements (every wall's first cells within 1% of 1e-5 chord,
        its lines within 1 degree of the normal, growth within the case's
        1.45) with a wake from each trailing edge to the outflow (VTK's reader
        on the blocks' file), no folded cell; checkMesh (Mesh OK, skewness at
        most 4, non-orthogonality at most 70 degrees), cgnscheck and meshio
        read the merged mesh."""
        with tempfile.TemporaryDirectory() as d:
            code, stdout, stderr = run("run", os.path.join(EXAMPLES, "two-element-airfoil.toml"), "-o", d)
            self.assertEqual(code, 0, stdout + stderr)
            self.assertIn("quality: 0 folded cells in the set", stdout)
            walls = re.findall(r"wall layer block (\w+) (\w+): first cell \S+ \(median; (\S+) to (\S+), asked (\S+)"
                               r"(?: to (\S+))?\), growth (\S+) over 30 cells, angle (\S+) deg", stdout)
            self.assertEqual(sorted((b, s) for b, s, *_ in walls),
                             [("below_flap", "top"), ("lower", "bottom"), ("slot", "bottom"), ("slot", "top"),
                              ("upper", "bottom"), ("wake", "bottom"), ("wake", "top")])
            for b, side, lo, hi, asked, asked_hi, growth, angle in walls:
                # the sides that hold a wake ask 1e-5 on the wall, growing to 4e-3 along the wake
                self.assertEqual(float(asked), 1e-5)
                self.assertEqual(float(asked_hi or asked), 4e-3 if (b, side) in self.WAKES else 1e-5, (b, side))
                self.assertLess(abs(float(lo) / 1e-5 - 1), 0.01, (b, side))
                self.assertLess(abs(float(hi) / float(asked_hi or asked) - 1), 0.05, (b, side))
                self.assertLessEqual(float(growth), 1.45, (b, side))
                self.assertLess(float(angle), 1.0, (b, side))
            name = os.path.join(d, "two-element-airfoil")
            check_cgns_file(self, name + ".cgns", ["main", "flap", "inflow", "farfield", "outflow"])
            checkmesh = shutil_which("checkMesh")
            if checkmesh:
                env = dict(os.environ)
                env.setdefault("WM_PROJECT_DIR", "/usr/share/openfoam")
                out = subprocess.run([checkmesh, "-case", name + "_foam"], capture_output=True, text=True,
                                     env=env).stdout
                self.assertIn("Mesh OK.", out)
                self.assertLessEqual(float(re.search(r"Max skewness = ([0-9.eE+-]+)", out).group(1)), 4.0)
                self.assertLessEqual(float(re.search(r"non-orthogonality Max: ([0-9.eE+-]+)", out).group(1)), 70.0)
            try:
                import meshio
            except ImportError:
                meshio = None
            if meshio:
                mesh = meshio.read(name + ".su2")
                self.assertEqual(sum(len(c.data) for c in mesh.cells if c.type == "quad"),
                                 224 * 128 + 264 * 128 + 74 * 117 + 24 * 96 + 112 * 96 + 128 * 128)
            try:
                import vtk
            except ImportError:
                return
            reader = vtk.vtkXMLMultiBlockDataReader()
            reader.SetFileName(name + ".vtm")
            reader.Update()
            blocks = reader.GetOutput()
            # Each wake: the row on the wall side of a block, from the trailing
            # edge (node n_upper - 1 of "upper", the case's second block, and
            # n_flap - 1 of "below_flap", its sixth) downstream to the outflow at x = 10.5.
            self.assertEqual(blocks.GetNumberOfBlocks(), 6)
            for k, block in ((1, "upper"), (5, "below_flap")):
                self.assertEqual(blocks.GetMetaData(k).Get(vtk.vtkCompositeDataSet.NAME()), block)  # the case's names
                grid = blocks.GetBlock(k)
                ni, nj, _ = grid.GetDimensions()
                j, first, edge = (0, 160, (0.9436, 0.01454)) if block == "upper" else (nj - 1, 64, (1.2049, -0.10267))
                xs = [grid.GetPoint(j * ni + i)[:2] for i in range(first, ni)]
                self.assertAlmostEqual(xs[0][0], edge[0], places=5, msg=block)
                self.assertAlmostEqual(xs[0][1], edge[1], places=5, msg=block)
                self.assertAlmostEqual(xs[-1][0], 10.5, places=9, msg=block)
                self.assertTrue(all(b[0] > a[0] for a, b in zip(xs, xs[1:])), block)

    def test_two_element_airfoil_multigrid_falls_back(self):
        """The example's earlier layout (make_case.py's options before the
        ones that took its non-orthogonality within 70 degrees) by
        multigrid: its coarse levels cannot carry the layer's controls (the
        first pass diverges in 3 cycles), so the layer is made by line SOR
        instead, said in the run's notes, with its first cells."""
        here = os.path.join(os.path.dirname(EXAMPLES), "bench", "two-element-airfoil")
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "earlier.toml")
            p = subprocess.run([sys.executable, os.path.join(here, "make_case.py"), "--held", "--first-cell", "1e-5",
                                "--n-far", "129", "--n-slot", "97", "--legs", "auto", "--phia", "250", "--phib", "262",
                                "--ds-fte", "0.003", "--d-wake1", "0.004", "--growth-limit", "1.45", "-o", path],
                               capture_output=True, text=True)
            self.assertEqual(p.returncode, 0, p.stderr)
            with open(path) as f:
                text = re.sub(r"formats = \[[^]]*\]", 'formats = ["plot3d"]', f.read())
            with open(path, "w") as f:
                f.write(text)
            code, stdout, stderr = run("run", path, "-o", d)
            self.assertEqual(code, 0, stdout + stderr)
            self.assertRegex(stdout, r"wall layer \(graded, set of blocks\): on its lines' controls multigrid diverged "
                                     r"in \d+ iteration\(s\) \(residual \S+\); the layer is made by line SOR instead")
            self.assertIn("first cells within 0.083% of their heights", stdout)
            self.assertIn("quality: 0 folded cells in the set", stdout)

    def test_set_controls(self):
        """A set's [controls] holds wall_growth_limit only (its walls' heights
        are each block's wall_spacing): other keys and a limit below 1 are
        refused at the key."""
        for controls, message in (("wall_spacing = 1e-5", "controls.wall_spacing': unknown key (expected one of: "
                                                          "wall_growth_limit)"),
                                  ("wall_growth_limit = 0.5", "controls.wall_growth_limit': must be >= 1")):
            with tempfile.TemporaryDirectory() as d:
                path = os.path.join(d, "ring.toml")
                with open(path, "w") as f:
                    f.write(self.RING.replace("[output]", f"[controls]\n{controls}\n[output]"))
                code, stdout, stderr = run("run", path, "-o", d)
                self.assertEqual(code, 3, stdout + stderr)
                self.assertIn(message, stderr)

    def test_refused_set_says_why(self):
        """A set the library refuses before it runs (bench/two-element-airfoil's
        get-run-error.toml: a wake curve through the flap) is refused with the
        solve's reason, not eg2d_blocks_get_run's "has not run"."""
        case = os.path.join(os.path.dirname(EXAMPLES), "bench", "two-element-airfoil", "get-run-error.toml")
        with tempfile.TemporaryDirectory() as d:
            code, stdout, stderr = run("run", case, "-o", os.path.join(d, "out"))
            self.assertEqual(code, 4, stdout + stderr)
            self.assertIn("eg2d_blocks_solve: the boundary crosses itself: JMIN segment 30-31 crosses JMAX segment "
                          "48-49", stderr)
            self.assertNotIn("stopped after", stdout)

    def test_step_runs_and_writes_one_mesh(self):
        with tempfile.TemporaryDirectory() as d:
            out = os.path.join(d, "out")
            code, stdout, stderr = run("run", os.path.join(EXAMPLES, self.STEP + ".toml"), "-o", out)
            self.assertEqual(code, 0, stdout + stderr)
            self.assertIn("a set of 3 blocks, 2 joins", stdout)
            for block in ("upstream 25 x 41", "upper 81 x 41", "lower 81 x 17"):
                self.assertIn("block " + block.replace(" ", ": ", 1), stdout)
            self.assertRegex(stdout, r"converged in \d+ iterations, residual [0-9.e+-]+, 5281 nodes solved for")
            m = re.search(r"turns up to ([0-9.]+) deg at the joined nodes, ([0-9.]+) deg one line into", stdout)
            self.assertTrue(m, stdout)
            self.assertLessEqual(float(m.group(1)), float(m.group(2)))  # no kinks at the joins
            self.assertIn("quality: 0 folded cells in the set", stdout)
            self.assertEqual(sorted(os.listdir(out)),
                             sorted([self.STEP + ".su2", self.STEP + "_foam", self.STEP + ".svg"] +
                                    [f"{self.STEP}-{b}.vts" for b in ("upstream", "upper", "lower")]))
            # SU2: one zone, the joined nodes once, the joins no markers
            with open(os.path.join(out, self.STEP + ".su2")) as f:
                text = f.read()
            self.assertEqual(int(re.search(r"^NELEM=\s*(\d+)", text, re.M).group(1)), self.CELLS)
            self.assertEqual(int(re.search(r"^NPOIN=\s*(\d+)", text, re.M).group(1)), self.POINTS)
            names = re.findall(r"^MARKER_TAG=\s*(\S+)", text, re.M)
            sizes = [int(n) for n in re.findall(r"^MARKER_ELEMS=\s*(\d+)", text, re.M)]
            self.assertEqual(dict(zip(names, sizes)), self.PATCHES)
            # one picture of the set: every block's lines, the joins not drawn as walls
            check_svg(self, os.path.join(out, self.STEP + ".svg"))
            # each block's own file has the block's nodes
            with open(os.path.join(out, self.STEP + "-lower.vts")) as f:
                self.assertIn('WholeExtent="0 80 0 16 0 0"', f.read())
            # OpenFOAM: checkMesh (where installed) finds one region, the joins interior faces
            case = os.path.join(out, self.STEP + "_foam")
            check_mesh(self, case)
            checkmesh = shutil_which("checkMesh")
            if checkmesh:
                env = dict(os.environ)
                env.setdefault("WM_PROJECT_DIR", "/usr/share/openfoam")
                log = subprocess.run([checkmesh, "-case", case], capture_output=True, text=True, env=env).stdout
                self.assertIn("\nMesh OK.", log)
                self.assertIn("Number of regions: 1 (OK).", log)
                self.assertEqual(int(re.search(r"^\s*cells:\s+(\d+)", log, re.M).group(1)), self.CELLS)
                table = {k: int(v) for k, v in re.findall(r"^\s{4}(\w+)\s+(\d+)\s+\d+\s+ok", log, re.M)}
                self.assertEqual(table, dict(self.PATCHES, frontAndBack=2 * self.CELLS))

    def test_step_as_vtk_multiblock(self):
        # vtm: the set's .vtm and its block directory, staged and put in place together
        with tempfile.TemporaryDirectory() as d:
            path = case_from_example(d, self.STEP, ('formats = ["su2", "openfoam", "vts", "svg"]', 'formats = ["vtm"]'))
            out, name = os.path.join(d, "out"), "case"  # named by the case file
            for _ in range(2):  # again over the first: the block directory is there
                code, stdout, stderr = run("run", path, "-o", out)
                self.assertEqual(code, 0, stdout + stderr)
                self.assertEqual(sorted(os.listdir(out)), [name, name + ".vtm"])  # no stage left
                files = [f"{name}_{k}.vts" for k in range(3)]
                self.assertEqual(sorted(os.listdir(os.path.join(out, name))), files)
                for f in files:
                    self.assertIn("wrote " + os.path.join(out, name, f), stdout)
                with open(os.path.join(out, name + ".vtm")) as f:
                    text = f.read()
                self.assertEqual(re.findall(r'file="([^"]+)"', text), [name + "/" + f for f in files])
            # the blocks named as the case file names them (eg2d_blocks_set_name), read by VTK
            import vtk
            reader = vtk.vtkXMLMultiBlockDataReader()
            reader.SetFileName(os.path.join(out, name + ".vtm"))
            reader.Update()
            data = reader.GetOutput()
            self.assertEqual([data.GetMetaData(k).Get(vtk.vtkCompositeDataSet.NAME()) for k in range(data.GetNumberOfBlocks())],
                             ["upstream", "upper", "lower"])
            with open(os.path.join(out, name, files[2])) as f:
                self.assertIn('WholeExtent="0 80 0 16 0 0"', f.read())

    def test_demo_runs_the_step(self):
        with tempfile.TemporaryDirectory() as d:
            code, stdout, stderr = run("demo", self.STEP, "-o", d, "--quiet")
            self.assertEqual(code, 0, stdout + stderr)
            self.assertIn(self.STEP + ".su2", os.listdir(d))

    def bad(self, replacements, code, message):
        with tempfile.TemporaryDirectory() as d:
            path = case_from_example(d, self.STEP, *replacements)
            got, stdout, stderr = run("run", path, "-o", os.path.join(d, "out"))
            self.assertEqual(got, code, stdout + stderr)
            self.assertIn(message, stderr)
            self.assertTrue(stderr.startswith("eg2d: " + path + ":"), stderr)
            self.assertFalse(os.path.exists(os.path.join(d, "out")) and os.listdir(os.path.join(d, "out")))

    def test_join_to_an_unknown_block(self):
        self.bad([('b = { block = "upper", side = "left" }', 'b = { block = "uper", side = "left" }')], 3,
                 "key 'joins[0].b.block': no block is named \"uper\" (the blocks: upstream, upper, lower)")

    def test_compact_join(self):
        # "BLOCK.SIDE": the whole side; the step solves as with the tables
        with tempfile.TemporaryDirectory() as d:
            path = case_from_example(d, self.STEP, ('a = { block = "upstream", side = "right" }', 'a = "upstream.right"'),
                                     ('b = { block = "lower", side = "top" }', 'b = "lower.top"'))
            code, stdout, stderr = run("run", path, "-o", os.path.join(d, "out"))
            self.assertEqual(code, 0, stdout + stderr)
            self.assertIn("turns up to 7.34 deg at the joined nodes", stdout)
        self.bad([('b = { block = "lower", side = "top" }', 'b = "lower.up"')], 3,
                 "key 'joins[1].b': \"up\" is not one of: bottom, right, top, left")
        self.bad([('b = { block = "lower", side = "top" }', 'b = "lower"')], 3,
                 "key 'joins[1].b': \"lower\": expected \"BLOCK.SIDE\" (a whole side) or {block, side, first, last}")

    # The lower block's walls (under and behind the step) with first cells of
    # their own: wall_spacing as [controls] takes it, for the block's sides.
    LOWER = 'name = "lower"\nsize = ["n_down", "n_lower"]\n'
    LOWER_WALLS = LOWER + "wall_spacing = { bottom = 1e-3, left = 1e-3 }\n"

    def bad_at_line(self, old, new, message):
        """bad(), and the message at the line of the new text."""
        case = self.LOWER_WALLS.replace(old, new)
        with tempfile.TemporaryDirectory() as d:
            path = case_from_example(d, self.STEP, (self.LOWER, case))
            with open(path) as f:
                text = f.read()
            line = text[:text.index(new)].count("\n") + 1
            got, stdout, stderr = run("run", path, "-o", os.path.join(d, "out"))
            self.assertEqual(got, 3, stdout + stderr)
            self.assertTrue(stderr.startswith(f"eg2d: {path}:{line}:"), stderr)
            self.assertIn(message, stderr)

    def test_block_wall_spacing_refused_with_the_key(self):
        self.bad_at_line("left = 1e-3", "lft = 1e-3",
                         "key 'blocks[2].wall_spacing.lft': unknown key (expected one of: bottom, right, top, left)")
        self.bad_at_line("left = 1e-3", "left = -1e-3",
                         "key 'blocks[2].wall_spacing.left': must be >= 0 (0 = orthogonality only)")
        self.bad_at_line("wall_spacing = { bottom = 1e-3, left = 1e-3 }", 'wall_spacing = "1e-3"',
                         "key 'blocks[2].wall_spacing'")

    # A block's wall_spacing reaches the set's graded wall layer. The
    # example's sides are not spaced for a first cell of 1e-3 (the floor's
    # first cell off the step's face is 0.52): the run says so, says the
    # layer could not be made on them, writes an unfolded grid and exits
    # EXIT_GEOMETRY for the layer that misses its first cell (a single
    # grid's run does so for one that grows too fast).
    def test_block_wall_spacing_on_unspaced_sides(self):
        with tempfile.TemporaryDirectory() as d:
            path = case_from_example(d, self.STEP, (self.LOWER, self.LOWER_WALLS))
            code, stdout, stderr = run("run", path, "-o", os.path.join(d, "out"))
            self.assertEqual(code, 4, stdout + stderr)
            self.assertIn("the wall layer at block lower bottom has a median first cell of 0.1308 where 0.001 was asked", stderr)
            self.assertTrue(os.listdir(os.path.join(d, "out")), "the files are written")
            self.assertIn("quality: 0 folded cells in the set", stdout)
            self.assertIn("line(s) of the boundary leave a wall with a first cell more than 2 times off its height",
                          stdout)
            self.assertIn("wall layer (graded, set of blocks): not made", stdout)

    def test_join_of_different_node_counts(self):
        self.bad([('a = { block = "upstream", side = "right" }', 'a = { block = "upstream", side = "right", last = 30 }')], 3,
                 "key 'joins[0].b': spans 41 nodes (0 to 40) but a spans 31 (0 to 30): a join is node to node")

    def test_missing_side(self):
        with open(os.path.join(EXAMPLES, self.STEP + ".toml")) as f:
            text = f.read()
        lower_top = text.index('[blocks.sides.top]\nx = "20*tanh(2*s)/tanh(2)"\ny = "1"\n', text.index('name = "lower"'))
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "case.toml")
            with open(path, "w") as f:
                f.write(text[:lower_top] + text[lower_top:].replace('[blocks.sides.top]\nx = "20*tanh(2*s)/tanh(2)"\ny = "1"\n', "", 1))
            got, _, stderr = run("run", path, "-o", os.path.join(d, "out"))
            self.assertEqual(got, 3, stderr)
            self.assertIn("key 'blocks[2].sides.top': missing (a single-block case needs the sides bottom, right, top, left)",
                          stderr)

    def test_join_range_outside_the_side(self):
        self.bad([('b = { block = "lower", side = "top" }', 'b = { block = "lower", side = "top", first = 1, last = 81 }')], 3,
                 "key 'joins[1].b.last': last = 81: need a whole number in [0, 80] (side top of block lower has 81 nodes)")

    def test_duplicate_block_name(self):
        self.bad([('name = "lower"', 'name = "upper"')], 3, "key 'blocks[2].name': \"upper\" names two blocks")

    def test_block_name_refused_by_the_library(self):
        self.bad([('name = "lower"', 'name = "lower part"'), ('block = "lower"', 'block = "lower part"')], 3,
                 "key 'blocks[2].name': eg2d_blocks_set_name: name \"lower part\": a block's name is 1 to 32 letters")

    def test_one_grid_keys_refused(self):
        self.bad([('system = "winslow"', 'system = "winslow"\nsize = [9, 9]')], 3,
                 "key 'size': not in a case of [[blocks]]")

    def test_size_option_refused(self):
        code, _, stderr = run("run", os.path.join(EXAMPLES, self.STEP + ".toml"), "-o", "/nonexistent/x", "--size", "9x9")
        self.assertEqual(code, 2, stderr)
        self.assertIn("--size does not apply to a case of [[blocks]]", stderr)

    def test_run_files_refused(self):
        self.bad([('formats = ["su2", "openfoam", "vts", "svg"]', 'formats = ["su2", "history"]')], 3,
                 "key 'output.formats[1]': is not written for a set of blocks")

    def test_output_set_all_or_nothing(self):
        # a case path that is a file: refused before solving, nothing of the set written;
        # a second run replaces the set, and an existing case directory is updated in place
        with tempfile.TemporaryDirectory() as d:
            out = os.path.join(d, "out")
            os.mkdir(out)
            blocker = os.path.join(out, self.STEP + "_foam")
            with open(blocker, "w") as f:
                f.write("old")
            code, stdout, stderr = run("run", os.path.join(EXAMPLES, self.STEP + ".toml"), "-o", out)
            self.assertEqual(code, 8, stdout + stderr)
            self.assertIn("not a directory, so no case can be written there (checked before solving)", stderr)
            self.assertNotIn("converged", stdout)
            self.assertEqual(os.listdir(out), [self.STEP + "_foam"])
            os.remove(blocker)
            for _ in range(2):
                code, stdout, stderr = run("run", os.path.join(EXAMPLES, self.STEP + ".toml"), "-o", out)
                self.assertEqual(code, 0, stdout + stderr)
            self.assertEqual(len(os.listdir(out)), 6)
            self.assertTrue(os.path.isfile(os.path.join(out, self.STEP + "_foam", "constant", "polyMesh", "points")))

    def test_library_refusals_and_exit_codes(self):
        # what the library's set does not support, at the key that asks for it (exit 9)
        self.bad([('system = "winslow"', 'system = "variational"')], 9,
                 "key 'system': eg2d_blocks_check: block 0: the variational system on a set of blocks is not available")
        # the iteration limit (block 0's): exit 5, nothing written
        self.bad([("[output]", "[solver]\nmax_iterations = 2\n\n[output]")], 5,
                 "eg2d_blocks_solve: the set reached the iteration limit (2)")
        # a block no join reaches: exit 4, the blocks named by their indices
        self.bad([('[[joins]]\na = { block = "upper", side = "bottom" }\nb = { block = "lower", side = "top" }', "")], 4,
                 "key 'blocks': eg2d_blocks_check: the set is not connected: no chain of joins from block 0 to block 2 "
                 "(blocks 0, 1, ...: upstream, upper, lower)")

    def test_library_error_names_the_join(self):
        # the lower block's top moved up: the joined nodes do not coincide (eg2d_blocks_check)
        with tempfile.TemporaryDirectory() as d:
            with open(os.path.join(EXAMPLES, self.STEP + ".toml")) as f:
                text = f.read()
            k = text.index('name = "lower"')
            text = text[:k] + text[k:].replace('x = "20*tanh(2*s)/tanh(2)"\ny = "1"', 'x = "20*tanh(2*s)/tanh(2)"\ny = "1.5"', 1)
            text = text.replace('y = "0.5 + 0.5*tanh(2.5*(2*s - 1))/tanh(2.5)"', 'y = "1.5*(0.5 + 0.5*tanh(2.5*(2*s - 1))/tanh(2.5))"')
            path = os.path.join(d, "case.toml")
            with open(path, "w") as f:
                f.write(text)
            code, stdout, stderr = run("run", path, "-o", os.path.join(d, "out"))
            self.assertEqual(code, 4, stdout + stderr)
            self.assertIn("key 'joins[1]': eg2d_blocks_check: join block 1 side JMIN", stderr)
            self.assertIn("are 0.5 apart", stderr)
            self.assertIn("(blocks 0, 1, ...: upstream, upper, lower)", stderr)
            self.assertFalse(os.path.exists(os.path.join(d, "out")))


def shutil_which(name):
    import shutil
    return shutil.which(name)

def main():
    global TOOL, EXAMPLES
    TOOL, EXAMPLES = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    args = sys.argv[3:]
    if args[:1] == ["--example"]:
        Example.name, Example.size = args[1], args[2]
        suite = unittest.defaultTestLoader.loadTestsFromTestCase(Example)
        sys.exit(0 if unittest.TextTestRunner(verbosity=2).run(suite).wasSuccessful() else 1)
    unittest.main(argv=[sys.argv[0], *args], verbosity=2)


if __name__ == "__main__":
    main()
