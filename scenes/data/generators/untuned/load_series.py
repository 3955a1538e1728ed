"""plate_050.vtu, plate_100.vtu, plate_150.vtu + plate_series.pvd: a load
series of the plate with a hole in MILLIMETRES and MPa, three steps at the
remote tension 50, 100 and 150 MPa, as a user sweeping the load would save
it: one file per step on the same mesh (~30k linear tetrahedra; `--cells
small` ~8k), plus a ParaView collection naming the three with timesteps 50,
100, 150 (written by hand exactly as ParaView's vtkPVDWriter does).

Plate 200 x 100 x 5 mm (x in [-100, 100], y in [-50, 50], z in [0, 5]),
hole of radius 10 mm at the origin, tension along x. Stress: Kirsch's
plane-stress solution (kirsch.py, shared with plate_hole_large.py), POINT
data "stress", 9 components row-major, active tensors, MPa.

A correct picture of each step: the Kirsch pattern (trajectories along x
bending round the hole; 3 S tension at (0, +-10), i.e. 150, 300, 450 MPa;
hoop compression -S at (+-10, 0)), identical in shape for all steps. A
SERIES rendering (one glyph scale and colour range for all steps) must show
the glyphs and colours growing with the load, 1 : 2 : 3; three independent
renderings would look the same.
"""
import os

import kirsch
import untuned_common as uc

args = uc.parse_args(__doc__)
LENGTH, WIDTH, THICK, RADIUS = 200.0, 100.0, 5.0, 10.0   # mm
LOADS = [50, 100, 150]                                     # MPa
H_HOLE, H_FAR = {'full': (0.93, 3.7), 'small': (1.5, 6.0)}[args.cells]

points, tets = kirsch.plate_tets(LENGTH, WIDTH, THICK, RADIUS, H_HOLE, H_FAR)
entries = []
for S in LOADS:
    ug = kirsch.plate_grid(points, tets, float(S), RADIUS)
    name = 'plate_%03d.vtu' % S
    print('S = %d MPa:' % S)
    kirsch.check_hole(ug, S, RADIUS)
    uc.common.write_xml(ug, os.path.join(args.outdir, name))
    entries.append('    <DataSet timestep="%d" group="" part="0" file="%s"/>\n' % (S, name))

path = os.path.join(args.outdir, 'plate_series.pvd')
with open(path, 'w', newline='\n') as f:
    f.write('<?xml version="1.0"?>\n'
            '<VTKFile type="Collection" version="0.1" byte_order="LittleEndian" '
            'header_type="UInt64" compressor="vtkZLibDataCompressor">\n'
            '  <Collection>\n' + ''.join(entries) + '  </Collection>\n</VTKFile>\n')
print('wrote', path, os.path.getsize(path), 'bytes')
