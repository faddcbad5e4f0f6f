#!/usr/bin/env bash
# Installs the build tree to a scratch prefix and builds consumers against it:
# the swan example in C with pkg-config (shared and static) and as a CMake
# project using find_package(eg2d); a C++ program using eg2d.hpp; the Fortran
# swan with pkg-config eg2d-fortran and with find_package(eg2d COMPONENTS
# Fortran); and the Python package from the prefix, with no EG2D_LIBRARY.
# Usage: run.sh SOURCE_DIR BUILD_DIR [FORTRAN(ON|OFF) [PYTHON]]
set -euo pipefail
src=$1
build=$2
fortran=${3:-OFF}
python=${4:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix
passed=0

cmake --install "$build" --prefix "$prefix" > "$work/install.log"
libdir=$(dirname "$(find "$prefix" -name 'libeg2d.so.1' | head -n 1)")
export PKG_CONFIG_PATH=$libdir/pkgconfig

echo "== pkg-config: $(pkg-config --modversion eg2d), $(pkg-config --cflags --libs eg2d)"
cc -std=c99 -Wall -Wextra -Werror "$src/examples/c/swan.c" $(pkg-config --cflags --libs eg2d) \
   -Wl,-rpath,"$libdir" -o "$work/swan_pkgconfig"
"$work/swan_pkgconfig"
passed=$((passed + 1))
# The static library links with the private libraries pkg-config lists.
cc -std=c99 "$src/examples/c/swan.c" $(pkg-config --cflags eg2d) "$libdir/libeg2d.a" \
   $(pkg-config --libs-only-l --static eg2d | sed 's/-leg2d//') -o "$work/swan_static"
"$work/swan_static"
passed=$((passed + 1))

echo "== find_package(eg2d)"
cmake -S "$src/tests/install/consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$prefix" \
      -DEG2D_SWAN_SOURCE="$src/examples/c/swan.c" > "$work/consumer.log"
cmake --build "$work/consumer" > "$work/consumer-build.log"
"$work/consumer/swan_cmake"
passed=$((passed + 1))

echo "== C++: eg2d.hpp"
c++ -std=c++17 -Wall -Wextra -pedantic -Werror "$src/tests/install/consumer_hpp.cpp" \
    $(pkg-config --cflags --libs eg2d) -Wl,-rpath,"$libdir" -o "$work/hpp_consumer"
"$work/hpp_consumer"
passed=$((passed + 1))

if [ "$fortran" = ON ]; then
  echo "== Fortran: pkg-config eg2d-fortran: $(pkg-config --cflags --libs eg2d-fortran)"
  gfortran "$src/examples/fortran/swan.f90" $(pkg-config --cflags --libs eg2d-fortran) \
           -Wl,-rpath,"$libdir" -J "$work" -o "$work/swan_fortran_pkgconfig"
  "$work/swan_fortran_pkgconfig" | tee "$work/swan_fortran.out"
  grep -q "swan 65x65: centre node (0.510461, 0.286403)" "$work/swan_fortran.out"
  passed=$((passed + 1))
  echo "== Fortran: find_package(eg2d COMPONENTS Fortran)"
  cmake -S "$src/tests/install/consumer_fortran" -B "$work/consumer_fortran" -DCMAKE_PREFIX_PATH="$prefix" \
        -DEG2D_SWAN_SOURCE="$src/examples/fortran/swan.f90" > "$work/consumer_fortran.log"
  cmake --build "$work/consumer_fortran" > "$work/consumer_fortran-build.log"
  "$work/consumer_fortran/swan_fortran_cmake"
  passed=$((passed + 1))
fi

if [ -n "$python" ]; then
  pydir=$(dirname "$(dirname "$(find "$prefix" -path '*/eg2d/_location.py' | head -n 1)")")
  echo "== Python: the package in $pydir"
  (cd "$work" && unset EG2D_LIBRARY && PYTHONPATH="$pydir" PYTHONDONTWRITEBYTECODE=1 "$python" - "$prefix" <<'PY'
import sys
import numpy as np
import eg2d
from eg2d import _capi
prefix = sys.argv[1]
assert eg2d.__file__.startswith(prefix), eg2d.__file__
assert _capi.lib._name.startswith(prefix), _capi.lib._name  # the installed library, found via _location.py
n = 65
s = np.arange(n) / (n - 1)
with eg2d.Grid(n, n) as g:
    g.set_side(eg2d.SIDE_JMIN, s, 0 * s)
    g.set_side(eg2d.SIDE_IMAX, 1 + 2 * s - 2 * s * s, s)
    g.set_side(eg2d.SIDE_JMAX, s, 1 - 2 * s + 2 * s * s)
    g.set_side(eg2d.SIDE_IMIN, 0 * s, s)
    g.set_tolerance(1e-10)
    g.solve()
    x, y = g.get_coordinates()
print("python swan %dx%d from %s: centre node (%.6f, %.6f)" % (n, n, _capi.lib._name, x[32, 32], y[32, 32]))
assert (round(x[32, 32], 6), round(y[32, 32], 6)) == (0.510461, 0.286403)
PY
  )
  passed=$((passed + 1))
fi

# The optional CGNS plugin is installed next to the library, which finds it
# there (the core itself does not link libcgns).
if [ -f "$build/src/libeg2d_cgns.so" ]; then
  echo "== CGNS plugin from the installed library"
  test -f "$libdir/libeg2d_cgns.so"
  cat > "$work/cgns.c" <<'EOF_C'
#include <stdio.h>
#include "eg2d.h"
int main(int argc, char **argv) {
    eg2d_grid *g;
    double x[9] = {0, 1, 2, 0, 1, 2, 0, 1, 2}, y[9] = {0, 0, 0, 1, 1, 1, 2, 2, 2};
    int s = eg2d_create(3, 3, &g) || eg2d_set_coordinates(g, x, y) || eg2d_write(g, argv[1], EG2D_FORMAT_CGNS);
    if (s) printf("%s\n", eg2d_last_error(g));
    eg2d_destroy(g);
    return s != 0 || argc != 2;
}
EOF_C
  cc -std=c99 "$work/cgns.c" $(pkg-config --cflags --libs eg2d) -Wl,-rpath,"$libdir" -o "$work/cgns"
  (unset EG2D_PLUGIN_DIR; "$work/cgns" "$work/grid.cgns")
  test -s "$work/grid.cgns"
  passed=$((passed + 1))
fi
echo "install consumers: $passed passed, 0 failed"
