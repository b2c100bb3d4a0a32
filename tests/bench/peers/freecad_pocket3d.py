# FreeCAD 0.20's 3D Pocket operation (PathScripts.PathPocket, "Path 3D Pocket") on the mould example,
# side by side with ours (scripts/bench-3d.sh). Run with freecadcmd; settings from the environment:
#   CAMWB_MOULD_STEP  the part (default resources/examples/example-mould.step)
#   CAMWB_3D_OUT      the G-code written by the last run (default: a temporary file)
#   CAMWB_3D_RUNS     timed runs after one cold run (default 3; 0: the cold run alone is timed)
#   CAMWB_3D_PATTERN  Offset (default) or ZigZag
#   CAMWB_3D_FINAL    the final depth (default 10, the floor; see FINAL)
# Each run is what a user does, headless: read the STEP, a Job on it (stock = the part's box), a
# 3D Pocket on the whole model (no faces picked: the cavity), flat end mill D10, stepover
# 50 %, step-down 2 mm from Z 30 to the floor at Z 10, offset pattern, 0.3 mm side stock
# (ExtraOffset; no bottom stock, see FINAL), doc.recompute(), then the linuxcnc post writes the file.
# It prints each phase's time and the medians; each run's path is checked to be the work asked
# (tool, levels, side stock at the +X wall), a wrong one stops it with status 1.
import os
import statistics
import sys
import tempfile
import time

import FreeCAD
import Part
import PathScripts.PathJob as PathJob
import PathScripts.PathPocket as PathPocket
from PathScripts.post import linuxcnc_post

STEP = os.environ.get('CAMWB_MOULD_STEP', 'resources/examples/example-mould.step')
OUT = os.environ.get('CAMWB_3D_OUT') or os.path.join(tempfile.mkdtemp(), 'pocket3d.ngc')
RUNS = int(os.environ.get('CAMWB_3D_RUNS', '3'))
PATTERN = os.environ.get('CAMWB_3D_PATTERN', 'Offset')
TOOL_D, STEPOVER_PCT, STEP_DOWN, SIDE_STOCK, TOP = 10.0, 50, 2.0, 0.3, 30.0
# FreeCAD 0.20's 3D Pocket has no bottom stock to leave. A final depth of 10.2 (the floor + 0.2)
# would stand for it, but then FreeCAD makes no pass below Z 12 at all ("Discard empty section"
# from Path.Area; 11.0 the same), leaving 2 mm on the floor: the final depth is the floor, Z 10.
FINAL = float(os.environ.get('CAMWB_3D_FINAL', '10'))


def log(*args):
    print(*args, file=sys.stderr)


def fail(message):
    """freecadcmd swallows SystemExit: say why and leave with status 1 ourselves."""
    log(message)
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(1)


def run_once(index):
    """One whole operation, checked; returns (seconds by phase, G-code lines written)."""
    times = {}
    start, cpu = time.perf_counter(), time.process_time()
    doc = FreeCAD.newDocument('mould%d' % index)
    model = doc.addObject('Part::Feature', 'Mould')
    model.Shape = Part.read(STEP)
    times['read'] = time.perf_counter() - start

    mark = time.perf_counter()
    job = PathJob.Create('Job', [model])
    for ext in ('ExtXneg', 'ExtXpos', 'ExtYneg', 'ExtYpos', 'ExtZneg', 'ExtZpos'):
        setattr(job.Stock, ext, 0)  # the stock is the part's box
    tc = job.Tools.Group[0]
    tc.Tool.Diameter = TOOL_D  # the default bit is an end mill (endmill.fcstd)
    tc.HorizFeed, tc.VertFeed, tc.SpindleSpeed = '600 mm/min', '150 mm/min', 3000
    doc.recompute()  # the job, its stock and tool
    times['job'] = time.perf_counter() - mark

    mark, mark_cpu = time.perf_counter(), time.process_time()
    op = PathPocket.Create('Pocket3D', parentJob=job)
    for name, value in (('StartDepth', TOP), ('StepDown', STEP_DOWN), ('FinalDepth', FINAL)):
        op.setExpression(name, None)  # the setup sheet's expressions would set them again
        setattr(op, name, value)
    op.StepOver = STEPOVER_PCT
    op.OffsetPattern = PATTERN
    op.ExtraOffset = SIDE_STOCK
    doc.recompute()  # the 3D pocket's own work: removal solid, sections, pockets, path
    times['op'] = time.perf_counter() - mark
    times['op_cpu'] = time.process_time() - mark_cpu

    mark = time.perf_counter()
    gcode = linuxcnc_post.export([tc, op], OUT, '--no-show-editor')
    times['post'] = time.perf_counter() - mark
    times['whole'] = time.perf_counter() - start
    times['whole_cpu'] = time.process_time() - cpu
    check(op)
    FreeCAD.closeDocument(doc.Name)
    return times, (gcode or '').count('\n')


