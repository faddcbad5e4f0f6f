"""The readers' memory is bounded by the file's real size: files whose headers
claim far more than they hold (a 100000 x 100000 Plot3D grid in 24 bytes, a
million grids, a Lednicer airfoil of 2e9 points) and files that are large but
hold almost nothing (16 MB of blank lines, 48 MB of one-digit numbers) are read
under `ulimit -v` at 200 MB, by the library's readers (read_one) and by the
eg2d command. Each must end in a clean format error naming the file, never
EG2D_ERR_MEMORY, a crash or a hang. The command's own reader, of case files,
refuses one above 1 MiB unparsed; a grid too large for the limit is exit 10,
"out of memory". Left out of the sanitizer presets (label no-sanitizer):
their runtimes reserve terabytes of address space.

    bounded_memory.py READ_ONE [EG2D_COMMAND]
"""
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import unittest

READ_ONE = TOOL = None
LIMIT_KB = 200 * 1024
BIG = 16 << 20  # the "large but empty" files: 16 MB


def limited(*args, cwd=None):
    """Runs args under `ulimit -v LIMIT_KB`; (exit code, stdout, stderr)."""
    p = subprocess.run(["bash", "-c", f'ulimit -v {LIMIT_KB} && exec "$0" "$@"', *args], capture_output=True,
                       text=True, cwd=cwd, timeout=120)
    return p.returncode, p.stdout, p.stderr


def marked(payload):
    """A Fortran record: payload between two 4-byte length markers (little-endian)."""
    return struct.pack("<i", len(payload)) + payload + struct.pack("<i", len(payload))


