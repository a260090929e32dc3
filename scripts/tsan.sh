#!/usr/bin/env bash
# The threaded code under ThreadSanitizer: the parallel propagation (GeodesicOptions::threads),
# independent queries (compute_many, distance_matrix), and the apps' --separate/--matrix.
#   scripts/tsan.sh [BUILD_DIR]     (default: build-tsan; a Debug-ish build, ~5 minutes)
# Exits non-zero on any race report.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build-tsan}
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGSP_SANITIZE=thread -DGSP_WITH_CGAL=OFF \
  -DGSP_BUILD_APPS=OFF > /dev/null
ninja -C "$build" geodesic_parallel_test geodesic_batch_test
export TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1"
"$build/bin/geodesic_parallel_test"
"$build/bin/geodesic_batch_test"
echo "tsan: no races reported"
