"""``agrirecipe schema``: print the JSON Schema of a scene recipe."""

from __future__ import annotations

import argparse
import sys
from typing import Any


def register(subparsers: Any) -> None:
    """Add the ``schema`` sub-command."""
    parser = subparsers.add_parser(
        "schema",
        help="print the JSON Schema of a scene recipe",
        description="Print the JSON Schema (draft 2020-12) that recipe files follow.",
    )
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    """Print the schema."""
    from agrirecipe.recipe import schema_text

    sys.stdout.write(schema_text())
    return 0
