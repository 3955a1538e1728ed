"""ccx_block.frd: CalculiX 2.20 results (ASCII .frd, *NODE FILE / *EL FILE)
of a real solve of a cantilever meshed with quadratic hexahedra and quadratic
wedges, in two load steps.

Model: a beam x from 0 to 10, y from 0 to 2, z from 0 to 2 (mm), built with
numpy as a structured mesh extruded along y (2 layers of 1): the side
(x, z) is cut into 10 x 4 cells of 1 x 0.5. Cells with x < 5 are 20-node
hexahedra C3D20 (frd type 4: 40 of them); cells with x > 5 are each split
along their diagonal into two 15-node wedges C3D15 (frd type 5: 80), whose
triangles lie in the planes y = const. The two regions share the nodes of
the plane x = 5 (a conforming quadratic mesh): 120 elements, 617 nodes.
Linear elastic, E = 200,000 MPa, nu = 0.3. The end x = 0 is clamped (all
nodes fixed).
  step 1 (time 1): a pressure of 1 MPa on the top face z = 2 (pushing down);
  step 2 (time 2): the same pressure plus a traction of 50 MPa along +x on
         the free end x = 10 (*DLOAD P = -50 there; step 1's pressure stays).

What the file holds: header (1U lines, dates fixed, see below), 2C 617
nodes, 3C 120 elements: types 4 (he20, group 0, material 1) and 5 (pe15);
then per step the blocks DISP (D1 D2 D3 [ALL]), STRESS (SXX SYY SZZ SXY SYZ
SZX, MPa), TOSTRAIN (EXX EYY EZZ EXY EYZ EZX, tensor strain) and ERROR
(STR(%)): 8 result blocks, 1PSTEP 1..8, 100CL with step numbers 1 and 2 and
times 1.0 and 2.0. Numbers are E12.5.

Node order (checked against the input deck): ccx writes a he20 in the frd
as the input's nodes 1-12, 17-20, 13-16 (the 4 midside nodes of the edges
parallel to 1-5 come before the 4 of the top face 5-6-7-8), and a pe15 as
1-9, 13-15, 10-12 (the 3 midside nodes of the edges 1-4, 2-5, 3-6 before
those of the top triangle 4-5-6). The input (Abaqus/ccx) orders are corners,
bottom edges, top edges, vertical edges, as VTK's quadratic hexahedron has
them; VTK's quadratic wedge differs again (its first triangle points the
other way). The 3C block's he20 and pe15 are thus not in the input's order.

Expected picture: a cantilever bent down by the top pressure. Beam theory:
sigma_xx = 0.75 (10 - x)^2 (z - 1) MPa for p = 1, tension on top (z = 2),
compression below, zero on the mid-plane z = 1: +-42.2 at x = 2.5 (this
solve: top 42.2 .. 42.4, bottom -42.4 .. -42.2, mid-plane 0.00). The
largest values are at the clamp's edges, where the full clamp makes the
stress singular: SXX 94.3 at (0, 0, 2), -93.7 at (0, 0, 0) (beam theory's
root value is 75). Step 2 adds a uniform 50 of tension: at x = 2.5 top 92.1
.. 92.7, mid-plane 50.1 .. 50.3, bottom 7.8 .. 7.9 (beam theory 92.2, 50,
7.8); 50 at the free end; SXX max 165.9 at (0, 0, 2). A reader that shows
only step 1, or mixes the steps, is easy to see.

Checks (read back with ccx_plate.read_frd): the element types and counts,
the frd node order against the deck, the block names and component orders,
the two steps' numbers and times, the clamp's reactions (from the .dat,
*NODE PRINT RF TOTALS=ONLY) against the loads (fz 19.667 = 20 less the 1/3
that the pressure puts straight on clamped nodes; fx -200 in step 2), and
SXX at x = 2.5 against beam theory (within 5 %). The wedges' orientation is
ccx's: given the other way round ccx stops with "nonpositive jacobian".

Determinism: the date and time lines are fixed as in ccx_plate.py
("01.january.2000", "00:00:00"); two runs give identical bytes. ccx's other
outputs are deleted with its temporary folder.
"""
import numpy as np

import formats_common as fc
from ccx_plate import (E_MOD, NU, block, element_cards, faces_on, nset,
                       node_cards, read_frd, run_ccx)

L, B, H = 10.0, 2.0, 2.0            # x, y, z extents (mm)
NX, NY, NZ = 10, 2, 4               # cells
X_SPLIT = 5.0                       # hexahedra for x < 5, wedges for x > 5
PRESSURE, TIP_TRACTION = 1.0, 50.0  # MPa

HEX_FACES = [(0, 1, 2, 3), (4, 7, 6, 5), (0, 4, 5, 1), (1, 5, 6, 2), (2, 6, 7, 3), (3, 7, 4, 0)]
WEDGE_FACES = [(0, 1, 2), (3, 4, 5), (0, 1, 4, 3), (1, 2, 5, 4), (2, 0, 3, 5)]
# frd order of a he20 / pe15, as positions in the input (ccx) order
FRD_HE20 = list(range(12)) + [16, 17, 18, 19, 12, 13, 14, 15]
FRD_PE15 = list(range(9)) + [12, 13, 14, 9, 10, 11]


