#!/usr/bin/env bash
# Builds everything and runs every test (unit, golden, GUI under Xvfb, and the round trips through
# peers such as LinuxCNC's rs274), ending in ctest's summary; then builds the kernels and the CLI
# once more with AddressSanitizer and UndefinedBehaviorSanitizer and runs the unit, golden and
# CLI tests again under them (any finding fails its test). The peers come from
# install-deps.sh --external; build.sh then finds everything present. Extra arguments go to both
# ctest runs. Exit status: 0 only when both runs pass.
set -uo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --external || exit 1
scripts/build.sh default || exit 1
status=0
ctest --preset default -j2 "$@" || status=1
echo "== sanitizer build (ASan + UBSan): unit, golden and CLI tests =="
if scripts/build.sh sanitize; then
  ctest --preset sanitize -j2 "$@" || status=1
else
  status=1
fi
exit $status
