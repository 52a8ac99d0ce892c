#!/usr/bin/env bash
# Configures (Release, Ninja) and builds exactvis in build/ (or $EXACTVIS_BUILD_DIR): everything (tests and
# benchmarks included), or only the targets given as arguments (e.g. `bash scripts/build.sh exactvis`).
# Uses all cores ($EXACTVIS_JOBS overrides).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${EXACTVIS_BUILD_DIR:-$root/build}"
jobs="${EXACTVIS_JOBS:-$(nproc 2>/dev/null || echo 2)}"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release
if [ $# -gt 0 ]; then
  cmake --build "$build" -j "$jobs" --target "$@"
else
  cmake --build "$build" -j "$jobs"
fi
