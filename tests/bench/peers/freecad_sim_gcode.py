# FreeCAD 0.20's Path simulator run headless on a G-code file, whole command against whole command
# with `camwb-cli sim prog.ngc --stock ... --tool-table ... --resolution R --stl out.stl`.
# It does what PathSimulatorGui.PerformCutVoxel does for a user, without the GUI: each motion
# command to PathSimulator.PathSim.ApplyCommand, G2/G3 split into G1 chords with the GUI's own
# count (ceil(sqrt(r / resolution * angle^2))), G81/G82/G83 expanded as the GUI does (G0 to R on
# the first hole, G0 over the hole at R, G1 down to Z, G1 back up to R; a G98 block then goes back
# to the Z before the cycle, which the GUI leaves out but the machine does), the tool shape set
# at each M6 from the tool table (flat cylinders, as the other side reads the same table), and
# the result mesh (outer and inner, joined as the GUI's RemoveInnerMaterial does) written as STL.
#
# Why not Path.Path().setFromGCode: FreeCAD's parser folds a modal line ("Z25.000" after a G0
# line, a hole "X8 Y52" after G83) into the command before it, losing moves, and drops T words;
# a line-by-line reader with modal state is what reads LinuxCNC G-code faithfully.
#
# Inputs (freecadcmd takes no script arguments, so they come in the environment):
#   CAMWB_SIM_GCODE  the G-code file (G17, G21, G90 and G91.1 only; anything else is an error)
#   CAMWB_SIM_TOOLS  LinuxCNC tool table (T<n> P<pocket> D<diameter> Z<length>)
#   CAMWB_SIM_STOCK  xmin,ymin,zmin,xmax,ymax,zmax   CAMWB_SIM_RES  resolution in mm (0.1)
#   CAMWB_SIM_STL    where the cut stock goes (binary STL)
import math
import os
import re
import sys
import time

import FreeCAD
import Mesh
import Part
import Path
import PathSimulator

WORD = re.compile(r'([A-Z])\s*([-+]?[0-9]*\.?[0-9]+)')
COMMENT = re.compile(r'\([^)]*\)|;.*$')
MOTION = {'G0', 'G1', 'G2', 'G3', 'G80', 'G81', 'G82', 'G83'}
IGNORED = {'G17', 'G21', 'G90', 'G91.1', 'G94', 'G40', 'G49', 'G43', 'G54', 'G64', 'G61', 'G98', 'G99'}


def fail(where, message):
    sys.stderr.write('freecad_sim_gcode: %s: %s\n' % (where, message))
    sys.exit(1)


def read_tool_table(path):
    tools = {}
    with open(path) as table:
        for number, line in enumerate(table, 1):
            words = dict((k, float(v)) for k, v in WORD.findall(line.split(';')[0].upper()))
            if 'T' in words:
                if 'D' not in words:
                    fail('%s:%d' % (path, number), 'tool without D')
                tools[int(words['T'])] = (words['D'], words.get('Z', 0.0))
    return tools


def flat_tool(diameter, length):
    return Part.makeCylinder(diameter / 2, max(length, diameter))


