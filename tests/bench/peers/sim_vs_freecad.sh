#!/usr/bin/env bash
# The simulator's headline figure (issue 14): `camwb-cli sim` against FreeCAD 0.20's Path simulator
# (freecad_sim_gcode.py under freecadcmd), whole command against whole command, on the same
# LinuxCNC G-code, stock box, flat tools and resolution, each writing the cut stock as STL.
# Programs: the example job posted with the linuxcnc post, and the benchmark program
# (camwb-bench-dump, MOVES records) posted the same way. Times with hyperfine, then prints the
# volume of each side's STL (stl_volume.py). Usage, from the repository root after a build:
#   tests/bench/peers/sim_vs_freecad.sh [build dir] [work dir]     (RUNS=10 MOVES=20000 RESOLUTIONS="0.1 0.2")
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
work=${2:-/tmp/camwb-simbench}
runs=${RUNS:-10}
moves=${MOVES:-20000}
resolutions=${RESOLUTIONS:-"0.1 0.2"}
cli=$build/app/cli/camwb-cli
peer=$here/freecad_sim_gcode.py
mkdir -p "$work"
cd "$work"

# The example job's tools (resources/examples/example-block.camwb: T1 flat D10, T2 flat D6,
# T3 drill D5), all flat on both sides; the benchmark program's one tool as a D6 flat end mill.
"$cli" post "$root/resources/examples/example-block.camwb" --post linuxcnc -o example.ngc
printf 'T1 P1 D10 Z40\nT2 P2 D6 Z40\nT3 P3 D5 Z40\n' >example.tbl
"$build/tests/bench/camwb-bench-dump" "$moves" "bench$moves.dump"
"$cli" post "bench$moves.dump" --post linuxcnc -o "bench$moves.ngc"
printf 'T1 P1 D6 Z40\n' >bench.tbl

# program, tool table, stock box: the example job's box, and one around the benchmark program.
cases=("example.ngc example.tbl -2,-2,0,92,62,16" "bench$moves.ngc bench.tbl -4,-8,0,76,4,3")

echo "== $(date -u '+%F %T') UTC; $(uptime); $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores"
for res in $resolutions; do
    for c in "${cases[@]}"; do
        read -r prog tbl stock <<<"$c"
        name=${prog%.ngc}-$res
        export CAMWB_SIM_GCODE=$prog CAMWB_SIM_TOOLS=$tbl CAMWB_SIM_STOCK=$stock CAMWB_SIM_RES=$res
        export CAMWB_SIM_STL=$name-freecad.stl
        # The last two commands are the breakdown, not the headline: ours without writing the STL,
        # and freecadcmd starting and importing the modules the peer uses, with no simulation.
        hyperfine --warmup 1 --runs "$runs" --export-json "$name.json" \
            -n "camwb-cli sim $prog @$res" "$cli sim $prog --stock $stock --tool-table $tbl --resolution $res --stl $name-camwb.stl" \
            -n "freecad PathSim $prog @$res" "freecadcmd $peer" \
            -n "(camwb-cli sim without --stl)" "$cli sim $prog --stock $stock --tool-table $tbl --resolution $res" \
            -n "(freecadcmd start + imports)" "freecadcmd $here/freecad_imports_only.py"
        python3 "$here/stl_volume.py" "$name-camwb.stl" "$name-freecad.stl"
        echo "stock box volume: camwb $(python3 -c "b=[float(v) for v in '$stock'.split(',')]; print('%.1f' % ((b[3]-b[0])*(b[4]-b[1])*(b[5]-b[2])))"); FreeCAD's grid is one cell longer each way ($res mm)"
    done
done
echo "== $(uptime)"
echo "== medians (s): camwb, FreeCAD, FreeCAD/camwb; camwb without --stl, freecadcmd start + imports"
for json in example-*.json "bench$moves"-*.json; do
    python3 -c "import json, sys
r = [x['median'] for x in json.load(open(sys.argv[1]))['results']]
print('%-24s %7.3f %7.3f %6.2fx   %7.3f %7.3f' % (sys.argv[1], r[0], r[1], r[1] / r[0], r[2], r[3]))" "$json"
done
