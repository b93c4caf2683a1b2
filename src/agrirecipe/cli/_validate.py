"""``agrirecipe validate FILE...``: check recipe files, printing every problem with its path."""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path
from typing import Any


def register(subparsers: Any) -> None:
    """Add the ``validate`` sub-command."""
    parser = subparsers.add_parser(
        "validate",
        help="check recipe files against the schema and the hierarchy",
        description="Check recipe files with the JSON Schema, the pydantic models and the "
        "asset hierarchy. Prints every problem with its path; exits 1 if any file is invalid.",
    )
    parser.add_argument("files", nargs="+", type=Path, metavar="FILE", help="recipe JSON files")
    parser.add_argument("--hierarchy", type=Path, help="a custom hierarchy.yaml")
    parser.add_argument(
        "--max-plants", type=int, default=None, help="cap on plants per recipe (default 10,000,000)"
    )
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    """Validate each file; print problems; return 1 if any failed."""
    from agrirecipe.hierarchy import load_hierarchy
    from agrirecipe.recipe import DEFAULT_MAX_PLANTS, check_recipe_data

    hierarchy = load_hierarchy(args.hierarchy) if args.hierarchy else None
    max_plants = args.max_plants or DEFAULT_MAX_PLANTS
    failed = 0
    for file in args.files:
        try:
            data = json.loads(file.read_text(encoding="utf-8"))
        except FileNotFoundError:
            print(f"{file}: error: no such file", file=sys.stderr)
            failed += 1
            continue
        except (json.JSONDecodeError, UnicodeDecodeError) as exc:
            print(f"{file}: error: not valid JSON: {exc}", file=sys.stderr)
            failed += 1
            continue
        recipe, problems = check_recipe_data(data, hierarchy=hierarchy, max_plants=max_plants)
        if recipe is None:
            failed += 1
            for path, message in problems:
                print(f"{file}: {path}: {message}", file=sys.stderr)
        else:
            plants, drawn = recipe.nominal_plant_count, recipe.drawn_plant_count
            thinned = f", {drawn:,} drawn" if drawn != plants else ""
            print(
                f"{file}: ok ({len(recipe.fields)} field(s), {plants:,} planting positions"
                f"{thinned})"
            )
    return 1 if failed else 0
