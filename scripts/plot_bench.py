#!/usr/bin/python3
"""Plots gsp-bench results: accuracy against throughput (like Figure 8 of the GSP paper) and
a per-mesh Markdown table of the figures the benchmark is about.

    scripts/plot_bench.py bench.csv [more.csv ...] -o docs/benchmarks/accuracy_speed.png \
        [--markdown table.md] [--title TEXT]

Several CSV files (e.g. the shards of one run, --shard i/n) are merged: rows of the same
(mesh, method) are combined with weights equal to their source counts (times and mean errors
averaged, max errors maximised, ratios recomputed from the merged times).

Needs Debian's python3-matplotlib (hence /usr/bin/python3 above, not a virtualenv's python);
draws with the headless Agg backend.
"""
import argparse
import csv
import itertools
import math
import sys
from collections import OrderedDict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402 (after the backend is chosen)

# Drawing order and colours; methods not listed here get the next colour of the cycle.
METHOD_STYLE = OrderedDict([
    ("gsp", ("#d62728", "o")),
    ("gsp-hybrid", ("#ff7f0e", "o")),
    ("gsp-pq", ("#e377c2", "o")),
    ("gsp-bfs", ("#8c564b", "o")),
    ("gsp-double", ("#bcbd22", "o")),
    ("gsp-no-layout", ("#9467bd", "o")),
    ("gsp-random-layout", ("#7f7f7f", "o")),
    ("gsp-input-faces", ("#17becf", "o")),
    ("dijkstra", ("#1f77b4", "s")),
    ("heat", ("#2ca02c", "^")),
    ("heat-idt", ("#98df8a", "^")),
    ("exact", ("#000000", "D")),
])


# Columns merged across shards as source-weighted means. vertices_per_s is taken from the CSV,
# not recomputed from the mesh size: it counts the vertices a query reaches (its component).
AVERAGED = ("precompute_s", "query_s", "vertices_per_s", "cycles_per_vertex", "update_steps_per_triangle", "mre",
            "state_bytes_per_vertex", "solver_bytes_per_vertex")


def number(text):
    return float(text) if text not in ("", None) else math.nan


def read_rows(paths):
    """(mesh, method) -> merged row (dict of floats plus mesh/method/status)."""
    merged = OrderedDict()
    for path in paths:
        with open(path, newline="") as f:
            for row in csv.DictReader(f):
                key = (row["mesh"], row["method"])
                n = int(row["sources"] or 0)
                r = merged.setdefault(key, {"mesh": row["mesh"], "method": row["method"], "status": row["status"],
                                            "vertices": int(row["vertices"]), "faces": int(row["faces"]),
                                            "sources": 0, "_w": {}, "max_re": math.nan})
                if row["status"] != "ok":
                    r["status"] = row["status"]
                r["sources"] += n
                for col in AVERAGED:
                    v = number(row[col])
                    if not math.isnan(v):
                        s, w = r["_w"].get(col, (0.0, 0))
                        r["_w"][col] = (s + v * n, w + n)
                mx = number(row["max_re"])
                if not math.isnan(mx):
                    r["max_re"] = mx if math.isnan(r["max_re"]) else max(r["max_re"], mx)
    for r in merged.values():
        for col, (s, w) in r.pop("_w").items():
            r[col] = s / w if w else math.nan
        for col in AVERAGED:
            r.setdefault(col, math.nan)
    return merged


def ratio(rows, mesh, a, b):
    ra, rb = rows.get((mesh, a)), rows.get((mesh, b))
    if not ra or not rb or not (ra["query_s"] > 0) or not (rb["query_s"] > 0):
        return math.nan
    return ra["query_s"] / rb["query_s"]


def geomean(values):
    values = [v for v in values if v > 0 and math.isfinite(v)]
    return math.exp(sum(math.log(v) for v in values) / len(values)) if values else math.nan


