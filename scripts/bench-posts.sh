#!/usr/bin/env bash
# Posting as a user runs it, side by side with FreeCAD 0.20: `camwb-cli post bench.dump --post
# <id> -o out` (read the dump, post, write the NC) against freecadcmd reading the same dump into
# Path.Commands, exporting them with its linuxcnc_post (or heidenhain_post, beside our
# heidenhain-itnc530) and writing the NC (tests/bench/peers/freecad_post.py): separate processes, the same input, each timed
# whole from outside by /usr/bin/time (CPU = user + sys, so that other work on a shared machine
# counts less), peak RSS beside it. The commands take turns, run after run, so that a machine
# whose speed drifts (a shared VM) slows both sides alike; each run's ratio is FreeCAD's CPU over
# ours in that run, and the script prints the medians of RUNS runs. Then the Google Benchmark
# rows: the post kernel alone and each importer alone. Needs the peers: scripts/install-deps.sh
# --external. docs/benchmarks.md records the figures.
# Usage: [RUNS=3] scripts/bench-posts.sh [moves ...]   (default: 200000 1000000)
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${RUNS:-3}
sizes=("$@")
if [ ${#sizes[@]} -eq 0 ]; then
  sizes=(200000 1000000)
fi
scripts/build.sh > /dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
bin=build/tests/bench
echo "bench-posts: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg) at the start, $runs runs each"

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2) }'; }

# once <key> <command...>: runs it once; appends "cpu wall rss_kb" to $work/<key>.
once() {
  local key=$1
  shift
  if ! /usr/bin/time -f "%e %U %S %M" -o "$work/time" "$@" > "$work/out" 2>&1; then
    echo "bench-posts: $key failed:" && cat "$work/out" && exit 1
  fi
  read -r wall user sys rss < "$work/time"
  echo "$(echo "$user + $sys" | bc) $wall $rss" >> "$work/$key"
}

# report <key> <label>: the median CPU, wall and peak memory of its runs.
report() {
  echo "$2: cpu $(cut -d' ' -f1 "$work/$1" | median) s (runs: $(cut -d' ' -f1 "$work/$1" | tr '\n' ' '))," \
       "wall $(cut -d' ' -f2 "$work/$1" | median) s, peak $(( $(cut -d' ' -f3 "$work/$1" | median | cut -d. -f1) / 1024 )) MB"
}

# ratio <key> [<peer key>]: the peer's CPU (FreeCAD's linuxcnc_post unless named) over <key>'s,
# run by run, and their median.
ratio() {
  local each peer=${2:-freecad}
  each=$(paste -d' ' <(cut -d' ' -f1 "$work/$peer") <(cut -d' ' -f1 "$work/$1") |
    awk '{ printf "%.1f\n", $1 / $2 }')
  echo "  $peer / $1, CPU: $(echo "$each" | median)x (runs: $(echo "$each" | tr '\n' ' '))"
}

freecad=0
command -v freecadcmd > /dev/null && freecad=1
[ $freecad = 1 ] || echo "bench-posts: freecadcmd not found (scripts/install-deps.sh --external installs FreeCAD)"

for moves in "${sizes[@]}"; do
  build/tests/bench/camwb-bench-dump "$moves" "$work/bench.dump"
  echo "== $moves moves: $(wc -l < "$work/bench.dump") dump lines, $(( $(stat -c %s "$work/bench.dump") / 1000000 )) MB"
  rm -f "$work/sinumerik828d-emco" "$work/linuxcnc" "$work/heidenhain-itnc530" "$work/import" \
        "$work/freecad" "$work/freecad-heidenhain"
  for _ in $(seq "$runs"); do
    for post in sinumerik828d-emco linuxcnc heidenhain-itnc530; do
      once "$post" build/app/cli/camwb-cli post "$work/bench.dump" --post "$post" -o "$work/out.nc"
    done
    once import "$bin/camwb_import_bench" --read "$work/bench.dump"
    if [ $freecad = 1 ]; then
      once freecad env CAMWB_BENCH_DUMP="$work/bench.dump" CAMWB_BENCH_OUT="$work/freecad.ngc" \
        freecadcmd tests/bench/peers/freecad_post.py
      grep '^freecad-' "$work/out" || true
      once freecad-heidenhain env CAMWB_BENCH_POST=heidenhain_post CAMWB_BENCH_DUMP="$work/bench.dump" \
        CAMWB_BENCH_OUT="$work/freecad.h" freecadcmd tests/bench/peers/freecad_post.py
      grep '^freecad-' "$work/out" || true
    fi
  done
  report sinumerik828d-emco "camwb-cli post --post sinumerik828d-emco (read, post, write)"
  report linuxcnc "camwb-cli post --post linuxcnc (read, post, write)"
  report heidenhain-itnc530 "camwb-cli post --post heidenhain-itnc530 (read, post, write)"
  report import "camwb_import_bench --read (the dump import alone)"
  if [ $freecad = 1 ]; then
    report freecad "freecadcmd: read the dump, linuxcnc_post export, write"
    ratio linuxcnc
    ratio sinumerik828d-emco
    report freecad-heidenhain "freecadcmd: read the dump, heidenhain_post export, write"
    ratio heidenhain-itnc530 freecad-heidenhain
  fi
done

# The kernel alone (no import, no process start) and each importer alone, in-process.
"$bin/camwb_post_bench" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
  --benchmark_filter="(Sinumerik828dToFile|LinuxCncToFile)/1000000/" 2>/dev/null | grep -E "median" || true
"$bin/camwb_import_bench" --benchmark_repetitions=3 --benchmark_report_aggregates_only=true \
  --benchmark_filter="/1000000" 2>/dev/null | grep -E "median" || true
