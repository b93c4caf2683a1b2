"""Atomic file writing: a reader never sees a half-written output."""

from __future__ import annotations

import contextlib
import os
import re
import tempfile
from collections.abc import Iterator
from pathlib import Path

__all__ = ["atomic_path", "remove_stale_temporaries", "write_atomic"]

#: Permissions of written outputs (rw-r--r--, like a file created with open()).
_OUTPUT_MODE = 0o644


def write_atomic(path: str | Path, data: str | bytes) -> Path:
    """Write ``data`` to ``path`` through a temporary file in the same folder and a rename."""
    target = Path(path)
    target.parent.mkdir(parents=True, exist_ok=True)
    payload = data.encode("utf-8") if isinstance(data, str) else data
    handle, temporary = tempfile.mkstemp(dir=target.parent, prefix=_prefix(target), suffix=".tmp")
    try:
        # mkstemp makes the file private (0600); an output file should be readable like any other.
        Path(temporary).chmod(_OUTPUT_MODE)
        with os.fdopen(handle, "wb") as stream:
            stream.write(payload)
            stream.flush()
            os.fsync(stream.fileno())
        Path(temporary).replace(target)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise
    return target


@contextlib.contextmanager
def atomic_path(path: str | Path, *, suffix: str = ".tmp") -> Iterator[Path]:
    """A temporary path beside ``path`` to write to; renamed onto ``path`` on success.

    For outputs too large to hold in memory or written by a foreign library
    (e.g. ``pxr`` exporting a stage): write to the yielded path, and the file
    appears at ``path`` only once complete. On an exception the temporary file
    is removed. ``suffix`` lets libraries that pick a format from the file
    extension (``".usda"``) see the right one.
    """
    target = Path(path)
    target.parent.mkdir(parents=True, exist_ok=True)
    handle, temporary = tempfile.mkstemp(dir=target.parent, prefix=_prefix(target), suffix=suffix)
    os.close(handle)
    Path(temporary).chmod(_OUTPUT_MODE)  # not mkstemp's private 0600
    try:
        yield Path(temporary)
        with Path(temporary).open("rb+") as stream:
            os.fsync(stream.fileno())
        Path(temporary).replace(target)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise


# What _prefix and mkstemp name a temporary: ".<name>.<pid>.<8 random characters><suffix>".
_TEMPORARY = re.compile(r"\.(?P<name>.+)\.(?P<pid>[0-9]+)\.[A-Za-z0-9_]{8}\.[A-Za-z0-9]+")


def _prefix(target: Path) -> str:
    # The writer's process id is in the name: a later write can tell a temporary
    # left by a killed process from one another process is still writing.
    return f".{target.name}.{os.getpid()}."


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # another user's live process
        return True
    return True


def remove_stale_temporaries(folder: str | Path) -> list[Path]:
    """Delete the temporaries that killed writes left in ``folder`` and its subfolders.

    A write killed with SIGKILL cannot remove its own temporary file
    (``.<name>.<pid>.<random><suffix>``, possibly hundreds of megabytes); the next
    write into the folder removes those whose process no longer runs. Temporaries
    of live processes (a concurrent write) are left alone. Returns what was removed.
    """
    root = Path(folder)
    if not root.is_dir():
        return []
    removed: list[Path] = []
    for path in root.rglob(".*"):
        match = _TEMPORARY.fullmatch(path.name)
        if match is None or not path.is_file() or _alive(int(match["pid"])):
            continue
        path.unlink(missing_ok=True)
        removed.append(path)
    return removed
