# FreeCAD 0.20's linuxcnc_post on the benchmark program, side by side with ours
# (scripts/bench-posts.sh). Run with freecadcmd; the dump to post comes in CAMWB_BENCH_DUMP (a
# FreeCAD path dump written by camwb-bench-dump). The whole command, as a user runs it: read the
# dump into Path.Commands, export() them with linuxcnc_post, write the NC to CAMWB_BENCH_OUT;
# the script's own clock splits the three (bench-posts.sh times the whole process from outside,
# as it times camwb-cli). Without CAMWB_BENCH_OUT the NC is not written (export() alone, as the
# kernel-only comparison times it).
import os
import re
import sys
import time

import FreeCAD  # noqa: F401  (initialises FreeCAD's modules)
import Path

sys.path.append('/usr/share/freecad/Mod/Path')
from PathScripts.post import linuxcnc_post  # noqa: E402

COMMAND = re.compile(r'^Command (\S+) \[ (.*) \]$')

start = time.time()
commands = []
with open(os.environ['CAMWB_BENCH_DUMP']) as dump:
    for line in dump:
        match = COMMAND.match(line.strip())
        if not match:
            continue
        params = {}
        for word in match.group(2).split():
            key, value = word.split(':')
            params[key] = float(value)
        commands.append(Path.Command(match.group(1), params))
read = time.time() - start


class PathObject:
    """What linuxcnc_post.export reads from a job's operation."""
    def __init__(self, path):
        self.Path = path
        self.Label = 'Benchmark'
        self.Name = 'Benchmark'


objects = [PathObject(Path.Path(commands))]
start = time.time()
gcode = linuxcnc_post.export(objects, '-', '--no-show-editor')
seconds = time.time() - start
start = time.time()
output = os.environ.get('CAMWB_BENCH_OUT')
if output:
    with open(output, 'w') as out:
        out.write(gcode)
written = time.time() - start
moves = sum(1 for c in commands if c.Name in ('G0', 'G1', 'G2', 'G3'))
lines = gcode.count('\n')
print('freecad-linuxcnc_post moves=%d lines=%d read=%.3f seconds=%.3f write=%.3f blocks_per_second=%.0f'
      % (moves, lines, read, seconds, written, lines / seconds))
