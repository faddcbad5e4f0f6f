#!/usr/bin/python3
"""The two-element airfoil of issue 39 (bench/two-element-airfoil): its case
files are what make_case.py writes (examples/two-element-airfoil.toml with
the options its header names), and the eg2d command accepts the first layout (geometry, six blocks,
seven joins, patches) and runs it: given one iteration, the set stops at its
iteration limit (exit 5) after printing the blocks. That layout does not
mesh (README.md there); this keeps it a valid reproducer. The example, which
meshes, is run by the cli tests (its example test, BlockSets.test_two_element_airfoil).

    two_element_airfoil.py EG2D_TOOL REPO_ROOT WORK_DIR"""
import os
import subprocess
import sys

tool, root, work = sys.argv[1], sys.argv[2], sys.argv[3]
here = os.path.join(root, "bench", "two-element-airfoil")
os.makedirs(work, exist_ok=True)
failed = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failed.append(what)


case = os.path.join(here, "two-element-airfoil.toml")
fresh = os.path.join(work, "two-element-airfoil.toml")
p = subprocess.run([sys.executable, os.path.join(here, "make_case.py"), "-o", fresh], capture_output=True, text=True)
check(p.returncode == 0, f"make_case.py exit {p.returncode} {p.stderr.strip()}")
with open(case) as f:
    committed = f.read()
with open(fresh) as f:
    made = f.read()
check(made == committed, "two-element-airfoil.toml is what make_case.py writes")

# the example: the options are those its header says wrote it
with open(os.path.join(root, "examples", "two-element-airfoil.toml")) as f:
    walls = f.read()
options = next(l for l in walls.splitlines() if l.startswith("# bench/two-element-airfoil/make_case.py"))
fresh = os.path.join(work, "walls.toml")
p = subprocess.run([sys.executable, os.path.join(here, "make_case.py"), *options.split()[2:], "-o", fresh],
                   capture_output=True, text=True)
check(p.returncode == 0, f"make_case.py {' '.join(options.split()[2:])}: exit {p.returncode} {p.stderr.strip()}")
with open(fresh) as f:
    check(f.read() == walls, "examples/two-element-airfoil.toml is what make_case.py writes with the options its header names")

one = os.path.join(work, "one-iteration.toml")
with open(one, "w") as f:
    f.write(committed.replace("[output]", "[solver]\nmax_iterations = 1\n\n[output]", 1))
p = subprocess.run([tool, "run", one, "-o", os.path.join(work, "out")], capture_output=True, text=True)
out = p.stdout + p.stderr
check(p.returncode == 5, f"eg2d run with one iteration: exit {p.returncode} == 5")
check("a set of 6 blocks, 7 joins, 33798 nodes" in out, "the set: 6 blocks, 7 joins, 33798 nodes")
for block, size in (("lower", "81 x 65"), ("upper", "185 x 65"), ("front", "49 x 65"),
                    ("slot", "25 x 49"), ("wake", "97 x 49"), ("below_flap", "113 x 65")):
    check(f"block {block}: {size}" in out, f"block {block}: {size}")
check("the set reached the iteration limit (1)" in out, "stopped at the iteration limit, not refused")
check(not os.path.exists(os.path.join(work, "out")), "no files written")
if failed:
    print(out)
sys.exit(1 if failed else 0)
