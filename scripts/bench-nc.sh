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

# One timed run of "$@": stdout to $work/$name.out (removed first, so that no run pays for deleting
# the last one's output), "wall cpu" appended to $work/$name.times. CPU = user + sys seconds.
run_once() {
  local name=$1
  shift
  rm -f "$work/$name.out" "$work/$name.trace"
  /usr/bin/time -f "%e %U %S" -o "$work/time.txt" "$@" < /dev/null > "$work/$name.out" 2> "$work/$name.err" || {
    echo "bench-nc: $name failed:" >&2
    tail -5 "$work/$name.err" >&2
    exit 1
  }
  awk '{printf "%s %.2f\n", $1, $2 + $3}' "$work/time.txt" >> "$work/$name.times"
}
# Runs "$@" $runs times after one warm-up run (file cache) and prints the runs.
timed() {
  local name=$1
  "${@:2}" > /dev/null 2>&1 < /dev/null || true
  : > "$work/$name.times"
  for _ in $(seq 1 "$runs"); do
    run_once "$@"
  done
  echo "$name runs (wall s, cpu s): $(tr '\n' ';' < "$work/$name.times") $(load)"
}
wall() { cut -d' ' -f1 "$work/$1.times" | median; }
cpu() { cut -d' ' -f2 "$work/$1.times" | median; }

# LinuxCNC's tool table in inches (no INI file), as tests/external writes it.
mkdir -p "$work/rs274"
echo "T1 P1 Z1.771653543307 D0.236220472441 ;" > "$work/rs274/tools.tbl"

# 1. The headline: both read the file, interpret and write one line per motion to a file. The
#    two alternate, run by run, so that the load of a shared machine weighs on both alike.
camwb=("$cli" nc trace "$work/bench.ngc" -o "$work/camwb.trace")
rs274=(env HOME="$work/rs274" rs274 -t "$work/rs274/tools.tbl" -g "$work/bench.ngc")
"${camwb[@]}" > /dev/null 2>&1 < /dev/null || true
"${rs274[@]}" > /dev/null 2>&1 < /dev/null || true
: > "$work/camwb.times"
: > "$work/rs274.times"
for _ in $(seq 1 "$runs"); do
  run_once camwb "${camwb[@]}"
  run_once rs274 "${rs274[@]}"
done
echo "camwb runs (wall s, cpu s): $(tr '\n' ';' < "$work/camwb.times")"
echo "rs274 runs (wall s, cpu s): $(tr '\n' ';' < "$work/rs274.times") $(load)"
echo "camwb-cli trace lines: $(wc -l < "$work/camwb.trace")"
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

# 3. Instructions per block, both sides (callgrind: the load does not change them), on ISO programs
#    of N and 2N blocks: per block at N, and per block added from N to 2N, which leaves out what
#    a process costs once (dynamic linking, start-up) on either side.
if [ "$callgrind_blocks" -gt 0 ] && command -v valgrind > /dev/null; then
  instructions() { valgrind --tool=callgrind --callgrind-out-file=/dev/null "$@" 2>&1 > /dev/null < /dev/null |
                     sed -n 's/.*Collected : *\([0-9]*\).*/\1/p'; }
  for n in "$callgrind_blocks" $((2 * callgrind_blocks)); do
    "$bench" --write-program "$work/cg$n.ngc" "$n" iso > /dev/null
    echo "$(wc -l < "$work/cg$n.ngc") $(instructions "$cli" nc trace "$work/cg$n.ngc" -o "$work/cg$n.trace")" \
         "$(HOME="$work/rs274" instructions rs274 -t "$work/rs274/tools.tbl" -g "$work/cg$n.ngc")" >> "$work/cg.txt"
  done
  awk 'NR == 1 {b = $1; c = $2; r = $3} NR == 2 {
    printf "callgrind, %d lines: camwb-cli nc trace -o %.0f instructions/block, rs274 %.0f, ratio %.1fx\n", b, c / b, r / b, r / c
    db = $1 - b; dc = ($2 - c) / db; dr = ($3 - r) / db
    printf "callgrind, per block from %d to %d lines: camwb-cli %.0f, rs274 %.0f, ratio %.1fx\n", b, $1, dc, dr, dr / dc
  }' "$work/cg.txt"
fi

# 4. Secondary: the interpreters in memory (Google Benchmark medians, no file, no process start).
"$bench" --benchmark_repetitions="$runs" --benchmark_report_aggregates_only=true 2> /dev/null |
  grep -E "_median" || true
echo "bench-nc: done, $(load)"
