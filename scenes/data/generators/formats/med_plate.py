"""aster_plate.med (and aster_plate_hexa.med): a stress result in MED as
Code_Aster lays it out, written by meshio 7.0 (Debian's python3-meshio 7.0.0,
which reports itself as 5.0.0 through its dist-info;
`meshio.write(..., file_format="med")`, with h5py), then completed with h5py:
a second time step, component units and a Gauss-point localization, in the
layout the MED-fichier 4.1 library itself writes (compared, when this script
was written, with a file the library wrote through python3-med; the library
reads this file back below).

aster_plate.med
  Mesh "mesh" (meshio's name), 3-D: the Kirsch plate [-10, 10] x [-5, 5] x
  [0, 1] (mm) with a hole of radius 1 on the z axis, the gmsh mesh of
  gmsh_plate_v41.msh (gmsh_views.plate_tet_mesh): 462 nodes, 1,381 TETRA4
  (MED type TE4, one block, no other cells). meshio writes the file as MED
  3.0.0 (INFOS_GENERALES) with FAMILLE_ZERO only.
  Node order: MED's, not VTK's. MED's TETRA4 is the mirror image of VTK's
  tetra: VTK wants ((p1 - p0) x (p2 - p0)) . (p3 - p0) > 0, MED (SALOME,
  Code_Aster) the opposite sign; MEDCoupling's volume of a tetra is
  -1/6 of that triple product (src/INTERP_KERNEL/VolSurfFormulae.hxx,
  calculateVolumeForTetra). So each cell is gmsh's (VTK-positive) tetra
  with its nodes 2 and 3 swapped: VTK (a, b, c, d) = MED (a, c, b, d).
  meshio does NOT convert (it writes and reads the node order as given),
  so a reader must swap back. Checked below: every cell as stored has a
  negative VTK volume (the first, nodes 221 220 222 145 (1-based), -0.0107).
  The nodes are those of gmsh_plate_v41.msh, same numbers, and the cells
  are its tetrahedra in the same order (with 2 and 3 swapped).
  Fields (names as Code_Aster writes them: the result's name "RESU" padded
  to 8 with "_", then the field's), each with two time steps (numdt,
  numit) = (1, 1) at time 1.0 (meshio's numbers; its time 0 set to 1) and
  (2, 2) at time 2.0 (added with h5py), the second exactly twice the first
  (load factor 2), float64, no profiles:
    RESU____DEPL       nodes (NOEU), 3: DX DY DZ (mm): Kirsch's displacement;
    RESU____SIGM_NOEU  nodes, 6: SIXX SIYY SIZZ SIXY SIXZ SIYZ (MPa), the
                       Kirsch stress at each node (Code_Aster's order:
                       XZ before YZ, unlike VTK's XY YZ XZ);
    RESU____SIGM_ELNO  per element node (MED_NODE_ELEMENT, "NOE.TE4", 4
                       values a cell in the cell's node order as stored),
                       6 components as above. Stored in MED's layout
                       (component, cell, node of the cell), which is not
                       meshio's: see below;
    RESU____SIEF_ELGA  per Gauss point ("MAI.TE4" with the localization
                       "TE4_FPG1": Code_Aster's 1-point rule of TETRA4 at
                       the reference centroid, weight 1/6, reference nodes
                       N1 (0,1,0) N2 (0,0,1) N3 (0,0,0) N4 (1,0,0)), 6
                       components: Kirsch at each cell's centroid.
  Component units "MPa" / "mm" (UNI); time unit empty.

aster_plate_hexa.med
  The hexahedral variant: the plate of kirsch_plate_blocks.vtm (gmsh
  quadrangles extruded in 2 layers), 2,622 nodes, 1,632 HEXA8 (HE8) in MED's
  order, again VTK's mirror: MED (0..7) = VTK (0, 3, 2, 1, 4, 7, 6, 5).
  One time step (1, 1) at time 1.0 (as meshio writes it), fields
  RESU____DEPL and RESU____SIGM_NOEU as above.

Load and expected picture: Kirsch, uniaxial tension 10 MPa along x, plane
stress (SIZZ = SIXZ = SIYZ = 0). Step 1: SIXX about 10 far from the hole,
the peak 30 (tension) at the top and bottom of the hole (0, +-1, z), -10
(SIYY, compression) at its sides (+-1, 0, z); SIEF_ELGA peaks lower (26.1
in the cells touching (0, +-1)). Step 2: the same doubled (60, -20).
A reader that keeps the MED node order shows every cell inside out (negative
volumes); one that reads the six components in VTK's order swaps SIXZ and
SIYZ (both zero here, so only a mislabeled order line shows it).

Read back: meshio (points, cells, every field at both steps, component
names), the MED library itself (python3-med 4.1: the mesh, the fields, their
steps, components, units, the localization; every value compared) and
`mdump` (Debian's libmed-tools 4.1, which reads the 3.0.0 file: it must run
through the file).

meshio 7.0 and per-element-node data: meshio writes (and reads) a field of
shape (cells, nodes of a cell, components) as the Fortran flattening of that
array, i.e. (component, node of the cell, cell), while the MED library reads
and writes (component, cell, node of the cell) (seen by reading meshio's
file with the library). Left as meshio writes it, the library (Code_Aster, SALOME,
mdump) would scramble SIGM_ELNO across cells. This script rewrites the
values in MED's layout with h5py; meshio's own read-back of SIGM_ELNO is
therefore reshuffled (the check asserts the exact permutation). Fields of
one value a cell or node are not affected.

Deterministic: h5py writes no time stamps (HDF5 object times are off by
default); two runs give identical bytes.
"""
import importlib.util
import os
import shutil
import subprocess

