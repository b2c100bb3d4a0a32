#!/usr/bin/env bash
# 3D pocket roughing side by side with FreeCAD 0.20 (issue 16): the whole operation as a user runs
# it, from the part to the written program, on the mould example (resources/examples/example-mould.step),
# flat end mill D10, stepover 50 %, step-down 2 mm, offset pattern, 0.3 mm side stock.
#   ours:    CAMWB_3D_OURS, by default `camwb-cli run resources/examples/example-mould.camwb -o …`
#            from CAMWB_3D_BUILD (default build-release): read the job and the STEP, compute, post;
#   FreeCAD: freecadcmd tests/bench/peers/freecad_pocket3d.py with CAMWB_3D_RUNS=0: read the STEP,
#            Job, 3D Pocket, doc.recompute(), linuxcnc post (see the .py for what it cannot match).
# Separate processes, each timed whole from outside by /usr/bin/time (CPU = user + sys, so other
# work on a shared machine counts less), taking turns run after run; medians of RUNS runs and the
# run-by-run ratio. Then FreeCAD's in-process figures after a cold run (the operation alone).
# Usage: [RUNS=5] [CAMWB_3D_BUILD=dir] [CAMWB_3D_OURS='command'] scripts/bench-3d.sh
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${RUNS:-5}
build=${CAMWB_3D_BUILD:-build-release}
# The same work as FreeCAD: the roughing alone, no bottom stock (FreeCAD has none).
job=${CAMWB_3D_JOB:-tests/bench/data/mould-rough.camwb}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# ---- ours (the camwb row): the command the lead's job runs; empty when it cannot run here yet.
ours=${CAMWB_3D_OURS:-}
if [ -z "$ours" ]; then
  if [ -x "$build/app/cli/camwb-cli" ] && [ -f "$job" ]; then
    ours="$build/app/cli/camwb-cli run $job -o $work/ours.mpf"
  else
    echo "bench-3d: ours skipped: needs $build/app/cli/camwb-cli and $job (or set CAMWB_3D_OURS)"
  fi
fi
command -v freecadcmd > /dev/null ||
  { echo "bench-3d: freecadcmd not found (scripts/install-deps.sh --external installs FreeCAD)"; exit 1; }
echo "bench-3d: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), load" \
     "$(cut -d' ' -f1-3 /proc/loadavg) at the start, $runs runs each"

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2) }'; }

# once <key> <command...>: runs it once; appends "cpu wall rss_kb" to $work/<key>.
once() {
  local key=$1
  shift
  if ! /usr/bin/time -f "%e %U %S %M" -o "$work/time" "$@" > "$work/out" 2>&1; then
    echo "bench-3d: $key failed:" && tail -20 "$work/out" && exit 1
  fi
  read -r wall user sys rss < "$work/time"
  echo "$(echo "$user + $sys" | bc) $wall $rss" >> "$work/$key"
}

report() {
  echo "$2: cpu $(cut -d' ' -f1 "$work/$1" | median) s (runs: $(cut -d' ' -f1 "$work/$1" | tr '\n' ' '))," \
       "wall $(cut -d' ' -f2 "$work/$1" | median) s, peak $(( $(cut -d' ' -f3 "$work/$1" | median | cut -d. -f1) / 1024 )) MB"
}

for _ in $(seq "$runs"); do
  # shellcheck disable=SC2086  # the command is words on purpose
  [ -z "$ours" ] || once ours $ours
  once freecad env CAMWB_3D_RUNS=0 CAMWB_3D_OUT="$work/freecad.ngc" freecadcmd tests/bench/peers/freecad_pocket3d.py
done
[ -z "$ours" ] || report ours "ours ($ours): read, 3D pocket, post, write"
report freecad "freecadcmd freecad_pocket3d.py (start, read, Job, 3D Pocket, post, write)"
grep -E '^freecad-pocket3d: (check|run)' "$work/out" | sed 's/^/  /'
if [ -n "$ours" ]; then
  each=$(paste -d' ' <(cut -d' ' -f1 "$work/freecad") <(cut -d' ' -f1 "$work/ours") | awk '{ printf "%.1f\n", $1 / $2 }')
  echo "  FreeCAD / ours, CPU: $(echo "$each" | median)x (runs: $(echo "$each" | tr '\n' ' '))"
fi

# FreeCAD in one process after a cold run: the 3D Pocket's recompute alone (median_op_*) and the
# whole operation without the process start and imports (median_whole_*), wall and CPU.
CAMWB_3D_RUNS="$runs" CAMWB_3D_OUT="$work/freecad.ngc" freecadcmd tests/bench/peers/freecad_pocket3d.py 2> "$work/err" |
  grep '^freecad-pocket3d' || { tail -20 "$work/err"; exit 1; }
echo "bench-3d: load $(cut -d' ' -f1-3 /proc/loadavg) at the end"