def mesh():
    """Points (n, 3) and the C3D20 and C3D15 connectivities (0-based, ccx
    order). Nodes live on the half-step grid (2 NX + 1) x (2 NY + 1) x
    (2 NZ + 1); only the used ones are kept, numbered in grid order."""
    hx, hy, hz = L / NX / 2, B / NY / 2, H / NZ / 2
    gx, gy, gz = 2 * NX + 1, 2 * NY + 1, 2 * NZ + 1

    def g(i, j, k):                    # grid index of half-step point (i, j, k)
        return i + gx * (j + gy * k)

    def mid(a, b):
        return tuple((np.array(a) + np.array(b)) // 2)

    hexes, wedges = [], []
    for ci in range(NX):
        for cj in range(NY):
            for ck in range(NZ):
                i, j, k = 2 * ci, 2 * cj, 2 * ck
                c = [(i, j, k), (i + 2, j, k), (i + 2, j + 2, k), (i, j + 2, k),
                     (i, j, k + 2), (i + 2, j, k + 2), (i + 2, j + 2, k + 2), (i, j + 2, k + 2)]
                if (ci + 1) * 2 * hx <= X_SPLIT + 1e-9:
                    edges = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4),
                             (0, 4), (1, 5), (2, 6), (3, 7)]
                    nodes = c + [mid(c[a], c[b]) for a, b in edges]
                    hexes.append([g(*p) for p in nodes])
                else:
                    # the (x, z) cell split along its diagonal (x0, z0)-(x1, z1)
                    # into two triangles, extruded from y0 to y1; each
                    # triangle ordered so its normal points to +y (to the
                    # second triangle): ccx's wedge
                    for tri in [((i, k), (i + 2, k + 2), (i + 2, k)),
                                ((i, k), (i, k + 2), (i + 2, k + 2))]:
                        bottom = [(a, j, b) for a, b in tri]
                        top = [(a, j + 2, b) for a, b in tri]
                        cs = bottom + top
                        edges = [(0, 1), (1, 2), (2, 0), (3, 4), (4, 5), (5, 3), (0, 3), (1, 4), (2, 5)]
                        nodes = cs + [mid(cs[a], cs[b]) for a, b in edges]
                        wedges.append([g(*p) for p in nodes])
    hexes, wedges = np.array(hexes), np.array(wedges)
    used = np.unique(np.concatenate([hexes.ravel(), wedges.ravel()]))
    renum = np.full(gx * gy * gz, -1)
    renum[used] = np.arange(len(used))
    k, rest = np.divmod(used, gx * gy)
    j, i = np.divmod(rest, gx)
    points = np.stack([i * hx, j * hy, k * hz], axis=1)
    return points, renum[hexes], renum[wedges]


def orientation_ok(points, hexes, wedges):
    """Positive volume the way ccx wants it: a hexahedron's face 1-2-3-4 and
    a wedge's 1-2-3 with their right-hand normals pointing into the element
    (to the opposite face)."""
    for conn, n in [(hexes, 4), (wedges, 3)]:
        p = points[conn]
        base = p[:, :n].mean(axis=1)
        top = p[:, n:2 * n].mean(axis=1)
        normal = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
        if np.any(np.einsum('ij,ij->i', normal, top - base) <= 0):
            return False
    return True


def deck(points, hexes, wedges):
    tol = 1e-9
    nh = len(hexes)
    d = ['*HEADING', 'Cantilever of C3D20 and C3D15, 2 steps (hsb test data)',
         '*NODE, NSET=NALL'] + node_cards(points)
    d += ['*ELEMENT, TYPE=C3D20, ELSET=EHEX'] + element_cards(hexes)
    d += ['*ELEMENT, TYPE=C3D15, ELSET=EWEDGE'] + element_cards(wedges, first=nh + 1)
    d += ['*ELSET, ELSET=EALL', 'EHEX, EWEDGE']
    d += nset('NCLAMP', np.nonzero(np.abs(points[:, 0]) < tol)[0])
    d += ['*MATERIAL, NAME=STEEL', '*ELASTIC', '%g, %g' % (E_MOD, NU),
          '*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL',
          '*BOUNDARY', 'NCLAMP, 1, 3']

    def on(coord, value):
        return lambda p: np.all(np.abs(p[:, coord] - value) < tol)

    top = faces_on(points, hexes, HEX_FACES, on(2, H)) + \
        [(e + nh, f) for e, f in faces_on(points, wedges, WEDGE_FACES, on(2, H))]
    tip = [(e + nh, f) for e, f in faces_on(points, wedges, WEDGE_FACES, on(0, L))]
    d += ['*STEP', '*STATIC', '*DLOAD'] + ['%d, P%d, %g' % (e, f, PRESSURE) for e, f in top]
    d += ['*NODE FILE', 'U', '*EL FILE', 'S, E',
          '*NODE PRINT, NSET=NCLAMP, TOTALS=ONLY', 'RF', '*END STEP']
    d += ['*STEP', '*STATIC', '*DLOAD'] + ['%d, P%d, %g' % (e, f, -TIP_TRACTION) for e, f in tip]
    d += ['*NODE FILE', 'U', '*EL FILE', 'S, E',
          '*NODE PRINT, NSET=NCLAMP, TOTALS=ONLY', 'RF', '*END STEP']
    return d, len(top), len(tip)