import h5py
import meshio
import numpy as np

import formats_common as fc

VTK_TO_MED_TETRA4 = [0, 2, 1, 3]
VTK_TO_MED_HEXA8 = [0, 3, 2, 1, 4, 7, 6, 5]
SIG_CMP = ['SIXX', 'SIYY', 'SIZZ', 'SIXY', 'SIXZ', 'SIYZ']
DEPL_CMP = ['DX', 'DY', 'DZ']
PREFIX = 'RESU____'
LOC_NAME = 'TE4_FPG1'
LOC_REF = [0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0]   # Code_Aster's TETRA4 reference nodes
LOC_GAUSS, LOC_WEIGHT = [0.25, 0.25, 0.25], [1 / 6]
MED_GEO = {'tetra': 'TE4', 'hexahedron': 'HE8'}
STEP1 = '0000000000000000000100000000000000000001'   # numdt 1, numit 1 (meshio's)
STEP2 = '0000000000000000000200000000000000000002'


def aster6(t):
    """(n, 3, 3) -> (n, 6) in Code_Aster's order SIXX SIYY SIZZ SIXY SIXZ SIYZ."""
    return np.stack([t[:, 0, 0], t[:, 1, 1], t[:, 2, 2],
                     t[:, 0, 1], t[:, 0, 2], t[:, 1, 2]], axis=1) + 0.0


def vtk_volumes(points, cells):
    """VTK's signed volume of the tetra (first 4 nodes) or, for a hexahedron,
    that of its corner tetra (0, 1, 3, 4) (its sign is the cell's
    orientation)."""
    p = points[cells]
    if cells.shape[1] == 4:
        a, b, c = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0], p[:, 3] - p[:, 0]
        return np.einsum('ij,ij->i', np.cross(a, b), c) / 6
    a, b, c = p[:, 1] - p[:, 0], p[:, 3] - p[:, 0], p[:, 4] - p[:, 0]
    return np.einsum('ij,ij->i', np.cross(a, b), c) / 6


def pad16(names):
    return np.bytes_(''.join('%-16s' % n for n in names))


def fields_of(points, cells):
    """Kirsch fields of one step (load factor 1) as numpy arrays."""
    sig = aster6(fc.kirsch_stress(points))
    fields = {'DEPL': fc.kirsch_displacement(points) + 0.0, 'SIGM_NOEU': sig}
    if cells.shape[1] == 4:
        p = points[cells]
        fields['SIGM_ELNO'] = aster6(fc.kirsch_stress(p.reshape(-1, 3))).reshape(len(cells), 4, 6)
        fields['SIEF_ELGA'] = aster6(fc.kirsch_stress(p.mean(axis=1)))
    return fields


