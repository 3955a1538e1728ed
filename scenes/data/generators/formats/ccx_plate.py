"""ccx_plate.frd and ccx_plate_binary.frd: CalculiX 2.20 (Debian's ccx)
results of a real solve of the Kirsch plate, the first all ASCII (*NODE FILE,
*EL FILE), the second CalculiX's binary .frd (*NODE OUTPUT, *ELEMENT OUTPUT:
the same cards, the same solve).

Model: the plate [-10, 10] x [-5, 5] x [0, 1] (mm) with a hole of radius 1 on
the z axis, meshed by gmsh 4.8 (gmsh_views.plate_tet_mesh(order=2): the mesh
of gmsh_plate_v41.msh raised to second order) into 1,381 quadratic
tetrahedra C3D10 with 2,725 nodes (the midside nodes of the hole's edges lie
on the cylinder). Nodes 1..462 are the corners, the nodes of
gmsh_plate_v41.msh with the same numbers (and the same cells in the same
order); 463..2725 are the midside nodes.
Linear elastic, E = 200,000 MPa, nu = 0.3. Load: a traction of 10 MPa along
x on both ends x = +-10 (*DLOAD P = -10 on the element faces there). Support
(exact symmetry conditions, no rigid motion): u_x = 0 on the plane x = 0,
u_y = 0 on the plane y = 0 (the mesh has nodes on both: the four quarters
are meshed conformingly) and u_z = 0 at the node (10, 5, 0). One static step.

Both files hold (ccx's own layout, node-based; element results are
extrapolated to the nodes and averaged):
  header: 1C, 1U lines (see determinism below), 1UMAT "STEEL";
  2C: 2,725 nodes; 3C: 1,381 elements, all of frd type 6 (te10), group 0,
      material 1; their 10 nodes are in ccx's C3D10 order (corners 1-4, then
      the midpoints of 1-2, 2-3, 3-1, 1-4, 2-4, 3-4), the order of the input;
  step 1 (1PSTEP 1..4, 100CL 101, time 1.0), four result blocks:
      DISP     4 names D1 D2 D3 ALL, 3 values a node (mm);
      STRESS   6: SXX SYY SZZ SXY SYZ SZX (MPa);
      TOSTRAIN 6: EXX EYY EZZ EXY EYZ EZX (tensor strain: EXY = gamma_xy/2);
      ERROR    1: STR(%), ccx's stress error estimator, written unasked
               along with S.
  The ASCII file writes numbers as E12.5 (6 significant digits; "1" in
  the last field of the 2C/3C/100CL lines: ccx's long format with 10-digit
  node numbers). The binary file differs only after each 2C/3C/100CL line
  (format flags 3, 2 and 2 there): the records follow as raw little-endian
  bytes with no " -1"/" -2" keys and no " -3" ends: nodes as int32 number +
  3 float64 coordinates (28 bytes); elements as 4 int32 (number, type,
  group, material) + int32 node numbers (56 bytes a te10); results as int32
  node number + float32 per value (DISP: 3 floats, 16 bytes; STRESS and
  TOSTRAIN: 6 floats, 28 bytes; ERROR: 1). The headers stay ASCII lines
  (1PSTEP, 100CL, -4, -5) and the file ends " 9999".

Expected picture: sigma_xx about 10 far from the hole (tension along x), the
concentration at the top and bottom of the hole (0, +-1, z): in this solve
SXX peaks at 32.98 at (0, -1, 0.5), mid-thickness, and is 29.5 on the faces
z = 0 and 1 (a 3-D effect: the mid-plane carries more). It is above
Kirsch's 3 x 10 because the plate is finite (hole diameter / width 0.2:
Heywood's gross factor ~3.14) and in 3-D. At the sides of the hole (+-1, 0)
SYY = -12.7 at mid-thickness, -8.9 on the faces (hoop compression; Kirsch
-10). Major stress trajectories run
along x and bend round the hole. A finer mesh (size 0.1 at the hole, 12k
elements) gives 32.55, so the mesh here is within about 1.3 %.

Checks (by reading the files back with the parser here): the block names,
component names and order, counts, every element of type 6 with the node
numbers of the input deck, STRESS and TOSTRAIN related by Hooke's law, the
binary file's coordinates (float64) exactly those of the deck (%.15g), its
elements equal to the ASCII's, and its values (float32) equal to the ASCII's
within their E12.5 rounding (5e-6 relative).

Determinism: ccx writes the date and time of the run in the 1UDATE and
1UTIME header lines; this script replaces them with the fixed text
"01.january.2000" and "00:00:00" (padded to the same length). Nothing else
varies (ccx runs with one thread: OMP_NUM_THREADS, CCX_NPROC_* = 1); two runs
give identical bytes. The other files ccx writes (.dat, .sta, .cvg, .12d,
spooles.out) stay in a temporary folder that is deleted.

The frd reader (ASCII and binary) and the ccx runner here are used by
ccx_block.py as well.
"""
import os
import re
import shutil
import struct
import subprocess
import tempfile

