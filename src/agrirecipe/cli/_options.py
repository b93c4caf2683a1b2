"""Options several commands share."""

from __future__ import annotations

import argparse

from agrirecipe.resolve._registry import BUILTIN_RESOLVERS

__all__ = ["add_resolver_option"]


def add_resolver_option(parser: argparse.ArgumentParser, help_text: str) -> None:
    """``--resolver``: "auto" or a built-in strategy, "finetuned" among them."""
    parser.add_argument(
        "--resolver",
        default="auto",
        choices=["auto", *BUILTIN_RESOLVERS],
        help=f"{help_text} (default auto)",
    )
