#!/usr/bin/env bash
# The installed package works for a user: `cmake --install` the build tree into a temporary prefix, build
# examples/ against it as a separate CMake project, run each example, and import the installed Python
# module. Run by scripts/test.sh (so by CI) after the test suite. Usage: scripts/test-install.sh [BUILD_DIR]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-${EXACTVIS_BUILD_DIR:-$root/build}}"
jobs="${EXACTVIS_JOBS:-$(nproc 2>/dev/null || echo 2)}"
tmp="$(mktemp -d "${TMPDIR:-/tmp}/exactvis-install.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT
prefix="$tmp/prefix"

cmake --install "$build" --prefix "$prefix" >"$tmp/install.log"
test -f "$prefix/lib/cmake/exactvis/exactvis-config.cmake"
test -f "$prefix/include/exactvis/api/visible.hpp"
cmake -S "$root/examples" -B "$tmp/examples" -G Ninja -DCMAKE_PREFIX_PATH="$prefix" >"$tmp/configure.log"
cmake --build "$tmp/examples" -j "$jobs"

# Small scenes (seconds): a town of 200 triangles, 12 random triangles.
town="$tmp/town.obj"
small="$tmp/small.obj"
"$prefix/bin/exactvis" generate town -n 200 --seed 1 -o "$town" 2>/dev/null
"$prefix/bin/exactvis" generate random -n 12 --seed 3 -o "$small" 2>/dev/null
if "$tmp/examples/visible_from_cell" "$town" 6 6 1 7 7 >/dev/null 2>&1; then exit 1; fi  # usage: exit 2
"$tmp/examples/visible_from_cell" "$town" 6 6 1 7 7 2 | tail -n 1 | grep -E '^[0-9]+ of 200 triangles visible$'
"$tmp/examples/visual_events" "$small" | grep '^counts {"EEE":null,"EV":[0-9]*}$'
"$tmp/examples/complex_2d" | grep -E '^[0-9]+ free bitangents, [0-9]+ edges, [0-9]+ faces$'
"$tmp/examples/pvs_grid" "$town" 1 1 1 | grep -E '^cell 0: [0-9]+ of 200 triangles visible$'
"$tmp/examples/skeleton_counts" "$root/scenes/lamp_room.obj" floor ceiling | tail -n 1 | grep '^counts {"nodes":{"VV":[1-9]'
"$tmp/examples/shadow_mesh" "$root/scenes/lamp_room.obj" lamp | tail -n 1 | grep '^counts {"receivers":16,'

# The Python package from the prefix (when it was built).
site="$(find "$prefix" -type d -name site-packages | head -n 1)"
if [ -n "$site" ] && [ -d "$site/exactvis" ]; then
  PYTHONPATH="$site" /usr/bin/python3 -c '
import sys, exactvis
vis, wit = exactvis.visible(sys.argv[1], cell=(6, 6, 1, 7, 7, 2))
assert vis.shape == (200,) and wit.shape == (vis.sum(), 2, 3), (vis.shape, wit.shape)
print("installed Python module:", exactvis.__version__, int(vis.sum()), "of", vis.size, "visible")' "$town"
fi
echo "install + examples: OK"
