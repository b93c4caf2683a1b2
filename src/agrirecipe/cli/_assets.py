"""``agrirecipe assets``: list the asset catalogue, parse an asset path, build the plant
meshes of the catalogue, or render their contact sheet (issue 9)."""

from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path
from typing import Any


def register(subparsers: Any) -> None:
    """Add the ``assets`` sub-command."""
    parser = subparsers.add_parser(
        "assets",
        help="list catalogue asset paths, parse one, build the plant meshes, or render a sheet",
        description="List the asset catalogue (optionally some crops'), parse an Unreal object "
        "path back into its attributes, or build the plant library: a glTF binary mesh "
        "(.glb) per catalogue asset and shape variant with a manifest.json, in the "
        "hierarchy's folder layout ('agrirecipe assets build -o plants/'), or render a "
        "contact sheet of every crop at each stage, season and health "
        "('agrirecipe assets sheet -o sheet.png').",
    )
    parser.add_argument(
        "action",
        nargs="?",
        choices=("list", "build", "sheet"),
        default="list",
        help="list (default), build or sheet",
    )
    parser.add_argument(
        "--crop", action="append", help="only this crop's assets (repeat for several)"
    )
    parser.add_argument("--parse", metavar="PATH", help="print the attributes of an asset path")
    parser.add_argument("--hierarchy", type=Path, help="a custom hierarchy.yaml")
    parser.add_argument("--knowledge", type=Path, help="a custom crops/ folder (build)")
    parser.add_argument("--content-root", help="Unreal content folder (default /Game/Agriculture)")
    parser.add_argument(
        "-o", "--output", type=Path, help="library folder (build) or PNG (sheet) to write"
    )
    parser.add_argument("--variety", help="the variety a sheet shows (default: each crop's first)")
    parser.add_argument(
        "--cell", type=int, default=150, help="pixels per plant on the sheet (default 150)"
    )
    parser.add_argument(
        "--variants", type=int, default=3, help="shape variants per asset, 1-16 (default 3)"
    )
    parser.add_argument(
        "--workers",
        type=int,
        default=os.cpu_count() or 1,
        help="worker processes (default: all cores; the files are the same for any number)",
    )
    parser.add_argument("--no-progress", action="store_true", help="no progress bar")
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    """List, parse or build."""
    from agrirecipe.hierarchy import load_hierarchy

    hierarchy = load_hierarchy(args.hierarchy, content_root=args.content_root)
    if args.action == "build":
        return _build(args, hierarchy)
    if args.action == "sheet":
        return _sheet(args, hierarchy)
    if args.parse:
        key = hierarchy.parse_asset_path(args.parse)
        for name in ("category", "crop", "variety", "stage", "season", "health"):
            print(f"{name}: {getattr(key, name)}")
        return 0
    crops = args.crop or []
    for crop in crops:
        hierarchy.crop(crop)  # unknown crop: a clear error listing the known ones
    for key in hierarchy.assets():
        if not crops or key.crop in crops:
            print(hierarchy.asset_path(key))
    return 0


def _build(args: argparse.Namespace, hierarchy: Any) -> int:
    from tqdm import tqdm

    from agrirecipe._errors import ConfigurationError
    from agrirecipe.knowledge import load_knowledge_base
    from agrirecipe.plants import build_library

    if args.output is None:
        raise ConfigurationError(
            "assets build needs an output folder", stage="plants", hint="add -o DIR"
        )
    knowledge = load_knowledge_base(args.knowledge, hierarchy)
    bar = tqdm(total=0, unit="mesh", disable=args.no_progress, file=sys.stderr, delay=1.0)

    def progress(done: int, total: int) -> None:
        bar.total = total
        bar.update(done - bar.n)

    started = time.perf_counter()
    written = build_library(
        args.output,
        knowledge=knowledge,
        crops=args.crop,
        variants=args.variants,
        workers=args.workers,
        progress=progress,
    )
    bar.close()
    size = sum(f.bytes for f in written)
    print(
        f"wrote {len(written)} meshes ({len(written) // args.variants} assets x "
        f"{args.variants} variants, {size / 1e6:.1f} MB) and manifest.json to {args.output} "
        f"in {time.perf_counter() - started:.1f} s"
    )
    return 0


def _sheet(args: argparse.Namespace, hierarchy: Any) -> int:
    from agrirecipe._errors import ConfigurationError
    from agrirecipe.knowledge import load_knowledge_base
    from agrirecipe.plants import contact_sheet

    if args.output is None:
        raise ConfigurationError(
            "assets sheet needs a PNG to write", stage="plants", hint="add -o sheet.png"
        )
    started = time.perf_counter()
    path = contact_sheet(
        args.output,
        knowledge=load_knowledge_base(args.knowledge, hierarchy),
        crops=args.crop,
        variety=args.variety,
        cell_px=args.cell,
    )
    print(f"wrote {path} in {time.perf_counter() - started:.1f} s")
    return 0
