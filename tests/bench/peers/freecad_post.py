# A FreeCAD 0.20 post (CAMWB_BENCH_POST: linuxcnc_post, the default, or heidenhain_post) on the
# benchmark program, side by side with ours (scripts/bench-posts.sh). Run with freecadcmd; the
# dump to post comes in CAMWB_BENCH_DUMP (a FreeCAD path dump written by camwb-bench-dump). The
# whole command, as a user runs it: read the dump into Path.Commands, export() them with the post,
# write the NC to CAMWB_BENCH_OUT;
# the script's own clock splits the three (bench-posts.sh times the whole process from outside,
# as it times camwb-cli). Without CAMWB_BENCH_OUT the NC is not written (export() alone, as the
# kernel-only comparison times it).
import os
import re
import sys
import time

import importlib

import FreeCAD  # noqa: F401  (initialises FreeCAD's modules)
import Path

sys.path.append('/usr/share/freecad/Mod/Path')
POST = os.environ.get('CAMWB_BENCH_POST', 'linuxcnc_post')
post = importlib.import_module('PathScripts.post.' + POST)
if POST == 'heidenhain_post':  # it asks these modules which kind of operation it posts
    for module in ('PathToolController', 'PathProfileEdges', 'PathMillFace', 'PathHelix'):
        importlib.import_module('PathScripts.' + module)

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
    """What the posts' export() reads from a job's operation."""
    def __init__(self, path):
        self.Path = path
        self.Label = 'Benchmark'
        self.Name = 'Benchmark'
        self.Proxy = None  # heidenhain_post asks which kind of operation it is: none it knows


objects = [PathObject(Path.Path(commands))]
output = os.environ.get('CAMWB_BENCH_OUT')
start = time.time()
if POST == 'heidenhain_post':
    # It writes the file itself (no text returned): its export includes the write.
    post.export(objects, output or os.devnull, '--no-show-editor --no-warns')
    seconds = time.time() - start
    written = 0.0
    lines = sum(1 for _ in open(output)) if output else 0
else:
    gcode = post.export(objects, '-', '--no-show-editor')
    seconds = time.time() - start
    start = time.time()
    if output:
        with open(output, 'w') as out:
            out.write(gcode)
    written = time.time() - start
    lines = gcode.count('\n')
moves = sum(1 for c in commands if c.Name in ('G0', 'G1', 'G2', 'G3'))
print('freecad-%s moves=%d lines=%d read=%.3f seconds=%.3f write=%.3f blocks_per_second=%.0f'
      % (POST, moves, lines, read, seconds, written, lines / seconds))