import numpy as np

import formats_common as fc

E_MOD, NU = 200e3, 0.3
TRACTION = 10.0
GMSH_TO_CCX_TET10 = [0, 1, 2, 3, 4, 5, 6, 7, 9, 8]   # gmsh 8 = mid(3,2), 9 = mid(3,1)
TET_FACES = [(0, 1, 2), (0, 3, 1), (1, 3, 2), (2, 3, 0)]   # ccx faces P1..P4 (corners)
FIXED_DATE, FIXED_TIME = '01.january.2000', '00:00:00'
FRD_NODES_PER_TYPE = {1: 8, 2: 6, 3: 4, 4: 20, 5: 15, 6: 10, 7: 3, 8: 6,
                      9: 4, 10: 8, 11: 2, 12: 3}


# ---------------------------------------------------------------- ccx input and run

def data_lines(values, per_line=16):
    """ccx data lines: at most 16 entries each."""
    values = list(values)
    return [', '.join(str(v) for v in values[k:k + per_line])
            for k in range(0, len(values), per_line)]


def node_cards(points):
    """*NODE data lines. ccx reads at most 20 characters a field: %.15g."""
    return ['%d, %.15g, %.15g, %.15g' % (i + 1, *p) for i, p in enumerate(points)]


def element_cards(conn, first=1):
    """*ELEMENT data lines (ids from `first`, 1-based nodes); ccx continues
    a line that ends with a comma."""
    out = []
    for i, row in enumerate(conn):
        vals = [i + first] + [int(n) + 1 for n in row]
        lines = data_lines(vals, 16)
        out += [l + ',' for l in lines[:-1]] + [lines[-1]]
    return out


def nset(name, ids0):
    return ['*NSET, NSET=' + name] + data_lines(np.asarray(ids0) + 1)


def faces_on(points, conn, faces, predicate):
    """(element id 1-based, face number 1-based) of every element face whose
    corner nodes all satisfy predicate(xyz (k, 3)) -> bool."""
    out = []
    for e, row in enumerate(conn):
        for f, corners in enumerate(faces):
            if predicate(points[row[list(corners)]]):
                out.append((e + 1, f + 1))
    return out


