#!/usr/bin/python3
"""Runs every app on every mesh of one or more folders and reports what breaks the CLI contract:
an exit by a signal (a crash), an exit code other than 0, 1 (bad input, one line on stderr), 2
(a usage error: an option the input cannot take, as --metric on a point cloud) and 3 (gsp-path:
no path), a run past the time limit, or exit 1 without exactly one stderr line.

    scripts/apps_sweep.py ../shared/data/corpus ../shared/data/meshes [--bin build/bin] [--timeout 120] [--all]
        [--random K --seed S]

Prints one line per finding and a count at the end; exit status 1 when there is any. Session
22's sweep of the 94 corpus and shared files found gsp-cvt-compare's CGAL crash on
libigl_degenerated.obj and the point clouds' --separate usage error (both fixed). Session 27's
with --all (20 jobs per file) found gsp-path's crash from a point in a zero-area face at an
unwelded pole (trimesh_capsule.obj; fixed, tests/pathfinding_pole_test.cpp).
"""
import argparse
import json
import os
import random
import subprocess
import sys
import tempfile

MESH_EXTENSIONS = (".obj", ".off", ".ply", ".stl", ".gltf", ".glb", ".xyz")


def jobs(out):
    """(name, app, arguments after the input) for every job; outputs go to `out`."""
    o = lambda name: os.path.join(out, name)
    return [
        ("info", "gsp-info", []),
        ("geodesic", "gsp-geodesic", ["--source-vertex", "0", "-o", o("g.ply")]),
        ("geodesic-separate", "gsp-geodesic", ["--source-vertex", "0,1", "--separate", "-o", o("gs.txt")]),
        ("geodesic-matrix", "gsp-geodesic", ["--source-vertex", "0,1,2", "--matrix", "-o", o("gm.csv")]),
        ("path", "gsp-path", ["--from", "0", "--to", "1", "-o", o("p.json")]),
        ("path-astar", "gsp-path", ["--from", "0", "--to", "2", "--method", "astar", "-o", o("p.obj")]),
        ("sample", "gsp-sample", ["--count", "500", "-o", o("s.ply")]),
        ("render", "gsp-render", ["-o", o("r.png")]),
    ]


def more_jobs(out):
    """--all: the other methods, sources and apps (windows, line sources, metrics, point
    domain, farthest-point sampling, remeshing)."""
    o = lambda name: os.path.join(out, name)
    return [
        ("geodesic-windows", "gsp-geodesic", ["--source-vertex", "0", "--method", "windows", "-o", o("w.ply")]),
        ("geodesic-face-point", "gsp-geodesic", ["--source-face", "0:0.3,0.3", "--labels", "-o", o("f.ply")]),
        ("geodesic-boundary", "gsp-geodesic", ["--source-boundary", "-o", o("b.ply")]),
        ("geodesic-edges", "gsp-geodesic", ["--source-edges", "0-1", "-o", o("e.ply")]),
        ("geodesic-metric", "gsp-geodesic", ["--source-vertex", "0", "--metric", "direction=1,0,0:ratio=3", "-o", o("m.ply")]),
        ("geodesic-curvature", "gsp-geodesic", ["--source-vertex", "0", "--metric", "curvature:ratio=2", "-o", o("c.ply")]),
        ("geodesic-points", "gsp-geodesic", ["--source-vertex", "0", "--domain", "points", "-o", o("pt.ply")]),
        ("geodesic-input-faces", "gsp-geodesic", ["--source-vertex", "0", "--input-faces", "--precision", "single", "-o", o("i.ply")]),
        ("path-points", "gsp-path", ["--from", "0:0.2,0.2", "--to", "1e9,1e9,1e9", "2", "-o", o("pp.json")]),
        ("path-settle", "gsp-path", ["--from", "0", "--to", "2", "--method", "settle", "-o", o("ps.json")]),
        ("sample-farthest", "gsp-sample", ["--count", "300", "--mode", "farthest", "-o", o("sf.ply")]),
        ("cvt", "gsp-cvt", ["--vertices", "400", "--feature-angle", "40", "-o", o("cvt.ply")]),
    ]


def mesh_facts(bin_dir, path):
    """(vertices, faces, bbox min, bbox max) of the mesh as the apps load it (STL and glTF
    welded), from gsp-info --stats; None for a point cloud or a file gsp-info refuses."""
    p = subprocess.run([os.path.join(bin_dir, "gsp-info"), path, "--stats", "-", "-q"], stdin=subprocess.DEVNULL,
                       capture_output=True, text=True, errors="replace", timeout=120)
    if p.returncode != 0:
        return None
    r = json.loads(p.stdout)["result"]
    if r.get("point_cloud"):
        return None
    welded = path.lower().endswith((".stl", ".gltf", ".glb"))
    t = r["topology"]["welded" if welded else "raw"]
    box = r["geometry"]["bbox"]
    return t["vertices"], t["faces"], box["min"], box["max"]


