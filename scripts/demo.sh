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
"$build/exactvis" visible "$root/scenes/town.obj" --cell 0.5,0.5,1,2,2,2 --triangles all \
  -o "$root/out/visible.json" --vtp "$root/out/visible.vtp"
