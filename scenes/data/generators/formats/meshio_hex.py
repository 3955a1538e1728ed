"""meshio_hex_beam.xdmf + meshio_hex_beam.h5: XDMF written by meshio 5.0's
own XDMF writer (meshio.write(..., file_format="xdmf"), i.e. XdmfWriter
with its defaults: data_format "HDF", compression "gzip", level 4; the
heavy data through h5py 3.7).

Mesh: the cantilever of moose_style.py: a beam 10 x 1 x 1 (x in [0, 10]
along the beam, y and z in [-0.5, 0.5]), 30 x 6 x 6 = 1,080 hexahedra
(XDMF TopologyType "Hexahedron", VTK/XDMF node order: the bottom face
z = k counter-clockwise seen from +z, then the top face), 1,519 nodes,
built with numpy. Units: mm, N, MPa.

XDMF layout (XDMF 3.0, one uniform Grid "Grid", no time):
  Geometry XYZ         /data0  1519 x 3 float64 (DataType Float, Precision 8)
  Topology Hexahedron  /data1  1080 x 8 int64   (DataType Int, Precision 8)
  Attribute "stress"    AttributeType Tensor6, Center Node,
                        /data2  1519 x 6 float64
  Attribute "von_mises" AttributeType Scalar, Center Cell,
                        /data3  1080 float64
All four h5 datasets are gzip-compressed (meshio's default) and so
chunked, with h5py's automatic chunk shapes ((760, 2), (270, 4), (380, 3),
(1080,)). The .xdmf is one line of XML with no declaration.

Component order of "stress": XX XY XZ YY YZ ZZ (the upper triangle, row by
row), the order XDMF users take for Tensor6 (Underworld reorders its
output to it, for one). meshio itself does not order anything: it labels
any n x 6 array "Tensor6" and writes it as given. The values make the order
visible: only XX and XZ are non-zero.

Field: Euler-Bernoulli bending of the beam clamped at x = 0 under a
downward tip load P = 1 N at x = 10 (I = 1/12 mm^4), as in moose_style.e's
first step: sigma_xx = 12 (10 - x) z (tension on top), sigma_xz =
-1.5 (1 - 4 z^2) (parabolic shear), all else 0. "von_mises" is the von
Mises stress of that field at each cell's centroid,
sqrt(sigma_xx^2 + 3 sigma_xz^2).

Expected picture: the same as moose_style.e at step 1. Trajectories along
the beam; tension (major eigenvalue up to +60) in the top half and
compression (down to -60) in the bottom half, both growing linearly
towards the clamped root x = 0 and vanishing at the tip x = 10; on the
neutral plane z = 0 pure shear, eigenvalues +-1.5 with principal directions
at 45 degrees in the x-z plane. von_mises is largest (49.2) in the root
cells along the top and bottom faces and smallest (1.15) in the tip cells
along those faces. A reader that takes the six values in VTK's order (XX YY ZZ
XY YZ XZ) turns the shear into a normal stress sigma_zz = -1.5 on the
neutral plane (no 45-degree directions): that is the wrong picture.

Checks: h5py reads the four datasets back (shapes, dtypes, gzip, values
equal to what was given); meshio.read reads the .xdmf back. (Debian's VTK
9.1 has no XDMF reader and Debian's python3-xdmf does not import.)
Determinism: h5py creates datasets without modification times (its
track_times is off unless asked for), and meshio's XML carries no date: two
runs a few seconds apart give identical bytes.
"""
import os

import numpy as np

import formats_common as fc

L, B, H = 10.0, 1.0, 1.0
NX, NY, NZ = 30, 6, 6
P = 1.0
I = B * H ** 3 / 12

x, y, z = np.meshgrid(np.linspace(0, L, NX + 1), np.linspace(-B / 2, B / 2, NY + 1),
                      np.linspace(-H / 2, H / 2, NZ + 1), indexing='ij')
points = np.stack([x.ravel(), y.ravel(), z.ravel()], axis=1)


