#!/usr/bin/env python3
"""Follows README.md literally: the "Install" commands for a prefix of your
own (with HOME a scratch directory), then the C and the Fortran example, saved
and built with the commands the README gives after each, and run.

    readme_examples.py SOURCE_DIR BUILD_DIR [--no-fortran]
"""
import os
import re
import subprocess
import sys
import tempfile


def blocks(text):
    """(language, code, the heading above it, the line just before it)."""
    out, heading = [], ""
    lines = text.splitlines()
    k = 0
    while k < len(lines):
        line = lines[k]
        if line.startswith("#"):
            heading = line.lstrip("# ").strip()
        m = re.match(r"^```(\w*)$", line)
        if m:
            end = lines.index("```", k + 1)
            before = next((l for l in reversed(lines[:k]) if l.strip()), "")
            out.append((m.group(1), "\n".join(lines[k + 1:end]) + "\n", heading, before))
            k = end
        k += 1
    return out


def main():
    src, build = sys.argv[1], os.path.abspath(sys.argv[2])
    fortran = "--no-fortran" not in sys.argv
    text = open(os.path.join(src, "README.md")).read()
    bs = blocks(text)
    install = next(c for lang, c, h, before in bs if h == "Install" and "own" in before)
    c_code = next(c for lang, c, h, _ in bs if lang == "c" and h == "C example")
    c_build = next(c for lang, c, h, _ in bs if lang == "sh" and h == "C example")
    f_code = next(c for lang, c, h, _ in bs if lang == "fortran" and h == "Fortran example")
    f_build = next(c for lang, c, h, _ in bs if lang == "sh" and h == "Fortran example")
    with tempfile.TemporaryDirectory() as home:
        os.symlink(build, os.path.join(home, "build"))  # the README runs from the checkout: build/ is there
        with open(os.path.join(home, "swan.c"), "w") as f:
            f.write(c_code)
        with open(os.path.join(home, "swan.f90"), "w") as f:
            f.write(f_code)
        script = "set -eo pipefail\n" + install + c_build + (f_build if fortran else "")
        env = {k: v for k, v in os.environ.items() if k not in ("PKG_CONFIG_PATH", "LD_LIBRARY_PATH")}
        env["HOME"] = home
        p = subprocess.run(["bash", "-c", script], cwd=home, env=env, capture_output=True, text=True)
        print(p.stdout, p.stderr, sep="\n")
        if p.returncode != 0:
            sys.exit(f"README: the install and example commands failed (exit {p.returncode})")
        if fortran and not re.search(r"swan 65x65: centre node \(0\.510461, 0\.286403\)", p.stdout):
            sys.exit("README: the Fortran example did not print the swan's centre node")
    print(f"README examples: {2 if fortran else 1} passed, 0 failed")


if __name__ == "__main__":
    main()