class Reader:
    """Reads the program line by line into ('T', number) and ('C', Path.Command) steps."""

    def __init__(self, top):
        self.pos = [0.0, 0.0, top]  # where the GUI starts the tool: (0, 0, stock top)
        self.motion = None
        self.retract_r = False  # G99
        self.cycle = {}
        self.first_drill = True
        self.pending_tool = None
        self.steps = []

    def line(self, text, where):
        text = COMMENT.sub('', text.upper()).strip()
        if not text or text.startswith('%'):
            return
        words = WORD.findall(text)
        if ''.join(k + v for k, v in words).replace('+', '') != re.sub(r'[\s+]', '', text):
            fail(where, 'cannot read "%s"' % text)
        values = {}
        for k, v in words:
            if k == 'G':
                g = 'G%g' % float(v)
                if g in MOTION:
                    self.motion = g
                    if g == 'G80':
                        self.first_drill = True
                elif g == 'G98':
                    self.retract_r = False
                elif g == 'G99':
                    self.retract_r = True
                elif g not in IGNORED:
                    fail(where, '%s is not simulated here' % g)
            elif k == 'M':
                if int(float(v)) == 6:
                    if self.pending_tool is None:
                        fail(where, 'M6 without a T word')
                    self.steps.append(('T', self.pending_tool))
            elif k == 'T':
                self.pending_tool = int(float(v))
            elif k == 'N':
                pass
            else:
                values[k] = float(v)
        if not any(a in values for a in 'XYZ'):
            return
        if self.motion in ('G0', 'G1'):
            self.move(self.motion, values)
        elif self.motion in ('G2', 'G3'):
            self.arc(self.motion, values, where)
        elif self.motion in ('G81', 'G82', 'G83'):
            self.drill(values)
        else:
            fail(where, 'coordinates without a motion mode')

    def target(self, values):
        return [values.get(a, self.pos[i]) for i, a in enumerate('XYZ')]

    def emit(self, name, xyz):
        self.steps.append(('C', Path.Command(name, {'X': xyz[0], 'Y': xyz[1], 'Z': xyz[2]})))
        self.pos = list(xyz)

    def move(self, name, values):
        self.first_drill = True
        self.emit(name, self.target(values))

    def arc(self, name, values, where):
        # PathSimulatorGui.PerformCutVoxel's chords, with its resolution (the stock's).
        self.first_drill = True
        end = self.target(values)
        i, j = values.get('I', 0.0), values.get('J', 0.0)
        if values.get('K', 0.0):
            fail(where, 'K in G17')
        cx, cy = self.pos[0] + i, self.pos[1] + j
        a0 = math.atan2(self.pos[1] - cy, self.pos[0] - cx)
        a1 = math.atan2(end[1] - cy, end[0] - cx)
        da = a1 - a0
        da = da % (2 * math.pi) if name == 'G3' else -((-da) % (2 * math.pi))
        r = math.hypot(i, j)
        n = max(1, math.ceil(math.sqrt(r / RES * da * da)))
        z0 = self.pos[2]
        for k in range(1, n + 1):
            a = a0 + da * k / n
            point = end if k == n else [cx + r * math.cos(a), cy + r * math.sin(a), z0 + (end[2] - z0) * k / n]
            self.emit('G1', point)

    def drill(self, values):
        self.cycle.update({k: values[k] for k in 'RZ' if k in values})
        x, y = values.get('X', self.pos[0]), values.get('Y', self.pos[1])
        r, bottom = self.cycle['R'], self.cycle['Z']
        if self.first_drill:
            self.initial_z = self.pos[2]
            self.emit('G0', [self.pos[0], self.pos[1], r])
            self.first_drill = False
        self.emit('G0', [x, y, r])
        self.emit('G1', [x, y, bottom])
        self.emit('G1', [x, y, r])
        if not self.retract_r and self.initial_z > r:
            self.emit('G0', [x, y, self.initial_z])


RES = float(os.environ.get('CAMWB_SIM_RES', '0.1'))


def main():
    box = [float(v) for v in os.environ['CAMWB_SIM_STOCK'].split(',')]
    tools = read_tool_table(os.environ['CAMWB_SIM_TOOLS'])
    gcode = os.environ['CAMWB_SIM_GCODE']

    t0 = time.time()
    reader = Reader(box[5])
    with open(gcode) as program:
        for number, text in enumerate(program, 1):
            reader.line(text, '%s:%d' % (gcode, number))
    t1 = time.time()

    stock = Part.makeBox(box[3] - box[0], box[4] - box[1], box[5] - box[2], FreeCAD.Vector(box[0], box[1], box[2]))
    sim = PathSimulator.PathSim()
    sim.BeginSimulation(stock, RES)
    placement = FreeCAD.Placement(FreeCAD.Vector(0, 0, box[5]), FreeCAD.Rotation())
    have_tool = False
    count = 0
    for kind, value in reader.steps:
        if kind == 'T':
            if value not in tools:
                fail(gcode, 'T%d is not in the tool table' % value)
            sim.SetToolShape(flat_tool(*tools[value]), RES)
            have_tool = True
        elif have_tool:
            placement = sim.ApplyCommand(placement, value)
            count += 1
        else:  # no tool yet: nothing cuts, the position still moves
            placement = FreeCAD.Placement(FreeCAD.Vector(value.x, value.y, value.z), FreeCAD.Rotation())
    t2 = time.time()

    outer, inner = sim.GetResultMesh()
    result = Mesh.Mesh()
    result.addMesh(outer)
    result.addMesh(inner)
    result.write(os.environ['CAMWB_SIM_STL'])
    t3 = time.time()
    sys.stderr.write('freecad_sim_gcode: %d moves at %.3f mm: read %.3f s, cut %.3f s, mesh+STL %.3f s, %d facets\n' %
                     (count, RES, t1 - t0, t2 - t1, t3 - t2, result.CountFacets))


# freecadcmd exits 0 when a script raises, so the error is turned into an exit code here.
try:
    main()
except Exception as error:  # noqa: BLE001 - any failure must fail the command
    fail(os.environ.get('CAMWB_SIM_GCODE', '?'), '%s: %s' % (type(error).__name__, error))
