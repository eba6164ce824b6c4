#!/usr/bin/env python3
"""Writes rough_platen_mesh.inp: a quarter of a cubic specimen, 3 x 3 x 3 C3D8I elements, between
rough platens. Run once by hand; the deck is committed and CI does not need Python."""
N = 3

HEAD = '''** Drained triaxial compression of a 2 m cubic specimen between ROUGH platens: a quarter of it
** (symmetry planes y = 0 and z = 0), 3 x 3 x 3 C3D8I elements over [0, 2] x [0, 1] x [0, 1] m
** (incompatible modes: the fully integrated C3D8 locks as the dense sand dilates). Axis 1 is the
** loading axis and the deposition direction of acst_sdvini.json. Base x = 0 and platen x = 2 allow
** no lateral slip; the platen moves down by 10 %; the faces y = 1 and z = 1 carry 100 kPa.
** Automatic increments: tests/calculix/ records the Newton iterations and cut-backs.
** Written by make_platen_meshes.py.'''


def node(i, j, k):
    return 1 + i + (N + 1) * (j + (N + 1) * k)


def deck():
    lines = [HEAD, '*HEADING', 'ACST umat_ in CalculiX: 27 elements between rough platens, e0 0.66, 100 kPa',
             '*NODE, NSET=NALL']
    for k in range(N + 1):
        for j in range(N + 1):
            for i in range(N + 1):
                lines.append(f'{node(i, j, k)}, {2 * i / N:.12g}, {j / N:.12g}, {k / N:.12g}')
    lines.append('*ELEMENT, TYPE=C3D8I, ELSET=EALL')
    elements = []
    for k in range(N):
        for j in range(N):
            for i in range(N):
                e = 1 + i + N * (j + N * k)
                elements.append((e, j, k))
                c = [node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
                     node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1)]
                lines.append(f'{e}, ' + ', '.join(map(str, c)))

    def nset(name, pick):
        ids = [node(i, j, k) for k in range(N + 1) for j in range(N + 1) for i in range(N + 1) if pick(i, j, k)]
        lines.append(f'*NSET, NSET={name}')
        for s in range(0, len(ids), 8):
            lines.append(', '.join(map(str, ids[s:s + 8])))

    nset('BASE', lambda i, j, k: i == 0)
    nset('PLATEN', lambda i, j, k: i == N)
    nset('Y0', lambda i, j, k: j == 0)
    nset('Z0', lambda i, j, k: k == 0)
    lines += ['*INCLUDE, INPUT=acst_material.inp', '*SOLID SECTION, ELSET=EALL, MATERIAL=ABAQUS_ACST',
              '*INITIAL CONDITIONS, TYPE=SOLUTION, USER', '*INITIAL CONDITIONS, TYPE=STRESS']
    for e, *_ in elements:
        for ip in range(1, 9):
            lines.append(f'{e}, {ip}, -100., -100., -100., 0., 0., 0.')
    lines += ['*AMPLITUDE, NAME=HELD', '0., 1., 1., 1.', '*BOUNDARY']
    lines += ['BASE, 1, 3', 'PLATEN, 2, 3', 'Y0, 2, 2', 'Z0, 3, 3', '*STEP, INC=10000', '*STATIC',
              '0.01, 1., 1.e-5, 0.05']
    lines += ['*BOUNDARY', 'PLATEN, 1, 1, -0.2', '*DLOAD, AMPLITUDE=HELD']
    for e, j, k in elements:
        if j == N - 1:
            lines.append(f'{e}, P5, 100.')
        if k == N - 1:
            lines.append(f'{e}, P2, 100.')
    lines += ['*NODE PRINT, NSET=PLATEN, TOTALS=ONLY', 'RF', '*END STEP']
    with open('rough_platen_mesh.inp', 'w') as f:
        f.write('\n'.join(lines) + '\n')


deck()
