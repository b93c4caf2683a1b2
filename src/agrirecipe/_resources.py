"""Where the data files shipped with agrirecipe live.

In a wheel they are packaged under ``agrirecipe/_data``; in a source checkout
(editable install) they are the repository's top-level ``hierarchy.yaml``,
``crops/``, ``schemas/``, ``models/`` and ``benchmarks/``.
"""

from __future__ import annotations

from pathlib import Path

__all__ = ["data_path"]

_PACKAGE_DIR = Path(__file__).resolve().parent


def data_path(name: str) -> Path:
    """Return the path of a shipped data file or folder such as ``"hierarchy.yaml"``."""
    packaged = _PACKAGE_DIR / "_data" / name
    if packaged.exists():
        return packaged
    checkout = _PACKAGE_DIR.parent.parent / name
    if checkout.exists():
        return checkout
    raise FileNotFoundError(
        f"agrirecipe data file {name!r} is missing from the installation "
        f"(looked in {packaged} and {checkout}); reinstall the package"
    )
