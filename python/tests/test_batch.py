"""gsp.batch on a real Dask cluster on this machine: a dask-scheduler and two dask-worker
processes on 127.0.0.1 (one thread each) running the real apps.

Covers: a folder with broken files (rows with the apps' one-line errors, the rest ok), outputs
byte-identical to the apps run one by one, a worker killed with SIGKILL in the middle of a run
(every mesh still accounted for), a second run that does nothing (all skipped) and a changed
option or input that re-runs, module:function jobs, timeouts and memory limits, gsp-path's
unreachable ends, gsp-bench's figures, and the command line's exit codes.
"""
import csv
import json
import os
import pathlib
import shutil
import signal
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

import pytest

from conftest import BIN_DIR, DATA_DIR, shared_mesh

import gsp
import gsp.batch as batch
from batch_jobs import surface

pytest.importorskip("distributed")

TESTS_DIR = pathlib.Path(__file__).resolve().parent
CORPUS_DIR = DATA_DIR.parent / "corpus"
GOOD = ["fertility.off", "camelhead.off", "manifold_offset1.obj", "newell_teapot.obj", "openscad_nonmanifold_crash.obj"]
# ~0.4-1.7 s each for `remesh --vertices 300 --iterations 5` (2 cores), for the worker-kill test.
REMESH_MESHES = ["blobby_shuffled.off", "cgal_bones.off", "pmp_sphere.off", "cow_remeshed_lowres.obj",
                 "cgal_anchor_dense.off", "spot_remeshed.obj", "libigl_arm.obj", "mannequin_devil.off",
                 "assimp_spider.obj", "blub_fish.obj"]
REMESH_OPTIONS = ["--vertices", "300", "--iterations", "5"]
# Of GOOD, those gsp-cvt remeshes with REMESH_OPTIONS (manifold_offset1's components are too
# small for 300 sites, openscad_nonmanifold_crash is non-manifold: both exit 1, by design).
REMESHABLE = ["fertility.off", "camelhead.off", "newell_teapot.obj"]


def _env():
    """The environment of the workers and the command line: the package and this folder importable."""
    env = dict(os.environ)
    package_dir = str(pathlib.Path(gsp.__file__).resolve().parent.parent)
    env["PYTHONPATH"] = os.pathsep.join(p for p in (package_dir, str(TESTS_DIR), env.get("PYTHONPATH")) if p)
    env["GSP_BIN_DIR"] = str(BIN_DIR)
    return env


class Cluster:
    """dask-scheduler + dask-worker processes, each in its own process group (killed as a whole)."""

    def __init__(self, folder, workers=2):
        self.folder = pathlib.Path(folder)
        self.scheduler_file = self.folder / "scheduler.json"
        self.procs = {}
        self.logs = []
        self.procs["scheduler"] = self._start(
            "scheduler", "distributed.cli.dask_scheduler", "--scheduler-file", str(self.scheduler_file),
            "--host", "127.0.0.1", "--port", "0", "--no-dashboard", "--dashboard-address", "127.0.0.1:0")
        self._wait(lambda: self.scheduler_file.exists() and self.scheduler_file.stat().st_size > 0, "the scheduler")
        for i in range(workers):
            self.add_worker(f"w{i}")
        self.wait_workers(workers)

    def _start(self, name, module, *args):
        log = open(self.folder / f"{name}.log", "wb")
        self.logs.append(log)
        return subprocess.Popen([sys.executable, "-m", module, *args], stdout=log, stderr=subprocess.STDOUT,
                                env=_env(), cwd=self.folder, start_new_session=True)

    def add_worker(self, name):
        self.procs[name] = self._start(name, "distributed.cli.dask_worker", "--scheduler-file",
                                       str(self.scheduler_file), "--nthreads", "1", "--no-nanny", "--name", name,
                                       "--host", "127.0.0.1", "--no-dashboard", "--memory-limit", "0",
                                       "--local-directory", str(self.folder / name))

    def _wait(self, ready, what, timeout=60):
        end = time.monotonic() + timeout
        while not ready():
            for name, p in self.procs.items():
                if p.poll() is not None:
                    raise RuntimeError(f"{name} exited with {p.returncode}: "
                                       f"{(self.folder / (name + '.log')).read_text(errors='replace')[-2000:]}")
            if time.monotonic() > end:
                raise RuntimeError(f"{what} did not start in {timeout} s")
            time.sleep(0.1)

    def client(self):
        from distributed import Client
        return Client(scheduler_file=str(self.scheduler_file), timeout="30s")

    def wait_workers(self, n):
        with self.client() as c:
            c.wait_for_workers(n, timeout=60)

    def worker_addresses(self):
        """{worker name: address} as the scheduler knows them."""
        with self.client() as c:
            return {w["name"]: a for a, w in c.scheduler_info()["workers"].items()}

    def kill(self, name, sig=signal.SIGKILL):
        p = self.procs[name]
        try:
            os.killpg(p.pid, sig)
        except ProcessLookupError:
            pass
        try:
            p.wait(timeout=20)
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            p.wait(timeout=20)

    def stop(self):
        for name in list(self.procs)[::-1]:
            if self.procs[name].poll() is None:
                self.kill(name, signal.SIGTERM)
        for log in self.logs:
            log.close()

    def alive(self):
        return [name for name, p in self.procs.items() if p.poll() is None]


