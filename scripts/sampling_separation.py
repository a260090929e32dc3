#!/usr/bin/env python3
"""Checks Poisson-disk samples against an independent field: gsp.sample at a radius of FRACTION of
the bounding box's diagonal on every mesh file given (folders: every mesh in them), then from
each sample GSP on the intrinsic Delaunay faces (the full query's default, not the input faces
the sampler's bounded runs propagate on), bounded by 1.5 r, read at every other sample through
its face's corners (a corner's value plus the straight segment: the length of a path, so an
upper bound of the distance). A pair whose bound is below 0.99 r is closer than the radius.
Prints one line per file and the totals (docs/apps/gsp-sample.md, "Long slivers and doubled
faces").

    /usr/bin/python3 scripts/sampling_separation.py ../shared/data/corpus ../shared/data/meshes [--fraction 0.05]
"""
import argparse
import glob
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'build', 'python'))
import gsp  # noqa: E402

EXTENSIONS = ('.obj', '.off', '.ply', '.stl', '.gltf', '.glb')


def files_of(paths):
    for p in paths:
        if os.path.isdir(p):
            yield from sorted(f for f in glob.glob(os.path.join(p, '*')) if f.lower().endswith(EXTENSIONS))
        else:
            yield p


def check(path, fraction, max_vertices):
    V, F = gsp.read_mesh(path)
    if len(F) == 0 or len(V) > max_vertices:
        return None
    r = fraction * np.linalg.norm(V.max(0) - V.min(0))
    s = gsp.sample(V, F, radius=r, seed=1)
    pts, faces, bary = np.asarray(s.points), np.asarray(s.faces), np.asarray(s.barycentric)
    solver = gsp.GeodesicSolver(V, F)
    close, closest = 0, np.inf
    for i in range(len(pts) - 1):
        d = solver.distance(gsp.SurfacePoint(int(faces[i]), tuple(bary[i])), max_distance=1.5 * r)
        corners = F[faces[i + 1:]]
        bound = np.min(d[corners] + np.linalg.norm(V[corners] - pts[i + 1:, None, :], axis=2), axis=1)
        close += int((bound < 0.99 * r).sum())
        closest = min(closest, float((bound / r).min()))
    return len(pts), close, closest


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('paths', nargs='+')
    ap.add_argument('--fraction', type=float, default=0.05, help='radius over the diagonal (default 0.05)')
    ap.add_argument('--max-vertices', type=int, default=60000)
    a = ap.parse_args()
    total_samples = total_pairs = files_with_pairs = 0
    for path in files_of(a.paths):
        try:
            got = check(path, a.fraction, a.max_vertices)
        except (ValueError, OSError) as e:
            print(f'{os.path.basename(path):45s} skipped: {e}', flush=True)
            continue
        if got is None:
            continue
        n, close, closest = got
        total_samples += n
        total_pairs += close
        files_with_pairs += close > 0
        print(f'{os.path.basename(path):45s} samples {n:5d}  pairs < 0.99 r: {close:3d}  closest {closest:.3f} r', flush=True)
    print(f'total: {total_samples} samples, {total_pairs} pairs closer than 0.99 r, {files_with_pairs} files with one')
    return 1 if total_pairs else 0


if __name__ == '__main__':
    sys.exit(main())
