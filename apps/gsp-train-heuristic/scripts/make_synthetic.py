#!/usr/bin/env python3
"""Synthetic anisotropic meshes for training the visibility heuristic (docs/heuristic.md).

CAD tessellations are full of slivers and fans; the shared data has only two such meshes that
CGAL accepts. These three add the same kinds of triangles on shapes whose geodesics bend:
  synth_cylinder.obj  closed cylinder, 2 rings of long side slivers, fan-triangulated caps
  synth_uvsphere.obj  UV sphere with few stacks and many slices (needles at the poles)
  synth_bumps.obj     a bumpy height field on a 10:1 stretched grid with random diagonals
Usage: make_synthetic.py OUTDIR   (deterministic: fixed seed)
"""
import math
import os
import random
import sys


def write_obj(path, verts, faces):
    with open(path, "w") as f:
        for v in verts:
            f.write("v %.9f %.9f %.9f\n" % v)
        for t in faces:
            f.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))


def cylinder(segments=160, rings=2, radius=1.0, height=3.0):
    verts, faces = [], []
    for r in range(rings + 1):
        z = height * r / rings
        for s in range(segments):
            a = 2 * math.pi * s / segments
            verts.append((radius * math.cos(a), radius * math.sin(a), z))
    for r in range(rings):
        for s in range(segments):
            a, b = r * segments + s, r * segments + (s + 1) % segments
            c, d = a + segments, b + segments
            faces += [(a, b, d), (a, d, c)]
    bottom, top = len(verts), len(verts) + 1
    verts += [(0.0, 0.0, 0.0), (0.0, 0.0, height)]
    for s in range(segments):   # fans: every cap triangle touches the centre
        faces.append((bottom, (s + 1) % segments, s))
        faces.append((top, rings * segments + s, rings * segments + (s + 1) % segments))
    return verts, faces


def uv_sphere(stacks=10, slices=120):
    verts = [(0.0, 0.0, 1.0)]
    for i in range(1, stacks):
        p = math.pi * i / stacks
        for j in range(slices):
            a = 2 * math.pi * j / slices
            verts.append((math.sin(p) * math.cos(a), math.sin(p) * math.sin(a), math.cos(p)))
    verts.append((0.0, 0.0, -1.0))
    south = len(verts) - 1
    ring = lambda i, j: 1 + (i - 1) * slices + j % slices
    faces = []
    for j in range(slices):
        faces.append((0, ring(1, j), ring(1, j + 1)))
        faces.append((south, ring(stacks - 1, j + 1), ring(stacks - 1, j)))
    for i in range(1, stacks - 1):
        for j in range(slices):
            a, b, c, d = ring(i, j), ring(i, j + 1), ring(i + 1, j), ring(i + 1, j + 1)
            faces += [(a, c, d), (a, d, b)]
    return verts, faces


def bumps(nx=30, ny=300, seed=7):
    rng = random.Random(seed)
    verts, faces = [], []
    for j in range(ny + 1):
        for i in range(nx + 1):
            x, y = 3.0 * i / nx, 3.0 * j / ny   # cells 0.1 x 0.01: aspect 10
            verts.append((x, y, 0.25 * math.sin(2.5 * x) * math.cos(3.0 * y)))
    idx = lambda i, j: j * (nx + 1) + i
    for j in range(ny):
        for i in range(nx):
            a, b, c, d = idx(i, j), idx(i + 1, j), idx(i, j + 1), idx(i + 1, j + 1)
            faces += [(a, b, d), (a, d, c)] if rng.random() < 0.5 else [(a, b, c), (b, d, c)]
    return verts, faces


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "."
    os.makedirs(out, exist_ok=True)
    write_obj(os.path.join(out, "synth_cylinder.obj"), *cylinder())
    write_obj(os.path.join(out, "synth_uvsphere.obj"), *uv_sphere())
    write_obj(os.path.join(out, "synth_bumps.obj"), *bumps())


if __name__ == "__main__":
    main()
