#!/usr/bin/env bash
# Tracing speed side by side: our plain ISO interpreter (Google Benchmark, tests/bench/NcTraceBench.cpp),
# `camwb-cli nc trace` end to end, and LinuxCNC 2.9's standalone interpreter `rs274` on the same file:
# a 1M-move program of lines and arcs as posts/linuxcnc.js writes it. rs274 runs as tests/external
# runs it (its own HOME, a tool table, stdin closed). Needs the peers: scripts/install-deps.sh --external.
# Prints every run, the medians (wall and CPU seconds) and the ratios; docs/benchmarks.md records them.
# Usage: scripts/bench-nc.sh [moves] [runs] [build dir]   (default 1000000 5 build)
set -euo pipefail
cd "$(dirname "$0")/.."
moves=${1:-1000000}
runs=${2:-5}
build=${3:-build}
if [ "$build" = build ]; then
  scripts/build.sh > /dev/null
fi
bench="$build/tests/bench/camwb_nc_bench"
cli="$build/app/cli/camwb-cli"
for tool in "$bench" "$cli"; do
  [ -x "$tool" ] || { echo "bench-nc: $tool not built" >&2; exit 1; }
done
command -v rs274 > /dev/null || { echo "bench-nc: rs274 not found (scripts/install-deps.sh --external)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$bench" --write-program "$work/bench.ngc" "$moves" > /dev/null
blocks=$(wc -l < "$work/bench.ngc")
echo "bench-nc: $moves moves, $blocks lines, $(du -h "$work/bench.ngc" | cut -f1); $(nproc) cores," \
     "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'); load $(cut -d' ' -f1-3 /proc/loadavg)"

# The median of the numbers on stdin.
median() { sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }

# Runs "$@" $runs times after one warm-up run (file cache), prints "wall cpu" per run to $1.times.
timed() {
  local name=$1
  shift
  "$@" > /dev/null 2>&1 || true
  : > "$work/$name.times"
  for _ in $(seq 1 "$runs"); do
    /usr/bin/time -f "%e %U %S" -o "$work/time.txt" "$@" > "$work/$name.out" 2> "$work/$name.err" || {
      echo "bench-nc: $name failed:" >&2
      tail -5 "$work/$name.err" >&2
      exit 1
    }
    awk '{printf "%s %.2f\n", $1, $2 + $3}' "$work/time.txt" >> "$work/$name.times"
  done
  echo "$name runs (wall s, cpu s): $(tr '\n' ';' < "$work/$name.times")"
}

# 1. The interpreter alone and into a recorder, in process (no file reading).
"$bench" --benchmark_repetitions="$runs" --benchmark_report_aggregates_only=true 2> /dev/null |
  grep -E "_median" || true

# 2. End to end: read the file, interpret, record, write the text trace (stdout to a file).
timed camwb "$cli" nc trace "$work/bench.ngc" --dialect iso
echo "camwb-cli trace lines: $(wc -l < "$work/camwb.out")"

# 3. LinuxCNC's rs274: canonical calls on stdout, its tool table in inches (no INI file).
mkdir -p "$work/rs274"
echo "T1 P1 Z1.771653543307 D0.236220472441 ;" > "$work/rs274/tools.tbl"
timed rs274 env HOME="$work/rs274" rs274 -t "$work/rs274/tools.tbl" -g "$work/bench.ngc" < /dev/null
echo "rs274 canonical lines: $(wc -l < "$work/rs274.out"); errors: $(grep -vc '^executing$' "$work/rs274.err" || true)"

camwb_wall=$(cut -d' ' -f1 "$work/camwb.times" | median)
camwb_cpu=$(cut -d' ' -f2 "$work/camwb.times" | median)
rs_wall=$(cut -d' ' -f1 "$work/rs274.times" | median)
rs_cpu=$(cut -d' ' -f2 "$work/rs274.times" | median)
awk -v b="$blocks" -v cw="$camwb_wall" -v cc="$camwb_cpu" -v rw="$rs_wall" -v rc="$rs_cpu" 'BEGIN {
  printf "median camwb-cli nc trace: %.2f s wall, %.2f s cpu, %.0f blocks/s (cpu)\n", cw, cc, b / cc
  printf "median rs274:              %.2f s wall, %.2f s cpu, %.0f blocks/s (cpu)\n", rw, rc, b / rc
  printf "ratio rs274 / camwb-cli:   %.1fx wall, %.1fx cpu\n", rw / cw, rc / cc
}'
