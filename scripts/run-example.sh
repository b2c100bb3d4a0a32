#!/usr/bin/env bash
# Builds everything and opens the workbench on the bundled example job. Without a display it
# runs the same job through camwb-cli and says where the NC file went.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
job=resources/examples/example-block.camwb
if [[ -n "${DISPLAY:-}" || -n "${WAYLAND_DISPLAY:-}" ]]; then
  exec build/app/gui/camwb "$job" "$@"
fi
echo "run-example: no display; posting $job with camwb-cli"
build/app/cli/camwb-cli run "$job" -o build/example-block.mpf
echo "run-example: NC program written to $(pwd)/build/example-block.mpf"
