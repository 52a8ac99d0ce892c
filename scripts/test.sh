#!/usr/bin/env bash
# README command (2): installs what is missing, builds (Release, build/), runs the whole test suite
# (CTest, two tests at a time: C++ and Python), then builds examples/ against an install (test-install.sh).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${EXACTVIS_BUILD_DIR:-$root/build}"
bash "$root/scripts/with-root.sh" bash "$root/scripts/install-deps.sh"
bash "$root/scripts/build.sh"
cd "$build"
ctest --output-on-failure -j2
bash "$root/scripts/test-install.sh" "$build"
