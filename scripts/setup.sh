#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine for the GSP toolkit and builds it:
#   1. installs the Debian packages the project needs (only those missing; apt is not
#      touched at all when everything is there),
#   2. configures and builds a Release build with Ninja in build/,
#   3. runs the main job on the bundled sample: geodesic distances from one vertex of
#      data/samples/fertility.off, written to out/fertility-distance.ply (float distance,
#      quality and colours per vertex) with a preview picture out/fertility-distance.png.
# Usage: scripts/setup.sh [--no-build]      (run as root, or with sudo available)
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."

build=1
for arg in "$@"; do
  case "$arg" in
    --no-build) build=0 ;;
    -h|--help) sed -n '2,8p' "$0"; exit 0 ;;
    *) echo "setup.sh: unknown argument '$arg' (use --no-build or --help)" >&2; exit 2 ;;
  esac
done

packages=(
  # build tools (clang for the fuzzers, python3-matplotlib for the plots in docs/)
  cmake ninja-build g++ clang pkg-config git python3 python3-matplotlib
  # the Python package (python/): bindings, its tests, pip install from the checkout
  python3-dev pybind11-dev python3-numpy python3-pytest python3-setuptools python3-wheel python3-pip python3-venv
  # gsp.batch: Dask distributed (scheduler, workers, LocalCluster)
  python3-distributed python3-dask
  # libraries
  libopenmesh-dev libcgal-dev libnanoflann-dev libeigen3-dev libembree-dev libtinygltf-dev
  libcli11-dev libtbb-dev libgtest-dev libbenchmark-dev libpng-dev
)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${db:Status-Abbrev}' "$p" 2>/dev/null || true)
  [[ "$status" == ii* ]] || missing+=("$p")
done

if ((${#missing[@]})); then
  echo "setup.sh: installing ${missing[*]}"
  sudo=()
  if ((EUID != 0)); then
    command -v sudo >/dev/null || { echo "setup.sh: not root and no sudo; install: ${missing[*]}" >&2; exit 1; }
    sudo=(sudo)
  fi
  export DEBIAN_FRONTEND=noninteractive
  "${sudo[@]}" apt-get update -q
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q "${missing[@]}"
else
  echo "setup.sh: all ${#packages[@]} packages present"
fi

((build)) || exit 0

jobs=${GSP_JOBS:-$(nproc)}
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$jobs"

# The main job on the bundled sample: a geodesic distance field and its picture (in out/).
mkdir -p out
build/bin/gsp-geodesic data/samples/fertility.off --source-vertex 0 \
  -o out/fertility-distance.ply --png out/fertility-distance.png --stats out/fertility-distance.json
echo "setup.sh: done; wrote out/fertility-distance.ply, out/fertility-distance.png and out/fertility-distance.json"
