"""``agrirecipe eval``: (being implemented)."""

from __future__ import annotations

import argparse
from typing import Any


def register(subparsers: Any) -> None:
    """Add the ``eval`` sub-command."""
    parser = subparsers.add_parser("eval", help="(not available yet)")
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    """Not available yet."""
    from agrirecipe._errors import ConfigurationError

    raise ConfigurationError("'eval' is not available in this build")
