#!/usr/bin/env python3
"""The header is a manual, not an essay: include/eg2d.h fails this check when

  - it names bench/ or RESULTS.md (measurements live in docs/);
  - it carries an internal label ("seed 003", "issue 38") instead of an author
    and year;
  - a comment holds a measured figure: a time (a number followed by s, ms,
    seconds, minutes), a speed-up ("3x faster", "2 times faster") or a cycle
    count ("12 cycles");
  - an EG2D_API function is not named in the contents list at the top (the
    check is one-directional: the contents may name calls declared later);
  - the ids of one kind (EG2D_PARAM_*, EG2D_QUALITY_*, ...) are not one block
    in increasing numeric order.

Usage: header_manual.py [SOURCE_DIR]     check SOURCE_DIR/include/eg2d.h
       header_manual.py --self-test     check that each rule can fail
Standard library only."""
import pathlib
import re
import sys

# Every kind of id whose #defines must be one block in increasing order.
KINDS = ("EG2D_ERR_", "EG2D_LIST_", "EG2D_VALUE_", "EG2D_WRITES_", "EG2D_SIDE_", "EG2D_TOPO_", "EG2D_INIT_", "EG2D_SYSTEM_", "EG2D_SOLVER_",
         "EG2D_ORTHO_", "EG2D_PARAM_", "EG2D_MARCH_END_", "EG2D_AIRFOIL_TE_", "EG2D_RUN_",
         "EG2D_QUALITY_", "EG2D_WALL_", "EG2D_FORMAT_", "EG2D_PLOT3D_", "EG2D_DIST_",
         "EG2D_CURVE_", "EG2D_CLUSTER_", "EG2D_PATCH_")

NUMBER = r"\d+(?:\.\d+)?(?:e[+-]?\d+)?"
MEASURED = [
    (re.compile(r"(?<![\w.])" + NUMBER + r"\s*(?:s|ms|us|sec|secs|seconds?|minutes?|min|hours?)\b", re.I),
     "a time"),
    (re.compile(NUMBER + r"\s*(?:x|times)\s+(?:faster|slower|quicker|the speed)", re.I), "a speed-up"),
    (re.compile(r"(?<![\w.])" + NUMBER + r"\s*(?:[A-Z]-|multigrid |FAS |Newton )?cycles?\b"), "a cycle count"),
]
LABEL = re.compile(r"seed 0|issue [0-9]", re.I)
COMMENT = re.compile(r"/\*.*?\*/", re.S)
DEFINE = re.compile(r"^\s*#\s*define\s+(EG2D_\w+)\s+(0x[0-9A-Fa-f]+|-?\d+)\b", re.M)
DECL = re.compile(r"EG2D_API\b[^;(]*?\b(eg2d_\w+)\s*\(")


def line_of(text, pos):
    return text.count("\n", 0, pos) + 1


def check(text):
    bad = []
    for m in re.finditer(r"bench/|RESULTS\.md", text):
        bad.append(f"{line_of(text, m.start())}: names {m.group(0)}: measurements belong in docs/")
    for m in LABEL.finditer(text):
        bad.append(f"{line_of(text, m.start())}: an internal label '{m.group(0)}...': cite author and year")
    for c in COMMENT.finditer(text):
        for pattern, what in MEASURED:
            for m in pattern.finditer(c.group(0)):
                bad.append(f"{line_of(text, c.start() + m.start())}: {what} in a comment: "
                           f"'{m.group(0)}' (move measurements to docs/)")

    # The contents: the part of the first comment from "Contents" on.
    first = COMMENT.search(text)
    contents = ""
    if first:
        k = first.group(0).find("Contents")
        contents = first.group(0)[k:] if k >= 0 else ""
    if not contents:
        bad.append("1: no contents list ('Contents') in the header's first comment")
    listed = set(re.findall(r"\beg2d_\w+", contents))
    code = COMMENT.sub(lambda m: "\n" * m.group(0).count("\n"), text)
    for m in DECL.finditer(code):
        if m.group(1) not in listed:
            bad.append(f"{line_of(code, m.start())}: {m.group(1)} is declared but not named in the contents")

    # Each kind of id: one block of #defines, values increasing.
    lines = code.splitlines()
    defines = [(line_of(code, m.start()), m.group(1), int(m.group(2), 0)) for m in DEFINE.finditer(code)]
    for kind in KINDS:
        rows = [d for d in defines if d[1].startswith(kind)]
        if not rows:
            continue
        for (n0, a, v0), (n1, b, v1) in zip(rows, rows[1:]):
            if v1 <= v0:
                bad.append(f"{n1}: {b} = {v1} follows {a} = {v0}: the {kind}* ids are not in increasing order")
        first_line, last_line = rows[0][0], rows[-1][0]
        names = {r[1] for r in rows}
        for n in range(first_line, last_line + 1):
            s = lines[n - 1].strip()
            m = re.match(r"#\s*define\s+(\w+)", s)
            if (m and m.group(1) not in names) or s.startswith(("EG2D_API", "typedef")):
                bad.append(f"{n}: '{s[:60]}' splits the {kind}* ids: one table per kind")
                break
    return bad


GOOD = """/*
 * Contents
 *  1. eg2d_a, eg2d_b, eg2d_later
 */
#define EG2D_PARAM_X 0  /* (0, 1), default 1e-8, length */
#define EG2D_PARAM_Y 1  /* default 2 = W cycle */
EG2D_API int eg2d_a(int x);
EG2D_API const char *eg2d_b(void);
"""
BAD = {
    "bench/": GOOD + "/* see bench/RESULTS.md */\n",
    "internal label": GOOD + "/* the swan of seed 003 */\n",
    "a time": GOOD + "/* converges in 0.7 s at 257 x 257 */\n",
    "a speed-up": GOOD + "/* 3x faster than SOR */\n",
    "a cycle count": GOOD + "/* takes 12 cycles */\n",
    "not named in the contents": GOOD + "EG2D_API int eg2d_c(int x);\n",
    "not in increasing order": GOOD + "#define EG2D_PARAM_Z 1\n",
    "splits the": GOOD.replace("#define EG2D_PARAM_Y", "EG2D_API int eg2d_a2(void);\n#define EG2D_PARAM_Y")
                      .replace("eg2d_later", "eg2d_a2"),
}


def self_test():
    failures = []
    if check(GOOD):
        failures.append(f"the good sample fails: {check(GOOD)}")
    for expect, text in BAD.items():
        found = check(text)
        if not any(expect in b for b in found):
            failures.append(f"a header with {expect!r} passes: {found}")
    for f in failures:
        print(f)
    print(f"header_manual self-test: {len(BAD) + 1} samples, {len(failures)} wrong")
    return 1 if failures else 0


def main(argv):
    if argv[1:2] == ["--self-test"]:
        return self_test()
    root = pathlib.Path(argv[1]) if len(argv) > 1 else pathlib.Path(__file__).resolve().parents[1]
    header = root / "include" / "eg2d.h"
    bad = check(header.read_text())
    for b in bad:
        print(f"include/eg2d.h:{b}")
    print(f"header_manual: {len(bad)} problem(s)")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
