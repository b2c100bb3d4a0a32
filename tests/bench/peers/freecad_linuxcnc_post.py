# FreeCAD 0.20's linuxcnc_post on the benchmark program, side by side with ours
# (scripts/bench-posts.sh). Run with freecadcmd; the dump to post comes in CAMWB_BENCH_DUMP (a
# FreeCAD path dump written by camwb-bench-dump). Only export() is timed, as our benchmark times
# only posting: reading the dump into Path.Commands happens before the clock starts.
import os
import re
import sys
import time

import FreeCAD  # noqa: F401  (initialises FreeCAD's modules)
import Path

sys.path.append('/usr/share/freecad/Mod/Path')
from PathScripts.post import linuxcnc_post  # noqa: E402

COMMAND = re.compile(r'^Command (\S+) \[ (.*) \]$')

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
moves = sum(1 for c in commands if c.Name in ('G0', 'G1', 'G2', 'G3'))
lines = gcode.count('\n')
print('freecad-linuxcnc_post moves=%d lines=%d seconds=%.3f blocks_per_second=%.0f'
      % (moves, lines, seconds, lines / seconds))
