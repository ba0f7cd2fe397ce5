"""CasADi functions as a shared library for the C++ core.

A model written with CasADi symbols is evaluated in C++ without Python: its functions
(``casadi.Function``) are written out as C by CasADi's code generator, compiled once with the
system C compiler into a shared library, and loaded by ``hinf_cpp.GeneratedFunction`` (C++:
``hinf/numerics/generated_function.hpp``)::

    import casadi as ca
    from hinf_cpp.models.codegen import compile_casadi_functions

    q = ca.SX.sym("q", 3)
    f = ca.Function("f", [q], [ca.sin(q)])
    lib = compile_casadi_functions([f, ca.Function("J", [q], [ca.jacobian(ca.sin(q), q)])], "demo")
    J = lib.function("J")            # hinf_cpp.GeneratedFunction
    J([0.1, 0.2, 0.3])               # [3 x 3 numpy array]

Libraries are cached: the file name carries a SHA-256 of the generated C source, the
compiler's identity (its path and ``--version``) and the flags, so the same functions compile
once per machine and compiler; a changed expression is another file. ``compile_c_source`` is
the compile step alone, for C source already written (a study's model carried to a Dask
worker): the same source gets the same library. The cache folder is ``$HINF_CPP_CACHE``, else
``$XDG_CACHE_HOME/hinf_cpp/casadi`` (``~/.cache/hinf_cpp/casadi``). Each file is written under
a temporary name and renamed into place, so processes compiling the same functions at once
each end with a complete library.

A file name can be computed by anyone with the same compiler, so the name alone is not trusted:
the cache folder is made private (mode 0700, whatever the umask), a folder that another user
owns or that group or others can write is refused (``CacheDirectoryError``, saying what to
do), and each library's SHA-256 is recorded beside it (``<library>.sha256``) and checked before
the library is loaded. An entry whose hash is missing or wrong, or that does not load, is
compiled anew under the same name. ``check_cache_folder`` and ``make_cache_folder`` apply
the same rules to the plan cache (``hinf_cpp.planning``).

The generated code is pinned to the ABI the C++ loader reads: ``casadi_real = double`` and
``casadi_int = long long int``; the library also reports both sizes
(``hinf_casadi_int_size()``, ``hinf_casadi_real_size()``), which the loader checks.
"""

from __future__ import annotations

import dataclasses
import functools
import hashlib
import os
import pathlib
import re
import secrets
import shlex
import shutil
import stat
import subprocess
import tempfile
import time
from typing import TYPE_CHECKING, Sequence

if TYPE_CHECKING:  # casadi is optional (the extra "symbolic"); imported when used
    import casadi

    from hinf_cpp._core import GeneratedFunction

# What the C++ loader reads (hinf/numerics/generated_function.hpp).
GENERATOR_OPTIONS = {"casadi_real": "double", "casadi_int": "long long int", "with_header": False}
# Reported by the library so that the loader can check the ABI it was compiled with.
ABI_FUNCTIONS = """
/* Added by hinf_cpp.models.codegen: the sizes of this file's types, checked by the loader. */
#ifdef __cplusplus
extern "C" {
#endif
CASADI_SYMBOL_EXPORT int hinf_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int hinf_casadi_real_size(void) { return (int) sizeof(casadi_real); }
#ifdef __cplusplus
} /* extern "C" */
#endif
"""
# -O2 (measured with GCC 12, docs/models.md): -O3 evaluates no faster; -O1 compiles long
# straight-line code (SX, 20000 lines) 4 times faster at the same speed, but evaluates the
# loops of MX code (matrix products) 3 times slower, and compilation happens once per entry.
# Extra arguments given with the compiler come after these (compiler="cc -O1" overrides -O2).
COMPILE_FLAGS = ("-O2", "-fPIC", "-shared")
LINK_LIBRARIES = ("-lm",)  # sin, exp, sqrt, ... of the generated code
# Part of every cache key: a change to how libraries are made changes every file name.
CACHE_FORMAT = "hinf_cpp.models.codegen 1"
C_IDENTIFIER = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")


class CompilationError(RuntimeError):
    """The C compiler is missing or failed on the generated code."""


class CacheDirectoryError(OSError):
    """The cache folder cannot be created or written, or is refused: another user owns it, or
    group or others can write it."""


