"""Output files: checked before a computation, written whole or not at all.

:func:`check_output_path` and :func:`check_output_folder` raise ValueError for a path that
cannot be written (empty, a directory, below a plain file, in a folder without write
permission), with the words of the C++ ``check_output_path`` that ``hinf-sim`` uses.
:func:`atomic_output` writes into a temporary file in the target's folder and renames it over
the target once complete (as C++ ``write_text_file``): a failed write, a full disk included,
leaves the previous file, or none, never a truncated one. An existing device or pipe
(``/dev/stdout``) is written in place. Write failures are OSError naming the path.
"""

from __future__ import annotations

import contextlib
import errno
import itertools
import os
import pathlib
from typing import BinaryIO, Iterator

__all__ = ["FIGURE_SUFFIXES", "atomic_output", "check_output_folder", "check_output_path", "write_text"]

#: The file endings a figure can be written as.
FIGURE_SUFFIXES = (".png", ".pdf", ".svg")

_counter = itertools.count()


def _nearest_existing_folder(start: str) -> str:
    folder = start or "."
    while not os.path.exists(folder):
        parent = os.path.dirname(folder) or "."
        if parent == folder:  # "/" or "." (a working directory that was removed)
            break
        folder = parent
    return folder


def _check_folder_above(folder: str, cannot: str) -> None:
    """The nearest existing folder at or above `folder` must be a writable folder."""
    existing = _nearest_existing_folder(folder)
    if not os.path.isdir(existing):
        raise ValueError(f"{cannot}'{existing}' is not a directory")
    if not os.access(existing, os.W_OK | os.X_OK):
        raise ValueError(f"{cannot}'{existing}': {os.strerror(errno.EACCES)}")


def check_output_path(path: str | os.PathLike, figure: bool = False) -> None:
    """Check, before a computation, that a file can be written at a path.

    Raises ValueError unless a file can be written at `path` (not empty, not a directory, not
    below a plain file, in a folder with write permission or one that can be made); with
    `figure`, its suffix must also be .png, .pdf or .svg. The words are those of the C++
    ``check_output_path`` that ``hinf-sim`` uses.

    Parameters
    ----------
    path : str or os.PathLike
        The file.
    figure : bool, optional
        The file is a figure (default False).

    Raises
    ------
    ValueError
        Naming the path and what is wrong.

    Examples
    --------
    >>> from hinf_cpp.output.files import check_output_path
    >>> check_output_path("out/run.json")  # the folder out/ would be made
    >>> check_output_path("paths.txt", figure=True)
    Traceback (most recent call last):
        ...
    ValueError: cannot write the figure 'paths.txt': its name must end in .png, .pdf or .svg
    >>> check_output_path(".")
    Traceback (most recent call last):
        ...
    ValueError: cannot write '.': it is a directory
    """
    path = os.fspath(path)
    if path == "":
        raise ValueError("an output file name is empty")
    cannot = f"cannot write '{path}': "
    if os.path.isdir(path):
        raise ValueError(cannot + "it is a directory")
    if figure and os.path.splitext(path)[1].lower() not in FIGURE_SUFFIXES:
        raise ValueError(f"cannot write the figure '{path}': its name must end in .png, .pdf or .svg")
    _check_folder_above(os.path.dirname(path), cannot)


def check_output_folder(path: str | os.PathLike) -> None:
    """Check, before a computation, that files can be written into a folder.

    Raises ValueError unless `path` is a folder files can be written into, or can be made
    one.

    Parameters
    ----------
    path : str or os.PathLike
        The folder.

    Raises
    ------
    ValueError
        An empty name, a path that is not a directory, a folder without write permission.

    Examples
    --------
    >>> from hinf_cpp.output.files import check_output_folder, write_text
    >>> check_output_folder("report")  # made when written into
    >>> _ = write_text("notes.txt", "a file\\n")
    >>> check_output_folder("notes.txt")
    Traceback (most recent call last):
        ...
    ValueError: cannot write into 'notes.txt': it is not a directory
    """
    path = os.fspath(path)
    if path == "":
        raise ValueError("an output folder name is empty")
    cannot = f"cannot write into '{path}': "
    if os.path.exists(path) and not os.path.isdir(path):
        raise ValueError(cannot + "it is not a directory")
    _check_folder_above(path, cannot)


def _open_temporary(folder: str, name: str) -> tuple[int, str]:
    """A new file next to the target, with the usual mode (0666 less the umask)."""
    while True:
        temporary = os.path.join(folder, f".{name}.{os.getpid()}.{next(_counter)}.tmp")
        try:
            return os.open(temporary, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_CLOEXEC, 0o666), temporary
        except FileExistsError:
            continue


@contextlib.contextmanager
def atomic_output(path: str | os.PathLike) -> Iterator[BinaryIO]:
    """A binary file to write that appears at `path` only when the block completes.

    ``with atomic_output(path) as f: f.write(...)`` writes into a temporary file in the
    target's folder and renames it over the target once complete; on any exception the
    target is left as it was. Missing folders are created. An existing device or pipe
    (``/dev/stdout``) is written in place.

    Parameters
    ----------
    path : str or os.PathLike
        The file.

    Yields
    ------
    BinaryIO
        The file to write (bytes).

    Raises
    ------
    ValueError
        A path that cannot be written (:func:`check_output_path`).
    OSError
        A write failure (a full disk), naming the path.

    Examples
    --------
    >>> from hinf_cpp.output.files import atomic_output
    >>> with atomic_output("data.bin") as f:
    ...     _ = f.write(b"complete")
    >>> try:
    ...     with atomic_output("data.bin") as f:
    ...         _ = f.write(b"part")
    ...         raise KeyboardInterrupt
    ... except KeyboardInterrupt:
    ...     pass
    >>> import pathlib
    >>> pathlib.Path("data.bin").read_bytes()  # the previous file, whole
    b'complete'
    """
    path = os.fspath(path)
    check_output_path(path)
    cannot = f"cannot write '{path}': "
    try:
        if os.path.exists(path) and not os.path.isfile(path):  # a device or a pipe: in place
            with open(path, "wb") as handle:
                yield handle
            return
        folder = os.path.dirname(path) or "."
        os.makedirs(folder, exist_ok=True)
        fd, temporary = _open_temporary(folder, os.path.basename(path))
        try:
            with os.fdopen(fd, "wb") as handle:
                yield handle
                handle.flush()
                os.fsync(handle.fileno())
            os.replace(temporary, path)
        except BaseException:
            with contextlib.suppress(OSError):
                os.unlink(temporary)
            raise
    except OSError as error:
        raise OSError(error.errno, cannot + (error.strerror or str(error))) from None


def write_text(path: str | os.PathLike, text: str) -> pathlib.Path:
    """Write a text file (UTF-8) whole or not at all (:func:`atomic_output`).

    Parameters
    ----------
    path : str or os.PathLike
        The file (missing folders are created).
    text : str
        The content.

    Returns
    -------
    pathlib.Path
        The path written.

    Raises
    ------
    ValueError
        A path that cannot be written.
    OSError
        The file could not be written.

    Examples
    --------
    >>> from hinf_cpp.output.files import write_text
    >>> path = write_text("notes/summary.md", "# Summary\\n")
    >>> path.read_text()
    '# Summary\\n'
    """
    with atomic_output(path) as handle:
        handle.write(text.encode("utf-8"))
    return pathlib.Path(path)