@pytest.fixture(scope="module")
def cluster(tmp_path_factory):
    c = Cluster(tmp_path_factory.mktemp("cluster"))
    yield c
    c.stop()
    assert not c.alive()


@pytest.fixture
def fresh_cluster(tmp_path):
    """A cluster of its own (a test kills one of its workers)."""
    (tmp_path / "cluster").mkdir()
    c = Cluster(tmp_path / "cluster")
    yield c
    c.stop()
    assert not c.alive()


@pytest.fixture(scope="module")
def mesh_folder(tmp_path_factory):
    """Five good meshes, a truncated OFF and a text file named .obj (plus a README that is no mesh)."""
    folder = tmp_path_factory.mktemp("meshes")
    for name in GOOD:
        shutil.copy(shared_mesh(name), folder / name)
    (folder / "truncated.off").write_bytes((DATA_DIR / "fertility.off").read_bytes()[:3000])
    (folder / "notes.obj").write_text("these are notes, not a mesh\n")
    (folder / "README.md").write_text("not an input\n")
    return folder


def app(name):
    return str(BIN_DIR / name)


def run_app(*argv):
    """An app one by one: (exit code, its last stderr line)."""
    p = subprocess.run([str(a) for a in argv], capture_output=True, text=True)
    lines = [l for l in p.stderr.splitlines() if l.strip()]
    return p.returncode, (lines[-1].strip() if lines else "")


def cli(*argv, cwd=None):
    """`python3 -m gsp.batch ARGV`: (exit code, stderr)."""
    p = subprocess.run([sys.executable, "-m", "gsp.batch", *map(str, argv)], capture_output=True, text=True,
                       env=_env(), cwd=cwd or TESTS_DIR, timeout=300)
    return p.returncode, p.stderr


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def by_name(rows):
    return {pathlib.Path(r["input"]).name: r for r in rows}


# ---------------------------------------------------------------------------------------------


