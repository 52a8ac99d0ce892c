#!/usr/bin/env bash
# Installs exactvis's build and test dependencies on Debian 12 (bookworm). Idempotent: it only runs apt-get
# (and `apt-get update`) when a package is missing. Run as root (or through sudo).
set -euo pipefail

packages=(
  cmake ninja-build g++ ccache
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev libeigen3-dev
  libvtk9-dev libglm-dev libopenmesh-dev libtbb-dev libembree-dev
  nlohmann-json3-dev libcli11-dev libgtest-dev
  libzip-dev          # reading Quake 3 .pk3 archives (io/zip_archive)
  assimp-testmodels   # broken model files the bad-input tests use
  openmpi-bin libopenmpi-dev  # mpirun exactvis pvs (apps/pvs_run); MPI::MPI_C for Debian's VTK rendering targets
  xvfb libgl1-mesa-dri  # `shadows --png` without a display: Xvfb + Mesa software OpenGL (io/render_png)
  pybind11-dev python3-dev python3-numpy python3-pytest  # the Python module (python/) and its tests
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi

if [ "$(id -u)" -ne 0 ]; then
  echo "install-deps: missing packages: ${missing[*]}; run as root (sudo bash scripts/install-deps.sh)" >&2
  exit 1
fi

echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update
apt-get install -y --no-install-recommends "${missing[@]}"