def check(op):
    """Stops with an error if FreeCAD did not do the work asked (tool, levels, side stock)."""
    if abs(op.ToolController.Tool.Diameter.Value - TOOL_D) > 1e-9:
        fail('freecad-pocket3d: the tool is D%s, not D%s' % (op.ToolController.Tool.Diameter, TOOL_D))
    x = y = z = None
    levels, feeds, max_x = set(), 0, {}
    for c in op.Path.Commands:
        p = c.Parameters
        x, y, z = p.get('X', x), p.get('Y', y), p.get('Z', z)
        if c.Name in ('G1', 'G2', 'G3') and z is not None:
            feeds += 1
            levels.add(round(z, 4))
            if x is not None:
                max_x[round(z, 4)] = max(max_x.get(round(z, 4), -1e9), x)
    if not feeds:
        fail('freecad-pocket3d: the operation made no cutting moves')
    if abs(min(levels) - FINAL) > 1e-6 or abs(max(levels) - (TOP - STEP_DOWN)) > 1e-6:
        fail('freecad-pocket3d: the levels go from %s down to %s, not %s to %s' %
             (max(levels), min(levels), TOP - STEP_DOWN, FINAL))
    # The +X wall at level z: X 90 - (30 - z) tan 10; the tool's centre a radius and the stock inside.
    worst = max(x - (90 - (TOP - z) * 0.17632698 - TOOL_D / 2 - SIDE_STOCK) for z, x in max_x.items())
    log('freecad-pocket3d: check: %d feed moves, %d levels %s..%s, pass nearest the +X wall %.3f mm from '
        'wall - R - stock (negative: inside)' % (feeds, len(levels), min(levels), max(levels), worst))
    if worst > 0.05:
        fail('freecad-pocket3d: a pass lies outside the wall less tool radius and side stock')


log('freecad-pocket3d: %s, tool D%g, stepover %d %%, step-down %g, %s, side stock %g, %d runs' %
    (STEP, TOOL_D, STEPOVER_PCT, STEP_DOWN, PATTERN, SIDE_STOCK, RUNS))
results = []
for i in range(RUNS + 1):  # run 0 is cold (imports, the tool bit's shape file): timed alone with RUNS 0
    times, lines = run_once(i)
    log('freecad-pocket3d: run %d%s: ' % (i, ' (cold)' if i == 0 else '') +
        ', '.join('%s %.3f s' % kv for kv in times.items()) + ', %d G-code lines' % lines)
    if i or not RUNS:
        results.append(times)
medians = {key: statistics.median(r[key] for r in results) for key in ('whole', 'whole_cpu', 'op', 'op_cpu')}
print('freecad-pocket3d median_whole_s=%(whole).4f median_whole_cpu_s=%(whole_cpu).4f median_op_s=%(op).4f '
      'median_op_cpu_s=%(op_cpu).4f' % medians + ' runs=%d lines=%d out=%s' % (len(results), lines, OUT))
