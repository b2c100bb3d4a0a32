#!/usr/bin/env python3
"""Makes tncscope-square-ramp.csv, a measured trace with a known deviation, for the simulator
dock's test: the planned motion of measured-square.ngc sampled by the kernel
(camwb-cli sim measured-square.ngc --trace-csv plan.csv --sample-ms 10, default machine limits) as
the nominal X Y Z, and the actual X = nominal X + 1 mm * t / T (T the last sample's time), so
that the actual tip is 0 mm from the nominal one at the start and 1 mm at the end (far more than
a real following error, so that the picture shows it). Written as TNCscope exports in Czech (';'
and decimal commas) in seed 003's column order.

    python3 make-measured-square.py plan.csv > tncscope-square-ramp.csv
"""
import csv
import sys

rows = list(csv.DictReader(open(sys.argv[1])))
end = float(rows[-1]["time_s"])
print("time;X_nom;X_act;Y_nom;Y_act;Z_nom;Z_act;A_nom;A_act;C_nom;C_act;dX;dY;dZ;dA;dC")
for r in rows:
    t = float(r["time_s"])
    x, y, z = (float(r[k]) for k in ("X", "Y", "Z"))
    offset = round(1.0 * t / end, 4)
    xa = round(x + offset, 4)
    values = [t, x, xa, y, y, z, z, 0, 0, 0, 0, round(x - xa, 4), 0, 0, 0, 0]
    print(";".join(f"{v:.4f}".replace(".", ",") for v in values))