@dataclasses.dataclass(frozen=True)
class CompiledLibrary:
    """A compiled library: its path, whether it came from the cache, and the seconds spent
    generating the C source (also on a cache hit: the key is its hash; 0 from
    :func:`compile_c_source`, given the source) and compiling it (0 on a cache hit)."""

    path: pathlib.Path
    cache_hit: bool
    generate_seconds: float
    compile_seconds: float

    def function(self, name: str) -> GeneratedFunction:
        """The function ``name`` of the library, loaded (``hinf_cpp.GeneratedFunction``)."""
        from hinf_cpp._core import GeneratedFunction

        return GeneratedFunction(str(self.path), name)


def default_cache_dir() -> pathlib.Path:
    """``$HINF_CPP_CACHE``, else ``$XDG_CACHE_HOME/hinf_cpp/casadi`` or ``~/.cache/hinf_cpp/casadi``."""
    if os.environ.get("HINF_CPP_CACHE"):
        return pathlib.Path(os.environ["HINF_CPP_CACHE"])
    base = os.environ.get("XDG_CACHE_HOME") or pathlib.Path.home() / ".cache"
    return pathlib.Path(base) / "hinf_cpp" / "casadi"


def _import_casadi():
    try:
        import casadi
    except ImportError as error:
        raise ImportError("hinf_cpp.models.codegen needs CasADi: pip install casadi "
                          "(or pip install 'hinf_cpp[symbolic]')") from error
    return casadi


def generate_c_source(functions: Sequence[casadi.Function], name: str) -> str:
    """One C file holding every function, as CasADi's code generator writes it with the
    options the C++ loader needs (GENERATOR_OPTIONS), plus the ABI functions."""
    casadi = _import_casadi()
    if not C_IDENTIFIER.fullmatch(name):
        raise ValueError(f"the library name must be a C identifier (letters, digits, _), got {name!r}")
    if isinstance(functions, casadi.Function) or not functions:
        raise ValueError("functions must be a non-empty list of casadi.Function")
    seen: set[str] = set()
    for f in functions:
        if not isinstance(f, casadi.Function):
            raise ValueError(f"functions must be casadi.Function objects, got {type(f).__name__}")
        if f.name() in seen:
            raise ValueError(f"two functions are named {f.name()!r}: names are the symbols of the library")
        seen.add(f.name())
    generator = casadi.CodeGenerator(f"{name}.c", GENERATOR_OPTIONS)
    for f in functions:
        generator.add(f)
    return generator.dump() + ABI_FUNCTIONS


def _compiler_command(compiler: str | None) -> list[str]:
    """The compiler as a command: the argument, else $CC, else cc (split like a shell would)."""
    if compiler:
        text, origin = compiler, "the compiler argument"
    elif os.environ.get("CC"):
        text, origin = os.environ["CC"], "$CC"
    else:
        text, origin = "cc", "the default"
    command = shlex.split(text)
    if not command:
        raise CompilationError(f"the C compiler command from {origin} is empty ({text!r})")
    found = shutil.which(command[0])
    if found is None:
        raise CompilationError(
            f"C compiler {command[0]!r} not found (from {origin}): install one (Debian/Ubuntu: "
            "apt-get install build-essential), or name it with $CC or the compiler argument")
    return [found, *command[1:]]


@functools.lru_cache(maxsize=None)
def _compiler_identity(command: tuple[str, ...]) -> str:
    """The compiler's resolved path and ``--version`` text: part of the cache key, so that
    another compiler (or an upgrade) compiles anew."""
    try:
        done = subprocess.run([*command, "--version"], capture_output=True, text=True, timeout=60)
        version = done.stdout
    except (OSError, subprocess.TimeoutExpired) as error:
        version = f"unknown ({error})"
    return f"{os.path.realpath(command[0])} {' '.join(command[1:])}\n{version}"


# What compile_casadi_functions writes, and what to do when its cache folder cannot be used.
WHAT = "compiled CasADi functions"
HINT = "Set HINF_CPP_CACHE to a writable folder, or pass cache_dir="
# A library is not loaded from a folder or file whose mode has one of these bits.
WRITABLE_BY_OTHERS = stat.S_IWGRP | stat.S_IWOTH


