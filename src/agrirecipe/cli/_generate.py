"""``agrirecipe generate PROMPT -o DIR``: the main job, a prompt in and a scene folder out."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

from agrirecipe.cli._options import add_resolver_option


def register(subparsers: Any) -> None:
    """Add the ``generate`` sub-command."""
    from agrirecipe._scene import DEFAULT_BACKENDS
    from agrirecipe.recipe import DEFAULT_MAX_PLANTS

    parser = subparsers.add_parser(
        "generate",
        help="turn a prompt into a recipe and scenes",
        description="Resolve a natural-language request into a scene recipe and write "
        "recipe.json, the Unreal and Blender scripts, the USD stage, plants.csv and a preview.",
    )
    parser.add_argument("prompt", help='e.g. "a healthy Pink Lady apple orchard in summer"')
    parser.add_argument("-o", "--output", type=Path, required=True, help="output folder")
    parser.add_argument("--seed", type=int, default=0, help="random seed (default 0)")
    add_resolver_option(parser, "resolution strategy")
    parser.add_argument(
        "--backends",
        default=",".join(DEFAULT_BACKENDS),
        help=f"comma-separated outputs to write (default {','.join(DEFAULT_BACKENDS)})",
    )
    parser.add_argument("--hierarchy", type=Path, help="a custom hierarchy.yaml")
    parser.add_argument("--latitude", type=float, default=None, help="scene latitude in degrees")
    parser.add_argument("--explain", action="store_true", help="show what each stage produced")
    parser.add_argument(
        "--max-plants",
        type=int,
        default=DEFAULT_MAX_PLANTS,
        help=f"cap on the scene's planting positions (default {DEFAULT_MAX_PLANTS:,})",
    )
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    """Generate and write the scene."""
    from agrirecipe import generate

    scene = generate(
        args.prompt,
        seed=args.seed,
        resolver=args.resolver,
        hierarchy=args.hierarchy,
        latitude_deg=args.latitude,
        explain=args.explain,
        max_plants=args.max_plants,
    )
    if args.explain and scene.explanation is not None:
        print(scene.explanation.render(), file=sys.stderr)
    for warning in scene.recipe.warnings:
        print(f"warning: {warning}", file=sys.stderr)
    backends = [name.strip() for name in args.backends.split(",") if name.strip()]
    written = scene.write(args.output, backends=backends)
    for spec in scene.recipe.fields:
        print(
            f"{spec.id}: {spec.variety} {spec.crop}, {spec.stage}, {spec.season}, {spec.health} "
            f"({spec.geometry.size_m[0]:g} x {spec.geometry.size_m[1]:g} m)"
        )
    for path in written:
        print(f"wrote {path}")
    return 0
