#!/usr/bin/env bash
# Runs a command as root: directly when already root (fresh machines and containers often have no sudo),
# else through sudo.
set -euo pipefail
if [ "$(id -u)" -eq 0 ] || ! command -v sudo >/dev/null 2>&1; then
  exec "$@"
fi
exec sudo "$@"
