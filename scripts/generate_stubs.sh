#!/usr/bin/env bash
# Writes the type stubs of the extension, python/hinf_cpp/_core.pyi, from the installed module
# (run after scripts/setup.sh or a rebuild). With a folder argument, writes <folder>/hinf_cpp/
# _core.pyi instead (tests/python/test_stubs.py compares that with the checked-in stub).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
PYTHON="${PYTHON:-$ROOT/.venv/bin/python}"
OUT="${1:-$ROOT/python}"
# Every enum-like default value (<Method.bdf: 0>) names an enum of hinf_cpp._core.
"$PYTHON" -m pybind11_stubgen hinf_cpp._core --output-dir "$OUT" --exit-code \
  --enum-class-locations ".+:hinf_cpp._core"
