#!/usr/bin/env bash
# README command (1): installs what is missing, builds, and runs the main job on the bundled default scene
# scenes/town.obj: its statistics, its VTK file out/town.vtp, and the exact from-region visibility of all its
# triangles from a street-level view cell (out/visible.json with witnesses, out/visible.vtp coloured
# visible/hidden with the witness segments; open the .vtp files in ParaView).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${EXACTVIS_BUILD_DIR:-$root/build}"
bash "$root/scripts/with-root.sh" bash "$root/scripts/install-deps.sh"
bash "$root/scripts/build.sh" exactvis
mkdir -p "$root/out"
"$build/exactvis" info "$root/scenes/town.obj"
"$build/exactvis" export "$root/scenes/town.obj" -o "$root/out/town.vtp"
# A street-level cell (between the houses, 1 to 2 units above the ground), not inside a building.
cell=6,6,1,7,7,2
echo "deciding exactly which triangles of scenes/town.obj are visible from the view cell [$cell] ..."
start=$SECONDS
"$build/exactvis" visible "$root/scenes/town.obj" --cell "$cell" --triangles all \
  -o "$root/out/visible.json" --vtp "$root/out/visible.vtp"
echo "done in $((SECONDS - start)) s; witnesses in out/visible.json, scene coloured visible/hidden with the"
echo "witness segments and the cell in out/visible.vtp, the scene in out/town.vtp (open them in ParaView)"