def test_folder_with_broken_files_equals_the_apps(cluster, mesh_folder, tmp_path):
    out = tmp_path / "out"
    seen = []
    rows = batch.run("geodesic", [mesh_folder], out, scheduler=cluster.scheduler_file, bin_dir=BIN_DIR,
                     options=["--source-vertex", "0"], progress=lambda row, done, total: seen.append((done, total)))
    assert [d for d, _ in seen] == list(range(1, 8)) and {t for _, t in seen} == {7}
    rows = by_name(rows)
    assert sorted(rows) == sorted(GOOD + ["truncated.off", "notes.obj"])   # README.md is not a mesh
    workers = set(cluster.worker_addresses().values())

    ref = tmp_path / "ref"
    ref.mkdir()
    for name in GOOD:
        row = rows[name]
        stem = pathlib.Path(name).stem
        assert row["status"] == "ok" and row["error"] == "" and row["output"] == stem + ".ply"
        assert row["worker"] in workers
        code, _ = run_app(app("gsp-geodesic"), mesh_folder / name, "--source-vertex", "0", "-o", ref / (stem + ".ply"),
                          "--stats", ref / (stem + ".json"), "-q")
        assert code == 0
        assert (out / row["output"]).read_bytes() == (ref / (stem + ".ply")).read_bytes(), name
        stats = json.loads((ref / (stem + ".json")).read_text())
        assert row["vertices"] == stats["input"]["vertices"] == len(gsp.read_mesh(mesh_folder / name)[0])
        assert row["faces"] == stats["input"]["triangles"]
        assert row["result.max_distance"] == stats["result"]["max_distance"]
        assert row["result.vertices_reached"] == stats["result"]["vertices_reached"]
        assert row["time_total"] > 0 and row["seconds"] >= row["time_total"]
    for name in ("truncated.off", "notes.obj"):
        row = rows[name]
        code, line = run_app(app("gsp-geodesic"), mesh_folder / name, "--source-vertex", "0", "-o", ref / "x.ply")
        assert code == 1 and line.startswith("gsp-geodesic: error: ")
        assert row["status"] == "error" and row["error"] == line and row["output"] is None
        assert row["vertices"] is None
    assert not (ref / "x.ply").exists()
    assert sorted(p.name for p in out.iterdir()) == sorted(
        [pathlib.Path(n).stem + ".ply" for n in GOOD] + ["manifest.jsonl", "results.csv", "results.json"])

    table = by_name(read_csv(out / "results.csv"))
    assert list(read_csv(out / "results.csv")[0])[:10] == batch.COLUMNS
    for name, row in rows.items():
        assert table[name]["status"] == row["status"] and table[name]["error"] == row["error"]
        assert table[name]["vertices"] == ("" if row["vertices"] is None else str(row["vertices"]))
    assert float(table["fertility.off"]["result.max_distance"]) == rows["fertility.off"]["result.max_distance"]
    doc = json.loads((out / "results.json").read_text())
    assert doc["job"] == "geodesic" and doc["options"] == ["--source-vertex", "0"]
    assert doc["counts"] == {"ok": 5, "skipped": 0, "error": 2}
    assert by_name(doc["rows"]) == rows


def test_second_run_skips_and_changes_rerun(cluster, tmp_path):
    meshes = tmp_path / "in"
    meshes.mkdir()
    for name in GOOD[:3]:
        shutil.copy(shared_mesh(name), meshes / name)
    out = tmp_path / "out"
    common = dict(scheduler=cluster.scheduler_file, bin_dir=BIN_DIR)
    first = batch.run("sample", [meshes / "*.off", meshes / "*.obj"], out, options=["--count", "40"], **common)
    assert [r["status"] for r in first] == ["ok"] * 3
    assert all(r["result.count"] > 30 for r in first)
    mtimes = {p.name: p.stat().st_mtime_ns for p in out.glob("*.ply")}
    assert len(mtimes) == 3

    # The same command again: nothing runs, every row is skipped with the first run's figures.
    code, err = cli("sample", meshes / "*.off", meshes / "*.obj", "-o", out, "--scheduler", cluster.scheduler_file,
                    "--count", "40")
    assert code == 0, err
    assert "3 meshes" in err and "0 ok, 3 skipped, 0 failed" in err
    again = by_name(json.loads((out / "results.json").read_text())["rows"])
    for r in first:
        name = pathlib.Path(r["input"]).name
        assert again[name]["status"] == "skipped"
        assert again[name]["result.count"] == r["result.count"]
        assert again[name]["output"] == r["output"]
    assert {p.name: p.stat().st_mtime_ns for p in out.glob("*.ply")} == mtimes

    # A changed option re-runs everything.
    changed = batch.run("sample", [meshes], out, options=["--count", "60"], **common)
    assert [r["status"] for r in changed] == ["ok"] * 3
    assert all(r["result.count"] > 45 for r in changed)
    mtimes = {p.name: p.stat().st_mtime_ns for p in out.glob("*.ply")}

    # A changed input re-runs that mesh only; so does a missing output.
    text = (meshes / "fertility.off").read_text()
    (meshes / "fertility.off").write_text(text + "\n")   # same mesh, other bytes
    (out / "camelhead.ply").unlink()
    rows = by_name(batch.run("sample", [meshes], out, options=["--count", "60"], **common))
    assert {n: r["status"] for n, r in rows.items()} == {
        "fertility.off": "ok", "camelhead.off": "ok", "manifold_offset1.obj": "skipped"}
    assert (out / "manifold_offset1.ply").stat().st_mtime_ns == mtimes["manifold_offset1.ply"]
    manifest = [json.loads(l) for l in (out / "manifest.jsonl").read_text().splitlines()]
    assert sorted(e["output_name"] for e in manifest) == ["camelhead.ply", "fertility.ply", "manifold_offset1.ply"]

    # --force re-runs what is complete.
    rows = batch.run("sample", [meshes], out, options=["--count", "60"], force=True, **common)
    assert [r["status"] for r in rows] == ["ok"] * 3


