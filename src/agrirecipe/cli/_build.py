"""``agrirecipe build RECIPE -o DIR``: compile a (hand-edited) recipe file into every output."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from agrirecipe._scene import DEFAULT_BACKENDS


def register(subparsers: Any) -> None:
    """Add the ``build`` sub-command."""
    parser = subparsers.add_parser(
        "build",
        help="validate a recipe file and write its scene",
        description="Validate a recipe file (as `agrirecipe validate` does) and write "
        "recipe.json and every output, exactly what `agrirecipe generate` writes for the "
        "same recipe.",
    )
    parser.add_argument("recipe", type=Path, metavar="RECIPE", help="a recipe.json file")
    parser.add_argument("-o", "--output", type=Path, required=True, help="output folder")
    add_output_options(parser)
    parser.set_defaults(handler=run)


def add_output_options(parser: argparse.ArgumentParser) -> None:
    """``--backends``, ``--hierarchy`` and ``--knowledge``, shared with ``edit``."""
    parser.add_argument(
        "--backends",
        default=",".join(DEFAULT_BACKENDS),
        help=f"comma-separated outputs to write (default {','.join(DEFAULT_BACKENDS)})",
    )
    parser.add_argument("--hierarchy", type=Path, help="a custom hierarchy.yaml")
    parser.add_argument("--knowledge", type=Path, help="a custom crops/ folder")


def load_scene(args: argparse.Namespace) -> Any:
    """The scene of ``args.recipe``, validated against the chosen hierarchy."""
    from agrirecipe import Scene
    from agrirecipe.knowledge import load_knowledge_base
    from agrirecipe.resolve._pipeline import _hierarchy

    hierarchy = _hierarchy(args.hierarchy)
    knowledge = None
    if args.knowledge or args.hierarchy:
        knowledge = load_knowledge_base(args.knowledge, hierarchy)
    return Scene.from_file(args.recipe, hierarchy=hierarchy, knowledge=knowledge)


def backends_of(args: argparse.Namespace) -> list[str]:
    """The backend names of ``--backends``."""
    return [name.strip() for name in args.backends.split(",") if name.strip()]


def run(args: argparse.Namespace) -> int:
    """Load, validate and write the recipe's scene."""
    scene = load_scene(args)
    for path in scene.write(args.output, backends=backends_of(args)):
        print(f"wrote {path}")
    return 0
