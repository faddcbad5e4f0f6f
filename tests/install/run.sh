#!/usr/bin/env bash
# Installs the build tree to a scratch prefix and builds the swan example
# against it twice: with pkg-config, and as a CMake project using
# find_package(eg2d). Usage: run.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
src=$1
build=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix

cmake --install "$build" --prefix "$prefix" > "$work/install.log"
libdir=$(dirname "$(find "$prefix" -name 'libeg2d.so.1' | head -n 1)")
export PKG_CONFIG_PATH=$libdir/pkgconfig

echo "== pkg-config: $(pkg-config --modversion eg2d), $(pkg-config --cflags --libs eg2d)"
cc -std=c99 -Wall -Wextra -Werror "$src/examples/c/swan.c" $(pkg-config --cflags --libs eg2d) \
   -Wl,-rpath,"$libdir" -o "$work/swan_pkgconfig"
"$work/swan_pkgconfig"
# The static library links with the private libraries pkg-config lists.
cc -std=c99 "$src/examples/c/swan.c" $(pkg-config --cflags eg2d) "$libdir/libeg2d.a" \
   $(pkg-config --libs-only-l --static eg2d | sed 's/-leg2d//') -o "$work/swan_static"
"$work/swan_static"

echo "== find_package(eg2d)"
cmake -S "$src/tests/install/consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$prefix" \
      -DEG2D_SWAN_SOURCE="$src/examples/c/swan.c" > "$work/consumer.log"
cmake --build "$work/consumer" > "$work/consumer-build.log"
"$work/consumer/swan_cmake"

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
fi
echo "install consumers: 3 passed, 0 failed"