def test_stopped_run_resumes(cluster, mesh_folder, tmp_path):
    """Ctrl-C after the first mesh: the tables say what finished, a second run does the rest."""
    out = tmp_path / "out"
    names = [n for n in GOOD if n in REMESHABLE]

    def stop(row, done, total):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        batch.run("remesh", [mesh_folder / n for n in names], out, scheduler=cluster.scheduler_file,
                  bin_dir=BIN_DIR, options=REMESH_OPTIONS, progress=stop)
    table = read_csv(out / "results.csv")
    assert len(table) == len(names)
    done = [r for r in table if r["status"] == "ok"]
    assert len(done) == 1
    assert {r["error"] for r in table if r["status"] != "ok"} == {"not finished: interrupted"}
    manifest = [json.loads(l) for l in (out / "manifest.jsonl").read_text().splitlines()]
    assert [e["output_name"] for e in manifest] == [done[0]["output"]]

    rows = batch.run("remesh", [mesh_folder / n for n in names], out, scheduler=cluster.scheduler_file,
                     bin_dir=BIN_DIR, options=REMESH_OPTIONS)
    assert sorted(r["status"] for r in rows) == ["ok"] * (len(names) - 1) + ["skipped"]
    assert next(r for r in rows if r["status"] == "skipped")["output"] == done[0]["output"]


def test_worker_killed_in_the_middle(fresh_cluster, tmp_path):
    meshes = tmp_path / "in"
    meshes.mkdir()
    for name in REMESH_MESHES:
        if not (CORPUS_DIR / name).exists():
            pytest.skip(f"corpus mesh {CORPUS_DIR / name} not present")
        shutil.copy(CORPUS_DIR / name, meshes / name)
    addresses = fresh_cluster.worker_addresses()
    victim = {}

    def progress(row, done, total):
        if not victim:     # the first result is in: kill the other worker, busy with its own mesh
            name = next(n for n, a in addresses.items() if a != row["worker"])
            fresh_cluster.kill(name)
            victim.update(name=name, address=addresses[name], done=done)

    out = tmp_path / "out"
    rows = batch.run("remesh", [meshes], out, scheduler=fresh_cluster.scheduler_file, bin_dir=BIN_DIR,
                     options=REMESH_OPTIONS, progress=progress)
    assert victim["done"] == 1 and fresh_cluster.procs[victim["name"]].poll() is not None
    survivor = next(a for n, a in addresses.items() if n != victim["name"])
    assert len(rows) == len(REMESH_MESHES)
    assert [r["status"] for r in rows] == ["ok"] * len(REMESH_MESHES), [(r["input"], r["error"]) for r in rows if r["status"] != "ok"]
    # Everything after the kill ran on the survivor (the killed worker's mesh was re-run there).
    assert sum(r["worker"] == victim["address"] for r in rows) <= 1
    assert sum(r["worker"] == survivor for r in rows) >= len(REMESH_MESHES) - 1

    ref = tmp_path / "ref"
    ref.mkdir()

    def one(name):
        target = ref / (pathlib.Path(name).stem + ".ply")
        return run_app(app("gsp-cvt"), meshes / name, *REMESH_OPTIONS, "-o", target, "-q")[0], target

    with ThreadPoolExecutor(2) as pool:
        for name, (code, target) in zip(REMESH_MESHES, pool.map(one, REMESH_MESHES)):
            assert code == 0
            assert (out / target.name).read_bytes() == target.read_bytes(), name
    rows = by_name(rows)
    for name in REMESH_MESHES:
        assert rows[name]["output_vertices"] > 200 and rows[name]["quality.min_angle"] > 0