def run_ccx(deck, job):
    """Run ccx on the deck text in a temporary folder; returns the .frd
    bytes and the .dat text. Single-threaded."""
    env = dict(os.environ, OMP_NUM_THREADS='1', CCX_NPROC_EQUATION_SOLVER='1',
               CCX_NPROC_RESULTS='1', CCX_NPROC_STIFFNESS='1', NUMBER_OF_CPUS='1')
    tmp = tempfile.mkdtemp(prefix='ccx_')
    try:
        with open(os.path.join(tmp, job + '.inp'), 'w') as f:
            f.write('\n'.join(deck) + '\n')
        r = subprocess.run(['ccx', '-i', job], cwd=tmp, env=env,
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        frd = os.path.join(tmp, job + '.frd')
        if r.returncode != 0 or 'ERROR' in r.stdout or not os.path.exists(frd):
            raise RuntimeError('ccx failed:\n' + r.stdout[-3000:])
        with open(frd, 'rb') as f:
            data = f.read()
        with open(os.path.join(tmp, job + '.dat')) as f:
            dat = f.read()
    finally:
        shutil.rmtree(tmp)
    return fix_header(data), dat


def fix_header(data):
    """Replace the run's date and time in the 1UDATE / 1UTIME lines with
    fixed text of the same length."""
    def sub(key, text, data):
        m = re.search(rb'\n    1U' + key + rb' +([^\n]*)\n', data[:4000])
        if not m:
            raise RuntimeError('no 1U%s line' % key.decode())
        old = m.group(1)
        new = text.encode().ljust(len(old))
        return data[:m.start(1)] + new + data[m.end(1):]
    return sub(b'TIME', FIXED_TIME, sub(b'DATE', FIXED_DATE, data))


# ---------------------------------------------------------------- frd reader

def read_frd(data):
    """Parse a ccx .frd (ASCII or binary: the format flag of each 2C, 3C and
    100CL line says which). Returns dict with 'header' (the 1U lines),
    'nodes' (ids, xyz), 'elements' (list of (id, type, group, mat, nodes)),
    'flags' {2C, 3C, 100CL: set of format flags}, 'steps' (list of dicts:
    step, time, name, ncomp, components, ids, values)."""
    pos, n = 0, len(data)
    out = dict(header=[], nodes=None, elements=[], steps=[],
               flags={'2C': set(), '3C': set(), '100CL': set()})

    def line():
        nonlocal pos
        end = data.index(b'\n', pos)
        text = data[pos:end].decode('ascii')
        pos = end + 1
        return text

    def fnum(s):
        return float(s.replace('D', 'E'))

    while pos < n:
        text = line()
        key = text[:6]
        if text.startswith('    1U'):
            out['header'].append(text)
        elif key == '    2C':
            count, flag = int(text[6:36]), int(text[36:].split()[0])
            out['flags']['2C'].add(flag)
            ids, xyz = np.zeros(count, np.int64), np.zeros((count, 3))
            if flag >= 2:
                rec = np.dtype([('id', '<i4'), ('x', '<f8', 3)] if flag == 3
                               else [('id', '<i4'), ('x', '<f4', 3)])
                arr = np.frombuffer(data, rec, count, pos)
                pos += count * rec.itemsize
                ids, xyz = arr['id'].astype(np.int64), arr['x'].astype(np.float64)
            else:
                for k in range(count):
                    r = line()
                    ids[k] = int(r[3:13])
                    xyz[k] = [fnum(r[13 + 12 * j:25 + 12 * j]) for j in range(3)]
                assert line().strip() == '-3'
            out['nodes'] = (ids, xyz)
        elif key == '    3C':
            count, flag = int(text[6:36]), int(text[36:].split()[0])
            out['flags']['3C'].add(flag)
            for _ in range(count):
                if flag >= 2:
                    eid, typ, grp, mat = struct.unpack_from('<4i', data, pos)
                    pos += 16
                    k = FRD_NODES_PER_TYPE[typ]
                    nodes = list(struct.unpack_from('<%di' % k, data, pos))
                    pos += 4 * k
                else:
                    h = line().split()
                    eid, typ, grp, mat = map(int, h[1:5])
                    nodes = []
                    while len(nodes) < FRD_NODES_PER_TYPE[typ]:
                        r = line()
                        assert r.startswith(' -2')
                        nodes += [int(r[3 + 10 * j:13 + 10 * j]) for j in range((len(r) - 3) // 10)]
                out['elements'].append((eid, typ, grp, mat, nodes))
            if flag < 2:
                assert line().strip() == '-3'
        elif text.startswith('    1PSTEP'):
            pass
        elif text.startswith('  100CL'):
            # ' 100' 'C' setname(6) value(E12) count(I12) text(20) ictype(I2)
            # step number(I5) analysis(10) format flag(I2)
            time, count = fnum(text[12:24]), int(text[24:36])
            rest = text[36:].split()
            stepnum, flag = int(rest[1]), int(rest[-1])
            out['flags']['100CL'].add(flag)
            head = line()
            assert head.startswith(' -4')
            name, ncomp = head[5:13].strip(), int(head[13:18])
            comps = []
            stored = 0
            while data[pos:pos + 3] == b' -5':
                # name, menu, ictype, icind1, icind2, iexist (1: not in
                # the file, e.g. DISP's ALL, which cgx computes)
                c = line()
                comps.append(c[5:13].strip())
                fields = c[13:].split()
                stored += 0 if len(fields) > 4 and fields[4].startswith('1') else 1
            nval = stored
            ids, vals = np.zeros(count, np.int64), np.zeros((count, nval))
            if flag >= 2:
                rec = np.dtype([('id', '<i4'), ('v', '<f4' if flag == 2 else '<f8', (nval,))])
                arr = np.frombuffer(data, rec, count, pos)
                pos += count * rec.itemsize
                ids, vals = arr['id'].astype(np.int64), arr['v'].astype(np.float64).reshape(count, nval)
            else:
                for k in range(count):
                    r = line()
                    ids[k] = int(r[3:13])
                    v = [fnum(r[13 + 12 * j:25 + 12 * j]) for j in range((len(r) - 13) // 12)]
                    while len(v) < nval:
                        r = line()
                        v += [fnum(r[13 + 12 * j:25 + 12 * j]) for j in range((len(r) - 13) // 12)]
                    vals[k] = v
                assert line().strip() == '-3'
            out['steps'].append(dict(step=stepnum, time=time, name=name, ncomp=ncomp,
                                     components=comps, ids=ids, values=vals))
        elif text.strip() == '9999':
            break
    return out


def check_same(asc, binary):
    """The binary file holds what the ASCII one does: the same node numbers,
    coordinates (E12.5 vs float64), elements, blocks and values (E12.5 vs
    float32)."""
    ia, xa = asc['nodes']
    ib, xb = binary['nodes']
    assert np.array_equal(ia, ib)
    assert np.allclose(xa, xb, rtol=1e-5, atol=1e-9)
    assert asc['elements'] == binary['elements']
    assert [(s['name'], s['components'], s['time']) for s in asc['steps']] == \
        [(s['name'], s['components'], s['time']) for s in binary['steps']]
    worst = 0.0
    for sa, sb in zip(asc['steps'], binary['steps']):
        assert np.array_equal(sa['ids'], sb['ids'])
        scale = np.abs(sa['values']).max()
        err = np.abs(sa['values'] - sb['values']) / np.maximum(np.abs(sa['values']), 1e-6 * scale)
        worst = max(worst, err.max())
    assert worst < 1e-5, worst
    return worst


def block(frd, name, step_index=0):
    """The step_index-th result block of this name."""
    return [s for s in frd['steps'] if s['name'] == name][step_index]


# ---------------------------------------------------------------- the plate

def plate_deck(points, tets, binary):
    tol = 1e-9
    x, y, z = points.T
    deck = ['*HEADING', 'Kirsch plate with a hole, tension 10 MPa along x (hsb test data)',
            '*NODE, NSET=NALL'] + node_cards(points)
    deck += ['*ELEMENT, TYPE=C3D10, ELSET=EALL'] + element_cards(tets)
    deck += nset('NX0', np.nonzero(np.abs(x) < tol)[0])
    deck += nset('NY0', np.nonzero(np.abs(y) < tol)[0])
    corner = np.nonzero((np.abs(x - 10) < tol) & (np.abs(y - 5) < tol) & (np.abs(z) < tol))[0]
    assert len(corner) == 1
    deck += nset('NZ0', corner)
    deck += ['*MATERIAL, NAME=STEEL', '*ELASTIC', '%g, %g' % (E_MOD, NU),
             '*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL',
             '*BOUNDARY', 'NX0, 1, 1', 'NY0, 2, 2', 'NZ0, 3, 3',
             '*STEP', '*STATIC', '*DLOAD']
    ends = faces_on(points, tets, TET_FACES,
                    lambda p: np.all(np.abs(p[:, 0] - 10) < tol) or np.all(np.abs(p[:, 0] + 10) < tol))
    deck += ['%d, P%d, %g' % (e, f, -TRACTION) for e, f in ends]
    if binary:
        deck += ['*NODE OUTPUT', 'U', '*ELEMENT OUTPUT', 'S, E']
    else:
        deck += ['*NODE FILE', 'U', '*EL FILE', 'S, E']
    deck += ['*NODE PRINT, NSET=NX0, TOTALS=ONLY', 'RF', '*END STEP']
    return deck, len(ends)


def check_plate(frd, points, tets, label):
    ids, xyz = frd['nodes']
    assert np.array_equal(ids, np.arange(1, len(points) + 1))
    assert np.allclose(xyz, points, rtol=1e-5, atol=1e-9)
    assert len(frd['elements']) == len(tets)
    assert all(t == 6 and g == 0 and m == 1 for _, t, g, m, _ in frd['elements'])
    conn = np.array([nodes for *_, nodes in frd['elements']]) - 1
    assert np.array_equal(conn, tets), 'frd te10 node order differs from the input'
    names = [(s['name'], s['components']) for s in frd['steps']]
    assert names == [('DISP', ['D1', 'D2', 'D3', 'ALL']),
                     ('STRESS', ['SXX', 'SYY', 'SZZ', 'SXY', 'SYZ', 'SZX']),
                     ('TOSTRAIN', ['EXX', 'EYY', 'EZZ', 'EXY', 'EYZ', 'EZX']),
                     ('ERROR', ['STR(%)'])], names
    s = block(frd, 'STRESS')['values']
    e = block(frd, 'TOSTRAIN')['values']
    # Hooke's law links the two blocks (tensor shear strain)
    tr = s[:, :3].sum(axis=1)
    e_hooke = (1 + NU) / E_MOD * s - np.outer(NU / E_MOD * tr, [1, 1, 1, 0, 0, 0])
    assert np.abs(e - e_hooke).max() < 1e-4 * np.abs(e).max() + 1e-9
    k = np.argmax(s[:, 0])
    far = np.abs(points[:, 0]) > 8
    side = (np.abs(np.abs(points[:, 0]) - 1) < 1e-9) & (np.abs(points[:, 1]) < 1e-9)
    print('%s: %d nodes, %d te10; blocks %s' % (label, len(ids), len(tets), [n for n, _ in names]))
    print('  SXX max %.4g at (%.3g, %.3g, %.3g); SXX for |x| > 8: %.4g .. %.4g; '
          'SYY at (+-1, 0, z): %.4g .. %.4g'
          % (s[k, 0], *points[k], s[far, 0].min(), s[far, 0].max(),
             s[side, 1].min(), s[side, 1].max()))
    return s[k, 0], points[k]


def main():
    from gmsh_views import plate_tet_mesh
    points, tets = plate_tet_mesh(order=2)
    tets = tets[:, GMSH_TO_CCX_TET10]
    results = {}
    for binary, name in [(False, 'ccx_plate.frd'), (True, 'ccx_plate_binary.frd')]:
        deck, nfaces = plate_deck(points, tets, binary)
        data, dat = run_ccx(deck, 'plate')
        path = fc.out_path(name)
        with open(path, 'wb') as f:
            f.write(data)
        fc.report(path)
        with open(path, 'rb') as f:
            frd = read_frd(f.read())
        assert frd['flags'] == ({'2C': {3}, '3C': {2}, '100CL': {2}} if binary else
                                {'2C': {1}, '3C': {1}, '100CL': {1}}), frd['flags']
        check_plate(frd, points, tets, name)
        if binary:   # float64 coordinates: exactly the deck's numbers
            deck_xyz = np.array([[float('%.15g' % v) for v in p] for p in points])
            assert np.array_equal(frd['nodes'][1], deck_xyz)
        results[binary] = frd
    print('loaded faces: %d; header: %s' % (nfaces, [h.strip() for h in results[False]['header'][2:4]]))
    worst = check_same(results[False], results[True])
    print('binary = ASCII to %.2g (relative; float32 vs E12.5)' % worst)


if __name__ == '__main__':
    main()
