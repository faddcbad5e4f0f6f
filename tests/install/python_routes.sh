#!/usr/bin/env bash
# The two ways to a working `import eg2d` that README.md gives, each in a
# scratch place, with neither EG2D_LIBRARY nor PYTHONPATH:
#  1. pip install ./bindings/python (offline) into a venv: setup.py builds
#     libeg2d and carries it inside the package;
#  2. cmake --install to the default prefix (/usr/local; staged with DESTDIR):
#     the package lands in a directory Debian's python3 has on sys.path.
# Usage: python_routes.sh SOURCE_DIR BUILD_DIR PYTHON
set -euo pipefail
src=$1 build=$2 python=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
check='import eg2d, numpy as np
g = eg2d.Grid(9, 9)
s = np.linspace(0, 1, 9)
g.set_side(eg2d.SIDE_JMIN, s, 0 * s); g.set_side(eg2d.SIDE_IMAX, 1 + 0 * s, s)
g.set_side(eg2d.SIDE_JMAX, s, 1 + 0 * s); g.set_side(eg2d.SIDE_IMIN, 0 * s, s)
g.solve()
print("import eg2d from", eg2d.__file__, "- a 9x9 grid solved")'

# 1. pip, offline, into a venv (its own copy of the source: pip builds in-tree).
cp -r "$src" "$work/src"
rm -rf "$work/src/build"* "$work/src/bindings/python/build"
"$python" -m venv --system-site-packages "$work/venv"
"$work/venv/bin/pip" install --no-build-isolation --no-index --quiet "$work/src/bindings/python" > "$work/pip.log" 2>&1 \
    || { cat "$work/pip.log"; exit 1; }
(cd "$work" && env -u EG2D_LIBRARY -u PYTHONPATH "$work/venv/bin/python" -c "$check") | tee "$work/pip.out"
grep -q "$work/venv/" "$work/pip.out"

# 2. cmake --install with the default prefix, staged under DESTDIR.
prefix=$(sed -n 's/^CMAKE_INSTALL_PREFIX:PATH=//p' "$build/CMakeCache.txt")
DESTDIR="$work/stage" cmake --install "$build" > "$work/install.log"
pkg=$(dirname "$(find "$work/stage" -path '*/eg2d/__init__.py' | head -n 1)")
site=$(dirname "$pkg")
target=${site#"$work/stage"}
echo "cmake --install put the package in $target (prefix $prefix)"
"$python" -c "import sys; p = sys.argv[1]; sys.exit(0 if p in sys.path else 'not on sys.path: ' + p)" "$target"
(cd "$work" && env -u EG2D_LIBRARY PYTHONPATH="$site" "$python" -c "$check")
echo "python routes: 2 passed, 0 failed"
