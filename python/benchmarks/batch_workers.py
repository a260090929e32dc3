"""gsp.batch with 1 and with 2 Dask workers on the same folder of meshes: meshes per second and their ratio.

    PYTHONPATH=build/python /usr/bin/python3 python/benchmarks/batch_workers.py [FOLDER]
        [--jobs geodesic,remesh] [--repeat 3] [--command-line] [--worker-processes]

Without FOLDER, 25 meshes of ../shared/data/corpus (ones every job here handles) are copied to a
temporary folder. Two LocalClusters are started before any clock runs, one of 1 worker and one
of 2 (one thread each); the time is the whole gsp.batch.run (manifest, submission, the
apps on the workers, the results table) with force=True, so every mesh is computed. The runs
alternate between the two clusters and the median of --repeat is kept. The load average before
and after is printed: on a shared machine, another process on one of the cores takes the
second worker's core. With --command-line the whole command is timed instead (the interpreter,
Dask's import, the cluster's start and stop: what a user waits for); --worker-processes makes
the local workers processes instead of threads of the batch's process. The apps are found as
gsp-batch finds them (GSP_BIN_DIR, PATH, the checkout's build/bin).

Jobs: `geodesic` (--source-vertex 0: one field per mesh, 20-500 ms, most of it starting the app
and reading the mesh) and `remesh` (--vertices 300 --iterations 5: 0.4-3 s per mesh).
"""
import argparse
import json
import os
import pathlib
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]
CORPUS = ROOT.parent / "shared" / "data" / "corpus"
MESHES = [
    "assimp_spider.obj", "blobby_shuffled.off", "blub_fish.obj", "boat_developable.obj", "cgal_anchor_dense.off",
    "cgal_blade.off", "cgal_bones.off", "cgal_man.off", "cgal_pig.stl", "cgal_turbine.off",
    "cow_remeshed_lowres.obj", "demosthenes_lowres.obj", "diplodocus.off", "fandisk_large.off",
    "great_white_shark.stl", "libigl_arm.obj", "mannequin_devil.off", "meshopt_pirate.obj", "pmp_sphere.off",
    "spot_remeshed.obj", "thingi10k_37863_log_cabin_log.stl", "thingi10k_50736_partial_gear.stl",
    "thingi10k_68435_viper_cookie_cutter.stl",
    "trimesh_capsule.obj", "triple_vierbein.obj",
]
OPTIONS = {
    "geodesic": ["--source-vertex", "0"],
    "sample": ["--count", "500"],
    "remesh": ["--vertices", "300", "--iterations", "5"],
    "path": ["--from", "0", "--to", "1"],
}


def measure_command_line(job, folder, repeat, scratch, processes):
    """The same for the whole command (`python3 -m gsp.batch JOB FOLDER -o OUT --workers W --force`):
    the interpreter, Dask's import and the local cluster's start and stop included."""
    times, own = {1: [], 2: []}, {1: [], 2: []}
    for i in range(repeat):
        for w in (1, 2):
            out = pathlib.Path(scratch) / f"{job}-{w}-{i}"
            argv = [sys.executable, "-m", "gsp.batch", job, str(folder), "-o", str(out), "--workers", str(w),
                    "--force", "-q", *(["--worker-processes"] if processes else []), "--", *OPTIONS[job]]
            t0 = time.perf_counter()
            done = subprocess.run(argv, capture_output=True, text=True)
            times[w].append(time.perf_counter() - t0)
            if done.returncode not in (0, 1):     # 1: some mesh failed (a row; the same in every run)
                sys.exit(f"{job}: {done.stderr.strip()}")
            with open(out / "results.json", encoding="utf-8") as f:
                rows = json.load(f)["rows"]
            own[w].append(sum(r.get("time_total") or 0 for r in rows))
            shutil.rmtree(out)
    failed = sum(r["status"] != "ok" for r in rows)
    return {w: (len(rows), statistics.median(times[w]), statistics.median(own[w]), failed) for w in times}


def measure(job, folder, repeat, scratch, processes=False):
    """{workers: (meshes, median seconds, the apps' own seconds, failed meshes)} for 1 and 2 workers; the runs
    alternate between the two clusters so that whatever else the machine does hits both alike."""
    import gsp.batch
    clusters = {w: gsp.batch.connect(workers=w, processes=processes) for w in (1, 2)}
    try:
        for w, (client, _) in clusters.items():
            client.wait_for_workers(w)
        times, own = {1: [], 2: []}, {1: [], 2: []}
        for i in range(repeat):
            for w, (client, _) in clusters.items():
                out = pathlib.Path(scratch) / f"{job}-{w}-{i}"
                t0 = time.perf_counter()
                rows = gsp.batch.run(job, [folder], out, client=client, options=OPTIONS[job], force=True)
                times[w].append(time.perf_counter() - t0)
                own[w].append(sum(r.get("time_total") or 0 for r in rows))
                shutil.rmtree(out)
        failed = sum(r["status"] != "ok" for r in rows)
        return {w: (len(rows), statistics.median(times[w]), statistics.median(own[w]), failed) for w in times}
    finally:
        for _, close in clusters.values():
            close()


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("folder", nargs="?", help="meshes (default: 24 corpus meshes)")
    ap.add_argument("--jobs", default="geodesic,remesh", help="comma-separated: geodesic, sample, remesh, path")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--worker-processes", action="store_true", help="the local workers as processes, not threads")
    ap.add_argument("--command-line", action="store_true",
                    help="time the whole command (cluster start and stop included), not run() on started clusters")
    args = ap.parse_args()
    with tempfile.TemporaryDirectory(prefix="gsp-batch-bench-") as scratch:
        folder = args.folder
        if folder is None:
            folder = pathlib.Path(scratch) / "meshes"
            folder.mkdir()
            for name in MESHES:
                shutil.copy(CORPUS / name, folder / name)
        print(f"{len(os.listdir(folder))} files in {folder}, {os.cpu_count()} cores, median of {args.repeat} runs, "
              f"workers as {'processes' if args.worker_processes else 'threads'}, "
              f"{'the whole command' if args.command_line else 'run() on started clusters'}")
        for job in args.jobs.split(","):
            load = os.getloadavg()[0]
            if args.command_line:
                results = measure_command_line(job, folder, args.repeat, scratch, args.worker_processes)
            else:
                results = measure(job, folder, args.repeat, scratch, args.worker_processes)
            n = results[1][0]
            rate = {w: n / results[w][1] for w in results}
            print(f"{job} {' '.join(OPTIONS[job])}: {n} meshes ({results[1][3]} failed), the apps' own time {results[1][2]:.2f} s; "
                  f"1 worker {results[1][1]:.2f} s ({rate[1]:.2f} meshes/s), "
                  f"2 workers {results[2][1]:.2f} s ({rate[2]:.2f} meshes/s), ratio {rate[2] / rate[1]:.2f}x "
                  f"(load average {load:.2f} before, {os.getloadavg()[0]:.2f} after)")


if __name__ == "__main__":    # worker processes are spawned: the guard is needed
    main()