def write(path, points, med_cells, cell_type, fields, second_step):
    point_names = [k for k in ('DEPL', 'SIGM_NOEU') if k in fields]
    cell_names = [k for k in ('SIGM_ELNO', 'SIEF_ELGA') if k in fields]
    components = [DEPL_CMP if k == 'DEPL' else SIG_CMP for k in point_names + cell_names]
    mesh = meshio.Mesh(points, [(cell_type, med_cells)],
                       point_data={PREFIX + k: fields[k] for k in point_names},
                       cell_data={PREFIX + k: [fields[k]] for k in cell_names},
                       field_data={'med:nom': components})
    meshio.write(path, mesh, file_format='med')
    with h5py.File(path, 'r+') as f:
        cha = f['CHA']
        for k in cell_names:
            if fields[k].ndim == 3:
                # meshio 7.0 stores per-element-node values as (component,
                # node of the cell, cell); MED's layout (what the MED library
                # reads and writes) is (component, cell, node of the cell)
                co = cha[PREFIX + k][STEP1]['NOE.' + MED_GEO[cell_type]]['MED_NO_PROFILE_INTERNAL']['CO']
                co[...] = fields[k].transpose(2, 0, 1).ravel()
        for k in point_names + cell_names:
            field = cha[PREFIX + k]
            field.attrs['UNI'] = pad16(['mm' if k == 'DEPL' else 'MPa'] * field.attrs['NCO'])
            step = field[STEP1]
            step.attrs['PDT'] = 1.0   # meshio writes time 0
        if 'SIEF_ELGA' in cell_names:
            # Gauss points: the localization, and the field pointing at it
            gauss = f.create_group('GAUSS')
            loc = gauss.create_group(LOC_NAME)
            loc.attrs.create('DIM', 3, dtype=np.int32)
            loc.attrs.create('GEO', 304, dtype=np.int32)     # MED_TETRA4
            loc.attrs.create('INM', np.bytes_(''))
            loc.attrs.create('NBR', 1, dtype=np.int32)
            # MED stores reference coordinates non-interlaced (x..., y..., z...)
            loc.create_dataset('COO', data=np.array(LOC_REF, dtype=np.float64).reshape(4, 3).T.ravel())
            loc.create_dataset('GAU', data=np.array(LOC_GAUSS, dtype=np.float64))
            loc.create_dataset('VAL', data=np.array(LOC_WEIGHT, dtype=np.float64))
            sup = cha[PREFIX + 'SIEF_ELGA'][STEP1]['MAI.TE4']
            sup.attrs['GAU'] = np.bytes_(LOC_NAME)
            sup['MED_NO_PROFILE_INTERNAL'].attrs['GAU'] = np.bytes_(LOC_NAME)
        if second_step:
            for k in point_names + cell_names:
                field = cha[PREFIX + k]
                f.copy(field[STEP1], field, name=STEP2)
                s2 = field[STEP2]
                s2.attrs['NDT'], s2.attrs['NOR'], s2.attrs['PDT'] = 2, 2, 2.0
                for sup in s2.values():
                    co = sup['MED_NO_PROFILE_INTERNAL']['CO']
                    co[...] = 2.0 * co[()]
    fc.report(path)


# ---------------------------------------------------------------- checks