def reactions(dat):
    """The clamp's total reaction (fx, fy, fz) of each step, from the .dat."""
    out, lines = [], dat.splitlines()
    for i, line in enumerate(lines):
        if 'total force' in line:
            out.append([float(v) for v in lines[i + 2].split()])
    return np.array(out)


def main():
    points, hexes, wedges = mesh()
    assert orientation_ok(points, hexes, wedges)
    text, ntop, ntip = deck(points, hexes, wedges)
    data, dat = run_ccx(text, 'block')
    path = fc.out_path('ccx_block.frd')
    with open(path, 'wb') as f:
        f.write(data)
    fc.report(path)

    rf = reactions(dat)
    # ccx's reaction leaves out the load put straight on clamped nodes: the
    # top pressure's consistent nodal loads on the edge x = 0, z = 2 (per
    # 8-node face of 1 x 1: -1/12 a corner, +1/3 a midside; two faces
    # there: 1/3 in all). The reaction opposes the load.
    load_z = -PRESSURE * L * B
    on_clamp = -PRESSURE * (L / NX) * (B / NY) * (2 * (1 / 3) + 2 * (-1 / 12) + 2 * (-1 / 12))
    assert np.allclose(rf[:, 2], -(load_z - on_clamp), rtol=1e-6), rf
    assert np.allclose(rf[:, 0], [0, -TIP_TRACTION * B * H], rtol=1e-6, atol=1e-6), rf

    with open(path, 'rb') as f:
        frd = read_frd(f.read())
    assert frd['flags'] == {'2C': {1}, '3C': {1}, '100CL': {1}}
    ids, xyz = frd['nodes']
    assert np.array_equal(ids, np.arange(1, len(points) + 1))
    assert np.allclose(xyz, points, rtol=1e-5, atol=1e-9)
    els = frd['elements']
    types = [t for _, t, _, _, _ in els]
    assert types == [4] * len(hexes) + [5] * len(wedges), 'element types'
    frd_hex = np.array([n for _, t, _, _, n in els if t == 4]) - 1
    frd_wedge = np.array([n for _, t, _, _, n in els if t == 5]) - 1
    assert np.array_equal(frd_hex, hexes[:, FRD_HE20]), 'he20 node order'
    assert np.array_equal(frd_wedge, wedges[:, FRD_PE15]), 'pe15 node order'
    names = [(s['name'], s['step'], s['time'], s['components']) for s in frd['steps']]
    expect = []
    for step in (1, 2):
        expect += [('DISP', step, float(step), ['D1', 'D2', 'D3', 'ALL']),
                   ('STRESS', step, float(step), ['SXX', 'SYY', 'SZZ', 'SXY', 'SYZ', 'SZX']),
                   ('TOSTRAIN', step, float(step), ['EXX', 'EYY', 'EZZ', 'EXY', 'EYZ', 'EZX']),
                   ('ERROR', step, float(step), ['STR(%)'])]
    assert names == expect, names

    print('mesh: %d nodes, %d C3D20 (frd 4), %d C3D15 (frd 5); loaded faces: top %d, tip %d'
          % (len(points), len(hexes), len(wedges), ntop, ntip))
    print('clamp reactions (fx, fy, fz) per step:', rf.round(6).tolist())
    x, y, z = points.T
    at = np.abs(x - 2.5) < 1e-9
    for k in (0, 1):
        s = block(frd, 'STRESS', k)['values'][:, 0]
        beam = 0.75 * (L - 2.5) ** 2 * PRESSURE + (TIP_TRACTION if k else 0.0)
        top, bot = s[at & (np.abs(z - H) < 1e-9)], s[at & (np.abs(z) < 1e-9)]
        mid = s[at & (np.abs(z - H / 2) < 1e-9)]
        print('step %d: SXX at x = 2.5: top %.4g .. %.4g, mid-plane %.3g .. %.3g, bottom %.4g .. %.4g '
              '(beam theory %.4g, %.4g, %.4g); SXX max %.4g at (%g, %g, %g), min %.4g at (%g, %g, %g)'
              % (k + 1, top.min(), top.max(), mid.min(), mid.max(), bot.min(), bot.max(),
                 beam, TIP_TRACTION * k, -0.75 * (L - 2.5) ** 2 * PRESSURE + (TIP_TRACTION if k else 0.0),
                 s.max(), *points[np.argmax(s)], s.min(), *points[np.argmin(s)]))
        assert abs(top.mean() - beam) < 0.05 * abs(beam)


if __name__ == '__main__':
    main()
