"""``agrirecipe render SOURCE -o scene.png``: a recipe file or a prompt, rendered in Blender."""

from __future__ import annotations

import argparse
import re
import sys
import time
from pathlib import Path
from typing import Any

_RESOLUTION = re.compile(r"^\s*(\d+)\s*[xX×]\s*(\d+)\s*$")


def _resolution(text: str) -> tuple[int, int]:
    match = _RESOLUTION.match(text)
    if match is None:
        raise argparse.ArgumentTypeError(f"{text!r} is not WIDTHxHEIGHT, e.g. 960x540")
    return int(match.group(1)), int(match.group(2))


def register(subparsers: Any) -> None:
    """Add the ``render`` sub-command."""
    from agrirecipe.backends.blender import ENGINES, RenderSettings

    defaults = RenderSettings()
    parser = subparsers.add_parser(
        "render",
        help="render a recipe file or a prompt to a PNG with Blender (headless, CPU)",
        description="Build the scene in Blender (the bpy module) with Geometry Nodes instancing "
        "and render it headless on the CPU. SOURCE is a recipe JSON file, or else a prompt "
        "that is resolved first, as `agrirecipe generate` would.",
    )
    parser.add_argument(
        "source", metavar="SOURCE", help='a recipe.json file, or a prompt such as "a wheat field"'
    )
    parser.add_argument(
        "-o", "--output", type=Path, default=Path("render.png"), help="PNG to write (render.png)"
    )
    parser.add_argument(
        "--resolution",
        type=_resolution,
        default=defaults.resolution,
        metavar="WxH",
        help=f"image size in pixels (default {defaults.resolution[0]}x{defaults.resolution[1]})",
    )
    parser.add_argument(
        "--samples",
        type=int,
        default=defaults.samples,
        help=f"render samples (default {defaults.samples}, denoised)",
    )
    parser.add_argument(
        "--engine",
        choices=ENGINES,
        default=defaults.engine,
        help="cycles: CPU path tracing (default); workbench: flat shading through software "
        "OpenGL, only quick for small scenes without a GPU; eevee: slow on CPU",
    )
    parser.add_argument("--no-denoise", action="store_true", help="turn Cycles denoising off")
    parser.add_argument(
        "--view",
        choices=("overview", "ground"),
        default="overview",
        help="overview: every field from above at an angle (default); ground: a robot's eye "
        "at the start of the first field, looking along its rows",
    )
    parser.add_argument(
        "--plants",
        choices=("meshes", "proxies"),
        default="meshes",
        help="meshes: the plant library's (default); proxies: simple shapes, faster",
    )
    parser.add_argument("--save-blend", type=Path, help="also save the built scene as a .blend")
    parser.add_argument("--save-script", type=Path, help="also write the blender_build.py used")
    parser.add_argument(
        "--timeout", type=float, default=None, help="give up after this many seconds"
    )
    parser.add_argument("--hierarchy", type=Path, help="a custom hierarchy.yaml")
    group = parser.add_argument_group("when SOURCE is a prompt")
    group.add_argument("--seed", type=int, default=0, help="random seed (default 0)")
    group.add_argument(
        "--resolver",
        default="auto",
        choices=["auto", "rules", "embedding", "llm", "hybrid"],
        help="resolution strategy (default auto)",
    )
    group.add_argument("--latitude", type=float, default=None, help="scene latitude in degrees")
    parser.set_defaults(handler=run)


def _scene(args: argparse.Namespace) -> Any:
    from agrirecipe import Scene, generate
    from agrirecipe._errors import ConfigurationError
    from agrirecipe.hierarchy import load_hierarchy

    source = Path(args.source)
    if source.is_file():
        hierarchy = load_hierarchy(args.hierarchy) if args.hierarchy else None
        return Scene.from_file(source, hierarchy=hierarchy)
    if source.suffix.lower() == ".json" or source.is_dir():
        raise ConfigurationError(
            f"no recipe file {args.source!r}",
            stage="render",
            hint="pass an existing recipe.json, or a prompt in quotes",
        )
    scene = generate(
        args.source,
        seed=args.seed,
        resolver=args.resolver,
        hierarchy=args.hierarchy,
        latitude_deg=args.latitude,
    )
    for warning in scene.recipe.warnings:
        print(f"warning: {warning}", file=sys.stderr)
    return scene


def run(args: argparse.Namespace) -> int:
    """Build and render the scene; print where the PNG went."""
    from agrirecipe._files import write_atomic
    from agrirecipe.backends.blender import RenderSettings, blender_script, render

    # Bad settings fail before any resolving or Blender work.
    settings = RenderSettings(
        resolution=args.resolution,
        samples=args.samples,
        engine=args.engine,
        denoise=not args.no_denoise,
        plants=args.plants,
        view=args.view,
    )
    scene = _scene(args)
    recipe = scene.recipe
    print(
        f"rendering {len(recipe.fields)} field(s), up to {recipe.drawn_plant_count:,} plants, "
        f"at {settings.resolution[0]}x{settings.resolution[1]} with {settings.engine} "
        f"({settings.samples} samples)...",
        file=sys.stderr,
    )
    if args.save_script is not None:
        script = blender_script(scene, settings, save_blend=args.save_blend)
        print(f"wrote {write_atomic(args.save_script, script)}")
    started = time.perf_counter()
    # A child process keeps Blender's output and any crash out of this one.
    png = render(
        scene,
        args.output,
        resolution=settings.resolution,
        samples=settings.samples,
        engine=settings.engine,
        denoise=settings.denoise,
        plants=settings.plants,
        view=settings.view,
        isolated=True,
        timeout_s=args.timeout,
        save_blend=args.save_blend,
    )
    print(f"rendered in {time.perf_counter() - started:.1f} s", file=sys.stderr)
    if args.save_blend is not None:
        print(f"wrote {args.save_blend}")
    print(f"wrote {png}")
    return 0
