#!/usr/bin/env bash
# Builds what is out of date in build/ and runs the whole test suite.
# Usage: scripts/test.sh [extra ctest arguments, e.g. -R apps]
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."

jobs=${GSP_JOBS:-$(nproc)}
if [[ ! -f build/build.ninja ]]; then
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
fi
cmake --build build -j "$jobs"
ctest --test-dir build -j2 --output-on-failure "$@"
