#!/usr/bin/python3
"""Plots a gsp-bench corpus run (gsp-bench --corpus): per mesh, GSP's, Dijkstra's and the heat
method's mean relative error against exact distances, and GSP's physical-bound deviations
(below the straight line, above the edge path) with the 1% lines; optionally the per-category
aggregate as a Markdown table.

    scripts/plot_corpus.py corpus.csv -o corpus.png [--markdown table.md|-] [--title TEXT]
    scripts/plot_corpus.py corpus.json -o corpus.png     # the --json report works as well

The aggregate is recomputed from the rows with gsp-bench's definitions (finite values only;
95th percentile interpolated linearly between ranks, numpy's default), so a CSV is enough.

Needs Debian's python3-numpy and python3-matplotlib (hence /usr/bin/python3 above, not a
virtualenv's python); draws with the headless Agg backend.
"""
import argparse
import csv
import json
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402 (after the backend is chosen)
import numpy as np  # noqa: E402

# The same colours as scripts/plot_bench.py; the marker says the mesh's category.
METHOD_COLOUR = {"gsp": "#d62728", "dijkstra": "#1f77b4", "heat": "#2ca02c"}
CATEGORY_MARKER = {"benign": "o", "malign": "^", "unknown": "s"}
FIGURES = [  # (key, label, scale to the unit shown)
    ("gsp_mre", "GSP MRE (%)", 100),
    ("gsp_max_re", "GSP max RE (%)", 100),
    ("dijkstra_mre", "Dijkstra MRE (%)", 100),
    ("heat_mre", "heat MRE (%)", 100),
    ("gsp_below_line", "GSP below line (%)", 100),
    ("gsp_above_edge", "GSP above edge path (%)", 100),
    ("gsp_steps_per_face", "GSP steps / face", 1),
    ("gsp_query_s", "GSP query (ms)", 1e3),
]


def number(text):
    if text in ("", None):
        return math.nan
    return float(text)


def rows_from_csv(path):
    with open(path, newline="") as f:
        return [dict(r) for r in csv.DictReader(f)]


def rows_from_json(path):
    """The JSON report's rows in the CSV's column names."""
    with open(path) as f:
        doc = json.load(f)
    rows = []
    for m in doc["meshes"]:
        r = {"mesh": m["name"], "category": m["category"], "status": m["status"],
             "exact_references": m["exact_references"], "gsp_steps_per_face": m["gsp_steps_per_face"],
             "gsp_beats_dijkstra": m["gsp_beats_dijkstra"], "gsp_beats_heat": m["gsp_beats_heat"],
             "gsp_violates_bounds": int(m["gsp_violates_bounds"])}
        for meth in m["methods"]:
            n = meth["method"]
            for key in ("mre", "max_re", "query_s"):
                r[n + "_" + key] = meth[key]
            if n == "gsp" and meth["bounds"]:
                r["gsp_below_line"] = meth["bounds"]["below_line"]
                r["gsp_above_edge"] = meth["bounds"]["above_edge"]
        rows.append({k: ("" if v is None else v) for k, v in r.items()})
    return rows


def value(row, key):
    v = row.get(key, "")
    if isinstance(v, bool):
        return float(v)
    return number(v) if isinstance(v, str) else float(v)


def spread(values):
    v = np.array([x for x in values if math.isfinite(x)])
    if v.size == 0:
        return 0, math.nan, math.nan, math.nan, math.nan
    return v.size, v.mean(), np.median(v), np.percentile(v, 95), v.max()


# GSP counts as less accurate only beyond this MRE difference (gsp-bench's kMreTie): below it
# the difference is GSP's single-precision rounding on meshes where the baseline is exact.
MRE_TIE = 1e-6


def gsp_worse(row, other):
    g, o = value(row, "gsp_mre"), value(row, other + "_mre")
    return math.isfinite(g) and math.isfinite(o) and g > o + MRE_TIE


def aggregate(rows):
    out = []
    for cat in ("benign", "malign", "all"):
        rs = [r for r in rows if cat == "all" or r["category"] == cat]
        ok = [r for r in rs if r["status"] == "ok"]
        counts = {
            "run": len(ok), "failed": len(rs) - len(ok),
            "with exact": sum(value(r, "exact_references") > 0 for r in ok),
            "GSP worse than Dijkstra": sum(gsp_worse(r, "dijkstra") for r in ok),
            "GSP worse than heat": sum(gsp_worse(r, "heat") for r in ok),
            "bound broken by > 1%": sum(value(r, "gsp_violates_bounds") > 0 for r in ok),
        }
        figures = [(label, [value(r, key) * scale for r in ok]) for key, label, scale in FIGURES]
        out.append((cat, counts, [(label, spread(v)) for label, v in figures]))
    return out


