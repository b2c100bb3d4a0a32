# FreeCAD 0.20's z-map simulator (PathSimulator.PathSim, what its Path simulator runs) on the
# straight moves camwb_sim_stock_bench writes (CAMWB_SIM_BENCH_MOVES=<dir>), side by side with
# our height field at the same resolution. Run with freecadcmd; the inputs come in
#   CAMWB_SIM_MOVES  the moves file ("T d kind corner angle flute", "G0|G1 x y z [f]")
#   CAMWB_SIM_STOCK  xmin,ymin,zmin,xmax,ymax,zmax     CAMWB_SIM_RES  resolution in mm
# and it prints the seconds ApplyCommand took over all moves (commands built beforehand), and
# the result mesh's time. The tool shapes follow FreeCAD's own (a revolved profile per kind).
import math
import os
import time

import FreeCAD
import Part
import Path
import PathSimulator

res = float(os.environ.get('CAMWB_SIM_RES', '0.1'))
box = [float(v) for v in os.environ['CAMWB_SIM_STOCK'].split(',')]


def tool_shape(d, kind, corner, angle, flute):
    r = d / 2
    flute = max(flute, d)
    if kind == 'ball':
        return Part.makeCylinder(r, flute - r, FreeCAD.Vector(0, 0, r)).fuse(Part.makeSphere(r, FreeCAD.Vector(0, 0, r)))
    if kind in ('drill', 'chamfer') and 0 < angle < 180:
        h = r / math.tan(math.radians(angle / 2))
        return Part.makeCone(0, r, h).fuse(Part.makeCylinder(r, flute, FreeCAD.Vector(0, 0, h)))
    if kind == 'bull' and corner > 0:
        body = Part.makeCylinder(r - corner, flute).fuse(Part.makeCylinder(r, flute - corner, FreeCAD.Vector(0, 0, corner)))
        return body.fuse(Part.makeTorus(r - corner, corner, FreeCAD.Vector(0, 0, corner)))
    return Part.makeCylinder(r, flute)


steps = []  # ('T', shape) or ('M', command)
start = None
with open(os.environ['CAMWB_SIM_MOVES']) as moves:
    for line in moves:
        w = line.split()
        if not w:
            continue
        if w[0] == 'T':
            steps.append(('T', tool_shape(float(w[1]), w[2], float(w[3]), float(w[4]), float(w[5]))))
            start = None
            continue
        params = {'X': float(w[1]), 'Y': float(w[2]), 'Z': float(w[3])}
        if start is None:
            start = FreeCAD.Vector(params['X'], params['Y'], params['Z'])
            steps.append(('P', start))
            continue
        if len(w) > 4:
            params['F'] = float(w[4])
        steps.append(('M', Path.Command(w[0], params)))

stock = Part.makeBox(box[3] - box[0], box[4] - box[1], box[5] - box[2], FreeCAD.Vector(box[0], box[1], box[2]))
sim = PathSimulator.PathSim()
t0 = time.time()
sim.BeginSimulation(stock, res)
t1 = time.time()
c1 = time.process_time()  # CPU seconds too: on a shared machine the wall clock includes waiting
placement = FreeCAD.Placement()
count = 0
for kind, value in steps:
    if kind == 'T':
        sim.SetToolShape(value, res)
    elif kind == 'P':
        placement = FreeCAD.Placement(value, FreeCAD.Rotation())
    else:
        placement = sim.ApplyCommand(placement, value)
        count += 1
t2 = time.time()
c2 = time.process_time()
result = sim.GetResultMesh()
t3 = time.time()
print('freecad-pathsim moves %d res %.3f begin %.3f s apply %.3f s wall %.3f s cpu (%.0f moves/s cpu) mesh %.3f s' %
      (count, res, t1 - t0, t2 - t1, c2 - c1, count / max(c2 - c1, 1e-9), t3 - t2))
