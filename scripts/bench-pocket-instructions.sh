#!/usr/bin/env bash
# Instruction counts of the pocket benchmark side by side (callgrind): independent of the load of
# a shared machine, where CPU times spread. Counts only the work both sides do for the pocket:
# ours inside ops::computePocket (camwb_pocket_bench --once: region to CL records), FreeCAD's
# inside Path::Area::makePocket and Path::Area::toPath (what Path.fromShapes runs), over the
# warm-up and one timed run of tests/bench/peers/freecad_pocket_face.py (so halved).
# Needs valgrind and FreeCAD (scripts/install-deps.sh --external). docs/benchmarks.md records them.
# Usage: scripts/bench-pocket-instructions.sh [build dir] [patterns] [levels]   (default build
#   "offset zigzag" 1). FreeCAD under callgrind takes several minutes per pattern.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
patterns=${2:-offset zigzag}
levels=${3:-1}
bench="$build/tests/bench/camwb_pocket_bench"
writer="$build/tests/bench/camwb-pocket-face"
for tool in "$bench" "$writer"; do
  [ -x "$tool" ] || { echo "bench-pocket-instructions: $tool not built" >&2; exit 1; }
done
command -v valgrind > /dev/null || { echo "bench-pocket-instructions: valgrind not found" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$writer" "$work/face.json" > /dev/null

# The "Collected" total of a callgrind run: the instructions inside the toggled functions.
collected() { grep -o 'Collected : [0-9]*' "$1" | awk '{print $3}'; }

for pattern in $patterns; do
  valgrind --tool=callgrind --callgrind-out-file=/dev/null --toggle-collect='camwb::ops::computePocket*' \
    "$bench" --once "$pattern" "$levels" > /dev/null 2> "$work/ours.log"
  ours=$(collected "$work/ours.log")
  echo "ours $pattern, $levels level(s): $ours instructions in computePocket"
  if ! command -v freecadcmd > /dev/null; then
    echo "bench-pocket-instructions: freecadcmd not found"
    continue
  fi
  CAMWB_POCKET_FACE="$work/face.json" CAMWB_POCKET_PATTERN="$pattern" CAMWB_POCKET_MODE=levels \
    CAMWB_POCKET_RUNS=1 CAMWB_POCKET_LEVELS="$levels" \
    valgrind --tool=callgrind --callgrind-out-file=/dev/null --toggle-collect='Path::Area::makePocket*' \
    --toggle-collect='Path::Area::toPath*' freecadcmd tests/bench/peers/freecad_pocket_face.py \
    > "$work/freecad.out" 2> "$work/freecad.log"
  grep '^freecad-pocket check' "$work/freecad.out" || true
  freecad=$(( $(collected "$work/freecad.log") / 2 ))
  awk -v p="$pattern" -v l="$levels" -v o="$ours" -v f="$freecad" 'BEGIN {
    printf "FreeCAD %s, %d level(s): %.0f instructions in makePocket + toPath per run; ratio %.1fx\n", p, l, f, f / o
  }'
done
