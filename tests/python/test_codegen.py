"""CasADi functions compiled by hinf_cpp.models.codegen and evaluated in C++ (GeneratedFunction),
against CasADi's own evaluation of the same functions; the compile cache; the error messages.
Every library is compiled into a temporary cache folder, never the user's."""

from __future__ import annotations

import hashlib
import os
import pathlib
import stat
import subprocess
import sys
import textwrap
import threading
import time

import numpy as np
import pytest

import hinf_cpp as hc

ca = pytest.importorskip("casadi")
from hinf_cpp.models import codegen# noqa: E402 - after the skip: the module is usable only with casadi

ROOT = pathlib.Path(__file__).resolve().parents[2]


def example_functions() -> list:
    """One function of each kind the loader must handle."""
    x = ca.SX.sym("x")
    v = ca.SX.sym("v", 3)
    y = ca.SX.sym("y", 2)
    A = ca.SX.sym("A", 2, 3)
    scalar = ca.Function("scalar", [x], [x**3 - 2 * x + 1], ["x"], ["r"])
    vector = ca.Function("vector", [v], [ca.vertcat(v[0] * v[1], v[2] - v[0], 3 * v[1])], ["v"], ["r"])
    # A 3 x 3 output with structural zeros.
    M = ca.SX(3, 3)
    M[0, 0] = v[0]
    M[2, 0] = v[1] * v[2]
    M[1, 2] = v[2] ** 2
    zeros = ca.Function("zeros", [v], [M], ["v"], ["M"])
    # A sparse Jacobian of a ship-like right-hand side.
    rhs = ca.vertcat(0.5 * v[1] * v[2] - v[0], -2 * v[1] + ca.sin(v[0]) * v[2], v[0] * ca.cos(v[2]))
    jacobian = ca.Function("jacobian", [v], [ca.jacobian(rhs, v)], ["v"], ["J"])
    # Several inputs and outputs, transcendental functions, a matrix input (not symmetric, so a
    # transposed read shows).
    several = ca.Function("several", [v, y, A],
                          [ca.sin(v) * y[0] + ca.cos(v[::-1]) * y[1],
                           ca.exp(-ca.sumsqr(v)) + ca.sqrt(1 + y[0] ** 2),
                           ca.mtimes(A, v) + ca.tanh(ca.mtimes(A, v))],
                          ["v", "y", "A"], ["s", "e", "Av"])
    return [scalar, vector, zeros, jacobian, several]


FUNCTIONS = {f.name(): f for f in example_functions()}


@pytest.fixture(scope="module")
def cache(tmp_path_factory) -> pathlib.Path:
    return tmp_path_factory.mktemp("casadi_cache")


@pytest.fixture(scope="module")
def compiled(cache) -> codegen.CompiledLibrary:
    return codegen.compile_casadi_functions(list(FUNCTIONS.values()), "examples", cache_dir=cache)


def random_inputs(f, rng) -> list:
    return [rng.uniform(-2.0, 2.0, size=f.size_in(i)) for i in range(f.n_in())]


def casadi_outputs(f, inputs) -> list[np.ndarray]:
    """CasADi's own evaluation (its virtual machine), as dense arrays."""
    out = f(*inputs)
    out = out if isinstance(out, (tuple, list)) else [out]
    return [np.array(ca.DM(o).full()) for o in out]


@pytest.mark.parametrize("name", sorted(FUNCTIONS))
def test_generated_function_equals_casadi(compiled, name):
    f = FUNCTIONS[name]
    g = compiled.function(name)
    assert (g.name(), g.n_in(), g.n_out()) == (name, f.n_in(), f.n_out())
    assert [g.input_shape(i) for i in range(g.n_in())] == [f.size_in(i) for i in range(f.n_in())]
    assert [g.output_shape(i) for i in range(g.n_out())] == [f.size_out(i) for i in range(f.n_out())]
    assert [g.input_name(i) for i in range(g.n_in())] == f.name_in()
    rng = np.random.default_rng(7)
    for _ in range(20):
        inputs = random_inputs(f, rng)
        actual = g(*inputs)
        expected = casadi_outputs(f, inputs)
        assert len(actual) == len(expected)
        for o, (a, e) in enumerate(zip(actual, expected)):
            assert a.shape == e.shape
            # The same expression graph evaluated by CasADi's virtual machine and by the C
            # compiler's build of the generated code: the same operations on the same libm, but
            # the compiler may reorder or contract them (fused multiply-add), a few ulps of the
            # terms (inputs and outputs are below 10 here).
            np.testing.assert_allclose(a, e, rtol=1e-13, atol=1e-13, err_msg=f"output {o}")
            # Structural zeros are exact zeros.
            sparsity = f.sparsity_out(o)
            structural_zero = np.ones(e.shape, dtype=bool)
            for r, c in zip(*sparsity.get_triplet()):
                structural_zero[r, c] = False
            assert np.all(a[structural_zero] == 0.0)


