#!/usr/bin/env bash
# Reading NC back, like for like: `camwb-cli nc trace file.ngc -o trace.txt` against LinuxCNC 2.9's
# standalone interpreter `rs274 -t tools.tbl -g file.ngc > out`, each in its own process on the same
# 1M-move ISO program (lines and arcs as posts/linuxcnc.js writes them): both read the file,
# interpret it and write one line per canonical motion to a file. rs274 runs as tests/external runs
# it (its own HOME, a tool table, stdin closed). Then `camwb-cli nc trace` end to end on the
# SINUMERIK and Heidenhain programs of tests/bench/NcBenchPrograms.h, and the in-memory Google
# Benchmark figures of camwb_nc_bench (secondary). Needs the peers: scripts/install-deps.sh --external.
# Prints every run (wall s, CPU s = user + sys), the medians, the ratios and the machine's load;
# with CALLGRIND_BLOCKS > 0 (default 100000) also instructions per block of both sides on an ISO
# program of that many blocks (valgrind --tool=callgrind), which the load of a shared machine does
# not change. docs/benchmarks.md records the figures.
# Usage: scripts/bench-nc.sh [blocks] [runs] [build dir]   (default 1000000 3 build)
set -euo pipefail
cd "$(dirname "$0")/.."
blocks=${1:-1000000}
runs=${2:-3}
build=${3:-build}
callgrind_blocks=${CALLGRIND_BLOCKS:-100000}
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

load() { echo "load $(cut -d' ' -f1-3 /proc/loadavg)"; }
echo "bench-nc: $blocks blocks, $runs runs each; $(nproc) cores," \
     "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'); $(load)"

# The programs: name, file.
programs="iso:bench.ngc sinumerik:bench.mpf sinumerik-loops:loops.mpf heidenhain:bench.h heidenhain-labels:labels.h"
for entry in $programs; do
  said=$("$bench" --write-program "$work/${entry#*:}" "$blocks" "${entry%%:*}")
  echo "program ${entry%%:*}: $said, $(du -h "$work/${entry#*:}" | cut -f1)"
  echo "$said" | sed -n 's/.* \([0-9]*\) blocks executed.*/\1/p' > "$work/${entry%%:*}.blocks"
done

# The median of the numbers on stdin.
median() { sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }

# Runs "$@" $runs times after one warm-up run (file cache), stdout to $work/$1.out, and prints
# "wall cpu" per run to $work/$1.times.
timed() {
  local name=$1
  shift
  "$@" > /dev/null 2>&1 || true
  : > "$work/$name.times"
  for _ in $(seq 1 "$runs"); do
    /usr/bin/time -f "%e %U %S" -o "$work/time.txt" "$@" < /dev/null > "$work/$name.out" 2> "$work/$name.err" || {
      echo "bench-nc: $name failed:" >&2
      tail -5 "$work/$name.err" >&2
      exit 1
    }
    awk '{printf "%s %.2f\n", $1, $2 + $3}' "$work/time.txt" >> "$work/$name.times"
  done
  echo "$name runs (wall s, cpu s): $(tr '\n' ';' < "$work/$name.times") $(load)"
}
wall() { cut -d' ' -f1 "$work/$1.times" | median; }
cpu() { cut -d' ' -f2 "$work/$1.times" | median; }

# LinuxCNC's tool table in inches (no INI file), as tests/external writes it.
mkdir -p "$work/rs274"
echo "T1 P1 Z1.771653543307 D0.236220472441 ;" > "$work/rs274/tools.tbl"

# 1. The headline: both read the file, interpret and write one line per motion to a file.
timed camwb "$cli" nc trace "$work/bench.ngc" -o "$work/trace.txt"
echo "camwb-cli trace lines: $(wc -l < "$work/trace.txt")"
timed rs274 env HOME="$work/rs274" rs274 -t "$work/rs274/tools.tbl" -g "$work/bench.ngc"
echo "rs274 canonical lines: $(wc -l < "$work/rs274.out"); errors: $(grep -vc '^executing$' "$work/rs274.err" || true)"
lines=$(wc -l < "$work/bench.ngc")
awk -v b="$lines" -v cw="$(wall camwb)" -v cc="$(cpu camwb)" -v rw="$(wall rs274)" -v rc="$(cpu rs274)" 'BEGIN {
  printf "median camwb-cli nc trace -o: %.2f s wall, %.2f s cpu, %.0f blocks/s (cpu)\n", cw, cc, b / cc
  printf "median rs274 > file:          %.2f s wall, %.2f s cpu, %.0f blocks/s (cpu)\n", rw, rc, b / rc
  printf "ratio rs274 / camwb-cli:      %.1fx wall, %.1fx cpu\n", rw / cw, rc / cc
}'

# 2. The other dialects end to end, per block executed (the loop programs execute far more blocks
#    than they have lines: camwb_nc_bench --write-program says how many).
for entry in $programs; do
  name=${entry%%:*}
  [ "$name" = iso ] && continue
  timed "$name" "$cli" nc trace "$work/${entry#*:}" -o "$work/$name.trace"
  awk -v n="$name" -v w="$(wall "$name")" -v c="$(cpu "$name")" -v b="$(cat "$work/$name.blocks")" \
      -v t="$(wc -l < "$work/$name.trace")" 'BEGIN {
    printf "median camwb-cli nc trace %s: %.2f s wall, %.2f s cpu, %.0f blocks/s (cpu), %d trace lines\n", n, w, c, b / c, t
  }'
done

# 3. Instructions per block on a smaller program, both sides (callgrind; the load does not change them).
if [ "$callgrind_blocks" -gt 0 ] && command -v valgrind > /dev/null; then
  "$bench" --write-program "$work/small.ngc" "$callgrind_blocks" iso > /dev/null
  small=$(wc -l < "$work/small.ngc")
  instructions() { valgrind --tool=callgrind --callgrind-out-file="$work/cg.out" "$@" 2>&1 > /dev/null < /dev/null |
                     sed -n 's/.*Collected : *\([0-9]*\).*/\1/p'; }
  ci=$(instructions "$cli" nc trace "$work/small.ngc" -o "$work/small.trace")
  ri=$(HOME="$work/rs274" instructions rs274 -t "$work/rs274/tools.tbl" -g "$work/small.ngc")
  awk -v b="$small" -v c="$ci" -v r="$ri" 'BEGIN {
    printf "callgrind, %d lines: camwb-cli nc trace %.0f instructions/block, rs274 %.0f, ratio %.1fx\n", b, c / b, r / b, r / c
  }'
fi

# 4. Secondary: the interpreters in memory (Google Benchmark medians, no file, no process start).
"$bench" --benchmark_repetitions="$runs" --benchmark_report_aggregates_only=true 2> /dev/null |
  grep -E "_median" || true
echo "bench-nc: done, $(load)"
