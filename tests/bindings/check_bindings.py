#!/usr/bin/env python3
"""Fails when a function or constant of include/eg2d.h lacks its bindings.

For every `EG2D_API ... eg2d_NAME(...)` in the header:
  - Fortran: a bind(C, name='eg2d_NAME') interface named eg2d_NAME with as
    many arguments (bindings/fortran/*.f90, *.inc);
  - Python: a PROTOTYPES entry "eg2d_NAME" with as many argtypes
    (bindings/python/eg2d/_capi.py), called as lib.eg2d_NAME( somewhere else
    in the package;
  - C++: a call ::eg2d_NAME( in include/eg2d.hpp.
For every integer `#define EG2D_X value` (decimal or hex): EG2D_X = value
(decimal) in the Fortran module and X = value in bindings/python/eg2d/constants.py.
And nothing is bound that the header lacks.

Usage: check_bindings.py SOURCE_DIR [--extra-declaration TEXT]
(the extra declaration, without its ';', is appended to the header: the
test of this check).
Text only: needs neither the library nor numpy.
"""
import glob
import os
import re
import sys


def strip_c_comments(text):
    return re.sub(r"/\*.*?\*/|//[^\n]*", " ", text, flags=re.S)


def count_c_args(args):
    args = args.strip()
    return 0 if args in ("", "void") else args.count(",") + 1


def count_top_level(items):
    depth, n, seen = 0, 0, False
    for ch in items:
        if ch in "([":
            depth += 1
        elif ch in ")]":
            depth -= 1
        elif ch == "," and depth == 0:
            n += 1
            continue
        if not ch.isspace():
            seen = True
    return n + 1 if seen else 0


def header_api(text):
    text = strip_c_comments(text)
    funcs = {m.group(1): count_c_args(m.group(2))
             for m in re.finditer(r"EG2D_API\s[^;{}]*?\b(eg2d_\w+)\s*\(([^)]*)\)\s*;", text)}
    consts = {m.group(1): int(m.group(2), 0)
              for m in re.finditer(r"^\s*#\s*define\s+EG2D_(\w+)\s+\(?(-?(?:0[xX][0-9a-fA-F]+|\d+))\)?\s*$",
                                   text, flags=re.M)}
    return funcs, consts


def fortran_api(src):
    text = ""
    for path in sorted(glob.glob(os.path.join(src, "bindings/fortran/*.f90")) +
                       glob.glob(os.path.join(src, "bindings/fortran/*.inc"))):
        text += open(path).read() + "\n"
    text = re.sub(r"![^\n]*", "", text)              # comments
    text = re.sub(r"&[ \t]*\n[ \t]*&?", " ", text)   # continuation lines
    funcs, problems = {}, []
    for m in re.finditer(r"(?:function|subroutine)\s+(\w+)\s*\(([^)]*)\)[^\n]*?"
                         r"bind\s*\(\s*C\s*,\s*name\s*=\s*['\"](\w+)['\"]\s*\)", text, flags=re.I):
        name, args, cname = m.group(1), m.group(2), m.group(3)
        if cname == "strlen":
            continue
        if name.lower() != cname.lower():
            problems.append(f"{cname}: the Fortran interface is named {name}, not {cname}")
        funcs[cname] = count_top_level(args)
    consts = {m.group(1).upper(): int(m.group(2))
              for m in re.finditer(r"parameter[^:\n]*::\s*EG2D_(\w+)\s*=\s*(-?\d+)\s*$", text, flags=re.M | re.I)}
    return funcs, consts, problems


def python_api(src):
    pkg = os.path.join(src, "bindings/python/eg2d")
    capi = open(os.path.join(pkg, "_capi.py")).read()
    protos = {m.group(1): count_top_level(m.group(2))
              for m in re.finditer(r'"(eg2d_\w+)"\s*:\s*\([^\[]*\[(.*?)\]\s*\)', capi)}
    called = set()
    for path in glob.glob(os.path.join(pkg, "*.py")):
        if os.path.basename(path) != "_capi.py":
            called |= set(re.findall(r"\blib\.(eg2d_\w+)\s*\(", open(path).read()))
    consts = {m.group(1): int(m.group(2), 0) for m in
              re.finditer(r"^(\w+)\s*=\s*(-?(?:0[xX][0-9a-fA-F]+|\d+))\s*$",
                          open(os.path.join(pkg, "constants.py")).read(), flags=re.M)}
    return protos, called, consts


def main(argv):
    src = argv[1]
    header = open(os.path.join(src, "include/eg2d.h")).read()
    if len(argv) > 3 and argv[2] == "--extra-declaration":
        header += "\n" + argv[3].rstrip(";") + ";\n"
    funcs, consts = header_api(header)
    ffuncs, fconsts, problems = fortran_api(src)
    pfuncs, pcalled, pconsts = python_api(src)
    hpp = open(os.path.join(src, "include/eg2d.hpp")).read()
    cxx = set(re.findall(r"::(eg2d_\w+)\s*\(", strip_c_comments(hpp)))

    for name, n in sorted(funcs.items()):
        if name not in ffuncs:
            problems.append(f"{name}: no bind(C) interface in bindings/fortran/eg2d_capi.inc")
        elif ffuncs[name] != n:
            problems.append(f"{name}: the Fortran interface has {ffuncs[name]} arguments, the header {n}")
        if name not in pfuncs:
            problems.append(f"{name}: no prototype in bindings/python/eg2d/_capi.py")
        elif pfuncs[name] != n:
            problems.append(f"{name}: the Python prototype has {pfuncs[name]} argtypes, the header {n}")
        if name not in pcalled:
            problems.append(f"{name}: no Python wrapper calls lib.{name}(")
        if name not in cxx:
            problems.append(f"{name}: include/eg2d.hpp does not call ::{name}(")
    for name in sorted(set(ffuncs) - set(funcs)):
        problems.append(f"{name}: bound in Fortran but not declared EG2D_API in include/eg2d.h")
    for name in sorted(set(pfuncs) - set(funcs)):
        problems.append(f"{name}: bound in Python but not declared EG2D_API in include/eg2d.h")
    for name, value in sorted(consts.items()):
        if fconsts.get(name.upper()) != value:
            problems.append(f"EG2D_{name} = {value}: the Fortran module has {fconsts.get(name.upper())}")
        if pconsts.get(name) != value:
            problems.append(f"EG2D_{name} = {value}: bindings/python/eg2d/constants.py has {pconsts.get(name)}")

    for p in problems:
        print("MISSING BINDING: " + p)
    print(f"bindings: {len(funcs)} functions, {len(consts)} constants checked; {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