def test_callable_jobs(cluster, mesh_folder, tmp_path):
    out = tmp_path / "out"
    rows = by_name(batch.run("batch_jobs:area", [mesh_folder], out, scheduler=cluster.scheduler_file))
    for name in GOOD:
        V, F = gsp.read_mesh(mesh_folder / name)
        a, euler = surface(V, F)
        row = rows[name]
        assert row["status"] == "ok" and row["vertices"] == len(V) and row["faces"] == len(F)
        assert row["area"] == pytest.approx(a, rel=1e-12) and row["euler"] == euler
        assert row["max_x"] == V[:, 0].max()
        gsp.write_mesh(tmp_path / "ref.ply", V, F)
        assert (out / row["output"]).read_bytes() == (tmp_path / "ref.ply").read_bytes()
        assert row["time_compute"] > 0
    assert rows["fertility.off"]["euler"] == -6     # genus 4
    for name in ("truncated.off", "notes.obj"):
        assert rows[name]["status"] == "error" and rows[name]["output"] is None
        assert rows[name]["error"].startswith("batch_jobs:area: error: OSError: ")
    assert "cannot fit" in rows["truncated.off"]["error"]
    assert not [p for p in out.iterdir() if ".tmp" in p.name]   # temporary names renamed or removed

    # A callable object from the Python API, the input= keyword, a job that writes nothing.
    import batch_jobs
    rows = batch.run(batch_jobs.name_only, [mesh_folder / "fertility.off"], tmp_path / "named",
                     scheduler=cluster.scheduler_file)
    assert rows[0]["status"] == "ok" and rows[0]["name"] == "fertility.off" and rows[0]["triangles"] == 9000
    assert rows[0]["output"] is None

    # The job's own failures are one-line errors.
    rows = by_name(batch.run("batch_jobs:refuse_small", [mesh_folder / "fertility.off",
                                                           mesh_folder / "manifold_offset1.obj"],
                             tmp_path / "refuse", scheduler=cluster.scheduler_file))
    assert rows["fertility.off"]["status"] == "ok" and rows["fertility.off"]["vertices_seen"] == 4494
    assert rows["manifold_offset1.obj"]["error"] == "batch_jobs:refuse_small: error: ValueError: only 2287 vertices"
    rows = batch.run("batch_jobs:not_a_dict", [mesh_folder / "fertility.off"], tmp_path / "list",
                     scheduler=cluster.scheduler_file)
    assert rows[0]["status"] == "error" and "returned a list, not a dict" in rows[0]["error"]