def node(i, j, k):
    return (i * (NY + 1) + j) * (NZ + 1) + k


hexes = np.array([[node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
                   node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1),
                   node(i, j + 1, k + 1)]
                  for i in range(NX) for j in range(NY) for k in range(NZ)], dtype=np.int64)


def beam_stress(p):
    """Euler-Bernoulli: (n, 3, 3) for points p."""
    px, pz = p[:, 0], p[:, 2]
    sxx = P * (L - px) * pz / I
    sxz = -1.5 * P / (B * H) * (1 - 4 * pz * pz / (H * H))
    zero = np.zeros_like(px)
    return fc.sym(sxx, zero, zero, zero, zero, sxz)


def von_mises_of(t):
    """Von Mises stress of (n, 3, 3) tensors, element by element (numpy's
    einsum, in formats_common.von_mises, can round differently from run to
    run with the arrays' memory alignment)."""
    d = (t[:, 0, 0] - t[:, 1, 1]) ** 2 + (t[:, 1, 1] - t[:, 2, 2]) ** 2 + (t[:, 2, 2] - t[:, 0, 0]) ** 2
    return np.sqrt(0.5 * d + 3.0 * (t[:, 0, 1] ** 2 + t[:, 1, 2] ** 2 + t[:, 0, 2] ** 2))


def xdmf6(t):
    """(n, 3, 3) -> (n, 6) in the order XX XY XZ YY YZ ZZ."""
    return np.stack([t[:, 0, 0], t[:, 0, 1], t[:, 0, 2],
                     t[:, 1, 1], t[:, 1, 2], t[:, 2, 2]], axis=1)


stress = xdmf6(beam_stress(points))
von_mises = von_mises_of(beam_stress(points[hexes].mean(axis=1)))

# positive volumes (VTK's check), the hexahedron order XDMF shares with VTK
import vtk  # noqa: E402
fc.common.check_positive_volumes(fc.common.unstructured_grid(points, [(vtk.VTK_HEXAHEDRON, hexes)]))

import meshio  # noqa: E402
import h5py  # noqa: E402

path = fc.out_path('meshio_hex_beam.xdmf')
h5path = path[:-5] + '.h5'
if os.path.exists(h5path):
    os.remove(h5path)
mesh = meshio.Mesh(points, [('hexahedron', hexes)],
                   point_data={'stress': stress}, cell_data={'von_mises': [von_mises]})
meshio.write(path, mesh, file_format='xdmf')   # HDF, gzip 4: meshio's defaults
fc.report(path)
fc.report(h5path)

with h5py.File(h5path, 'r') as f:
    names = sorted(f)
    assert names == ['data0', 'data1', 'data2', 'data3'], names
    expect = {'data0': points, 'data1': hexes, 'data2': stress, 'data3': von_mises}
    for name in names:
        d = f[name]
        assert d.compression == 'gzip' and d.dtype == expect[name].dtype, (name, d.compression, d.dtype)
        assert np.array_equal(d[()], expect[name]), name
        print('h5 %s: %s %s, %s (level %s), chunks %s'
              % (name, d.shape, d.dtype, d.compression, d.compression_opts, d.chunks))
back = meshio.read(path)
assert back.cells[0].type == 'hexahedron' and np.array_equal(back.cells[0].data, hexes)
assert np.array_equal(back.point_data['stress'], stress)
assert np.array_equal(back.cell_data['von_mises'][0], von_mises)
print('meshio.read: %d points, %d %s, point arrays %s, cell arrays %s'
      % (len(back.points), len(back.cells[0].data), back.cells[0].type,
         {k: v.shape for k, v in back.point_data.items()},
         {k: v[0].shape for k, v in back.cell_data.items()}))
print('stress XX from %.1f to %.1f, XZ from %.2f to %.2f; von_mises from %.2f to %.2f'
      % (stress[:, 0].min(), stress[:, 0].max(), stress[:, 2].min(), stress[:, 2].max(),
         von_mises.min(), von_mises.max()))
