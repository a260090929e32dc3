#!/usr/bin/env bash
# Renders the pictures of docs/gallery.md into docs/gallery/*.png: geodesic distance fields
# from gsp-geodesic drawn by gsp-render (or, when gsp-geodesic is not built, the meshes plain).
#
# Usage: scripts/make_gallery.sh [BUILD_DIR]        (default: build)
#   GSP_DATA_DIR     folder with the shared meshes (default: ../shared/data/meshes)
#   GSP_GALLERY_SIZE picture side in pixels (default: 384; the committed pictures use 384)
# Build the two apps first: cmake --build build --target gsp-render gsp-geodesic
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$root/build}"
data="${GSP_DATA_DIR:-$root/../shared/data/meshes}"
size="${GSP_GALLERY_SIZE:-384}"
out="$root/docs/gallery"
render="$build/bin/gsp-render"
geodesic="$build/bin/gsp-geodesic"

[[ -x "$render" ]] || { echo "make_gallery: $render not found; build the gsp-render target first" >&2; exit 1; }
[[ -d "$data" ]] || { echo "make_gallery: no mesh folder $data (set GSP_DATA_DIR)" >&2; exit 1; }
have_geodesic=1
[[ -x "$geodesic" ]] || { have_geodesic=0; echo "make_gallery: $geodesic not built: rendering plain meshes" >&2; }

mkdir -p "$out"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

# name  mesh  source-vertex  load-options  gsp-render options
# A source of "-" means no field: the mesh is drawn plain. Load options ("-" for none) go to
# both apps, so that the field's vertices are the ones gsp-render reads.
while read -r name mesh source load options; do
  [[ -z "$name" || "$name" == \#* ]] && continue
  [[ "$load" == "-" ]] && load=""
  args=(--size "$size" --aa --quiet)
  # shellcheck disable=SC2206  # the option columns are word lists on purpose
  args+=($load $options)
  if [[ "$source" != "-" && $have_geodesic == 1 ]]; then
    # shellcheck disable=SC2086
    "$geodesic" "$data/$mesh" $load --source-vertex "$source" -o "$tmp/$name.txt" --quiet
    args+=(--field "$tmp/$name.txt" --source-vertex "$source")
  fi
  "$render" "$data/$mesh" -o "$out/$name.png" "${args[@]}"
  echo "$out/$name.png ($(stat -c %s "$out/$name.png") bytes)"
done <<'LIST'
# closed genus-4 surface, the default view (azimuth 30, elevation 20)
fertility       fertility.off               0  -       --view 30,20
# range scan with holes; turbo colour map
bunny           stanford_bunny.obj          0  -       --colormap turbo
# isotropic remesh
armadillo       armadillo_remeshed.obj      0  -       --view 20,15
# profile view of a bust
nefertiti       nefertiti_lowres.obj        0  -       --view 90,10
# open surface (one boundary loop)
camelhead       camelhead.off               0  -       --view 30,20
# OBJ as stored: the body's texture seam is a cut the distances must go around; lid and spout
# are separate pieces, unreached (grey)
teapot          newell_teapot.obj           0  -       --view 30,25
# the same welded: the seam is gone
teapot-welded   newell_teapot.obj           0  --weld  --view 30,25
# four separate tyres (STL, welded on reading): three stay unreached
tires           thingi10k_99865_tires.stl   0  -       --up z --view 30,35
# no field: the triangles of a CAD export (long slivers)
sensor-wire     adis16480_sensor.stl        -  -       --wireframe --up z --view 30,20
LIST

# Geodesic Voronoi regions: five sources, each face coloured by its nearest source (the PLY's
# per-vertex `source` property), with the distance's iso-lines drawn over them.
if [[ $have_geodesic == 1 ]]; then
  sources=0,1000,2000,3000,4000
  "$geodesic" "$data/fertility.off" --source-vertex "$sources" -o "$tmp/voronoi.ply" --quiet
  "$render" "$tmp/voronoi.ply" --property distance --label-property source --source-vertex "$sources" \
    --iso 12 --size "$size" --aa --quiet -o "$out/fertility-voronoi.png"
  echo "$out/fertility-voronoi.png ($(stat -c %s "$out/fertility-voronoi.png") bytes)"
fi
