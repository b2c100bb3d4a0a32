#!/usr/bin/env bash
# Pocket speed side by side (issue 4): our ops::computePocket (Google Benchmark,
# tests/bench/PocketBench.cpp) and FreeCAD 0.20's pocket engine Path.Area plus Path.fromShapes
# (tests/bench/peers/freecad_pocket_face.py under freecadcmd) on the same face: a 1000-segment
# wavy outline with 20 islands (camwb-pocket-face writes it as JSON), tool D6, stepover 1 mm,
# 10 levels. Both run at the same nice level, one after the other; medians of CPU and wall time.
# Needs FreeCAD: scripts/install-deps.sh --external. docs/benchmarks.md records the figures.
# Usage: scripts/bench-pocket.sh [runs] [build dir] [patterns] [freecad modes] [levels]
#   (default 3 build "offset zigzag" levels 10; modes: levels and/or sections, see the .py;
#   levels 1 compares one level's work: our operation computes the pattern once for all levels)
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-3}
build=${2:-build}
patterns=${3:-offset zigzag}
modes=${4:-levels}
levels=${5:-10}
if [ "$build" = build ]; then
  scripts/build.sh > /dev/null
fi
bench="$build/tests/bench/camwb_pocket_bench"
writer="$build/tests/bench/camwb-pocket-face"
for tool in "$bench" "$writer"; do
  [ -x "$tool" ] || { echo "bench-pocket: $tool not built" >&2; exit 1; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$writer" "$work/face.json"
echo "bench-pocket: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//');" \
     "load $(cut -d' ' -f1-3 /proc/loadavg) before"

for pattern in $patterns; do
  name=$([ "$pattern" = zigzag ] && echo BM_PocketZigZag || echo BM_PocketOffset)
  "$bench" --once "$pattern" "$levels"
  # Ours: Google Benchmark repetitions; the medians in seconds (real and CPU).
  "$bench" --benchmark_filter="^$name/$levels/real_time\$" --benchmark_repetitions="$runs" --benchmark_format=json \
    > "$work/ours-$pattern.json" 2> /dev/null
  python3 - "$work/ours-$pattern.json" > "$work/ours-$pattern.txt" <<'EOF'
import json, sys
runs = json.load(open(sys.argv[1]))['benchmarks']
median = next(b for b in runs if b.get('aggregate_name') == 'median')
scale = {'ms': 1e-3, 'us': 1e-6, 'ns': 1e-9, 's': 1.0}[median['time_unit']]
each = ' '.join('%.4f' % (b['cpu_time'] * scale) for b in runs if b.get('run_type') == 'iteration')
print('%.6f %.6f %s' % (median['cpu_time'] * scale, median['real_time'] * scale, each))
EOF
  read -r ours_cpu ours_wall _ < "$work/ours-$pattern.txt"
  echo "ours $pattern: median ${ours_cpu} s cpu, ${ours_wall} s wall; runs (cpu s): $(cut -d' ' -f3- "$work/ours-$pattern.txt")"

  if ! command -v freecadcmd > /dev/null; then
    echo "bench-pocket: freecadcmd not found (scripts/install-deps.sh --external installs FreeCAD)"
    continue
  fi
  for mode in $modes; do
    CAMWB_POCKET_FACE="$work/face.json" CAMWB_POCKET_PATTERN="$pattern" CAMWB_POCKET_MODE="$mode" \
      CAMWB_POCKET_RUNS="$runs" CAMWB_POCKET_LEVELS="$levels" freecadcmd tests/bench/peers/freecad_pocket_face.py 2> /dev/null |
      grep '^freecad-pocket' | tee "$work/freecad-$pattern-$mode.txt"
    fc_cpu=$(grep -o 'median_cpu_s=[0-9.]*' "$work/freecad-$pattern-$mode.txt" | cut -d= -f2)
    fc_wall=$(grep -o 'median_wall_s=[0-9.]*' "$work/freecad-$pattern-$mode.txt" | cut -d= -f2)
    awk -v p="$pattern" -v m="$mode" -v l="$levels" -v oc="$ours_cpu" -v ow="$ours_wall" -v fc="$fc_cpu" -v fw="$fc_wall" 'BEGIN {
      printf "ratio FreeCAD (%s) / ours, %s, %d levels: %.1fx cpu, %.1fx wall\n", m, p, l, fc / oc, fw / ow
    }'
  done
done
echo "bench-pocket: load $(cut -d' ' -f1-3 /proc/loadavg) after"
