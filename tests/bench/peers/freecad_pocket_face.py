# FreeCAD 0.20's pocket on the pocket benchmark's face, side by side with ours
# (scripts/bench-pocket.sh). Run with freecadcmd; settings come from the environment:
#   CAMWB_POCKET_FACE     the face and parameters as JSON (written by camwb-pocket-face)
#   CAMWB_POCKET_PATTERN  offset (default) or zigzag
#   CAMWB_POCKET_MODE     levels (default) or sections, see below
#   CAMWB_POCKET_RUNS     timed runs after one warm-up run (default 3)
#   CAMWB_POCKET_LEVELS   step-down levels from the start depth (default: down to the JSON's finalZ)
# Both modes time FreeCAD's pocket engine, Path.Area (what its Pocket operations call), with the
# pocket parameters PathPocketBase sets, for every step-down level, then Path.fromShapes turning
# the pockets into the path (sorting, retracts, G1/G2/G3), as PathAreaOp._buildPathArea does:
#   levels:   the face placed at each level, Path.Area.makePocket per level (the engine alone);
#   sections: what the Pocket Shape operation does once it has its removal solid (the face
#             extruded from the final to the start depth): one Path.Area over the solid,
#             makeSections at the step-down heights (OCC sections, then a pocket per section).
# Building the face and the solid happen before the clock starts (our benchmark gets its region
# ready too). FreeCAD's operation objects need a Job and GUI-side setup, so they are not used.
# After the timed runs the script checks that FreeCAD did the work asked of it (makePocket takes
# its pocket parameters from its own keywords, not from setParams): the passes nearest the face's
# loops lie a tool radius from them, and the feed length per level times the stepover is about
# the face's area. A figure for the wrong work stops the script with an error.
import json
import math
import os
import statistics
import time

import FreeCAD
import Part
import Path

V = FreeCAD.Vector
PATTERNS = {'zigzag': 1, 'offset': 2}  # Path.Area PocketMode, as PathPocketBase maps them


def arc_midpoint(seg):
    cx, cy = seg['centre']
    sx, sy = seg['start']
    ex, ey = seg['end']
    a0 = math.atan2(sy - cy, sx - cx)
    sweep = math.atan2(ey - cy, ex - cx) - a0
    if seg['ccw']:
        sweep = sweep % (2 * math.pi) or 2 * math.pi
    else:
        sweep = -((-sweep) % (2 * math.pi) or 2 * math.pi)
    r = math.hypot(sx - cx, sy - cy)
    return V(cx + r * math.cos(a0 + sweep / 2), cy + r * math.sin(a0 + sweep / 2), 0)


def make_wire(loop):
    edges = []
    for seg in loop['segments']:
        start, end = V(*seg['start'], 0), V(*seg['end'], 0)
        if seg['kind'] == 'arc':
            edges.append(Part.Arc(start, arc_midpoint(seg), end).toShape())
        else:
            edges.append(Part.LineSegment(start, end).toShape())
    return Part.Wire(edges)


def feed_length_xy(path):
    """Length of the G1/G2/G3 moves projected on XY, in mm (arc centres relative, G17)."""
    x = y = 0.0
    total = 0.0
    counts = {'G0': 0, 'G1': 0, 'G2': 0, 'G3': 0}
    for c in path.Commands:
        p = c.Parameters
        nx, ny = p.get('X', x), p.get('Y', y)
        if c.Name in ('G1', 'G01'):
            total += math.hypot(nx - x, ny - y)
            counts['G1'] += 1
        elif c.Name in ('G2', 'G02', 'G3', 'G03'):
            cx, cy = x + p.get('I', 0.0), y + p.get('J', 0.0)
            a0 = math.atan2(y - cy, x - cx)
            sweep = math.atan2(ny - cy, nx - cx) - a0
            ccw = c.Name in ('G3', 'G03')
            sweep = sweep % (2 * math.pi) if ccw else (-sweep) % (2 * math.pi)
            if sweep < 1e-12:
                sweep = 2 * math.pi
            total += math.hypot(x - cx, y - cy) * sweep
            counts['G3' if ccw else 'G2'] += 1
        elif c.Name in ('G0', 'G00'):
            counts['G0'] += 1
        x, y = nx, ny
    return total, counts


def depths(start, final, step):
    """PathUtils.depth_params for equal steps: start - step, ..., final."""
    n = max(1, math.ceil((start - final) / step - 1e-9))
    return [start - (start - final) * (i + 1) / n for i in range(n)]


with open(os.environ['CAMWB_POCKET_FACE']) as f:
    spec = json.load(f)
pattern = os.environ.get('CAMWB_POCKET_PATTERN', 'offset')
runs = int(os.environ.get('CAMWB_POCKET_RUNS', '3'))
mode = os.environ.get('CAMWB_POCKET_MODE', 'levels')

wires = [make_wire(loop) for loop in spec['loops']]
face = Part.makeFace(wires, 'Part::FaceMakerBullseye')
if not face.isValid() or abs(face.Area - spec['areaMm2']) > 1e-6 * spec['areaMm2']:
    raise SystemExit('freecad-pocket: face invalid or area %.6f != %.6f' % (face.Area, spec['areaMm2']))