def fmt(v):
    return "-" if not math.isfinite(v) else f"{v:.4g}"


def markdown(rows):
    lines = []
    for cat, counts, figures in aggregate(rows):
        lines.append(f"**{cat}**: " + ", ".join(f"{k} {v}" for k, v in counts.items()))
        lines.append("")
        lines.append("| figure | n | mean | median | p95 | worst |")
        lines.append("|---|---:|---:|---:|---:|---:|")
        for label, (n, mean, med, p95, worst) in figures:
            lines.append(f"| {label} | {n} | {fmt(mean)} | {fmt(med)} | {fmt(p95)} | {fmt(worst)} |")
        lines.append("")
    return "\n".join(lines)


def plot(rows, out, title):
    ok = [r for r in rows if r["status"] == "ok"]
    # One x position per mesh: by GSP MRE, meshes without one (no exact) after, by name.
    ok.sort(key=lambda r: (not math.isfinite(value(r, "gsp_mre")), value(r, "gsp_mre") if math.isfinite(
        value(r, "gsp_mre")) else 0, r["mesh"]))
    x = np.arange(len(ok))
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(max(8.0, 0.14 * len(ok) + 3), 8.0), dpi=100, sharex=True)
    for method, colour in METHOD_COLOUR.items():
        for cat, marker in CATEGORY_MARKER.items():
            pts = [(i, value(r, method + "_mre") * 100) for i, r in zip(x, ok) if r["category"] == cat]
            pts = [(i, v) for i, v in pts if math.isfinite(v) and v > 0]
            if pts:
                top.scatter(*zip(*pts), s=18, color=colour, marker=marker, label=f"{method} ({cat})",
                            alpha=0.85, linewidths=0)
    top.set_yscale("log")
    top.set_ylabel("MRE vs exact (%)")
    top.grid(True, which="both", alpha=0.25)
    top.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)
    top.set_title(title, fontsize=10)

    for key, colour, label in (("gsp_below_line", "#9467bd", "GSP below straight line"),
                               ("gsp_above_edge", "#ff7f0e", "GSP above edge path")):
        for cat, marker in CATEGORY_MARKER.items():
            pts = [(i, value(r, key) * 100) for i, r in zip(x, ok) if r["category"] == cat]
            pts = [(i, v) for i, v in pts if math.isfinite(v)]
            if pts:
                bottom.scatter(*zip(*pts), s=18, color=colour, marker=marker, label=f"{label} ({cat})",
                               alpha=0.85, linewidths=0)
    bottom.axhline(1.0, color="black", lw=0.8, ls="--", label="1%")
    # symlog: 0 (bound respected) is a real value here, and must stay on the axis.
    bottom.set_yscale("symlog", linthresh=1e-3)
    worst = max([value(r, k) * 100 for r in ok for k in ("gsp_below_line", "gsp_above_edge")
                 if math.isfinite(value(r, k))] + [1.0])
    bottom.set_ylim(0, worst * 3)   # deviations are >= 0; headroom above the largest
    bottom.set_ylabel("worst deviation (%)")
    bottom.grid(True, which="both", alpha=0.25)
    bottom.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)
    bottom.set_xticks(x)
    bottom.set_xticklabels([r["mesh"] for r in ok], rotation=90, fontsize=5)
    fig.tight_layout()
    fig.savefig(out, dpi=100)


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("report", help="gsp-bench --corpus --csv (or --json) output")
    p.add_argument("-o", "--output", help="PNG to write")
    p.add_argument("--markdown", help="write the per-category aggregate here ('-' for stdout)")
    p.add_argument("--title", default="gsp-bench corpus: accuracy per mesh", help="plot title")
    a = p.parse_args(argv)
    if not a.output and not a.markdown:
        p.error("nothing to do: give -o PNG and/or --markdown FILE")
    rows = rows_from_json(a.report) if a.report.endswith(".json") else rows_from_csv(a.report)
    if a.output:
        plot(rows, a.output, a.title)
    if a.markdown:
        text = markdown(rows)
        if a.markdown == "-":
            sys.stdout.write(text)
        else:
            with open(a.markdown, "w") as f:
                f.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
