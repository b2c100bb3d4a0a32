#!/usr/bin/env bash
# Posting as a user runs it, side by side with FreeCAD 0.20: `camwb-cli post bench.dump --post
# <id> -o out` (read the dump, post, write the NC) against freecadcmd reading the same dump into
# Path.Commands, exporting them with its linuxcnc_post and writing the NC
# (tests/bench/peers/freecad_linuxcnc_post.py): separate processes, the same input, each timed
# whole from outside by /usr/bin/time (CPU = user + sys, so that other work on a shared machine
# counts less), medians of RUNS runs, peak RSS beside them. Then the Google Benchmark rows: the
# post kernel alone and each importer alone. Needs the peers: scripts/install-deps.sh --external.
# Prints medians; docs/benchmarks.md records them.
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

# measure <label> <command...>: runs it $runs times; prints the median CPU, wall and peak memory.
measure() {
  local label=$1
  shift
  : > "$work/runs"
  for _ in $(seq "$runs"); do
    if ! /usr/bin/time -f "%e %U %S %M" -o "$work/time" "$@" > "$work/out" 2>&1; then
      echo "bench-posts: $label failed:" && cat "$work/out" && exit 1
    fi
    read -r wall user sys rss < "$work/time"
    echo "$(echo "$user + $sys" | bc) $wall $rss" >> "$work/runs"
  done
  echo "$label: cpu $(cut -d' ' -f1 "$work/runs" | median) s (runs: $(cut -d' ' -f1 "$work/runs" | tr '\n' ' '))," \
       "wall $(cut -d' ' -f2 "$work/runs" | median) s, peak $(( $(cut -d' ' -f3 "$work/runs" | median | cut -d. -f1) / 1024 )) MB"
  grep '^freecad-' "$work/out" || true
}

for moves in "${sizes[@]}"; do
  build/tests/bench/camwb-bench-dump "$moves" "$work/bench.dump"
  echo "== $moves moves: $(wc -l < "$work/bench.dump") dump lines, $(( $(stat -c %s "$work/bench.dump") / 1000000 )) MB"
  for post in sinumerik828d-emco linuxcnc; do
    measure "camwb-cli post --post $post (read, post, write)" \
      build/app/cli/camwb-cli post "$work/bench.dump" --post "$post" -o "$work/out.nc"
  done
  measure "camwb_import_bench --read (the dump import alone)" "$bin/camwb_import_bench" --read "$work/bench.dump"
  if command -v freecadcmd > /dev/null; then
    measure "freecadcmd: read the dump, linuxcnc_post export, write" \
      env CAMWB_BENCH_DUMP="$work/bench.dump" CAMWB_BENCH_OUT="$work/freecad.ngc" \
      freecadcmd tests/bench/peers/freecad_linuxcnc_post.py
  else
    echo "bench-posts: freecadcmd not found (scripts/install-deps.sh --external installs FreeCAD)"
  fi
done

# The kernel alone (no import, no process start) and each importer alone, in-process.
"$bin/camwb_post_bench" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
  --benchmark_filter="(Sinumerik828dToFile|LinuxCncToFile)/1000000/" 2>/dev/null | grep -E "median" || true
"$bin/camwb_import_bench" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
  --benchmark_filter="/1000000" 2>/dev/null | grep -E "median" || true