def check_cache_folder(folder: pathlib.Path, what: str, hint: str) -> bool:
    """Whether the cache folder exists; raises CacheDirectoryError for one that is not the
    user's own and private: owned by another user, or writable by group or others (whoever can
    write it can put a file under a name this package computes, and have it loaded or read).

    `what` says what the folder keeps and `hint` where else to keep it, for the message."""
    folder = pathlib.Path(folder)
    try:
        info = folder.stat()
    except (FileNotFoundError, NotADirectoryError):
        return False
    except OSError as error:
        raise CacheDirectoryError(f"cannot use the cache folder {folder} for {what}: {error.strerror or error}. "
                                  f"{hint}") from error
    if not stat.S_ISDIR(info.st_mode):
        raise CacheDirectoryError(f"the cache folder {folder} for {what} is not a folder. {hint}")
    if info.st_uid != os.geteuid():
        raise CacheDirectoryError(
            f"refusing the cache folder {folder} for {what}: it is owned by another user (uid {info.st_uid}, "
            f"this process runs as uid {os.geteuid()}), who could have put files in it under the names this "
            f"package looks for. Remove it (or have its owner do so), or use a folder of your own: {hint}")
    if info.st_mode & WRITABLE_BY_OTHERS:
        who = " and ".join(name for bit, name in ((stat.S_IWGRP, "group"), (stat.S_IWOTH, "others"))
                           if info.st_mode & bit)
        raise CacheDirectoryError(
            f"refusing the cache folder {folder} for {what}: {who} can write it (mode "
            f"{stat.S_IMODE(info.st_mode):04o}), so anyone could have put files in it under the names this "
            f"package looks for. If its content is yours, make it private: chmod 700 {folder}; else remove "
            f"it, or use another folder: {hint}")
    return True


def make_cache_folder(folder: pathlib.Path, what: str, hint: str) -> None:
    """Creates the cache folder, and the missing folders above it, with mode 0700 whatever the
    umask (mkdir, then chmod); checks it (:func:`check_cache_folder`) and that a file can be
    written in it. Raises CacheDirectoryError otherwise."""
    folder = pathlib.Path(folder)
    missing = []
    for parent in (folder, *folder.parents):
        if os.path.lexists(parent):
            break
        missing.append(parent)
    try:
        for made in reversed(missing):
            try:
                os.mkdir(made, 0o700)
            except FileExistsError:  # made by another process meanwhile: checked below
                continue
            os.chmod(made, 0o700)
        check_cache_folder(folder, what, hint)
        probe = tempfile.NamedTemporaryFile(dir=folder, prefix=".probe-", delete=True)
        probe.close()
    except CacheDirectoryError:
        raise
    except OSError as error:
        raise CacheDirectoryError(f"cannot write {what} to the cache folder {folder}: {error.strerror or error}. "
                                  f"{hint}") from error


def _hash_path(library: pathlib.Path) -> pathlib.Path:
    """Where the library's SHA-256 is recorded (sha256sum's format: digest, two spaces, name)."""
    return library.with_name(library.name + ".sha256")