def check_meshio(path, points, med_cells, cell_type, fields, steps):
    m = meshio.read(path)
    assert np.array_equal(m.points, points)
    cells = m.cells_dict[cell_type]
    assert np.array_equal(cells, med_cells)     # meshio keeps the order as stored
    vol = vtk_volumes(m.points, cells)
    assert np.all(vol < 0), 'expected MED order: every VTK volume negative'
    for k, ref in fields.items():
        for s in range(steps):
            name = PREFIX + k if steps == 1 else '%s%s[%d] - %g' % (PREFIX, k, s, s + 1.0)
            got = m.point_data[name] if k in ('DEPL', 'SIGM_NOEU') else m.cell_data[name][0]
            expect = (s + 1) * ref
            if ref.ndim == 3:
                # meshio reads per-element-node values in its own layout, not
                # MED's: what it returns is the file's values reshuffled
                nc, ng, ncomp = ref.shape
                expect = expect.transpose(2, 0, 1).reshape(ncomp, ng, nc).transpose(2, 1, 0)
                assert not np.array_equal(got, (s + 1) * ref)
            assert np.array_equal(got, expect), name
    names = m.field_data['med:nom']
    print('meshio read %s: %d points, %d %s, first cell %s with VTK volume %.4g (all %d negative); '
          'arrays %s; components %s'
          % (os.path.basename(path), len(m.points), len(cells), cell_type, cells[0].tolist(),
             vol[0], len(vol), sorted(set(m.point_data) | set(m.cell_data)), names))


def check_medlib(path, points, med_cells, fields, steps):
    """Read back with the MED library (python3-med): mesh, fields, steps,
    components, units and values."""
    if importlib.util.find_spec('med') is None:
        print('NOT checked with the MED library: python3-med is not installed')
        return
    import med.medfield as mfd
    import med.medfile as mf
    import med.medlocalization as mloc
    import med.medmesh as mm
    from med.medenum import (MED_ACC_RDONLY, MED_ALL_CONSTITUENT, MED_CELL, MED_COMPACT_PFLMODE,
                             MED_CONNECTIVITY, MED_COORDINATE, MED_FULL_INTERLACE, MED_HEXA8,
                             MED_NODAL, MED_NODE, MED_NODE_ELEMENT, MED_NO_CMODE, MED_NO_DT,
                             MED_NO_IT, MED_TETRA4)
    fid = mf.MEDfileOpen(path, MED_ACC_RDONLY)
    try:
        geo = MED_TETRA4 if med_cells.shape[1] == 4 else MED_HEXA8
        n, _, _ = mm.MEDmeshnEntity(fid, 'mesh', MED_NO_DT, MED_NO_IT, MED_NODE, 0,
                                    MED_COORDINATE, MED_NO_CMODE)
        ncell, _, _ = mm.MEDmeshnEntity(fid, 'mesh', MED_NO_DT, MED_NO_IT, MED_CELL, geo,
                                        MED_CONNECTIVITY, MED_NODAL)
        assert (n, ncell) == (len(points), len(med_cells)), (n, ncell)
        coo = mf.MEDFLOAT(3 * n)
        mm.MEDmeshNodeCoordinateRd(fid, 'mesh', MED_NO_DT, MED_NO_IT, MED_FULL_INTERLACE, coo)
        assert np.array_equal(np.array(coo).reshape(-1, 3), points)
        conn = mf.MEDINT(ncell * med_cells.shape[1])
        mm.MEDmeshElementConnectivityRd(fid, 'mesh', MED_NO_DT, MED_NO_IT, MED_CELL, geo,
                                        MED_NODAL, MED_FULL_INTERLACE, conn)
        assert np.array_equal(np.array(conn).reshape(ncell, -1) - 1, med_cells)
        nfield = mfd.MEDnField(fid)
        seen = []
        for i in range(1, nfield + 1):
            ncomp = mfd.MEDfieldnComponent(fid, i)
            name, mesh, local, ftype, cname, cunit, dtunit, nstep = mfd.MEDfieldInfo(fid, i)
            key = name[len(PREFIX):]
            comps = [cname[16 * j:16 * j + 16].strip() for j in range(ncomp)]
            units = [cunit[16 * j:16 * j + 16].strip() for j in range(ncomp)]
            assert nstep == steps, (name, nstep)
            assert comps == (DEPL_CMP if key == 'DEPL' else SIG_CMP), comps
            for s in range(1, nstep + 1):
                numdt, numit, dt = mfd.MEDfieldComputingStepInfo(fid, name, s)
                assert (numdt, numit, dt) == (s, s, float(s)), (numdt, numit, dt)
                if key in ('DEPL', 'SIGM_NOEU'):
                    ent, g, npt = MED_NODE, 0, 1
                elif key == 'SIGM_ELNO':
                    ent, g, npt = MED_NODE_ELEMENT, geo, 4
                else:
                    ent, g, npt = MED_CELL, geo, 1
                nval, pname, psize, lname, ngauss = mfd.MEDfieldnValueWithProfile(
                    fid, name, numdt, numit, ent, g, 1, MED_COMPACT_PFLMODE)
                assert ngauss == npt, (name, ngauss)
                if key == 'SIEF_ELGA':
                    assert lname == LOC_NAME, lname
                vals = mf.MEDFLOAT(nval * ngauss * ncomp)
                mfd.MEDfieldValueRd(fid, name, numdt, numit, ent, g, MED_FULL_INTERLACE,
                                    MED_ALL_CONSTITUENT, vals)
                got = np.array(vals).reshape(fields[key].shape)
                assert np.array_equal(got, s * fields[key]), (name, s)
            seen.append('%s %s [%s] %d steps' % (name, comps, units[0], nstep))
        assert len(seen) == len(fields)
        nloc = mloc.MEDnLocalization(fid)
        locs = [mloc.MEDlocalizationInfo(fid, i + 1)[0] for i in range(nloc)]
        version = mf.MEDfileNumVersionRd(fid)
    finally:
        mf.MEDfileClose(fid)
    print('MED library read %s (file version %s): %d nodes, %d cells; fields: %s; localizations %s'
          % (os.path.basename(path), '.'.join(map(str, version)), n, ncell, '; '.join(seen), locs))


