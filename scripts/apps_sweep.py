#!/usr/bin/python3
"""Runs every app on every mesh of one or more folders and reports what breaks the CLI contract:
an exit by a signal (a crash), an exit code other than 0, 1 (bad input, one line on stderr) and
3 (gsp-path: no path), a run past the time limit, or exit 1 without exactly one stderr line.

    scripts/apps_sweep.py ../shared/data/corpus ../shared/data/meshes [--bin build/bin] [--timeout 120]

Prints one line per finding and a count at the end; exit status 1 when there is any. Session
22's sweep of the 94 corpus and shared files found gsp-cvt-compare's CGAL crash on
libigl_degenerated.obj and the point clouds' --separate usage error (both fixed).
"""
import argparse
import os
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


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("folders", nargs="+")
    ap.add_argument("--bin", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "build", "bin"))
    ap.add_argument("--timeout", type=float, default=120)
    a = ap.parse_args()
    files = sorted(os.path.join(f, n) for f in a.folders for n in os.listdir(f) if n.lower().endswith(MESH_EXTENSIONS))
    findings = 0
    with tempfile.TemporaryDirectory() as out:
        for i, path in enumerate(files):
            print(f"[{i + 1}/{len(files)}] {os.path.basename(path)}", file=sys.stderr, end="\r")
            for name, app, args in jobs(out):
                cmd = [os.path.join(a.bin, app), path, "-q"] + args
                if app == "gsp-info":
                    cmd.remove("-q")
                try:
                    p = subprocess.run(cmd, stdin=subprocess.DEVNULL, capture_output=True, text=True,
                                       errors="replace", timeout=a.timeout)
                except subprocess.TimeoutExpired:
                    print(f"{os.path.basename(path)} {name}: over {a.timeout:g} s")
                    findings += 1
                    continue
                err = [l for l in p.stderr.splitlines() if l.strip()]
                bad = p.returncode < 0 or p.returncode not in (0, 1, 3) or (p.returncode == 1 and len(err) != 1)
                if bad:
                    print(f"{os.path.basename(path)} {name}: exit {p.returncode}: {' | '.join(err)[:200]}")
                    findings += 1
    print(f"{len(files)} files, {len(jobs(''))} jobs each: {findings} finding(s)")
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
