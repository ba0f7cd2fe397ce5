"""The ``hinf-cpp`` command's entry point, outside the package so that it imports nothing first.

Importing :mod:`hinf_cpp` takes a second or two (NumPy, the C++ core, matplotlib later); a
Ctrl-C in that time ends the command as a Ctrl-C during its work does (``hinf_cpp.cli``): one
line, ``hinf-cpp: error: interrupted``, exit status 130, no traceback.
"""

import sys

INTERRUPTED = 130  # 128 + SIGINT, as a shell reports a process that SIGINT ended


def main() -> int:
    try:
        from hinf_cpp.cli import main as run

        return run()
    except KeyboardInterrupt:
        print("hinf-cpp: error: interrupted", file=sys.stderr)
        return INTERRUPTED
