#!/usr/bin/env bash
# Posting speed side by side: our posts (Google Benchmark, tests/bench) and FreeCAD 0.20's
# linuxcnc_post on the same CL: a 1M-move program of lines and arcs, handed to FreeCAD as a path
# dump. Needs the peers: scripts/install-deps.sh --external. Prints medians; docs/benchmarks.md
# records them. Usage: scripts/bench-posts.sh [moves] [freecad runs]
set -euo pipefail
cd "$(dirname "$0")/.."
moves=${1:-1000000}
runs=${2:-3}
scripts/build.sh > /dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

build/tests/bench/camwb-bench-dump "$moves" "$work/bench.dump"
echo "bench-posts: $moves moves, $(wc -l < "$work/bench.dump") dump lines"

build/tests/bench/camwb_post_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
  --benchmark_filter="(Sinumerik828dToFile|LinuxCncToFile)/$moves/" 2>/dev/null | grep -E "median" || true

# End to end through the CLI: read the dump, post, write the file.
for post in sinumerik828d-emco linuxcnc; do
  start=$(date +%s.%N)
  build/app/cli/camwb-cli post "$work/bench.dump" --post "$post" -o "$work/out.nc" > /dev/null 2>&1
  end=$(date +%s.%N)
  echo "camwb-cli post (import + post + write) $post: $(echo "$end - $start" | bc) s"
done

if ! command -v freecadcmd > /dev/null; then
  echo "bench-posts: freecadcmd not found (scripts/install-deps.sh --external installs FreeCAD)"
  exit 0
fi
for i in $(seq 1 "$runs"); do
  CAMWB_BENCH_DUMP="$work/bench.dump" freecadcmd tests/bench/peers/freecad_linuxcnc_post.py 2>/dev/null |
    grep '^freecad-linuxcnc_post'
done
