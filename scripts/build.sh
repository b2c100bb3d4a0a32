#!/usr/bin/env bash
# Installs missing packages, configures (Ninja, ccache) and builds everything into build/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
export CCACHE_DIR="${CCACHE_DIR:-$HOME/.cache/ccache}"
cmake --preset default
cmake --build --preset default
