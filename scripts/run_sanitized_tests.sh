#!/usr/bin/env bash
# The test suite against a sanitized build: the library, hinf-sim, the C++ tests and the Python
# extension built with AddressSanitizer and UndefinedBehaviorSanitizer (any UB is fatal) and with
# Eigen's and libstdc++'s assertions on (Debug: no NDEBUG), in build/sanitize/cmake
# (incremental). Then ctest, then pytest on the sanitized extension. Any sanitizer report, also
# from a subprocess whose failure a test expects, fails the step. Extra arguments go to pytest.
# scripts/run_tests.sh runs it after the plain pytest; this is where the C++ tests run. pytest
# skips what runs once, in the plain stage: the tests marked slow or text (tests/python/conftest.py).
# Timings: README.md, "Tests".
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
bash scripts/setup.sh
export PATH="$ROOT/.venv/bin:$PATH"

BUILD="$ROOT/build/sanitize/cmake"
# A virtual environment of its own: the tests start hinf-sim, hinf-cpp and `python -c` from the
# folder of sys.executable, so running pytest with this environment's python makes every one of
# them use the sanitized build. Its site-packages holds the staged package; a .pth file adds
# .venv's site-packages after it for NumPy, SciPy, Matplotlib and pytest.
STAGE="$ROOT/build/sanitize/venv"
REPORTS="$ROOT/build/sanitize/reports"

fail() { echo "sanitize: $*" >&2; exit 1; }
lap() { echo "sanitize: $1 took $((SECONDS - started)) s"; started=$SECONDS; }

# ---- build ----
# -O1: Eigen at -O0 under the sanitizers is several times slower. -g1: line tables, enough for
# the reports' stack traces, and 30% less compile time than -g.
started=$SECONDS
cmake -S . -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Debug \
      -DCMAKE_CXX_FLAGS_DEBUG="-g1 -O1 -D_GLIBCXX_ASSERTIONS" \
      -DHINF_SANITIZE=ON -DHINF_BUILD_PYTHON=ON \
      -DPython_EXECUTABLE="$ROOT/.venv/bin/python" \
      -Dpybind11_DIR="$(python -m pybind11 --cmakedir)" >/dev/null
cmake --build "$BUILD" -j 2
lap build

# ---- staging ----
[ -x "$STAGE/bin/python" ] || python -m venv --without-pip "$STAGE"
site="$("$STAGE/bin/python" -c 'import sysconfig; print(sysconfig.get_path("purelib"))')"
python -c 'import sysconfig; print(sysconfig.get_path("purelib"))' >"$site/hinf-dev-venv.pth"
core=("$BUILD"/cpp/python/_core.*.so)
[ -f "${core[0]}" ] || fail "no extension module in $BUILD/cpp/python"
# Rebuilt from scratch every time, so nothing stale of an earlier run is imported.
rm -rf "$site/hinf_cpp"
mkdir -p "$site/hinf_cpp"
# The package's tree (its subpackages), without bytecode caches, and the sanitized extension.
(cd python && find hinf_cpp -name __pycache__ -prune -o -type f -print | while read -r file; do
  install -D -m 644 "$file" "$site/$file"; done)
cp "${core[0]}" "$site/hinf_cpp/"
# The whole tree of scenarios/, as cpp/python/CMakeLists.txt installs it (subfolders included).
(cd scenarios && find . -name '*.toml' -exec install -D -m 644 {} "$site/hinf_cpp/scenarios/{}" \;)
cp "$BUILD/cpp/hinf-sim" "$STAGE/bin/hinf-sim"
cat >"$STAGE/bin/hinf-cpp" <<EOF
#!$STAGE/bin/python
import sys
from hinf_cpp.cli import main
sys.exit(main())
EOF
chmod +x "$STAGE/bin/hinf-cpp"

# ---- environment ----
# Python is not instrumented: the ASan runtime must be the first library of every Python process
# that loads the extension, hence LD_PRELOAD (inherited by the tests' subprocesses). libstdc++
# is preloaded with it: ASan looks up the real __cxa_throw when it starts, and Python itself does
# not load libstdc++, so the first C++ exception (of any extension) would hit a null pointer.
# The paths are the ones the extension was linked against.
runtime() { ldd "${core[0]}" | awk -v lib="$1" '$1 ~ "^" lib {print $3}'; }
asan_runtime="$(runtime libasan)"
cxx_runtime="$(runtime libstdc++)"
[ -f "$asan_runtime" ] && [ -f "$cxx_runtime" ] || fail "cannot find the ASan and C++ runtimes of ${core[0]}"
preload="$asan_runtime $cxx_runtime"
# ASan's reports go to files (one per process, report.PID), checked after each suite: a test that
# expects a subprocess to fail cannot mistake a report for the failure it expects. UBSan ignores
# log_path when it runs together with ASan (GCC 12) and reports on stderr. abort_on_error: every
# report of either ends its process with SIGABRT, a status no test expects (ctest counts it as a
# failure even for a WILL_FAIL test), and in the pytest process it makes pytest's faulthandler
# print the Python stack, which names the test.
rm -rf "$REPORTS"
mkdir -p "$REPORTS"
asan_options="abort_on_error=1:log_path=$REPORTS/report"
export UBSAN_OPTIONS="abort_on_error=1:halt_on_error=1:print_stacktrace=1"
export HINF_SANITIZER_STAGE="$STAGE"

check_reports() {
  local reports=("$REPORTS"/report.*)
  [ -e "${reports[0]}" ] || return 0
  cat "${reports[@]}" >&2
  fail "ASan reports after $1 (above; files in $REPORTS)"
}

# ---- C++ tests (leak detection on: no Python here) ----
ASAN_OPTIONS="$asan_options:detect_leaks=1" ctest --test-dir "$BUILD" --output-on-failure -j 2 ||
  { check_reports ctest; fail "ctest failed"; }
check_reports ctest
lap ctest

# ---- Python tests ----
# detect_leaks=0: CPython does not free its arenas and many objects at exit, by design.
# PYTHONMALLOC=malloc: Python objects come from malloc, not from pymalloc's arenas, so ASan also
# sees a use after free or an overrun of a Python object (a reference counting error in the
# bindings); about a third more time.
# --capture=sys: pytest captures the tests' output at the level of sys.stdout and sys.stderr,
# not of the file descriptors, so that a UBSan report in the pytest process reaches the log
# rather than a capture file that dies with the process.
# -n 2: two workers (pytest-xdist), as in the plain stage; a report aborts its worker, which
# pytest-xdist reports as crashed, naming the test it was running.
status=0
ASAN_OPTIONS="$asan_options:detect_leaks=0" LD_PRELOAD="$preload" PYTHONMALLOC=malloc \
  "$STAGE/bin/python" -m pytest -n 2 --capture=sys "$@" || status=$?
check_reports pytest
((status == 0)) || fail "pytest failed (status $status)"
lap pytest
