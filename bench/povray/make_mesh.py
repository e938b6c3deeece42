#!/usr/bin/python3
"""Writes the benchmark suite's mesh (docs/performance.md) in both formats, same vertices:
bench/scenes/bumpy.obj for raycast and bench/povray/bumpy.inc (a mesh2) for POV-Ray.
A latitude/longitude sphere of 64 x 32 quads (4,032 triangles once the pole quads become single
triangles), radius 1 displaced radially by 0.08 sin(5 theta) sin(4 phi): deterministic, no
randomness.  Run from anywhere: bench/povray/make_mesh.py"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
SEG, RINGS = 64, 32


def main():
    verts = [(0.0, 1.0, 0.0)]  # north pole
    for i in range(1, RINGS):
        theta = math.pi * i / RINGS
        for j in range(SEG):
            phi = 2 * math.pi * j / SEG
            r = 1 + 0.08 * math.sin(5 * theta) * math.sin(4 * phi)
            verts.append((r * math.sin(theta) * math.cos(phi), r * math.cos(theta),
                          r * math.sin(theta) * math.sin(phi)))
    verts.append((0.0, -1.0, 0.0))  # south pole
    south = len(verts) - 1

    def ring(i, j):  # vertex index of ring i (1..RINGS-1), segment j
        return 1 + (i - 1) * SEG + j % SEG

    tris = []
    for j in range(SEG):  # counter-clockwise seen from outside (y up, phi from x towards z)
        tris.append((0, ring(1, j + 1), ring(1, j)))
        tris.append((south, ring(RINGS - 1, j), ring(RINGS - 1, j + 1)))
    for i in range(1, RINGS - 1):
        for j in range(SEG):
            a, b = ring(i, j), ring(i, j + 1)
            c, d = ring(i + 1, j), ring(i + 1, j + 1)
            tris.append((a, b, d))
            tris.append((a, d, c))
    with open(os.path.join(HERE, '..', 'scenes', 'bumpy.obj'), 'w') as f:
        f.write('# bench/povray/make_mesh.py: %d vertices, %d triangles\n' % (len(verts), len(tris)))
        for v in verts:
            f.write('v %.9g %.9g %.9g\n' % v)
        for t in tris:
            f.write('f %d %d %d\n' % (t[0] + 1, t[1] + 1, t[2] + 1))
    with open(os.path.join(HERE, 'bumpy.inc'), 'w') as f:
        f.write('// bench/povray/make_mesh.py: the same mesh as bench/scenes/bumpy.obj\n')
        f.write('#declare Bumpy = mesh2 {\n  vertex_vectors { %d,\n' % len(verts))
        f.write(',\n'.join('    <%.9g, %.9g, %.9g>' % v for v in verts))
        f.write('\n  }\n  face_indices { %d,\n' % len(tris))
        f.write(',\n'.join('    <%d, %d, %d>' % t for t in tris))
        f.write('\n  }\n}\n')


main()
