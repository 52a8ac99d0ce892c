#!/usr/bin/env bash
# Configures (Release, Ninja) and builds exactvis, its tests and benchmarks in build/ (or $EXACTVIS_BUILD_DIR).
# Uses both cores by default ($EXACTVIS_JOBS overrides).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${EXACTVIS_BUILD_DIR:-$root/build}"
jobs="${EXACTVIS_JOBS:-$(nproc 2>/dev/null || echo 2)}"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j "$jobs"
