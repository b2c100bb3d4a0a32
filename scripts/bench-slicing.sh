#!/usr/bin/env bash
# Slicing speed (issue 16): ops::surface::sliceMesh of a part's 0.01 mm tessellation for a 100-level
# stack against OCCT's exact section (BRepAlgoAPI_Section) per level, the meshing alone, and a
# million-triangle sphere (tests/bench/SliceBench.cpp), then the largest distance between the two
# sections over the stack. Medians of CPU and wall time over the runs; the ratios are OCCT's
# median over ours. docs/benchmarks.md records the figures.
# Usage: scripts/bench-slicing.sh [runs] [build dir] [part.step]
#   (default 5, build, and the bench's own choice: example-mould.step where it exists, else the
#   five-axis example)
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-5}
build=${2:-build}
if [ -n "${3:-}" ]; then
  export CAMWB_SLICE_PART=$3
fi
if [ "$build" = build ]; then
  scripts/build.sh > /dev/null
fi
bench="$build/tests/bench/camwb_slice_bench"
[ -x "$bench" ] || { echo "bench-slicing: $bench not built" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

echo "bench-slicing: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//');" \
     "load $(cut -d' ' -f1-3 /proc/loadavg) before"
"$bench" --benchmark_repetitions="$runs" --benchmark_format=json > "$work/runs.json" 2> /dev/null
python3 - "$work/runs.json" <<'PY'
import json, sys
doc = json.load(open(sys.argv[1]))
scale = {'ms': 1e-3, 'us': 1e-6, 'ns': 1e-9, 's': 1.0}
rows = {}
for b in doc['benchmarks']:
    name = b['run_name'].split('/real_time')[0].split('/iterations')[0]
    if b.get('run_type') == 'iteration':
        rows.setdefault(name, {'cpu': [], 'wall': [], 'counters': b})
        rows[name]['cpu'].append(b['cpu_time'] * scale[b['time_unit']])
        rows[name]['wall'].append(b['real_time'] * scale[b['time_unit']])
median = lambda v: sorted(v)[len(v) // 2] if len(v) % 2 else sum(sorted(v)[len(v) // 2 - 1:len(v) // 2 + 1]) / 2
for name, r in rows.items():
    extra = ' '.join('%s=%g' % (k, r['counters'][k]) for k in ('triangles', 'loops') if k in r['counters'])
    print('%-26s median %.4f s cpu, %.4f s wall; runs (cpu s): %s  %s' % (
        name, median(r['cpu']), median(r['wall']), ' '.join('%.4f' % v for v in r['cpu']), extra))
ours, occt, mesh = rows['BM_SliceMesh'], rows['BM_OcctSection'], rows['BM_MeshPart']
for kind in ('cpu', 'wall'):
    print('ratio (%s): OCCT section / sliceMesh %.0fx; OCCT section / (meshing + sliceMesh) %.1fx' % (
        kind, median(occt[kind]) / median(ours[kind]), median(occt[kind]) / (median(mesh[kind]) + median(ours[kind]))))
PY
"$bench" --agreement
echo "bench-slicing: load $(cut -d' ' -f1-3 /proc/loadavg) after"
