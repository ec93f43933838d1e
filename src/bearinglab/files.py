"""Writing result files without ever leaving a half-written one."""

from __future__ import annotations

import os
import tempfile
from collections.abc import Callable
from pathlib import Path


def write_atomically(path: str | Path, write: Callable[[str], None]) -> Path:
    """Call ``write(tmp)`` on a temporary file beside ``path``, then rename it to ``path``.

    A failure (in ``write`` or the rename) or a Ctrl-C leaves no file behind (neither
    ``path`` half written nor the temporary file) and re-raises.

    Parameters
    ----------
    path : str or Path
        Destination; its directory must exist.
    write : callable
        Writes the content to the file name it is given.
    """
    path = Path(path)
    tmp = None
    try:
        fd, tmp = tempfile.mkstemp(suffix=path.suffix, dir=path.parent, prefix=f".{path.stem}-")
        os.close(fd)
        write(tmp)
        # mkstemp makes the file private (0600); give it the mode an ordinary file gets
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)
        os.replace(tmp, path)
    finally:  # a failure or a Ctrl-C (KeyboardInterrupt) in write: no file left behind
        if tmp is not None and os.path.exists(tmp):
            os.unlink(tmp)
    return path
