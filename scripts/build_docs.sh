#!/usr/bin/env bash
# Builds the API reference (docs/reference, Sphinx with numpydoc) from the installed package into
# build/docs/html (or the folder given). Strict: any warning, such as a reference that does not
# resolve or a malformed docstring section, fails the build. tests/python/test_reference.py
# runs it. Open build/docs/html/index.html.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
PYTHON="${PYTHON:-$ROOT/.venv/bin/python}"
OUT="${1:-$ROOT/build/docs/html}"
"$PYTHON" -m sphinx -W --keep-going -n -q -b html "$ROOT/docs/reference" "$OUT"
echo "the API reference: $OUT/index.html"