def test_outputs_depend_on_each_input(compiled):
    """A check that the comparison can fail: changing any one input changes some output."""
    g = compiled.function("several")
    rng = np.random.default_rng(3)
    inputs = random_inputs(FUNCTIONS["several"], rng)
    base = g(*inputs)
    for i in range(len(inputs)):
        moved = [x.copy() for x in inputs]
        moved[i] += 0.1
        assert any(not np.allclose(a, b) for a, b in zip(g(*moved), base)), f"input {i}"


def test_inputs_as_numbers_lists_and_arrays(compiled):
    scalar, several = compiled.function("scalar"), compiled.function("several")
    assert scalar(2.0)[0].shape == (1, 1) and scalar(2.0)[0][0, 0] == 5.0
    assert scalar(np.array([[2.0]]))[0][0, 0] == scalar(2)[0][0, 0] == 5.0
    v, y = [0.1, 0.2, 0.3], [1, 2]
    A = np.arange(6.0).reshape(2, 3)  # C order: the binding must read it by (row, column)
    expected = casadi_outputs(FUNCTIONS["several"], [np.array(v), np.array(y, dtype=float), A])
    for v_form in (v, np.array(v), np.array(v).reshape(3, 1)):
        for A_form in (A, np.asfortranarray(A), A.tolist()):
            for a, e in zip(several(v_form, y, A_form), expected):
                np.testing.assert_allclose(a, e, rtol=1e-13, atol=1e-13)  # as above


@pytest.mark.parametrize("args, message", [
    (([1.0, 2.0], [1.0, 2.0], np.zeros((2, 3))),
     r"input 0 \(v\) of 'several' must be an array of shape \(3, 1\) or of length 3, got list \[1.0, 2.0\]"),
    (([1.0, 2.0, 3.0], [1.0, 2.0], np.zeros((3, 2))),
     r"input 2 \(A\) of 'several' must be an array of shape \(2, 3\), got numpy.ndarray of shape \(3, 2\)"),
    (([1.0, 2.0, 3.0], np.zeros((1, 2)), np.zeros((2, 3))),
     r"input 1 \(y\) of 'several' must be an array of shape \(2, 1\) or of length 2, got numpy.ndarray of shape "
     r"\(1, 2\)"),
    (([1.0, 2.0, 3.0], ["a", "b"], np.zeros((2, 3))), r"input 1 \(y\) of 'several' must be an array"),
    (([1.0, 2.0, 3.0], [1.0, 2.0]), r"'several' takes 3 inputs \(v, y, A\), got 2"),
])
def test_wrong_inputs_are_value_errors(compiled, args, message):
    with pytest.raises(ValueError, match=message):
        compiled.function("several")(*args)


def test_index_out_of_range(compiled):
    with pytest.raises(ValueError, match=r"input index 3 out of range: 'several' has 3 inputs"):
        compiled.function("several").input_shape(3)