def plot(rows, out, title):
    methods = [m for m in METHOD_STYLE if any(k[1] == m for k in rows)]
    methods += sorted({k[1] for k in rows} - set(methods))
    fig, ax = plt.subplots(figsize=(7.0, 4.4), dpi=100)
    extra_colours = itertools.cycle(plt.rcParams["axes.prop_cycle"].by_key()["color"])
    for rank, method in enumerate(methods):
        z = 3 + len(methods) - rank   # the first methods (GSP as shipped) on top
        colour, marker = METHOD_STYLE[method] if method in METHOD_STYLE else (next(extra_colours), "o")
        pts = [(r["vertices_per_s"], r["mre"] * 100) for k, r in rows.items()
               if k[1] == method and r["vertices_per_s"] > 0 and r["mre"] > 0]
        if not pts:
            continue
        xs, ys = zip(*pts)
        ax.scatter(xs, ys, s=14, color=colour, marker=marker, alpha=0.55, linewidths=0, zorder=z)
        # The method's centre over all meshes (geometric means), large, with the legend entry.
        ax.scatter([geomean(xs)], [geomean(ys)], s=70, color=colour, marker=marker, edgecolors="black",
                   linewidths=0.6, label=method, zorder=z + len(methods))
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("throughput (vertices per second, single-source query)")
    ax.set_ylabel("mean relative error vs exact (%)")
    ax.grid(True, which="major", alpha=0.3)
    ax.grid(True, which="minor", alpha=0.1)
    ax.set_title(title, fontsize=10)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False,
              title="small: one mesh\nlarge: geo. mean", title_fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=100)


def fmt(v, spec):
    return "–" if not math.isfinite(v) else format(v, spec)


def markdown(rows):
    meshes = list(OrderedDict.fromkeys(k[0] for k in rows))
    get = lambda mesh, method, col: rows[(mesh, method)][col] if (mesh, method) in rows else math.nan  # noqa: E731
    lines = [
        "| mesh | vertices | GSP ms | GSP MRE % | Dijkstra ms | Dijkstra MRE % | heat ms | heat MRE % | "
        "heat-idt MRE % | exact s | GSP / Dijkstra | GSP / heat | random / opt. layout | no / opt. layout | "
        "steps / tri | state B / vertex |",
        "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|",
    ]
    cols = {k: [] for k in ("dij", "heat", "rand", "nolay")}
    for mesh in meshes:
        vertices = next(r["vertices"] for k, r in rows.items() if k[0] == mesh)
        r_dij = ratio(rows, mesh, "gsp", "dijkstra")
        r_heat = ratio(rows, mesh, "gsp", "heat")
        r_rand = ratio(rows, mesh, "gsp-random-layout", "gsp")
        r_nolay = ratio(rows, mesh, "gsp-no-layout", "gsp")
        for k, v in zip(cols, (r_dij, r_heat, r_rand, r_nolay)):
            cols[k].append(v)
        lines.append("| {} | {:,} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |".format(
            mesh, vertices,
            fmt(get(mesh, "gsp", "query_s") * 1e3, ".2f"), fmt(get(mesh, "gsp", "mre") * 100, ".3f"),
            fmt(get(mesh, "dijkstra", "query_s") * 1e3, ".2f"), fmt(get(mesh, "dijkstra", "mre") * 100, ".2f"),
            fmt(get(mesh, "heat", "query_s") * 1e3, ".2f"), fmt(get(mesh, "heat", "mre") * 100, ".2f"),
            fmt(get(mesh, "heat-idt", "mre") * 100, ".2f"), fmt(get(mesh, "exact", "query_s"), ".2f"),
            fmt(r_dij, ".2f"), fmt(r_heat, ".2f"), fmt(r_rand, ".2f"), fmt(r_nolay, ".2f"),
            fmt(get(mesh, "gsp", "update_steps_per_triangle"), ".2f"),
            fmt(get(mesh, "gsp", "state_bytes_per_vertex"), ".0f")))
    lines.append("| **geometric mean** | | | | | | | | | | **{}** | **{}** | **{}** | **{}** | | |".format(
        *(fmt(geomean(cols[k]), ".2f") for k in cols)))
    return "\n".join(lines) + "\n"


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("csv", nargs="+", help="gsp-bench --csv output (several: merged)")
    p.add_argument("-o", "--output", help="PNG to write (accuracy vs throughput)")
    p.add_argument("--markdown", help="write the per-mesh table here ('-' for stdout)")
    p.add_argument("--title", default="gsp-bench: accuracy vs throughput", help="plot title")
    a = p.parse_args(argv)
    if not a.output and not a.markdown:
        p.error("nothing to do: give -o PNG and/or --markdown FILE")
    rows = read_rows(a.csv)
    if not rows:
        p.error("no rows in " + ", ".join(a.csv))
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