def check_mdump(path):
    """mdump (libmed-tools) must read through the file; prints a summary."""
    if shutil.which('mdump') is None:
        print('NOT checked with mdump: libmed-tools is not installed')
        return
    r = subprocess.run(['mdump', path, 'NODALE', 'FULL_INTERLACE', '0'],
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                       errors='replace', input='\n' * 20)
    out = r.stdout
    if r.returncode != 0 or 'ERREUR' in out:
        raise RuntimeError('mdump failed on %s:\n%s' % (path, out[-2000:]))
    lines = [l.strip() for l in out.splitlines()
             if 'Champ' in l or 'Nombre de' in l or 'pas de temps' in l.lower()]
    print('mdump read %s: %d lines, e.g. %s' % (os.path.basename(path), len(out.splitlines()), lines[:6]))


def main():
    from gmsh_views import plate_tet_mesh
    points, tets = plate_tet_mesh(order=1)
    med_tets = tets[:, VTK_TO_MED_TETRA4]
    fields = fields_of(points, med_tets)
    path = fc.out_path('aster_plate.med')
    write(path, points, med_tets, 'tetra', fields, second_step=True)
    sig = fields['SIGM_NOEU']
    k = np.argmax(sig[:, 0])
    print('SIGM_NOEU step 1: SIXX max %.4g at (%g, %g, %g); SIYY min %.4g; SIEF_ELGA SIXX max %.4g'
          % (sig[k, 0], *points[k], sig[:, 1].min(), fields['SIEF_ELGA'][:, 0].max()))
    check_meshio(path, points, med_tets, 'tetra', fields, 2)
    check_medlib(path, points, med_tets, fields, 2)
    check_mdump(path)

    points2d, halves = fc.plate_mesh_2d()
    hpoints, hexes = fc.extrude(points2d, np.concatenate(halves))
    assert np.all(vtk_volumes(hpoints, hexes) > 0)
    med_hexes = hexes[:, VTK_TO_MED_HEXA8]
    hfields = fields_of(hpoints, med_hexes)
    hpath = fc.out_path('aster_plate_hexa.med')
    write(hpath, hpoints, med_hexes, 'hexahedron', hfields, second_step=False)
    check_meshio(hpath, hpoints, med_hexes, 'hexahedron', hfields, 1)
    check_medlib(hpath, hpoints, med_hexes, hfields, 1)
    check_mdump(hpath)


if __name__ == '__main__':
    main()
