"""gsp.batch with 1 and with 2 Dask workers on the same folder of meshes: meshes per second and their ratio.

    PYTHONPATH=build/python /usr/bin/python3 python/benchmarks/batch_workers.py [FOLDER]
        [--jobs geodesic,remesh] [--repeat 3]

Without FOLDER, 25 meshes of ../shared/data/corpus (ones every job here handles) are copied to a
temporary folder. Two LocalClusters are started before any clock runs, one of 1 worker process
and one of 2 (one thread each); the time is the whole gsp.batch.run (manifest, submission, the
apps on the workers, the results table) with force=True, so every mesh is computed. The runs
alternate between the two clusters and the median of --repeat is kept. The load average before
and after is printed: on a shared machine, another process on one of the cores takes the
second worker's core. The apps are found as gsp-batch finds them (GSP_BIN_DIR, PATH, the
checkout's build/bin).

Jobs: `geodesic` (--source-vertex 0: one field per mesh, 20-500 ms, most of it starting the app
and reading the mesh) and `remesh` (--vertices 300 --iterations 5: 0.4-3 s per mesh).
"""
import argparse
import os
import pathlib
import shutil
import statistics
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


def measure(job, folder, repeat, scratch):
    """{workers: (meshes, median seconds, the apps' own seconds)} for 1 and 2 workers; the runs
    alternate between the two clusters so that whatever else the machine does hits both alike."""
    import gsp.batch
    clusters = {w: gsp.batch.connect(workers=w) for w in (1, 2)}
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
                failed = [r for r in rows if r["status"] != "ok"]
                if failed:
                    sys.exit(f"{job}: {failed[0]['input']}: {failed[0]['error']}")
                own[w].append(sum(r["time_total"] for r in rows))
                shutil.rmtree(out)
        return {w: (len(rows), statistics.median(times[w]), statistics.median(own[w])) for w in times}
    finally:
        for _, close in clusters.values():
            close()


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("folder", nargs="?", help="meshes (default: 24 corpus meshes)")
    ap.add_argument("--jobs", default="geodesic,remesh", help="comma-separated: geodesic, sample, remesh, path")
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    with tempfile.TemporaryDirectory(prefix="gsp-batch-bench-") as scratch:
        folder = args.folder
        if folder is None:
            folder = pathlib.Path(scratch) / "meshes"
            folder.mkdir()
            for name in MESHES:
                shutil.copy(CORPUS / name, folder / name)
        print(f"{len(os.listdir(folder))} files in {folder}, {os.cpu_count()} cores, median of {args.repeat} runs")
        for job in args.jobs.split(","):
            load = os.getloadavg()[0]
            results = measure(job, folder, args.repeat, scratch)
            n = results[1][0]
            rate = {w: n / results[w][1] for w in results}
            print(f"{job} {' '.join(OPTIONS[job])}: {n} meshes, the apps' own time {results[1][2]:.2f} s; "
                  f"1 worker {results[1][1]:.2f} s ({rate[1]:.2f} meshes/s), "
                  f"2 workers {results[2][1]:.2f} s ({rate[2]:.2f} meshes/s), ratio {rate[2] / rate[1]:.2f}x "
                  f"(load average {load:.2f} before, {os.getloadavg()[0]:.2f} after)")


if __name__ == "__main__":    # LocalCluster starts its workers by spawning: the guard is needed
    main()
