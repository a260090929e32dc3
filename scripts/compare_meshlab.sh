#!/usr/bin/env bash
# Geodesic Poisson-disk sampling (gsp-sample) next to MeshLab's Poisson-disk Sampling filter
# (MeshLab 2020.09, Debian package `meshlab`, run headless through xvfb-run), same mesh, same
# radius: time and the quality figures gsp computes for both point sets (geodesic minimum
# distance / r, coverage radius / r, normalised radius).
#
#   scripts/compare_meshlab.sh MESH COUNT [BUILD_DIR]      (needs: apt-get install meshlab xvfb)
#
# MeshLab picks the radius for COUNT samples; gsp-sample then samples at that radius, and
# `gsp-sample --evaluate` measures MeshLab's points. MeshLab's time is its run minus a run
# that only loads and saves the mesh (its sampling alone); ours is layout + build + sampling
# (no file I/O). Prints one markdown table row.
set -euo pipefail
mesh=${1:?usage: compare_meshlab.sh MESH COUNT [BUILD_DIR]}
count=${2:?usage: compare_meshlab.sh MESH COUNT [BUILD_DIR]}
build=${3:-build}
command -v meshlabserver >/dev/null || { echo "compare_meshlab: meshlabserver not found (apt-get install meshlab xvfb)" >&2; exit 1; }
command -v xvfb-run >/dev/null || { echo "compare_meshlab: xvfb-run not found (apt-get install xvfb)" >&2; exit 1; }
sample="$build/bin/gsp-sample" info="$build/bin/gsp-info"
[[ -x "$sample" && -x "$info" ]] || { echo "compare_meshlab: build gsp-sample and gsp-info first" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Both read the same binary PLY (MeshLab 2020.09's OBJ reader asserts on some valid files).
name=$(basename "$mesh")
"$info" "$mesh" -o "$work/in.ply" --quiet > /dev/null
mesh="$work/in.ply"

cat > "$work/poisson.mlx" <<MLX
<!DOCTYPE FilterScript>
<FilterScript>
 <filter name="Poisson-disk Sampling">
  <Param type="RichInt" value="$count" name="SampleNum"/>
  <Param type="RichAbsPerc" value="0" min="0" max="100" name="Radius"/>
  <Param type="RichInt" value="20" name="MontecarloRate"/>
  <Param type="RichBool" value="false" name="SaveMontecarlo"/>
  <Param type="RichBool" value="false" name="ApproximateGeodesicDistance"/>
  <Param type="RichBool" value="false" name="Subsample"/>
  <Param type="RichBool" value="false" name="RefineFlag"/>
  <Param type="RichMesh" value="0" name="RefineMesh"/>
  <Param type="RichBool" value="true" name="BestSampleFlag"/>
  <Param type="RichInt" value="10" name="BestSamplePool"/>
  <Param type="RichBool" value="false" name="ExactNumFlag"/>
  <Param type="RichFloat" value="1" name="RadiusVariance"/>
 </filter>
</FilterScript>
MLX
printf '<!DOCTYPE FilterScript>\n<FilterScript>\n</FilterScript>\n' > "$work/none.mlx"

now() { date +%s.%N; }
meshlab() {   # meshlabserver with a script; its log goes to $3, and to stderr when it fails
  xvfb-run -a meshlabserver -i "$mesh" -o "$1" -s "$2" > "$3" 2>&1 || { cat "$3" >&2; echo "compare_meshlab: meshlabserver failed" >&2; exit 1; }
}
t0=$(now); meshlab "$work/copy.ply" "$work/none.mlx" "$work/none.log"; t1=$(now)
meshlab "$work/meshlab.ply" "$work/poisson.mlx" "$work/ml.log"; t2=$(now)
radius=$(grep -o 'expected radius of [0-9.eE+-]*' "$work/ml.log" | head -1 | awk '{print $4}')
[[ -n "$radius" ]] || { echo "compare_meshlab: no radius in MeshLab's log" >&2; cat "$work/ml.log" >&2; exit 1; }

"$sample" "$mesh" --radius "$radius" -o "$work/gsp.ply" --stats "$work/gsp.json" --quiet
"$sample" "$mesh" --evaluate "$work/meshlab.ply" --radius "$radius" --stats "$work/ml.json" --quiet

/usr/bin/python3 - "$name" "$radius" "$t0" "$t1" "$t2" "$work/gsp.json" "$work/ml.json" <<'PY'
import json, os, sys
mesh, r, t0, t1, t2, gsp_path, ml_path = sys.argv[1:]
g = json.load(open(gsp_path)); m = json.load(open(ml_path))
ml_time = max(0.0, (float(t2) - float(t1)) - (float(t1) - float(t0)))
tg = g["timings"]; gsp_time = tg.get("layout", 0) + tg.get("build", 0) + tg["compute"]
def q(j): return j["quality"]
print(f"| {mesh} | {float(r):.4g} | MeshLab | {m['result']['count']} | {ml_time:.2f} s | "
      f"{q(m)['min_distance_over_radius']:.3f} | {q(m)['coverage_over_radius']:.3f} | {q(m)['normalized_radius']:.3f} |")
print(f"| {mesh} | {float(r):.4g} | gsp-sample | {g['result']['count']} | {gsp_time:.2f} s | "
      f"{q(g)['min_distance_over_radius']:.3f} | {q(g)['coverage_over_radius']:.3f} | {q(g)['normalized_radius']:.3f} |")
PY
