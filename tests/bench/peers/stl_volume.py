#!/usr/bin/env python3
# stl_volume.py <file.stl>...: the enclosed volume (divergence theorem over the facets), facet count
# and bounding box of binary or ASCII STL files, to check that two simulators' cut stocks agree
# (freecad_sim_gcode.py beside `camwb-cli sim --stl`). Only the standard library and, when it is
# there, numpy (fast for the millions of facets a height field writes).
import struct
import sys


def triangles(path):
    with open(path, 'rb') as f:
        data = f.read()
    if len(data) >= 84:
        count = struct.unpack_from('<I', data, 80)[0]
        if 84 + 50 * count == len(data):
            try:
                import numpy
                rec = numpy.dtype([('n', '<f4', 3), ('v', '<f4', (3, 3)), ('a', '<u2')])
                return numpy.frombuffer(data, rec, count, 84)['v'].astype(numpy.float64)
            except ImportError:
                return [struct.unpack_from('<9f', data, 84 + 50 * k + 12) for k in range(count)]
    vertices = [tuple(map(float, line.split()[1:4])) for line in data.decode().splitlines()
                if line.strip().startswith('vertex')]
    return [sum(vertices[k:k + 3], ()) for k in range(0, len(vertices), 3)]


def measure(tris):
    try:
        import numpy
        t = numpy.asarray(tris, dtype=numpy.float64).reshape(-1, 3, 3)
        volume = numpy.einsum('ij,ij->i', t[:, 0], numpy.cross(t[:, 1], t[:, 2])).sum() / 6
        flat = t.reshape(-1, 3)
        return volume, len(t), flat.min(axis=0).tolist(), flat.max(axis=0).tolist()
    except ImportError:
        volume = 0.0
        lo, hi = [float('inf')] * 3, [float('-inf')] * 3
        for x0, y0, z0, x1, y1, z1, x2, y2, z2 in tris:
            volume += (x0 * (y1 * z2 - z1 * y2) - y0 * (x1 * z2 - z1 * x2) + z0 * (x1 * y2 - y1 * x2)) / 6
            for i, v in enumerate(((x0, x1, x2), (y0, y1, y2), (z0, z1, z2))):
                lo[i], hi[i] = min(lo[i], *v), max(hi[i], *v)
        return volume, len(tris), lo, hi


for path in sys.argv[1:]:
    volume, count, lo, hi = measure(triangles(path))
    print('%s: volume %.1f mm3, %d facets, box %s .. %s' %
          (path, volume, count, ','.join('%.2f' % v for v in lo), ','.join('%.2f' % v for v in hi)))
