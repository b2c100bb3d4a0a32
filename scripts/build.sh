#!/usr/bin/env bash
# Installs missing packages, configures (Ninja, ccache) and builds everything of a CMake preset:
# `default` into build/ (the argument's default), `sanitize` into build-sanitize/ (ASan + UBSan,
# no GUI).
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-default}"
scripts/install-deps.sh
export CCACHE_DIR="${CCACHE_DIR:-$HOME/.cache/ccache}"
cmake --preset "$preset"
cmake --build --preset "$preset"