def _sha256(path: pathlib.Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def _usable_entry(library: pathlib.Path, symbol: str) -> bool:
    """Whether a cached library may be used: a regular file of this user that group and others
    cannot write, whose SHA-256 is the one recorded beside it, and that loads (with `symbol`)."""
    try:
        info = os.lstat(library)
        if not stat.S_ISREG(info.st_mode) or info.st_uid != os.geteuid() or info.st_mode & WRITABLE_BY_OTHERS:
            return False
        recorded = _hash_path(library).read_text().split()
        if not recorded or recorded[0] != _sha256(library):
            return False
    except (OSError, UnicodeDecodeError):
        return False
    from hinf_cpp._core import GeneratedFunction

    try:
        GeneratedFunction(str(library), symbol)
    except (ValueError, RuntimeError):
        return False
    return True


def _write_atomically(path: pathlib.Path, write) -> None:
    """Writes through write(temporary path) and renames the result into place: readers see the
    old file or the new one, never a part. The temporary name is unique to this call (process
    id and random digits) and write() creates the file, so its permissions follow the umask
    like any new file's (mkstemp would make it private to the user), less write permission for
    group and others (a cache entry they could write is not used)."""
    temporary = path.with_name(f".{path.name}.{os.getpid()}.{secrets.token_hex(8)}.tmp")
    try:
        write(temporary)
        os.chmod(temporary, stat.S_IMODE(os.stat(temporary).st_mode) & ~WRITABLE_BY_OTHERS)
        os.replace(temporary, path)
    finally:
        temporary.unlink(missing_ok=True)


def compile_casadi_functions(functions: Sequence[casadi.Function], name: str,
                             cache_dir: str | os.PathLike | None = None,
                             compiler: str | None = None) -> CompiledLibrary:
    """Compile CasADi functions into one shared library for the C++ core, or find it cached.

    Generates one C file with every function (``casadi_real = double``,
    ``casadi_int = long long int``, plus the ABI functions the loader checks) and compiles it
    with ``-O2 -fPIC -shared`` into the cache folder. The file name carries a SHA-256 of the
    C source, the compiler's identity and the flags: the same functions compile once per
    machine and compiler. Files are written under a temporary name and renamed into place.
    The cache folder is made with mode 0700; a cached library is used only if its SHA-256 is
    the one recorded beside it (``<library>.sha256``) and it loads, else it is compiled anew.

    Parameters
    ----------
    functions : sequence of casadi.Function
        The functions, with distinct names (the library's symbols).
    name : str
        The library's name (a C identifier), the start of its file name.
    cache_dir : str or os.PathLike, optional
        The folder of the libraries (default ``$HINF_CPP_CACHE``, else
        ``$XDG_CACHE_HOME/hinf_cpp/casadi`` or ``~/.cache/hinf_cpp/casadi``).
    compiler : str, optional
        The C compiler command (default ``$CC``, else ``cc``); arguments in it come after
        the flags (``"cc -O1"`` overrides ``-O2``).

    Returns
    -------
    CompiledLibrary
        ``path`` (the ``.so``; its C source is beside it), ``cache_hit``, ``generate_seconds``
        and ``compile_seconds`` (0 on a cache hit); ``function(name)`` loads one function as a
        ``hinf_cpp.GeneratedFunction``.

    Raises
    ------
    ValueError
        Bad arguments: a name that is not a C identifier, no functions, objects that are not
        ``casadi.Function``, two functions of the same name.
    hinf_cpp.models.codegen.CompilationError
        The compiler is missing or fails (with the end of its error output).
    hinf_cpp.models.codegen.CacheDirectoryError
        The cache folder cannot be created or written, or is refused: another user owns it, or
        group or others can write it (an OSError; the message says what to do).

    Examples
    --------
    >>> import casadi as ca
    >>> from hinf_cpp.models import compile_casadi_functions
    >>> x = ca.SX.sym("x", 3)
    >>> library = compile_casadi_functions(
    ...     [ca.Function("f", [x], [ca.sin(x)]), ca.Function("J", [x], [ca.jacobian(ca.sin(x), x)])],
    ...     "demo", cache_dir="cache")
    >>> library.path.suffix, library.cache_hit
    ('.so', False)
    >>> J = library.function("J")  # hinf_cpp.GeneratedFunction
    >>> J([0.0, 0.0, 0.0])[0]      # one array per output
    array([[1., 0., 0.],
           [0., 1., 0.],
           [0., 0., 1.]])
    """
    started = time.perf_counter()
    source = generate_c_source(functions, name)
    generate_seconds = time.perf_counter() - started
    library = compile_c_source(source, name, functions[0].name(), cache_dir, compiler)
    return dataclasses.replace(library, generate_seconds=generate_seconds)


def compile_c_source(source: str, name: str, symbol: str, cache_dir: str | os.PathLike | None = None,
                     compiler: str | None = None) -> CompiledLibrary:
    """Compile C source into a shared library in the private cache, or find it cached.

    The compile step of :func:`compile_casadi_functions`, for C source that is already written
    (by ``generate_c_source``, or carried from another machine, as a study carries its
    models to Dask workers). The library's file name is ``<name>-<key>.so``, where the key is a
    SHA-256 of the source, the compiler's identity (its path and ``--version``) and the flags:
    the same source gets the same name here as from :func:`compile_casadi_functions`, and
    compiles once per machine and compiler. The source is written beside the library
    (``.c``), the library's SHA-256 beside it too (``<library>.sha256``), each under a
    temporary name renamed into place. The cache folder is made with mode 0700; a cached
    library is used only if its SHA-256 is the one recorded beside it and it loads (with
    `symbol`), else it is compiled anew under the same name.

    Parameters
    ----------
    source : str
        The C source, with the ABI functions the loader checks (as ``generate_c_source``
        writes it).
    name : str
        The library's name (a C identifier), the start of its file name.
    symbol : str
        A function of the library: a cached entry is used only if it loads with this function.
    cache_dir : str or os.PathLike, optional
        The folder of the libraries, as for :func:`compile_casadi_functions` (default the
        package's cache folder).
    compiler : str, optional
        The C compiler command, as for :func:`compile_casadi_functions` (default ``$CC``, else
        ``cc``).

    Returns
    -------
    CompiledLibrary
        ``path`` (the ``.so``; its C source is beside it), ``cache_hit``, ``generate_seconds``
        (0: the source was given) and ``compile_seconds`` (0 on a cache hit).

    Raises
    ------
    ValueError
        A name that is not a C identifier.
    hinf_cpp.models.codegen.CompilationError, hinf_cpp.models.codegen.CacheDirectoryError
        As from :func:`compile_casadi_functions`: the compiler is missing or fails; the cache
        folder cannot be used.

    Examples
    --------
    >>> import casadi as ca
    >>> from hinf_cpp.models import compile_c_source
    >>> from hinf_cpp.models.codegen import generate_c_source
    >>> x = ca.SX.sym("x", 2)
    >>> source = generate_c_source([ca.Function("twice", [x], [2 * x])], "demo")
    >>> library = compile_c_source(source, "demo", "twice", cache_dir="cache")
    >>> library.path.suffix, library.cache_hit
    ('.so', False)
    >>> compile_c_source(source, "demo", "twice", cache_dir="cache").path == library.path  # cached
    True
    >>> library.function("twice")([1.0, 2.0])[0]  # a 2 x 1 output
    array([[2.],
           [4.]])
    """
    if not C_IDENTIFIER.fullmatch(name):
        raise ValueError(f"the library name must be a C identifier (letters, digits, _), got {name!r}")
    command = _compiler_command(compiler)
    key_text = "\0".join([CACHE_FORMAT, _compiler_identity(tuple(command)), " ".join(COMPILE_FLAGS + LINK_LIBRARIES),
                          source])
    key = hashlib.sha256(key_text.encode()).hexdigest()[:32]
    folder = pathlib.Path(cache_dir) if cache_dir is not None else default_cache_dir()
    library = folder / f"{name}-{key}.so"
    if check_cache_folder(folder, WHAT, HINT) and _usable_entry(library, symbol):
        return CompiledLibrary(library, True, 0.0, 0.0)

    # Absent, damaged, planted or unloadable: compiled anew under the same name.
    make_cache_folder(folder, WHAT, HINT)
    started = time.perf_counter()
    # The source is kept beside the library (same key), for reading and debugging.
    c_file = library.with_suffix(".c")
    _write_atomically(c_file, lambda temporary: temporary.write_text(source))

    def compile_to(output: pathlib.Path) -> None:
        arguments = [command[0], *COMPILE_FLAGS, *command[1:], "-o", str(output), str(c_file), *LINK_LIBRARIES]
        try:
            done = subprocess.run(arguments, capture_output=True, text=True, timeout=3600)
        except OSError as error:
            raise CompilationError(f"cannot run the C compiler {command[0]}: {error}") from error
        if done.returncode != 0:
            tail = "\n".join((done.stderr or done.stdout).strip().splitlines()[-30:])
            raise CompilationError(
                f"the C compiler failed (exit status {done.returncode}) on the generated code of '{name}' "
                f"({c_file}):\n$ {shlex.join(arguments)}\n{tail or '(no output)'}")

    _write_atomically(library, compile_to)
    digest = _sha256(library)
    _write_atomically(_hash_path(library), lambda temporary: temporary.write_text(f"{digest}  {library.name}\n"))
    return CompiledLibrary(library, False, 0.0, time.perf_counter() - started)