def test_timeout_memory_and_unreachable_paths(cluster, mesh_folder, tmp_path):
    camel = mesh_folder / "camelhead.off"
    rows = batch.run("remesh", [camel], tmp_path / "t", scheduler=cluster.scheduler_file, bin_dir=BIN_DIR,
                     options=["--vertices", "20000"], timeout=0.5)
    assert rows[0]["status"] == "error" and rows[0]["error"] == "gsp-cvt: timed out after 0.5 s"
    assert not list((tmp_path / "t").glob("*.ply"))

    rows = batch.run("remesh", [camel], tmp_path / "m", scheduler=cluster.scheduler_file, bin_dir=BIN_DIR,
                     options=["--vertices", "20000"], max_memory="200M")
    # Refused before the working mesh is built: the address-space limit is the memory it may
    # plan for (gsp::available_memory); a run that got further would end "out of memory".
    assert rows[0]["status"] == "error" and rows[0]["error"].startswith(f"gsp-cvt: error: {camel}: ")
    assert "GB of memory is available: ask for fewer vertices" in rows[0]["error"], rows[0]["error"]

    two_parts = CORPUS_DIR / "tetra_and_separate_triangle.off"
    if not two_parts.exists():
        pytest.skip(f"{two_parts} not present")
    rows = by_name(batch.run("path", [two_parts, mesh_folder / "fertility.off"], tmp_path / "p",
                             scheduler=cluster.scheduler_file, bin_dir=BIN_DIR, options=["--from", "0", "--to", "5"]))
    code, line = run_app(app("gsp-path"), two_parts, "--from", "0", "--to", "5", "-o", tmp_path / "x.ply")
    assert code == 3
    assert rows[two_parts.name]["status"] == "error" and rows[two_parts.name]["error"] == line
    assert rows[two_parts.name]["result.found"] == 0 and rows[two_parts.name]["output"] is None
    ok = rows["fertility.off"]
    assert ok["status"] == "ok" and ok["result.found"] == 1 and ok["result.paths"][0]["length"] > 0

    rows = batch.run("bench", [mesh_folder / "fertility.off"], tmp_path / "b", scheduler=cluster.scheduler_file,
                     bin_dir=BIN_DIR, options=["--methods", "gsp,dijkstra", "--sources", "2", "--repetitions", "1"])
    row = rows[0]
    assert row["status"] == "ok" and row["output"] == "fertility.json"
    assert row["vertices"] == 4494 and row["gsp.query_s"] > 0 and row["dijkstra.status"] == "ok"
    report = json.loads((tmp_path / "b" / "fertility.json").read_text())
    assert report["meshes"][0]["methods"][0]["query_s"] == row["gsp.query_s"]


def test_command_line_exit_codes(cluster, mesh_folder, tmp_path):
    sched = ["--scheduler", cluster.scheduler_file]
    good = [mesh_folder / "fertility.off", mesh_folder / "manifold_offset1.obj"]
    code, err = cli("geodesic", *good, "-o", tmp_path / "ok", *sched, "--", "--source-vertex", "0")
    assert code == 0, err
    assert err.strip().splitlines()[-1].startswith("gsp-batch: 2 meshes in ")
    assert (tmp_path / "ok" / "fertility.ply").exists() and (tmp_path / "ok" / "results.csv").exists()

    code, err = cli("geodesic", mesh_folder, "-o", tmp_path / "some", *sched, "--source-vertex", "0", "-q")
    assert code == 1
    assert "5 ok, 0 skipped, 2 failed" in err and "notes.obj" not in err   # -q: the summary only
    assert len(read_csv(tmp_path / "some" / "results.csv")) == 7

    # A callable from the current folder (the tests), and the gsp-batch entry point's main().
    code, err = cli("batch_jobs:area", good[0], "-o", tmp_path / "callable", *sched)
    assert code == 0, err
    assert read_csv(tmp_path / "callable" / "results.csv")[0]["euler"] == "-6"

    usage = [
        (["geodesic"], "the following arguments are required"),
        (["frobnicate", good[0], "-o", tmp_path / "u"], "frobnicate: unknown job"),
        (["geodesic", tmp_path / "missing.off", "-o", tmp_path / "u"], "missing.off: no such file or folder"),
        (["geodesic", str(tmp_path / "*.nothing"), "-o", tmp_path / "u"], "no file matches"),
        (["geodesic", good[0], "-o", tmp_path / "u", "--workers", "2", *sched], "not allowed with argument"),
        (["geodesic", good[0], "-o", tmp_path / "u", "--workers", "0"], "--workers 0: at least 1"),
        (["geodesic", good[0], "-o", tmp_path / "u", "--worker-processes", *sched],
         "--worker-processes applies to a local cluster"),
        (["geodesic", good[0], "-o", tmp_path / "u", "--stats", "x.json"], "--stats: gsp-batch sets this option"),
        (["batch_jobs:nothing", good[0], "-o", tmp_path / "u"], "batch_jobs has no nothing"),
        (["no_such_module:f", good[0], "-o", tmp_path / "u"], "cannot import no_such_module"),
        (["geodesic", good[0], "-o", tmp_path / "u", "--bin", tmp_path], "gsp-geodesic not found"),
        # The app's own usage error (its exit 2) stops the batch: it would fail every mesh.
        (["geodesic", *good, "-o", tmp_path / "u", *sched, "--source-vertex", "0", "--no-such-option"],
         "--no-such-option"),
    ]
    for argv, message in usage:
        code, err = cli(*argv)
        assert code == 2, (argv, err)
        assert message in err, (argv, err)
        assert err.startswith("gsp-batch: error: "), err           # one line, then the hint
        assert err.splitlines()[1:] == ["Run with --help for more information."], err
    assert not (tmp_path / "u" / "results.csv").exists()


