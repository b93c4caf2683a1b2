"""``agrirecipe assets``: list the asset catalogue or parse an asset path."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any


def register(subparsers: Any) -> None:
    """Add the ``assets`` sub-command."""
    parser = subparsers.add_parser(
        "assets",
        help="list catalogue asset paths, or parse one",
        description="List the asset catalogue (optionally one crop's) or parse an Unreal "
        "object path back into its attributes.",
    )
    parser.add_argument("--crop", help="only this crop's assets")
    parser.add_argument("--parse", metavar="PATH", help="print the attributes of an asset path")
    parser.add_argument("--hierarchy", type=Path, help="a custom hierarchy.yaml")
    parser.add_argument("--content-root", help="Unreal content folder (default /Game/Agriculture)")
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    """List or parse."""
    from agrirecipe.hierarchy import load_hierarchy

    hierarchy = load_hierarchy(args.hierarchy, content_root=args.content_root)
    if args.parse:
        key = hierarchy.parse_asset_path(args.parse)
        for name in ("category", "crop", "variety", "stage", "season", "health"):
            print(f"{name}: {getattr(key, name)}")
        return 0
    if args.crop:
        hierarchy.crop(args.crop)  # unknown crop: a clear error listing the known ones
    for key in hierarchy.assets():
        if args.crop is None or key.crop == args.crop:
            print(hierarchy.asset_path(key))
    return 0
