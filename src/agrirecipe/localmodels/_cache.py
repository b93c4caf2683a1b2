"""Where agrirecipe keeps files it derives at run time (assembled GGUF, embedding indexes)."""

from __future__ import annotations

import os
from pathlib import Path

__all__ = ["cache_dir"]


def cache_dir(override: str | Path | None = None) -> Path:
    """The cache folder.

    The argument, else ``AGRIRECIPE_CACHE_DIR``, else ``$XDG_CACHE_HOME/agrirecipe``
    (``~/.cache/agrirecipe``).
    """
    if override is not None:
        path = Path(override)
    elif os.environ.get("AGRIRECIPE_CACHE_DIR"):
        path = Path(os.environ["AGRIRECIPE_CACHE_DIR"])
    else:
        path = Path(os.environ.get("XDG_CACHE_HOME", Path.home() / ".cache")) / "agrirecipe"
    path.mkdir(parents=True, exist_ok=True)
    return path
