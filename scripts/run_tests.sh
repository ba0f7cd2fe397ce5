#!/usr/bin/env bash
# The whole test suite: set-up (scripts/setup.sh), then the C++ tests (ctest, plain CMake
# build in build/cmake) and the Python tests (pytest).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
bash scripts/setup.sh
export PATH="$ROOT/.venv/bin:$PATH"

cmake -S . -B build/cmake -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build/cmake
ctest --test-dir build/cmake --output-on-failure -j 2
python -m pytest "$@"
