#!/usr/bin/python3
"""Runs gsp-cvt-compare (gsp-cvt against CGAL's isotropic remeshing at the same vertex count) on
every mesh of one or more folders and writes one CSV row per mesh, plus the per-category
aggregate (benign / malign / all: mean, p95, worst) as Markdown.

    scripts/cvt_corpus.py ../shared/data/corpus --vertices 5000 --csv cvt.csv [--markdown -]
    scripts/cvt_corpus.py --summary cvt.csv [--markdown -] [FOLDER]  # aggregate an existing CSV
    scripts/cvt_corpus.py --summary after.csv --before before.csv --markdown - FOLDER

Each mesh runs in its own process under a time limit, so a crash, an error or a timeout is a
row with its reason and the run goes on. The category is read as gsp-bench --corpus reads it:
the `Character` column (first word benign / malign) of the SOURCES.md beside the mesh; its
`Cat.` column (a scan / remesh, b CAD / 3D print, c modelled / soup, d tiny) is kept as `kind`.
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import tempfile
import time

MESH_EXTENSIONS = (".obj", ".off", ".ply", ".stl", ".gltf", ".glb")
METHODS = (("gsp", "gsp-cvt"), ("cgal", "CGAL"))
OUTPUT_FIELDS = ("status", "vertices", "min_angle", "percent_below_30", "remeshed_min_angle", "remeshed_faces",
                 "hausdorff_percent_of_diagonal",
                 "feature_distance_percent_of_diagonal",
                 "manifold", "euler_characteristic", "boundary_loops", "components", "duplicate_vertices",
                 "inconsistent_edges", "topology_kept", "topology_difference", "seconds", "note")
PHASES = ("subdivide", "prepare", "initial", "propagate", "centroids", "fix", "remesh")
INPUT_FIELDS = ("vertices", "faces", "components", "surface_components", "manifold", "euler_characteristic",
                "boundary_loops", "inconsistent_edges", "feature_edges")


def table_rows(path):
    """{file name: {column: cell}} of every markdown table with a File column in SOURCES.md."""
    out, header = {}, None
    try:
        lines = open(path, encoding="utf-8").read().splitlines()
    except OSError:
        return out
    for line in lines:
        line = line.strip()
        if not line.startswith("|"):
            header = None
            continue
        cells = [c.strip() for c in line.strip("|").split("|")]
        if header is None:
            header = cells if "File" in cells else []
            continue
        if not header or len(cells) != len(header) or set(cells[0]) <= set("-: "):
            continue
        row = dict(zip(header, cells))
        out.setdefault(row["File"].strip("`"), {}).update(row)   # several tables name the file
    return out


def category(sources, name):
    row = sources.get(name, {})
    first = row.get("Character", "").replace("(", " ").replace(",", " ").split()
    cat = first[0] if first and first[0] in ("benign", "malign") else "unknown"
    return cat, row.get("Cat.", "")


def run_mesh(args, path):
    with tempfile.TemporaryDirectory() as tmp:
        stats = os.path.join(tmp, "stats.json")
        cmd = [args.compare, path, "--vertices", str(args.vertices), "--hausdorff-samples",
               str(args.hausdorff_samples), "--stats", stats, "--quiet"]
        if args.feature_angle is not None:
            cmd += ["--feature-angle", str(args.feature_angle)]
        if args.cone_angle is not None:
            cmd += ["--cone-angle", str(args.cone_angle)]
        if args.method is not None:
            cmd += ["--method", args.method]
        if args.cvt_tolerance is not None:
            cmd += ["--cvt-tolerance", str(args.cvt_tolerance)]
        if args.sizing_angle is not None:
            cmd += ["--sizing-angle", str(args.sizing_angle)]
        start = time.monotonic()
        try:
            p = subprocess.run(cmd, capture_output=True, text=True, timeout=args.timeout)
        except subprocess.TimeoutExpired:
            return {"status": "timeout", "reason": f"over {args.timeout} s"}
        wall = time.monotonic() - start
        if p.returncode != 0:
            lines = (p.stderr or "").strip().splitlines()
            reason = lines[-1] if lines else f"exit code {p.returncode}"
            return {"status": "crash" if p.returncode < 0 else "error", "reason": reason}
        with open(stats) as f:
            doc = json.load(f)
    row = {"status": "ok", "reason": "", "wall_s": round(wall, 2)}
    for k in INPUT_FIELDS:
        row["input_" + k] = doc["input_topology"].get(k, "")
    for (prefix, _), r in zip(METHODS, doc["rows"]):
        if "error" in r:
            row[prefix + "_status"] = "error"
            row[prefix + "_note"] = r["error"]
            continue
        m = r["measures"]
        row[prefix + "_status"] = "ok"
        for k in OUTPUT_FIELDS[1:]:
            v = r.get(k, m.get(k, ""))
            row[prefix + "_" + k] = "" if v is None else v
        for k in PHASES:
            if k in r.get("phases", {}):
                row[prefix + "_" + k + "_s"] = r["phases"][k]
        if "components" in r:   # gsp: what happened to each input component
            outcomes = {}
            for c in r["components"]:
                key = c["outcome"] + ("_by_edges" if c.get("by_edge_operations") else "") + ("_without_features" if c.get("features_dropped") else "")
                outcomes[key] = outcomes.get(key, 0) + 1
            row[prefix + "_component_outcomes"] = " ".join(f"{k}:{v}" for k, v in sorted(outcomes.items()))
            row[prefix + "_kept_reasons"] = "; ".join(sorted({c["reason"] for c in r["components"] if c["reason"]}))[:300]
    if row.get("gsp_status") == "ok" and row.get("cgal_status") == "ok" and row["cgal_seconds"] > 0:
        row["time_ratio"] = row["gsp_seconds"] / row["cgal_seconds"]
    return row


def columns():
    cols = ["mesh", "category", "kind", "status", "reason", "wall_s"] + ["input_" + k for k in INPUT_FIELDS]
    for prefix, _ in METHODS:
        cols += [prefix + "_" + k for k in OUTPUT_FIELDS]
    cols += ["gsp_" + k + "_s" for k in PHASES] + ["time_ratio", "gsp_component_outcomes", "gsp_kept_reasons"]
    return cols


def number(v):
    if v in ("", None):
        return math.nan
    if isinstance(v, str) and v in ("True", "False"):
        return float(v == "True")
    return float(v)


def spread(values, worst_is_min):
    v = sorted(x for x in values if math.isfinite(x))
    if not v:
        return 0, math.nan, math.nan, math.nan
    mean = sum(v) / len(v)
    # 95th percentile on the bad side, interpolated between ranks (numpy's default).
    q = 0.05 if worst_is_min else 0.95
    pos = q * (len(v) - 1)
    lo, hi = math.floor(pos), math.ceil(pos)
    p = v[lo] + (v[hi] - v[lo]) * (pos - lo)
    return len(v), mean, p, (v[0] if worst_is_min else v[-1])


FIGURES = (  # (column suffix, label, worst is the minimum)
    ("min_angle", "min angle (deg)", True),
    ("percent_below_30", "angles < 30 deg (%)", False),
    ("hausdorff_percent_of_diagonal", "Hausdorff (% diag)", False),
    ("feature_distance_percent_of_diagonal", "feature curves to output (% diag)", False),
    ("seconds", "time (s)", False),
)


def fmt(v):
    return "-" if not math.isfinite(v) else f"{v:.3g}"


def markdown(rows):
    lines = []
    for cat in ("benign", "malign", "all"):
        rs = [r for r in rows if cat == "all" or r["category"] == cat]
        lines.append(f"**{cat}** ({len(rs)} meshes)")
        lines.append("")
        lines.append("| figure | method | n | mean | p95 (bad side) | worst |")
        lines.append("|---|---|---:|---:|---:|---:|")
        for key, label, low in FIGURES:
            for prefix, name in METHODS:
                ok = [r for r in rs if r.get(prefix + "_status") == "ok"]
                n, mean, p, worst = spread([number(r.get(prefix + "_" + key)) for r in ok], low)
                lines.append(f"| {label} | {name} | {n} | {fmt(mean)} | {fmt(p)} | {fmt(worst)} |")
        n, mean, p, worst = spread([number(r.get("time_ratio")) for r in rs], False)
        lines.append(f"| time gsp / CGAL | | {n} | {fmt(mean)} | {fmt(p)} | {fmt(worst)} |")
        lines.append("")
        for prefix, name in METHODS:
            ok = [r for r in rs if r.get(prefix + "_status") == "ok"]
            kept = sum(number(r.get(prefix + "_topology_kept")) == 1 for r in ok)
            manifold = sum(number(r.get(prefix + "_manifold")) == 1 for r in ok)
            dups = sum(number(r.get(prefix + "_duplicate_vertices")) > 0 for r in ok)
            floor = sum(number(r.get(prefix + "_min_angle")) >= 20 for r in ok)
            own = sum(number(r.get(prefix + "_remeshed_min_angle")) >= 20 for r in ok)
            failed = sum(r.get(prefix + "_status") != "ok" for r in rs)
            lines.append(f"- {name}: ran {len(ok)}, failed {failed}; manifold {manifold}; topology per component "
                         f"kept {kept}; with duplicate vertices {dups}; min angle >= 20 deg {floor} "
                         f"(on the remeshed components alone: {own})")
        outcomes = {}
        for r in rs:
            for item in (r.get("gsp_component_outcomes") or "").split():
                k, v = item.split(":")
                outcomes[k] = outcomes.get(k, 0) + int(v)
        if outcomes:
            lines.append("- gsp-cvt components: " + ", ".join(f"{k} {v}" for k, v in sorted(outcomes.items())))
        lines.append("")
    return "\n".join(lines)


def cell(rows, prefix, key, low):
    ok = [r for r in rows if r.get(prefix + "_status") == "ok"]
    n, mean, p, worst = spread([number(r.get(prefix + "_" + key)) for r in ok], low)
    return f"{fmt(mean)} / {fmt(p)} / {fmt(worst)}" if n else "-"


def counts(rows, prefix):
    ok = [r for r in rows if r.get(prefix + "_status") == "ok"]
    kept = sum(number(r.get(prefix + "_topology_kept")) == 1 for r in ok)
    manifold = sum(number(r.get(prefix + "_manifold")) == 1 for r in ok)
    floor = sum(number(r.get(prefix + "_min_angle")) >= 20 for r in ok)
    own = sum(number(r.get(prefix + "_remeshed_min_angle")) >= 20 for r in ok)
    return (f"{len(ok)} ran; {manifold} manifold; {kept} topology kept; {floor} with min angle >= 20"
            + (f" ({own} on the remeshed components alone)" if any(r.get(prefix + "_remeshed_min_angle") not in ("", None)
                                                               for r in ok) else ""))


def remeshed_counts(rows):
    """Meshes whose components were all remeshed, some, none (gsp-cvt kept the rest as they are)."""
    full = part = none = 0
    for r in rows:
        outcomes = (r.get("gsp_component_outcomes") or "").split()
        if r.get("gsp_status") != "ok" or not outcomes:
            continue
        done = [o.startswith("remeshed") for o in outcomes]
        full += all(done)
        none += not any(done)
        part += any(done) and not all(done)
    return f"all remeshed {full}, some {part}, none {none}"


def before_after(before, after):
    """gsp before and after, CGAL (of the after run): mean / p95 / worst per category."""
    lines = []
    for cat in ("benign", "malign", "all"):
        b = [r for r in before if cat == "all" or r["category"] == cat]
        a = [r for r in after if cat == "all" or r["category"] == cat]
        lines.append(f"**{cat}** ({len(a)} meshes; mean / p95 on the bad side / worst)")
        lines.append("")
        lines.append("| figure | gsp-cvt before | gsp-cvt after | CGAL |")
        lines.append("|---|---|---|---|")
        for key, label, low in FIGURES:
            lines.append(f"| {label} | {cell(b, 'gsp', key, low)} | {cell(a, 'gsp', key, low)} | "
                         f"{cell(a, 'cgal', key, low)} |")
        ratio = lambda rs: fmt(spread([number(r.get("time_ratio")) for r in rs], False)[1])
        lines.append(f"| time gsp / CGAL (mean) | {ratio(b)} | {ratio(a)} | 1 |")
        lines.append(f"| meshes | {counts(b, 'gsp')} | {counts(a, 'gsp')} | {counts(a, 'cgal')} |")
        lines.append(f"| gsp-cvt components | whole mesh at once | {remeshed_counts(a)} | |")
        lines.append("")
    return "\n".join(lines)


def main():
    # A soup of thousands of components writes a long per-component outcome cell.
    csv.field_size_limit(1 << 30)
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("folders", nargs="*", help="folders of meshes (not recursive)")
    ap.add_argument("--vertices", type=int, default=5000)
    ap.add_argument("--csv", help="write the rows here")
    ap.add_argument("--summary", help="aggregate this CSV instead of running")
    ap.add_argument("--before", help="with --summary: an earlier run's CSV, for a before / after table")
    ap.add_argument("--markdown", help="write the aggregate here ('-': stdout)")
    ap.add_argument("--compare", default=os.path.join(os.path.dirname(__file__), "..", "build", "bin",
                                                      "gsp-cvt-compare"))
    ap.add_argument("--method", choices=("cvt", "edges"), help="gsp-cvt's --method (default: gsp-cvt's default)")
    ap.add_argument("--sizing-angle", type=float, help="gsp-cvt's --sizing-angle (default: gsp-cvt's default)")
    ap.add_argument("--cvt-tolerance", type=float, help="gsp-cvt's --tolerance (default: gsp-cvt's default)")
    ap.add_argument("--feature-angle", type=float, help="gsp-cvt's --feature-angle (default: gsp-cvt's default)")
    ap.add_argument("--cone-angle", type=float, help="gsp-cvt's --cone-angle (default: gsp-cvt's default)")
    ap.add_argument("--timeout", type=float, default=300, help="seconds per mesh (default 300)")
    ap.add_argument("--hausdorff-samples", type=int, default=50000)
    ap.add_argument("--only", nargs="*", default=[], help="run only meshes whose name contains one of these")
    ap.add_argument("--resume", action="store_true", help="keep the rows already in --csv, run the other meshes")
    ap.add_argument("--reverse", action="store_true",
                    help="meshes in reverse name order (a second process from the other end; merge the CSVs)")
    args = ap.parse_args()
    if args.summary:
        with open(args.summary, newline="") as f:
            rows = list(csv.DictReader(f))
        for folder in args.folders:   # categories again from SOURCES.md, for rows that lack one
            sources = table_rows(os.path.join(folder, "SOURCES.md"))
            for r in rows:
                if r.get("category") in ("", "unknown", None) and r["mesh"] in sources:
                    r["category"], r["kind"] = category(sources, r["mesh"])
    else:
        if not args.folders or not args.csv:
            ap.error("give folders and --csv (or --summary CSV)")
        rows = []
        if args.resume and os.path.exists(args.csv):
            with open(args.csv, newline="") as f:
                rows = list(csv.DictReader(f))
        done = {r["mesh"] for r in rows}
        with open(args.csv, "a" if rows else "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=columns(), extrasaction="ignore")
            if not rows:
                w.writeheader()
            for folder in args.folders:
                sources = table_rows(os.path.join(folder, "SOURCES.md"))
                for name in sorted(os.listdir(folder), reverse=args.reverse):
                    if not name.lower().endswith(MESH_EXTENSIONS):
                        continue
                    if args.only and not any(s in name for s in args.only):
                        continue
                    if name in done:
                        continue
                    cat, kind = category(sources, name)
                    row = {"mesh": name, "category": cat, "kind": kind}
                    row.update(run_mesh(args, os.path.join(folder, name)))
                    print(f"{name}: {row['status']} {row.get('reason', '')} gsp {row.get('gsp_min_angle', '-')} deg "
                          f"{row.get('gsp_seconds', '-')} s, CGAL {row.get('cgal_min_angle', '-')} deg "
                          f"{row.get('cgal_seconds', '-')} s", file=sys.stderr, flush=True)
                    w.writerow(row)
                    f.flush()
                    rows.append({k: str(v) for k, v in row.items()})
    if args.markdown:
        text = markdown(rows)
        if args.before:
            with open(args.before, newline="") as f:
                before = list(csv.DictReader(f))
            for folder in args.folders:
                sources = table_rows(os.path.join(folder, "SOURCES.md"))
                for r in before:
                    if r.get("category") in ("", "unknown", None) and r["mesh"] in sources:
                        r["category"], r["kind"] = category(sources, r["mesh"])
            text = before_after(before, rows)
        if args.markdown == "-":
            print(text)
        else:
            open(args.markdown, "w").write(text + "\n")


if __name__ == "__main__":
    main()
