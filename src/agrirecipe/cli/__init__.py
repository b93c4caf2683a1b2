"""The ``agrirecipe`` command: one sub-command per module of this package.

Every sub-command module defines ``register(subparsers)`` which adds its parser
and sets ``handler`` (a function taking the parsed arguments and returning an
exit code). Errors a user can cause are printed as one clear message with exit
code 2; nothing prints a traceback for them.
"""

from __future__ import annotations

import argparse
import importlib
import sys
from collections.abc import Sequence

from agrirecipe._errors import AgrirecipeError

__all__ = ["build_parser", "main"]

_COMMAND_MODULES = (
    "generate",
    "validate",
    "schema",
    "render",
    "eval",
    "assets",
    "build",
    "edit",
    "app",
    "dataset",
    "finetune",
)


def build_parser() -> argparse.ArgumentParser:
    """The argument parser with every sub-command."""
    from agrirecipe import __version__

    parser = argparse.ArgumentParser(
        prog="agrirecipe",
        description="Turn a natural-language request into agricultural scenes for Unreal "
        "Engine 5, Blender and OpenUSD, offline.",
    )
    parser.add_argument("--version", action="version", version=f"agrirecipe {__version__}")
    subparsers = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    for name in _COMMAND_MODULES:
        module = importlib.import_module(f"agrirecipe.cli._{name}")
        module.register(subparsers)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; return the exit code."""
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        code: int = args.handler(args)
    except AgrirecipeError as exc:
        print(f"agrirecipe: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("agrirecipe: interrupted", file=sys.stderr)
        return 130
    return code
