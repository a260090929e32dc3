#!/usr/bin/env python3
"""GSP on corpus meshes changed the way users' files differ from clean ones: vertices or faces
shuffled, 30% of the faces reversed, 5% of them written twice, scaled by 1e-7 and 1e7, moved by
1e6, 2% of the faces removed, every face with vertices of its own (unwelded). Per mutation it
checks what holds on any surface: no exception other than gsp's typed ones, no NaN, no distance
more than 1% below the straight line, none more than 1% above the shortest path along the edges
(meshes under 60k vertices), nothing left unreached that the edges reach. With --paths, also
the default geodesic path from the source to the farthest vertex: between the straight line
and the edge path, and within --path-slack of the field (docs/pathfinding.md, "Scale and
winding", lists what that still finds). With --sampling, also gsp.sample(count=200): the count
within 1%, every sample in a face of the mesh (a doubled face's copy once made it run without
end: docs/apps/gsp-sample.md). Prints the failures and a line per mesh
(docs/gsp-core.md, "Doubled faces", is what it found first).

    /usr/bin/python3 scripts/mutation_sweep.py ../shared/data/corpus ../shared/data/meshes
"""
import argparse
import glob
import heapq
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'build', 'python'))
import gsp  # noqa: E402


def edge_paths(V, F, s):
    """Dijkstra along the mesh edges from vertex s: written here, independent of the library,
    because it is the bound the library's results are checked against."""
    n = len(V)
    E = np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]])
    L = np.linalg.norm(V[E[:, 0]] - V[E[:, 1]], axis=1)
    adj = [[] for _ in range(n)]
    for (a, b), l in zip(E.tolist(), L.tolist()):
        adj[a].append((b, l))
        adj[b].append((a, l))
    d = np.full(n, np.inf)
    d[s] = 0
    heap = [(0.0, s)]
    while heap:
        dd, v = heapq.heappop(heap)
        if dd > d[v]:
            continue
        for w, l in adj[v]:
            if dd + l < d[w]:
                d[w] = dd + l
                heapq.heappush(heap, (d[w], w))
    return d


def check_sampling(V, F):
    """'' when Poisson sampling by count holds, else what failed."""
    try:
        got = gsp.sample(V, F, count=200, seed=1)
    except (gsp.Error, ValueError):
        return ''
    except Exception as e:  # noqa: BLE001
        return f'sampling: untyped {type(e).__name__}: {e}'
    n = len(got.points)
    if abs(n - 200) > 2:
        return f'sampling: {n} samples for a count of 200'
    faces = np.asarray(got.faces)
    if n and (faces.min() < 0 or faces.max() >= len(F)):
        return 'sampling: a sample names a face that does not exist'
    return ''


def check(V, F, s, edge_limit, path_slack=None):
    """'' when every check holds, else what failed."""
    try:
        solver = gsp.GeodesicSolver(V, F)
        d = solver.distance(int(s))
    except (gsp.Error, ValueError):
        return ''   # a typed refusal is a valid answer
    except Exception as e:  # noqa: BLE001 - anything else is the finding
        return f'untyped {type(e).__name__}: {e}'
    if np.isnan(d).any():
        return f'NaN at {int(np.isnan(d).sum())} vertices'
    line = np.linalg.norm(V - V[s], axis=1)
    fin = np.isfinite(d)
    ep = edge_paths(V, F, s) if len(V) <= edge_limit else None
    problems = []
    if path_slack is not None and fin.sum() > 1:
        b = int(np.flatnonzero(fin)[np.argmax(d[fin])])
        try:
            p = solver.path(int(s), b)
            if p.length < 0.99 * line[b]:
                problems.append(f'path to {b} {p.length:.6g} below the straight line {line[b]:.6g}')
            if ep is not None and p.length > 1.01 * ep[b]:
                problems.append(f'path to {b} {p.length:.6g} above the edge path {ep[b]:.6g}')
            if p.length > (1 + path_slack) * d[b]:
                problems.append(f'path to {b} {100 * (p.length / d[b] - 1):.3g}% over the field')
        except (gsp.Error, ValueError) as e:
            problems.append(f'path to {b}: {type(e).__name__}: {e}')
    below = float(((line[fin] - d[fin]) / np.maximum(line[fin], 1e-300)).max()) if fin.any() else 0.0
    if below > 0.01:
        problems.append(f'{100 * below:.3g}% below the straight line')
    if ep is not None:
        m = np.isfinite(ep) & (ep > 0) & fin
        above = float(((d[m] - ep[m]) / ep[m]).max()) if m.any() else 0.0
        if above > 0.01:
            problems.append(f'{100 * above:.3g}% above the edge path')
        unreached = int((np.isfinite(ep) & ~fin).sum())
        if unreached:
            problems.append(f'{unreached} vertices unreached')
    return '; '.join(problems)


def mutations(V, F, s, rng):
    n = len(V)
    p = rng.permutation(n)
    inv = np.empty(n, np.int64)
    inv[p] = np.arange(n)
    yield 'vertices shuffled', V[p], inv[F], inv[s]
    yield 'faces shuffled', V, F[rng.permutation(len(F))], s
    G = F.copy()
    k = rng.random(len(F)) < 0.3
    G[k] = G[k][:, ::-1]
    yield '30% of the faces reversed', V, G, s
    yield '5% of the faces doubled', V, np.concatenate([F, F[rng.random(len(F)) < 0.05]]), s
    yield 'scaled 1e-7', V * 1e-7, F, s
    yield 'scaled 1e7', V * 1e7, F, s
    yield 'moved by 1e6', V + 1e6, F, s
    G = F[rng.random(len(F)) > 0.02]
    yield '2% of the faces removed', V, G, (s if s in G else int(G[0, 0]))
    yield 'unwelded', V[F.ravel()], np.arange(3 * len(F)).reshape(-1, 3), 0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('folders', nargs='+')
    ap.add_argument('--max-vertices', type=int, default=100000)
    ap.add_argument('--edge-check-vertices', type=int, default=60000, help='edge-path check up to this size')
    ap.add_argument('--seed', type=int, default=7)
    ap.add_argument('--paths', action='store_true', help='also check the path to the farthest vertex')
    ap.add_argument('--path-slack', type=float, default=0.02, help='allowed path excess over the field (0.02: 2%%)')
    ap.add_argument('--sampling', action='store_true', help='also sample by count (200) and check the count')
    a = ap.parse_args()
    rng = np.random.default_rng(a.seed)
    files = sorted(f for d in a.folders for f in glob.glob(os.path.join(d, '*'))
                   if os.path.isfile(f) and not f.endswith('.md'))
    failed = 0
    for f in files:
        try:
            V, F = gsp.read_mesh(f)
        except Exception:  # noqa: BLE001 - not a mesh (or a broken one: the readers' tests)
            continue
        V, F = np.asarray(V, float), np.asarray(F, np.int64)
        if len(F) == 0 or len(V) > a.max_vertices:
            continue
        s = int(F[0, 0])
        bad = 0
        for name, V2, F2, s2 in mutations(V, F, s, rng):
            why = check(V2, F2, s2, a.edge_check_vertices, a.path_slack if a.paths else None)
            if a.sampling:
                why = '; '.join(w for w in (why, check_sampling(V2, F2)) if w)
            if why:
                print(f'FAIL {os.path.basename(f)}, {name}: {why}', flush=True)
                bad += 1
        failed += bad
        print(f'{os.path.basename(f)}: {"ok" if not bad else f"{bad} failed"}', flush=True)
    print(f'{failed} failures')
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
