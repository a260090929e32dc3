#!/usr/bin/python3
"""GSP's accuracy on meshes split at edge midpoints: the same surface with more (and flatter)
vertices, as meshes refined for simulation come. Each mesh is split --splits times; GSP runs
on the split mesh and is compared at the input's vertices (the split mesh's first ones) with
CGAL's exact geodesics on the input (gsp-exact: the input is small, the split mesh need not
be). Prints per mesh the mean relative error and its signed mean, then mean / 95th percentile
/ worst over the meshes, and writes them as CSV with --csv (docs/benchmarks.md, "Flat creases
that end at saddles").

    scripts/split_accuracy.py MESH... --splits 2 [--sources 1] [--seed 1] [--csv out.csv]

Files that cannot be read and meshes CGAL's exact method refuses (non-manifold, degenerate
faces) are reported and skipped.
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "build", "python"))
import gsp  # noqa: E402  (the build's package unless one is installed)

EXACT = os.path.join(HERE, "..", "build", "bin", "gsp-exact")


def midpoint_split(V, F):
    """Every face into four at its edge midpoints (gsp::midpoint_subdivide's rule); the input's
    vertices keep their indices."""
    edges = np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1)
    unique, inverse = np.unique(edges, axis=0, return_inverse=True)
    mid = len(V) + inverse.ravel().reshape(3, len(F)).T   # columns: edges 01, 12, 20
    V = np.concatenate([V, 0.5 * (V[unique[:, 0]] + V[unique[:, 1]])])
    a, b, c = F[:, 0], F[:, 1], F[:, 2]
    ab, bc, ca = mid[:, 0], mid[:, 1], mid[:, 2]
    F = np.concatenate([np.stack(x, 1) for x in ([a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca])])
    return V, F


def exact(V, F, sources, exact_bin):
    """CGAL's exact distances from each source, one array per source (the mesh as given)."""
    with tempfile.TemporaryDirectory() as tmp:
        mesh, out = os.path.join(tmp, "m.ply"), os.path.join(tmp, "d.txt")
        gsp.write_mesh(mesh, V, F)
        result = []
        for s in sources:
            r = subprocess.run([exact_bin, mesh, "--no-weld", "--source-vertex", str(s), "-o", out, "--quiet"],
                               capture_output=True, text=True)
            if r.returncode != 0:
                raise RuntimeError(r.stderr.strip().splitlines()[-1] if r.stderr.strip() else "gsp-exact failed")
            result.append(np.loadtxt(out))
        return result


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("meshes", nargs="+")
    ap.add_argument("--splits", type=int, default=2)
    ap.add_argument("--sources", type=int, default=1, help="random source vertices per mesh")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--exact-bin", default=EXACT)
    ap.add_argument("--csv")
    args = ap.parse_args()
    rows = []
    for path in args.meshes:
        name = os.path.basename(path)
        try:
            V, F = gsp.read_mesh(path)
        except (OSError, ValueError) as e:
            print(f"{name}: skipped ({e})", flush=True)
            continue
        F = np.asarray(F, dtype=np.int64)
        rng = np.random.default_rng(args.seed)
        sources = [int(s) for s in rng.choice(len(V), size=min(args.sources, len(V)), replace=False)]
        try:
            references = exact(V, F, sources, args.exact_bin)
        except RuntimeError as e:
            print(f"{name}: skipped (exact: {e})", flush=True)
            continue
        V2, F2 = V, F
        for _ in range(args.splits):
            V2, F2 = midpoint_split(V2, F2)
        solver = gsp.GeodesicSolver(V2, F2)
        mre, signed = [], []
        for s, ex in zip(sources, references):
            d = solver.distance(s)[: len(V)]
            m = (ex > 0) & np.isfinite(ex)
            rel = (d[m] - ex[m]) / ex[m]
            mre.append(100 * np.abs(rel).mean())
            signed.append(100 * rel.mean())
        row = {"mesh": name, "vertices": len(V2), "mre_percent": np.mean(mre), "signed_percent": np.mean(signed)}
        rows.append(row)
        print(f"{name:44s} {len(V2):9d} vertices  MRE {row['mre_percent']:.4f}%  signed {row['signed_percent']:+.4f}%",
              flush=True)
    if rows:
        a = np.array([r["mre_percent"] for r in rows])
        print(f"{len(rows)} meshes, {args.splits} splits: MRE mean {a.mean():.4f}%  p95 {np.percentile(a, 95):.4f}%  "
              f"worst {a.max():.4f}%")
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=["mesh", "vertices", "mre_percent", "signed_percent"])
            w.writeheader()
            w.writerows(rows)


if __name__ == "__main__":
    main()
