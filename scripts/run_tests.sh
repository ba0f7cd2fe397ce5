#!/usr/bin/env bash
# The whole test suite, as CI runs it (.ci/run): set-up (scripts/setup.sh), pytest against the
# installed package (the Release build), then scripts/run_sanitized_tests.sh: the C++ tests
# (ctest) and pytest again, against a build with AddressSanitizer, UndefinedBehaviorSanitizer and
# Eigen's and libstdc++'s assertions. Extra arguments go to both pytest runs.
# Each test runs where it checks the most, once: the C++ tests only in the sanitized build
# (compiling them twice would double the longest part of the run); the tests marked slow or text
# only here (tests/python/conftest.py).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
bash scripts/setup.sh
export PATH="$ROOT/.venv/bin:$PATH"

# Two pytest workers (pytest-xdist): most tests run one thread; those that start Dask or thread
# pools of their own bound them, so two workers keep a 2-core machine busy without oversubscribing.
python -m pytest -n 2 "$@"
bash scripts/run_sanitized_tests.sh "$@"