def test_local_cluster_from_the_command_line(mesh_folder, tmp_path):
    code, err = cli("sample", mesh_folder / "fertility.off", mesh_folder / "newell_teapot.obj", "-o", tmp_path / "o",
                    "--workers", "2", "--count", "30")
    assert code == 0, err
    lines = err.strip().splitlines()
    assert lines[0].startswith("gsp-batch: dashboard http://127.0.0.1:"), err    # LocalCluster's
    assert "2 ok, 0 skipped, 0 failed" in lines[-1]
    rows = read_csv(tmp_path / "o" / "results.csv")
    assert [r["status"] for r in rows] == ["ok", "ok"]
    assert len({r["worker"] for r in rows}) >= 1
    # The same with the workers as processes: other workers, the same outputs.
    code, err = cli("sample", mesh_folder / "fertility.off", mesh_folder / "newell_teapot.obj", "-o", tmp_path / "p",
                    "--workers", "2", "--worker-processes", "--count", "30")
    assert code == 0, err
    rows = read_csv(tmp_path / "p" / "results.csv")
    assert [r["status"] for r in rows] == ["ok", "ok"]
    assert all(r["worker"].startswith("tcp://127.0.0.1:") for r in rows), rows
    for r in rows:
        assert (tmp_path / "p" / r["output"]).read_bytes() == (tmp_path / "o" / r["output"]).read_bytes()
    # Nothing left to do: no cluster is started.
    code, err = cli("sample", mesh_folder / "fertility.off", mesh_folder / "newell_teapot.obj", "-o", tmp_path / "o",
                    "--workers", "2", "--count", "30")
    assert code == 0 and "dashboard" not in err and "0 ok, 2 skipped" in err


def test_local_workers_are_threads_unless_asked():
    for processes in (False, True):
        client, close = batch.connect(workers=2, processes=processes)
        try:
            client.wait_for_workers(2)
            pids = set(client.run(os.getpid).values())
            if processes:
                assert len(pids) == 2 and os.getpid() not in pids
            else:
                assert pids == {os.getpid()}      # both workers are threads of this process
        finally:
            close()


def test_output_names_are_unique():
    paths = [pathlib.Path(p) for p in ("/d/a/bunny.obj", "/d/a/bunny.stl", "/d/a/x.off", "/d/b/x.off",
                                       "/d/a/results.off", "/d/a/cow.ply")]
    names = batch._output_names(paths, ".json")
    assert names == ["bunny.obj.json", "bunny.stl.json", "a_x.off.json", "b_x.off.json", "results.off.json",
                     "cow.json"]
    assert batch._output_names([pathlib.Path("/d/manifest.off")], ".jsonl") == ["manifest.off.jsonl"]


def test_geodesic_jobs_run_on_one_core_unless_asked():
    from gsp.batch.runner import _app_extra
    assert _app_extra("geodesic", ["--source-vertex", "0"]) == ["--threads", "1"]
    assert _app_extra("geodesic", ["--threads", "2"]) == []
    assert _app_extra("geodesic", ["--threads=2"]) == []
    assert _app_extra("bench", []) == ["--no-table"]
    assert _app_extra("sample", ["--count", "10"]) == []


def test_job_options_split_from_batch_options():
    own, job = batch._split_argv(["geodesic", "in/", "-o", "out", "--source-vertex", "0", "--workers=2",
                                  "--source-point", "-1.5,0,2", "--labels", "--timeout", "9", "--", "-o", "x"])
    assert own == ["geodesic", "in/", "-o", "out", "--workers=2", "--timeout", "9"]
    assert job == ["--source-vertex", "0", "--source-point", "-1.5,0,2", "--labels", "-o", "x"]
