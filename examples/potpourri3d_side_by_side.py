"""The potpourri3d calls a user would replace, and their gsp equivalents (run on a real mesh).

    python3 examples/potpourri3d_side_by_side.py [MESH]

potpourri3d (comments)                                gsp
---------------------------------------------------   -------------------------------------------
V, F = pp3d.read_mesh(path)                           V, F = gsp.read_mesh(path)
solver = pp3d.MeshHeatMethodDistanceSolver(V, F)      solver = gsp.GeodesicSolver(V, F)
d = solver.compute_distance(v)                        d = solver.distance(v)
d = solver.compute_distance_multisource([a, b])       d = solver.distance([a, b])
(no source inside a face)                             d = solver.distance(gsp.SurfacePoint(f, (u, v, w)))
tracer = pp3d.EdgeFlipGeodesicSolver(V, F)            p = solver.path(a, b)
pts = tracer.find_geodesic_path(a, b)                 p.points, p.length, p.faces, p.barycentric
(loop over compute_distance)                          D = solver.distance_matrix(vertices)
pc = pp3d.PointCloudHeatSolver(P)                     pc = gsp.PointCloudSolver(P)
d = pc.compute_distance(i)                            d = pc.distance(i)
"""
import argparse
import pathlib

import numpy as np

import gsp

HERE = pathlib.Path(__file__).resolve().parent


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("mesh", nargs="?", default=HERE.parent / "data" / "samples" / "fertility.off")
    args = ap.parse_args()
    V, F = gsp.read_mesh(args.mesh)
    solver = gsp.GeodesicSolver(V, F)
    d = solver.distance(0)
    d2 = solver.distance([0, len(V) // 2])
    d3 = solver.distance(gsp.SurfacePoint(10, (0.2, 0.3, 0.5)))
    p = solver.path(0, len(V) - 1)
    D = solver.distance_matrix([0, 1, 2, 3])
    pc = gsp.PointCloudSolver(V).distance(0)
    print(f"distance: max {d.max():.4g}; two sources: max {d2.max():.4g}; face point: max {d3.max():.4g}")
    print(f"path: {len(p)} points, length {p.length:.4g} (field: {d[len(V) - 1]:.4g})")
    print(f"matrix:\n{np.array2string(D, precision=4)}")
    print(f"point cloud of the vertices: max {pc[np.isfinite(pc)].max():.4g}")


if __name__ == "__main__":
    main()
