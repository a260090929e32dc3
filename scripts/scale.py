#!/usr/bin/python3
"""Time and peak memory of a one-shot gsp-geodesic run against the vertex count, GSP beside
Dijkstra on the same meshes in the same run: every phase's seconds and the peak resident
memory when it ended (the app's --stats), per method and mesh. Writes a CSV, a Markdown table
and a log-log plot (docs/scale.md shows one).

    scripts/scale.py MESH... --csv scale.csv --markdown scale.md --plot scale.png [--source 0]

Each run is its own process (what a user waits for: read, prepare, compute, write), so the
peak is that of one run. Each mesh runs --repeat times per method (default 3), the two methods
alternating which goes first, and the run with the median whole time is kept: on a virtual
machine the first process to touch memory freed by another can pay the host's faults (an
8.9M-vertex run: the first of a series 7.4-8.8 s, the next ones 5.1-6.1 s, whichever method). Make large meshes with a subdivision, e.g. gsp-bench's meshes or
any mesh split 1-to-4 a few times.
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import tempfile

BIN = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "build", "bin", "gsp-geodesic")
PHASES = ("read", "layout", "build", "compute", "write")


def run_one(app, mesh, method, source, threads):
    with tempfile.TemporaryDirectory() as tmp:
        out, stats = os.path.join(tmp, "d.ply"), os.path.join(tmp, "s.json")
        cmd = [app, mesh, "--method", method, "--source-vertex", str(source), "-o", out, "--stats", stats, "-q"]
        if threads:
            cmd += ["--threads", str(threads)]
        p = subprocess.run(cmd, capture_output=True, text=True)
        if p.returncode != 0:
            return {"error": (p.stderr.strip().splitlines() or ["exit %d" % p.returncode])[-1]}
        s = json.load(open(stats))
    row = {"vertices": s["input"]["vertices"], "faces": s["input"]["triangles"]}
    t, m = s["timings"], s.get("memory", {})
    for ph in PHASES:
        row[ph + "_s"] = t.get(ph, 0.0)
        row[ph + "_peak_mb"] = m.get("peak_after", {}).get(ph, 0) / 2**20
    row["total_s"] = t["total"]
    row["peak_mb"] = m.get("peak_bytes", 0) / 2**20
    row["peak_bytes_per_vertex"] = m.get("peak_bytes_per_vertex", 0)
    row["steps_per_face"] = s["operations"].get("update_steps_per_face", "")
    return row


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("meshes", nargs="+")
    ap.add_argument("--app", default=BIN)
    ap.add_argument("--source", type=int, default=0)
    ap.add_argument("--threads", type=int, default=0)
    ap.add_argument("--csv")
    ap.add_argument("--markdown")
    ap.add_argument("--plot")
    ap.add_argument("--repeat", type=int, default=3, help="runs per mesh and method; the median is kept")
    a = ap.parse_args()
    rows = []
    for mesh in a.meshes:
        runs = {"gsp": [], "dijkstra": []}
        for i in range(max(1, a.repeat)):
            for method in (("gsp", "dijkstra") if i % 2 == 0 else ("dijkstra", "gsp")):
                r = run_one(a.app, mesh, method, a.source, a.threads)
                r.update(mesh=os.path.basename(mesh), method=method)
                runs[method].append(r)
                print(json.dumps(r), file=sys.stderr, flush=True)
        for method, done in runs.items():
            ok = sorted((r for r in done if "error" not in r), key=lambda r: r["total_s"])
            rows.append(ok[(len(ok) - 1) // 2] if ok else done[0])
    keys = ["mesh", "method", "vertices", "faces", "total_s", "peak_mb", "peak_bytes_per_vertex", "steps_per_face"]
    keys += [ph + "_s" for ph in PHASES] + [ph + "_peak_mb" for ph in PHASES] + ["error"]
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.DictWriter(f, keys, extrasaction="ignore")
            w.writeheader()
            w.writerows(rows)
    pairs = []
    for mesh in dict.fromkeys(r["mesh"] for r in rows):
        g = next((r for r in rows if r["mesh"] == mesh and r["method"] == "gsp"), {})
        d = next((r for r in rows if r["mesh"] == mesh and r["method"] == "dijkstra"), {})
        if "error" not in g and "error" not in d:
            pairs.append((mesh, g, d))
    if a.markdown:
        lines = ["| mesh | vertices | GSP total s (read / layout / build / compute / write) | Dijkstra total s | "
                 "GSP / Dijkstra time | GSP peak MB (B / vertex) | Dijkstra peak MB (B / vertex) | "
                 "GSP / Dijkstra peak | steps / face |",
                 "|---|---:|---|---:|---:|---:|---:|---:|---:|"]
        for mesh, g, d in pairs:
            phases = " / ".join("%.2f" % g[ph + "_s"] for ph in PHASES)
            lines.append("| %s | %d | %.2f (%s) | %.2f | %.2f | %.0f (%.0f) | %.0f (%.0f) | %.2f | %.2f |" % (
                mesh, g["vertices"], g["total_s"], phases, d["total_s"], g["total_s"] / d["total_s"], g["peak_mb"],
                g["peak_bytes_per_vertex"], d["peak_mb"], d["peak_bytes_per_vertex"], g["peak_mb"] / d["peak_mb"],
                g["steps_per_face"]))
        text = "\n".join(lines) + "\n"
        if a.markdown == "-":
            sys.stdout.write(text)
        else:
            open(a.markdown, "w").write(text)
    if a.plot and pairs:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        n = [g["vertices"] for _, g, _ in pairs]
        fig, ax = plt.subplots(1, 2, figsize=(10, 4))
        for method, idx, style in (("GSP", 1, "o-"), ("Dijkstra", 2, "s--")):
            ax[0].loglog(n, [p[idx]["total_s"] for p in pairs], style, label=method + " (whole run)")
            ax[1].loglog(n, [p[idx]["peak_mb"] for p in pairs], style, label=method)
        ax[0].loglog(n, [p[1]["compute_s"] for p in pairs], "o:", label="GSP compute only")
        ax[0].set_xlabel("vertices"), ax[0].set_ylabel("seconds"), ax[0].legend(), ax[0].grid(True, which="both", alpha=0.3)
        ax[1].set_xlabel("vertices"), ax[1].set_ylabel("peak resident MB"), ax[1].legend()
        ax[1].grid(True, which="both", alpha=0.3)
        fig.tight_layout()
        fig.savefig(a.plot, dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main())
