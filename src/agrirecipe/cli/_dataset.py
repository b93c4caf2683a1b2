"""``agrirecipe dataset SOURCE... -o DIR``: synthetic training images with exact labels."""

from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path
from typing import Any

from agrirecipe.cli._options import add_resolver_option

_RESOLUTION = re.compile(r"^\s*(\d+)\s*[xX×]\s*(\d+)\s*$")


def _resolution(text: str) -> tuple[int, int]:
    match = _RESOLUTION.match(text)
    if match is None:
        raise argparse.ArgumentTypeError(f"{text!r} is not WIDTHxHEIGHT, e.g. 640x480")
    return int(match.group(1)), int(match.group(2))


def register(subparsers: Any) -> None:
    """Add the ``dataset`` sub-command."""
    parser = subparsers.add_parser(
        "dataset",
        help="render a synthetic training dataset (RGB, depth, masks, COCO, YOLO) in Blender",
        description="For every variant (a layout seed; with --vary-conditions also the hour, "
        "overcast sky, fog and wet soil) and camera view, render an RGB image and exact "
        "labels: depth in metres, semantic and instance masks (instance ids are plants.csv "
        "rows), boxes, COCO and YOLO files, camera intrinsics and extrinsics, and one "
        "manifest.json. Blender (Cycles, CPU) runs in a child process per variant, on a local "
        "process pool or a Ray cluster; the outputs are the same bytes either way, and a rerun "
        "resumes where an interrupted one stopped. SOURCE is a recipe JSON file or a prompt.",
    )
    parser.add_argument("sources", nargs="+", metavar="SOURCE", help="recipe.json files or prompts")
    parser.add_argument("-o", "--output", type=Path, required=True, help="dataset folder")
    parser.add_argument("--variants", type=int, default=1, help="variants per source (default 1)")
    parser.add_argument("--views", type=int, default=1, help="camera views per variant (default 1)")
    parser.add_argument(
        "--resolution", type=_resolution, default=(640, 480), metavar="WxH", help="default 640x480"
    )
    parser.add_argument(
        "--camera",
        choices=("robot", "drone", "overview", "random"),
        default="random",
        help="robot: between two rows, looking along them; drone: above a field; overview: "
        "every field from above at an angle; random: one of them per view (default)",
    )
    parser.add_argument(
        "--weeds",
        default=None,
        metavar="DENSITY",
        help="weeds per m² (0.5 or 0.5/m2) or few/some/many; weeds are their own class",
    )
    parser.add_argument(
        "--vary-conditions",
        action="store_true",
        help="draw hour of day, overcast sky, fog and wet soil per variant",
    )
    parser.add_argument(
        "--vary",
        default="",
        metavar="ATTRS",
        help="comma-separated attributes to draw per variant where the prompt left them open: "
        "stage, season, health",
    )
    parser.add_argument("--samples", type=int, default=None, help="Cycles samples (default 16)")
    parser.add_argument("--denoise", action="store_true", help="denoise the RGB renders")
    parser.add_argument(
        "--device",
        choices=("cpu", "gpu"),
        default="cpu",
        help="cpu (default; identical bytes everywhere) or gpu (OptiX, CUDA, HIP, oneAPI or "
        "Metal where Cycles finds one, else the CPU)",
    )
    rig = parser.add_argument_group(
        "camera rigs (defaults in agrirecipe/dataset/data/dataset.yaml)"
    )
    rig.add_argument("--robot-height", type=float, metavar="M", help="robot camera height")
    rig.add_argument("--robot-pitch", type=float, metavar="DEG", help="robot pitch (down < 0)")
    rig.add_argument("--drone-altitude", type=float, metavar="M", help="drone altitude")
    rig.add_argument("--drone-view", choices=("nadir", "oblique"), help="drone camera angle")
    rig.add_argument(
        "--gsd", type=float, metavar="M", help="drone ground sampling distance (m/pixel)"
    )
    run = parser.add_argument_group("execution")
    run.add_argument("--executor", choices=("local", "ray"), default="local", help="default local")
    run.add_argument(
        "--workers",
        type=int,
        default=None,
        help="local processes (default: half the cores; each render uses cores/workers threads)",
    )
    run.add_argument("--ray-address", default=None, help="an existing Ray cluster (ray://...)")
    run.add_argument("--timeout", type=float, default=None, help="seconds per variant")
    run.add_argument("--seed", type=int, default=0, help="dataset seed (default 0)")
    add_resolver_option(run, "how prompts are resolved")
    run.add_argument("--quiet", action="store_true", help="no progress bar")
    parser.set_defaults(handler=run_dataset)


def run_dataset(args: argparse.Namespace) -> int:
    """Render the dataset; print where its manifest went."""
    from agrirecipe.dataset import CameraRigs, dataset

    rigs = CameraRigs.defaults().with_overrides(
        robot_height_m=args.robot_height,
        robot_pitch_deg=args.robot_pitch,
        drone_altitude_m=args.drone_altitude,
        drone_view=args.drone_view,
        drone_gsd_m=args.gsd,
    )
    report = dataset(
        args.sources,
        args.output,
        variants=args.variants,
        views=args.views,
        resolution=args.resolution,
        camera=args.camera,
        weeds=args.weeds,
        vary_conditions=args.vary_conditions,
        vary=[a.strip() for a in args.vary.split(",") if a.strip()],
        executor=args.executor,
        workers=args.workers,
        seed=args.seed,
        samples=args.samples,
        denoise=True if args.denoise else None,
        device=args.device,
        rigs=rigs,
        resolver=args.resolver,
        ray_address=args.ray_address,
        timeout_s=args.timeout,
        progress=not args.quiet,
    )
    print(
        f"{report.images} images ({len(report.rendered)} variants rendered, "
        f"{len(report.skipped)} already done) in {report.seconds:.1f} s",
        file=sys.stderr,
    )
    print(f"wrote {report.manifest}")
    return 0
