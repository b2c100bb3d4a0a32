#!/usr/bin/env bash
# Builds everything and runs every test (unit, golden, GUI under Xvfb, and the round trips through
# peers such as LinuxCNC's rs274), ending in ctest's summary. The peers come from
# install-deps.sh --external; build.sh then finds everything present.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --external
scripts/build.sh
ctest --preset default -j2 "$@"