def random_jobs(out, facts, rng, count):
    """`count` jobs with random arguments inside the mesh's ranges (vertices, faces, barycentric
    weights, points in and around the bounding box): sources and end points the fixed jobs never
    use (a vertex of a sliver, a point in a zero-area face, the same point twice)."""
    nv, nf, lo, hi = facts
    o = lambda name: os.path.join(out, name)
    v = lambda: str(rng.randrange(nv))
    bary = lambda: f"{rng.random():.6f},{rng.random() * 0.999:.6f}"
    face_point = lambda: f"{rng.randrange(nf)}:" + (lambda a, b: f"{a:.6f},{min(b, 1 - a):.6f}")(rng.random(), rng.random())
    point = lambda: ",".join(f"{l + (h - l) * (1.4 * rng.random() - 0.2):.6g}" for l, h in zip(lo, hi))
    end = lambda: rng.choice([v, face_point, point])()
    method = lambda: rng.choice(["windows", "astar", "settle", "full", "dijkstra-edges"])
    templates = [
        lambda: ("geodesic", ["--source-vertex", f"{v()},{v()}", "--labels", "-o", o("g.ply")]),
        lambda: ("geodesic", ["--source-face", face_point(), "--method", rng.choice(["gsp", "windows"]), "-o", o("g.ply")]),
        lambda: ("geodesic", ["--source-point", point(), "-o", o("g.obj")]),
        lambda: ("geodesic", ["--source-vertex", ",".join(v() for _ in range(3)), "--matrix", "-o", o("m.csv")]),
        lambda: ("geodesic", ["--source-vertex", v(), "--strategy",
                              rng.choice(["speed-limiter-postpone", "static-postpone", "dynamic-postpone", "hybrid-postpone",
                                          "bfs", "priority-queue"]), "--precision", rng.choice(["single", "double"]),
                              "-o", o("g.ply")]),
        lambda: ("path", ["--from", end(), "--to", end(), end(), "--method", method()] +
                 (["--one-end"] if rng.random() < 0.3 else []) + ["-o", o("p.json")]),
        lambda: ("path", ["--from", v(), "--to", v(), "--method", method(), "-o", o("p.obj")]),
        lambda: ("sample", ["--count", str(rng.randrange(1, 3000)), "--mode", rng.choice(["poisson", "farthest"]),
                            "-o", o("s.ply")]),
        lambda: ("cvt", rng.choice([["--vertices", str(rng.randrange(3, 800))],
                                    ["--edge-length", f"{rng.choice([0.5, 2, 5, 20, 60])}%"]]) +
                 ["--feature-angle", str(rng.choice([0, 20, 40, 89, 179])), "--init",
                  rng.choice(["poisson", "farthest", "random"]), "--iterations", str(rng.choice([0, 1, 5, 50])),
                  "--faces-per-site", str(rng.choice([0, 1, 12, 30])), "--threads", str(rng.choice([0, 1]))] +
                 [f for f in ("--no-fix", "--no-flip", "--no-smooth") if rng.random() < 0.2] +
                 ["--regions", o("r.ply"), "-o", o("c.ply")]),
        lambda: ("cvt", ["--vertices", str(rng.randrange(3, 800)), "--method", "edges", "--sizing-angle",
                         str(rng.choice([0, 1, 20, 57, 180])), "--feature-angle", str(rng.choice([0, 40, 89])),
                         "--threads", str(rng.choice([0, 1])), "-o", o("e.ply")]),
    ]
    apps = {"geodesic": "gsp-geodesic", "path": "gsp-path", "sample": "gsp-sample", "cvt": "gsp-cvt"}
    jobs = []
    for i in range(count):
        name, args = rng.choice(templates)()
        jobs.append((f"random-{i}-{name}", apps[name], args))
    return jobs


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("folders", nargs="+")
    ap.add_argument("--bin", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "build", "bin"))
    ap.add_argument("--timeout", type=float, default=120)
    ap.add_argument("--all", action="store_true", help="also the other methods, sources and apps (more_jobs)")
    ap.add_argument("--random", type=int, default=0, metavar="K", help="also K jobs per mesh with random arguments")
    ap.add_argument("--seed", type=int, default=1, help="seed of --random's arguments")
    a = ap.parse_args()
    rng = random.Random(a.seed)
    job_list = lambda out: jobs(out) + (more_jobs(out) if a.all else [])
    files = sorted(os.path.join(f, n) for f in a.folders for n in os.listdir(f) if n.lower().endswith(MESH_EXTENSIONS))
    findings = 0
    with tempfile.TemporaryDirectory() as out:
        for i, path in enumerate(files):
            print(f"[{i + 1}/{len(files)}] {os.path.basename(path)}", file=sys.stderr, end="\r")
            extra = []
            if a.random > 0:
                facts = mesh_facts(a.bin, path)
                if facts and facts[0] > 0 and facts[1] > 0:
                    extra = random_jobs(out, facts, rng, a.random)
            for name, app, args in job_list(out) + extra:
                cmd = [os.path.join(a.bin, app), path, "-q"] + args
                if app == "gsp-info":
                    cmd.remove("-q")
                try:
                    p = subprocess.run(cmd, stdin=subprocess.DEVNULL, capture_output=True, text=True,
                                       errors="replace", timeout=a.timeout)
                except subprocess.TimeoutExpired:
                    print(f"{os.path.basename(path)} {name}: over {a.timeout:g} s")
                    print(f"    {' '.join(cmd)}")
                    findings += 1
                    continue
                err = [l for l in p.stderr.splitlines() if l.strip()]
                bad = p.returncode < 0 or p.returncode not in (0, 1, 2, 3) or (p.returncode == 1 and len(err) != 1)
                if bad:
                    print(f"{os.path.basename(path)} {name}: exit {p.returncode}: {' | '.join(err)[:200]}")
                    print(f"    {' '.join(cmd)}")
                    findings += 1
    print(f"{len(files)} files, {len(job_list(''))} fixed jobs each (+ {a.random} random): {findings} finding(s)")
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
