"""``agrirecipe render``: (being implemented)."""

from __future__ import annotations

import argparse
from typing import Any


def register(subparsers: Any) -> None:
    """Add the ``render`` sub-command."""
    parser = subparsers.add_parser("render", help="(not available yet)")
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    """Not available yet."""
    from agrirecipe._errors import ConfigurationError

    raise ConfigurationError("'render' is not available in this build")