class Readers(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.addCleanup(self.dir.cleanup)

    def file(self, name, data):
        path = os.path.join(self.dir.name, name)
        with open(path, "wb") as f:
            f.write(data if isinstance(data, bytes) else data.encode())
        return path

    def refused(self, kind, path, status, message):
        code, out, err = limited(READ_ONE, kind, path)
        self.assertEqual(code, 0, f"{kind} {path}: exit {code}\n{out}{err}")
        self.assertEqual(out, f"{status}: {message}\n")

    def binary_refused(self, data):
        path = self.file("grid.x", data)
        self.refused("plot3d", path, "EG2D_ERR_IO",
                     f"eg2d_read_plot3d_into: {path}: not a Plot3D grid file: it has NUL bytes (binary) but no Plot3D "
                     "binary layout fits its size")

    def ascii_refused(self, text, count):
        path = self.file("grid.txt", text)
        self.refused("plot3d", path, "EG2D_ERR_IO",
                     f"eg2d_read_plot3d_into: {path}: not a Plot3D grid file: its {count} numbers fit no 2D/3D, "
                     "single-/multi-grid layout (truncated?)")

    def test_plot3d_binary_header_claims_1e10_nodes(self):
        self.binary_refused(marked(struct.pack("<2i", 100000, 100000)) + marked(b"\0" * 16))

    def test_plot3d_stream_header_claims_1e10_nodes(self):
        self.binary_refused(struct.pack("<2i", 100000, 100000) + b"\0" * 16)

    def test_plot3d_record_marker_claims_2_gb(self):
        self.binary_refused(struct.pack("<i", 2**31 - 1) + struct.pack("<2i", 3, 3) + b"\0" * 12)

    def test_plot3d_a_million_grids(self):
        # the grid count's record, then the dimension record's marker for 2^20 grids of 2 ints, and no more
        self.binary_refused(marked(struct.pack("<i", 1 << 20)) + struct.pack("<i", 8 << 20) + b"\0" * 16)

    def test_plot3d_ascii_header_claims_1e10_nodes(self):
        self.ascii_refused("100000 100000\n0 1 2 3\n", 6)

    def test_plot3d_ascii_48_mb_of_numbers_that_are_no_grid(self):
        # 24 million numbers: 192 MB as doubles, had they been kept
        n = 3 * BIG // 2
        self.ascii_refused("1 " * n, n)

    def test_plot3d_ascii_16_mb_grid_is_read(self):
        # a real grid of the same size is read whole: 2 x 2 x 1 million nodes
        n = 1000
        numbers = " ".join(["1"] * (2 * n * n))
        path = self.file("grid.txt", f"{n} {n}\n{numbers}\n")
        code, out, _ = limited(READ_ONE, "plot3d", path)
        self.assertEqual((code, out), (0, "EG2D_OK\n"))

    def test_points_16_mb_of_blank_lines(self):
        path = self.file("blank.txt", "\n" * BIG)
        for kind, call in (("points", "eg2d_read_points"), ("side", "eg2d_set_side_from_file")):
            self.refused(kind, path, "EG2D_ERR_IO", f"{call}: {path}: no points in the file")

    def test_lednicer_header_claims_2e9_points(self):
        path = self.file("lednicer.dat", "NACA\n1000000000 1000000000\n0 0\n0.5 0.1\n1 0\n0 0\n0.5 -0.1\n1 0\n")
        self.refused("airfoil", path, "EG2D_ERR_ARGUMENT",
                     f"eg2d_curve_read_airfoil: Lednicer file \"{path}\" (line 2): announces 1000000000 + 1000000000 "
                     "points but has 6 (3 + 3: the lower surface starts at line 6, where x returns to the leading "
                     "edge): correct the counts")

    def test_airfoil_one_line_of_300_mb(self):
        # Beyond the limit when read whole: refused at its 4097th byte.
        path = os.path.join(self.dir.name, "long.dat")
        with open(path, "wb") as f:
            f.write(b"NACA\n1 0\n")
            f.truncate(300 << 20)  # a sparse file: the line is 300 MB of NUL bytes
        self.refused("airfoil", path, "EG2D_ERR_ARGUMENT",
                     f"eg2d_curve_read_airfoil: airfoil file \"{path}\", line 3: longer than 4096 bytes: \""
                     + "\\x00" * 60 + "\"...")

    def test_airfoil_16_mb_of_blank_lines(self):
        path = self.file("blank.dat", "NACA\n" + "\n" * BIG)
        self.refused("airfoil", path, "EG2D_ERR_ARGUMENT",
                     f"eg2d_curve_read_airfoil: airfoil file \"{path}\": 0 points, need at least 4")


class Command(unittest.TestCase):
    """The eg2d command under the same limit: a grid larger than memory, a case file larger than a case file
    is, an airfoil piece of blank lines."""

    def run_case(self, text, files=()):
        """Runs the case file `text` (beside it, files: (name, text) pairs) under the limit:
        (exit code, stdout, stderr, its path, the output dir)."""
        d = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, d)
        case = os.path.join(d, "case.toml")
        for name, content in (("case.toml", text), *files):
            with open(os.path.join(d, name), "w") as f:
                f.write(content)
        out_dir = os.path.join(d, "out")
        return (*limited(TOOL, "run", case, "-o", out_dir, "--quiet"), case, out_dir)

    def test_grid_beyond_the_limit_is_out_of_memory(self):
        code, out, err, _, out_dir = self.run_case(
            'size = [20000, 20000]\n[sides.bottom]\nx = "s"\ny = "0"\n[sides.right]\nx = "1"\ny = "s"\n'
            '[sides.top]\nx = "s"\ny = "1"\n[sides.left]\nx = "0"\ny = "s"\n')
        self.assertEqual(code, 10, out + err)
        self.assertRegex(err, r"^eg2d: out of memory: the grid is too large for this machine \(.*\)\n$")
        self.assertFalse(os.path.exists(out_dir))

    def test_case_file_above_1_mib_is_refused_unparsed(self):
        # 8 million numbers: TOML's parser takes ~40 bytes for each byte of such a file
        code, out, err, case, _ = self.run_case("size = [9, 9]\nx = [" + "1," * (BIG // 2) + "1]\n")
        self.assertEqual(code, 3, out + err)
        self.assertEqual(err, f"eg2d: {case}: more than 1 MiB, too large for a case file (large point sets go in "
                              'point files: file = "...")\n')

    def test_case_file_just_below_1_mib_is_parsed(self):
        text = "size = [9, 9]\nx = [" + "1," * ((1 << 19) - 32) + "1]\n"
        self.assertLess(len(text), 1 << 20)
        code, out, err, case, _ = self.run_case(text)
        self.assertEqual(code, 3, out + err)
        self.assertTrue(err.startswith(f"eg2d: {case}:2:1: key 'x': unknown key"), err)

    def test_airfoil_piece_of_blank_lines(self):
        code, out, err, case, _ = self.run_case(
            'size = [33, 9]\ntopology = "o"\n[sides.inner]\nairfoil = "blank.dat"\n'
            '[sides.outer]\nx = "0.5 + 5*cos(2*pi*s)"\ny = "-5*sin(2*pi*s)"\n',
            files=[("blank.dat", "NACA\n" + "\n" * BIG)])
        self.assertIn(code, (3, 4), out + err)
        self.assertIn(f'{os.path.dirname(case)}/blank.dat": 0 points, need at least 4', err)
        self.assertNotIn("memory", err)


def main():
    global READ_ONE, TOOL
    READ_ONE = os.path.abspath(sys.argv[1])
    TOOL = os.path.abspath(sys.argv[2]) if len(sys.argv) > 2 and sys.argv[2] else None
    names = ["Readers"] + (["Command"] if TOOL else [])
    suite = unittest.TestSuite(unittest.defaultTestLoader.loadTestsFromName(n, sys.modules[__name__]) for n in names)
    sys.exit(0 if unittest.TextTestRunner(verbosity=2).run(suite).wasSuccessful() else 1)


if __name__ == "__main__":
    main()