def test_concurrent_evaluation_equals_serial(compiled):
    """The binding releases the GIL while C++ evaluates: threads share one GeneratedFunction
    (and its workspace pool)."""
    g = compiled.function("jacobian")
    rng = np.random.default_rng(11)
    inputs = [rng.uniform(-1, 1, 3) for _ in range(4000)]
    serial = [g(x)[0] for x in inputs]
    results: dict[int, list] = {}

    def work(k: int) -> None:
        results[k] = [g(x)[0] for x in inputs[k::4]]

    threads = [threading.Thread(target=work, args=(k,)) for k in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for k in range(4):
        for a, b in zip(results[k], serial[k::4]):
            assert np.array_equal(a, b)  # the same code on the same input


# ---- the cache ----

def test_second_compile_is_a_cache_hit(compiled, cache):
    again = codegen.compile_casadi_functions(example_functions(), "examples", cache_dir=cache)
    assert again.cache_hit and not compiled.cache_hit
    assert again.path == compiled.path and again.path.parent == cache
    assert again.compile_seconds == 0.0 and compiled.compile_seconds > 0.0
    assert again.path.name.startswith("examples-") and again.path.suffix == ".so"
    # Only finished files in the cache: libraries, their sources and SHA-256 (sha256sum's
    # format), no temporary files.
    assert again.path.with_suffix(".c").exists()
    assert all(p.suffix in (".so", ".c", ".sha256") and not p.name.startswith(".") for p in cache.iterdir())
    digest = hashlib.sha256(again.path.read_bytes()).hexdigest()
    assert (cache / f"{again.path.name}.sha256").read_text() == f"{digest}  {again.path.name}\n"


def test_cached_files_have_the_permissions_of_new_files(tmp_path):
    """The library and its source are readable by whoever the umask lets read new files (not
    private to the user, as temporary files would be); the folder is private (next test)."""
    previous = os.umask(0o022)
    try:
        library = codegen.compile_casadi_functions([FUNCTIONS["scalar"]], "shared", cache_dir=tmp_path)
    finally:
        os.umask(previous)
    assert stat.S_IMODE(library.path.with_suffix(".c").stat().st_mode) == 0o644
    assert stat.S_IMODE(library.path.stat().st_mode) & 0o755 == 0o755  # readable and executable by all


def test_the_cache_folder_is_private_whatever_the_umask(tmp_path):
    """The folders made for the cache are 0700 (mkdir, then chmod), and no file in them can be
    written by group or others, even under umask 0."""
    folder = tmp_path / "made" / "cache"
    previous = os.umask(0)
    try:
        library = codegen.compile_casadi_functions([FUNCTIONS["scalar"]], "private", cache_dir=folder)
    finally:
        os.umask(previous)
    assert stat.S_IMODE(folder.stat().st_mode) == 0o700
    assert stat.S_IMODE(folder.parent.stat().st_mode) == 0o700
    for path in folder.iterdir():
        assert stat.S_IMODE(path.stat().st_mode) & 0o022 == 0, path


def private_folder(path: pathlib.Path) -> pathlib.Path:
    path.mkdir()
    path.chmod(0o700)
    return path


def expected_library_name(tmp_path, functions, name) -> str:
    """The file name compile_casadi_functions gives these functions (anyone with the same
    compiler can compute it: found here by compiling them elsewhere)."""
    return codegen.compile_casadi_functions(functions, name, cache_dir=tmp_path / "elsewhere").path.name


PLANTED_C = r"""
#include <stdio.h>
__attribute__((constructor)) static void planted(void) {
    FILE* f = fopen(MARKER, "w");
    if (f) { fputs("the planted library was loaded\n", f); fclose(f); }
}
double scalar(double x) { return x; }
"""


@pytest.mark.parametrize("planted", ["library", "library with a wrong hash", "garbage", "library with its hash"])
def test_a_planted_library_is_not_loaded_and_is_rebuilt(tmp_path, planted):
    """A file put in the cache folder under the computed name is not loaded (its code would run
    at load: here a constructor that writes a file), unless its SHA-256 is recorded beside it;
    it is compiled anew. Recorded beside it (the user's own entry) but not loading with the
    function asked for, it is compiled anew too."""
    functions = [FUNCTIONS["scalar"]]
    name = expected_library_name(tmp_path, functions, "planted")
    cache = private_folder(tmp_path / "cache")
    marker = tmp_path / "marker"
    target = cache / name
    if planted == "garbage":
        target.write_bytes(b"\x7fELF" + os.urandom(4000))
    else:
        source = tmp_path / "planted.c"
        source.write_text(PLANTED_C)
        subprocess.run(["cc", "-shared", "-fPIC", f'-DMARKER="{marker}"', "-o", str(target), str(source)], check=True)
    if planted == "library with a wrong hash":
        (cache / f"{name}.sha256").write_text(f"{'0' * 64}  {name}\n")
    if planted == "library with its hash":  # loads, but has none of CasADi's symbols: not usable
        (cache / f"{name}.sha256").write_text(f"{hashlib.sha256(target.read_bytes()).hexdigest()}  {name}\n")
    library = codegen.compile_casadi_functions(functions, "planted", cache_dir=cache)
    if planted != "library with its hash":
        assert not marker.exists(), "the planted library was loaded"
    assert not library.cache_hit and library.path == target
    assert library.function("scalar")(2.0)[0][0, 0] == 5.0  # 2^3 - 2*2 + 1: the real one
    assert (cache / f"{name}.sha256").read_text().split()[0] == hashlib.sha256(target.read_bytes()).hexdigest()
    assert codegen.compile_casadi_functions(functions, "planted", cache_dir=cache).cache_hit


@pytest.mark.parametrize("damage", ["truncated", "hash removed"])
def test_a_damaged_entry_is_rebuilt(tmp_path, damage):
    first = codegen.compile_casadi_functions([FUNCTIONS["vector"]], "damaged", cache_dir=tmp_path)
    if damage == "truncated":
        data = first.path.read_bytes()
        first.path.write_bytes(data[:len(data) // 2])
    else:
        (tmp_path / f"{first.path.name}.sha256").unlink()
    again = codegen.compile_casadi_functions([FUNCTIONS["vector"]], "damaged", cache_dir=tmp_path)
    assert not again.cache_hit and again.path == first.path
    np.testing.assert_array_equal(again.function("vector")([1.0, 2.0, 3.0])[0].ravel(), [2.0, 2.0, 6.0])


@pytest.mark.parametrize("mode, who", [(0o777, "group and others"), (0o720, "group"), (0o702, "others")],
                         ids=["0777", "0720", "0702"])
def test_a_cache_folder_others_can_write_is_refused(tmp_path, mode, who):
    """Refused also when it holds a good entry: who can write the folder could have put it there."""
    cache = tmp_path / "shared"
    codegen.compile_casadi_functions([FUNCTIONS["scalar"]], "shared", cache_dir=cache)
    cache.chmod(mode)
    with pytest.raises(codegen.CacheDirectoryError,
                       match=rf"refusing the cache folder {cache} .*: {who} can write it \(mode 0{mode:o}\).*"
                             rf"chmod 700 {cache}.*HINF_CPP_CACHE"):
        codegen.compile_casadi_functions([FUNCTIONS["scalar"]], "shared", cache_dir=cache)


@pytest.mark.skipif(not hasattr(os, "geteuid") or os.geteuid() != 0, reason="chown to another user needs root")
def test_a_cache_folder_of_another_user_is_refused(tmp_path):
    cache = tmp_path / "theirs"
    codegen.compile_casadi_functions([FUNCTIONS["scalar"]], "theirs", cache_dir=cache)
    os.chown(cache, 65534, -1)
    with pytest.raises(codegen.CacheDirectoryError,
                       match=rf"refusing the cache folder {cache} .*owned by another user \(uid 65534"):
        codegen.compile_casadi_functions([FUNCTIONS["scalar"]], "theirs", cache_dir=cache)


def test_another_expression_is_another_library(compiled, cache):
    x = ca.SX.sym("x")
    changed = ca.Function("scalar", [x], [x**3 - 2 * x + 2], ["x"], ["r"])  # + 2 instead of + 1
    other = codegen.compile_casadi_functions([changed], "examples", cache_dir=cache)
    assert not other.cache_hit and other.path != compiled.path
    assert other.function("scalar")(2.0)[0][0, 0] == 6.0


def test_compiler_arguments_are_part_of_the_key(compiled, cache):
    """Arguments given with the compiler come after the default flags (-O1 overrides -O2) and
    make another library."""
    at_o1 = codegen.compile_casadi_functions(list(FUNCTIONS.values()), "examples", cache_dir=cache, compiler="cc -O1")
    assert not at_o1.cache_hit and at_o1.path != compiled.path
    x = [0.3, -0.2, 0.9]
    np.testing.assert_allclose(at_o1.function("jacobian")(x)[0], compiled.function("jacobian")(x)[0],
                               rtol=1e-13, atol=1e-13)  # the same code, another optimization level


def test_default_cache_folder_is_hinf_cpp_cache(monkeypatch, tmp_path):
    monkeypatch.setenv("HINF_CPP_CACHE", str(tmp_path / "from_env"))
    assert codegen.default_cache_dir() == tmp_path / "from_env"
    library = codegen.compile_casadi_functions([FUNCTIONS["scalar"]], "env")
    assert library.path.parent == tmp_path / "from_env"
    monkeypatch.delenv("HINF_CPP_CACHE")
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    assert codegen.default_cache_dir() == tmp_path / "xdg" / "hinf_cpp" / "casadi"


CONCURRENT_SCRIPT = textwrap.dedent("""
    import sys, time
    import casadi as ca
    from hinf_cpp.models import codegen
    cache, start = sys.argv[1], float(sys.argv[2])
    x = ca.SX.sym("x", 4)
    f = ca.Function("concurrent", [x], [ca.jacobian(ca.sin(x) * ca.sumsqr(x), x)])
    while time.time() < start:  # both processes compile at the same moment
        time.sleep(0.001)
    library = codegen.compile_casadi_functions([f], "concurrent", cache_dir=cache)
    value = library.function("concurrent")([0.1, 0.2, 0.3, 0.4])[0]
    expected = f([0.1, 0.2, 0.3, 0.4]).full()
    assert abs(value - expected).max() <= 1e-13, (value, expected)
    print(library.path, library.cache_hit)
""")


def test_concurrent_compiles_of_the_same_functions_both_succeed(tmp_path):
    start = time.time() + 3.0  # after both interpreters have imported casadi
    processes = [subprocess.Popen([sys.executable, "-c", CONCURRENT_SCRIPT, str(tmp_path), str(start)],
                                  stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True) for _ in range(2)]
    outputs = [p.communicate(timeout=300) for p in processes]
    for p, (out, err) in zip(processes, outputs):
        assert p.returncode == 0, err
    paths = {out.split()[0] for out, _ in outputs}
    assert len(paths) == 1
    assert sorted(p.suffix for p in tmp_path.iterdir()) == [".c", ".sha256", ".so"]  # no temporary files left


# ---- errors ----

def test_missing_library_file(tmp_path):
    with pytest.raises(ValueError, match=r"no shared library at '.*nope\.so': the file does not exist"):
        hc._core.GeneratedFunction(str(tmp_path / "nope.so"), "f")


def test_file_that_is_not_a_library(tmp_path):
    path = tmp_path / "text.so"
    path.write_text("not a library\n" * 20)
    with pytest.raises(ValueError, match=r"'.*text\.so' is not a whole shared library for this machine: "
                                         r"it is not an ELF file"):
        hc._core.GeneratedFunction(str(path), "f")


def test_wrong_function_name(compiled):
    with pytest.raises(ValueError, match=r"has no function 'nope' \(the symbol nope is missing\): the library was not "
                                         r"generated by CasADi's code generator, or the function name is wrong"):
        hc._core.GeneratedFunction(str(compiled.path), "nope")


def test_failure_flag_of_the_generated_code_is_a_hinf_error(tmp_path):
    library = tmp_path / "handwritten.so"
    subprocess.run(["cc", "-shared", "-fPIC", "-o", str(library),
                    str(ROOT / "tests" / "cpp" / "fixtures" / "handwritten_functions.c")], check=True)
    failing = hc._core.GeneratedFunction(str(library), "failing")
    assert failing(2.0)[0][0, 0] == 2.0
    with pytest.raises(hc.HinfError, match=r"the generated function 'failing' in '.*' returned 1"):
        failing(-1.0)


def test_unwritable_cache_folder(tmp_path):
    blocker = tmp_path / "a_file"
    blocker.write_text("")
    folder = blocker / "cache"  # under a regular file: cannot be made (even by root)
    with pytest.raises(codegen.CacheDirectoryError, match=rf"cache folder {folder}: .*Set HINF_CPP_CACHE"):
        codegen.compile_casadi_functions([FUNCTIONS["scalar"]], "blocked", cache_dir=folder)


def test_compiler_not_found(tmp_path):
    with pytest.raises(codegen.CompilationError,
                       match=r"C compiler 'no-such-compiler-hinf' not found .*apt-get install build-essential"):
        codegen.compile_casadi_functions([FUNCTIONS["scalar"]], "x", cache_dir=tmp_path, compiler="no-such-compiler-hinf")


def test_broken_compiler_from_cc(tmp_path, monkeypatch):
    monkeypatch.setenv("CC", "false")
    with pytest.raises(codegen.CompilationError, match=r"(?s)the C compiler failed \(exit status 1\) on the generated "
                                                      r"code of 'broken'.*\$ .*false -O2 -fPIC -shared"):
        codegen.compile_casadi_functions([FUNCTIONS["scalar"]], "broken", cache_dir=tmp_path)
    assert not list(tmp_path.glob("*.so")) and not list(tmp_path.glob(".*tmp"))


def test_compiler_errors_are_shown(tmp_path):
    # A macro that breaks the generated code: the compiler's own message must reach the user.
    with pytest.raises(codegen.CompilationError, match=r"(?s)the C compiler failed.*no_such_type"):
        codegen.compile_casadi_functions([FUNCTIONS["scalar"]], "typo", cache_dir=tmp_path,
                                         compiler="cc -Dcasadi_real=no_such_type")


@pytest.mark.parametrize("functions, name, message", [
    ([], "x", "non-empty list"),
    (None, "x", "non-empty list"),
    ([FUNCTIONS["scalar"], FUNCTIONS["scalar"]], "x", "two functions are named 'scalar'"),
    (["f"], "x", "casadi.Function objects, got str"),
    ([FUNCTIONS["scalar"]], "not-an-identifier", "C identifier"),
])
def test_bad_arguments(tmp_path, functions, name, message):
    with pytest.raises(ValueError, match=message):
        codegen.compile_casadi_functions(functions, name, cache_dir=tmp_path)