# As PathPocketShape builds its removal solid: the face a hair below the final depth, extruded
# up to the start depth.
buffer = 0.000001
start_z, final_z = spec['startZ'], spec['finalZ']
if os.environ.get('CAMWB_POCKET_LEVELS'):
    final_z = start_z - spec['stepDownMm'] * int(os.environ['CAMWB_POCKET_LEVELS'])
face.translate(V(0, 0, final_z - buffer))
solid = face.extrude(V(0, 0, start_z - final_z + buffer))
heights = depths(start_z, final_z, spec['stepDownMm'])
radius = spec['toolDiameterMm'] / 2

area_params = {
    'Fill': 0, 'Coplanar': 0, 'PocketMode': PATTERNS[pattern], 'SectionCount': -1, 'Angle': 0.0,
    'FromCenter': False, 'PocketStepover': spec['stepoverMm'], 'PocketExtraOffset': 0.0,
    'ToolRadius': radius, 'PocketLastStepover': 0.0, 'Accuracy': spec['toleranceMm'],
}
path_params = {
    'orientation': 1,  # climb, as ours
    'feedrate': spec['cuttingFeedMmPerMin'] / 60.0, 'feedrate_v': spec['plungeFeedMmPerMin'] / 60.0,
    'verbose': True, 'resume_height': spec['safeZ'], 'retraction': spec['clearanceZ'],
    'return_end': True, 'preamble': False,
}


def workplane(z):
    """PathUtils.makeWorkplane: a circle at the shape's lowest Z."""
    return Part.makeCircle(10, V(100, 75, z))


def pockets_by_sections():
    area = Path.Area()
    area.setPlane(workplane(solid.BoundBox.ZMin))
    area.add(solid)
    area.setParams(**area_params)
    sections = area.makeSections(mode=0, project=False, heights=heights)
    return [sec.getShape() for sec in sections]


def pockets_by_levels():
    shapes = []
    for z in heights:
        level = face.translated(V(0, 0, z - face.BoundBox.ZMin))
        area = Path.Area()
        area.setPlane(workplane(z))
        area.add(level)
        area.setParams(**area_params)
        # makePocket's keywords have their own defaults (ZigZagOffset, radius 1), not the area's.
        shapes.append(area.makePocket(mode=area_params['PocketMode'], tool_radius=radius,
                                      extra_offset=0.0, stepover=spec['stepoverMm'], last_stepover=0.0,
                                      from_center=False, angle=area_params['Angle']))
    return shapes


last_shapes = []


def pocket_once():
    t0, c0 = time.perf_counter(), time.process_time()
    shapes = pockets_by_sections() if mode == 'sections' else pockets_by_levels()
    t1, c1 = time.perf_counter(), time.process_time()
    path, _ = Path.fromShapes(shapes=shapes, **path_params)
    t2, c2 = time.perf_counter(), time.process_time()
    last_shapes[:] = shapes
    return path, len(shapes), (t1 - t0, t2 - t1, t2 - t0), (c1 - c0, c2 - c1, c2 - c0)


def check_same_work(first_pocket, path, levels):
    """The pocket has the tool radius and stepover asked for (see the top of this file)."""
    z = first_pocket.BoundBox.ZMin
    loops = Part.Compound(face.translated(V(0, 0, z - face.BoundBox.ZMin)).Wires)
    nearest = Part.Compound(first_pocket.Wires).distToShape(loops)[0]
    length, _ = feed_length_xy(path)
    coverage = length / levels * spec['stepoverMm'] / face.Area
    print('freecad-pocket check: nearest pass %.3f mm from the face (tool radius %.3f), feed per level x stepover '
          '/ face area %.2f' % (nearest, radius, coverage))
    if abs(nearest - radius) > 0.05 or not 0.6 < coverage < 1.4:
        print('freecad-pocket error: FreeCAD did not pocket with tool radius %.3f and stepover %.3f'
              % (radius, spec['stepoverMm']))
        raise SystemExit(1)


pocket_once()  # warm-up
walls, cpus = [], []
for run in range(runs):
    path, levels, (area_wall, path_wall, wall), (area_cpu, path_cpu, cpu) = pocket_once()
    walls.append(wall)
    cpus.append(cpu)
    length, counts = feed_length_xy(path)
    print('freecad-pocket pattern=%s mode=%s run=%d levels=%d area_cpu_s=%.3f fromshapes_cpu_s=%.3f cpu_s=%.3f '
          'wall_s=%.3f commands=%d G0=%d G1=%d G2=%d G3=%d feed_xy_m=%.3f'
          % (pattern, mode, run + 1, levels, area_cpu, path_cpu, cpu, wall, len(path.Commands), counts['G0'],
             counts['G1'], counts['G2'], counts['G3'], length / 1000))
check_same_work(last_shapes[0], path, levels)
print('freecad-pocket pattern=%s mode=%s median_cpu_s=%.3f median_wall_s=%.3f runs=%d'
      % (pattern, mode, statistics.median(cpus), statistics.median(walls), runs))
