#!/usr/bin/env bash
# README command (1): installs what is missing, builds, and runs the main job on the bundled default scene
# scenes/town.obj: its statistics, then its VTK file out/town.vtp (open it in ParaView).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${EXACTVIS_BUILD_DIR:-$root/build}"
bash "$root/scripts/with-root.sh" bash "$root/scripts/install-deps.sh"
bash "$root/scripts/build.sh" exactvis
mkdir -p "$root/out"
"$build/exactvis" info "$root/scenes/town.obj"
"$build/exactvis" export "$root/scenes/town.obj" -o "$root/out/town.vtp"
