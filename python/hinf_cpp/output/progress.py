"""A one-line live progress display on stderr for the longer commands.

``[3/12] running lqr on poor_heading_135 ...`` is rewritten in place (carriage return) as
the work advances and erased at the end. It is shown only when the stream is a terminal
(``stream.isatty()``) and ``quiet`` is false, so pipes, files, CI logs and tests see nothing.
"""

from __future__ import annotations

import sys
import threading
from typing import Callable, TextIO

__all__ = ["Progress", "ProgressCallback"]

#: What the data functions (compare, recovery_study, sweep_gamma) call before each run:
#: callback(index, total, message), index counting from 1.
ProgressCallback = Callable[[int, int, str], None]


def _is_terminal(stream: TextIO) -> bool:
    isatty = getattr(stream, "isatty", None)
    try:
        return bool(isatty()) if isatty is not None else False
    except (ValueError, OSError):  # a closed stream
        return False


class Progress:
    """Live progress line, used as the ``progress`` callback of the data functions.

    ``progress(index, total, message)`` shows ``[index/total] message ...`` in place of the
    previous line (carriage return); ``close()`` (or the end of a ``with`` block) erases it.
    Nothing is written unless the stream is a terminal and `quiet` is false.

    Parameters
    ----------
    quiet : bool, optional
        True turns the display off (default False).
    stream : file-like, optional
        Where to write (default ``sys.stderr``); nothing is written unless
        ``stream.isatty()`` is true.

    Examples
    --------
    >>> from hinf_cpp.analysis import compare
    >>> from hinf_cpp.output.progress import Progress
    >>> with Progress() as progress:  # shown on a terminal only
    ...     comparison = compare(hc.load_scenario(hc.scenario_path("paper_fig1")), "hinf,lqr",
    ...                          progress=progress)
    >>> import io
    >>> class Terminal(io.StringIO):
    ...     def isatty(self):
    ...         return True
    >>> stream = Terminal()
    >>> with Progress(stream=stream) as progress:
    ...     progress(1, 2, "running hinf")
    >>> stream.getvalue()
    '\\r[1/2] running hinf ...\\r                      \\r'
    """

    def __init__(self, quiet: bool = False, stream: TextIO | None = None):
        self.stream = stream if stream is not None else sys.stderr
        self.enabled = not quiet and _is_terminal(self.stream)
        self._width = 0
        self._lock = threading.Lock()

    def __call__(self, index: int, total: int, message: str) -> None:
        """Shows ``[index/total] message ...`` in place of the previous line."""
        if not self.enabled:
            return
        line = f"[{index}/{total}] {message} ..."
        with self._lock:
            self.stream.write("\r" + line.ljust(self._width))
            self.stream.flush()
            self._width = max(self._width, len(line))

    def close(self) -> None:
        """Erases the line (the terminal is left as it was before)."""
        if not self.enabled or self._width == 0:
            return
        with self._lock:
            self.stream.write("\r" + " " * self._width + "\r")
            self.stream.flush()
            self._width = 0

    def __enter__(self) -> "Progress":
        return self

    def __exit__(self, *exc) -> None:
        self.close()
