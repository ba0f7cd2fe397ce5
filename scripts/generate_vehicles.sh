#!/usr/bin/env bash
# Writes the C code of the built-in vehicles, cpp/src/models/generated/<kind>.c, from their
# statements (python/hinf_cpp/models/builtin.py) with CasADi (the version pinned in
# requirements-dev.txt). Run after changing a statement or a default parameter of a vehicle, then
# rebuild; tests/python/test_generated_vehicles.py fails while the files differ from what the
# statements generate.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
PYTHON="${PYTHON:-$ROOT/.venv/bin/python}"
"$PYTHON" -c "import sys; from hinf_cpp.models.builtin import write_generated_sources
for path in write_generated_sources(sys.argv[1]): print(path)" "$ROOT/cpp/src/models/generated"
