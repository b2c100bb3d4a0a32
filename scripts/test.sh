#!/usr/bin/env bash
# Builds everything and runs every test (unit, golden, GUI under Xvfb), ending in ctest's summary.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
ctest --preset default -j2 "$@"
