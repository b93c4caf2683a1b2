"""``agrirecipe edit RECIPE "make the pears ill" -o DIR``: change a scene by words."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

from agrirecipe.cli._build import add_output_options, backends_of, load_scene


def register(subparsers: Any) -> None:
    """Add the ``edit`` sub-command."""
    parser = subparsers.add_parser(
        "edit",
        help="change one thing about a scene, said in words",
        description="Apply an instruction such as 'make the pears ill', 'remove the carrots', "
        "'add a wheat field south of the orchard' or 'rows 50 cm apart' to a recipe file. "
        "Fields the instruction does not touch keep their ids, geometry and every plant "
        "position. Prints the changes and writes the edited scene.",
    )
    parser.add_argument("recipe", type=Path, metavar="RECIPE", help="a recipe.json file")
    parser.add_argument("instruction", help='e.g. "make the pears ill"')
    parser.add_argument("-o", "--output", type=Path, required=True, help="output folder")
    parser.add_argument(
        "--dry-run", action="store_true", help="print the changes and write nothing"
    )
    add_output_options(parser)
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    """Edit, print the diff, write the new scene."""
    scene = load_scene(args)
    edited = scene.edit(args.instruction)
    for line in edited.changes:
        print(line)
    known = set(scene.recipe.warnings)
    for warning in edited.recipe.warnings:
        if warning not in known:
            print(f"warning: {warning}", file=sys.stderr)
    if args.dry_run:
        return 0
    for path in edited.write(args.output, backends=backends_of(args)):
        print(f"wrote {path}")
    return 0
