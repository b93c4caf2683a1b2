"""``dataset()``: variants x views rendered by a local process pool or Ray, then merged.

Layout of a dataset folder::

    manifest.json            everything: settings, classes, variants, images, cameras
    coco.json                COCO instances (boxes, compressed RLE masks) of all images
    dataset.yaml             YOLO data file (Ultralytics)
    images/v0000_c00.png     RGB
    labels/v0000_c00.txt     YOLO boxes
    depth/v0000_c00.npy      float32 metres along the optical axis (0: sky)
    semantic/v0000_c00.png   uint8 class ids
    instance/v0000_c00.npy   uint32 plant ids (plants.csv row, weeds.csv instance_id)
    variants/v0000/          recipe.json, plants.csv, weeds.csv, variant.json (last)

The merged files are rebuilt from the variants' ``variant.json`` in variant
order, so they do not depend on the executor, the worker count or the order in
which variants finished.
"""

from __future__ import annotations

import json
import os
import time
from collections.abc import Callable, Iterator, Sequence
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass
from multiprocessing import get_context
from pathlib import Path
from typing import TYPE_CHECKING, Any, Literal

from agrirecipe._errors import AgrirecipeError, BackendError, ConfigurationError
from agrirecipe._files import remove_stale_temporaries, write_atomic
from agrirecipe.dataset._config import (
    CAMERA_KINDS,
    CameraKind,
    CameraRigs,
    dataset_defaults,
    parse_weed_density,
    weeds_in_prompt,
)
from agrirecipe.dataset._labels import SEMANTIC_BASE
from agrirecipe.dataset._plan import stream, variant_seed
from agrirecipe.dataset._render import MARKER, job_digest, render_variant
from agrirecipe.dataset._variation import check_attributes, vary_recipe
from agrirecipe.recipe import SceneRecipe

if TYPE_CHECKING:
    from agrirecipe._scene import ResolverName, Scene

__all__ = ["EXECUTORS", "DatasetReport", "ExecutorName", "dataset"]

ExecutorName = Literal["local", "ray"]
#: Where variants are rendered: a local process pool (default) or a Ray cluster.
EXECUTORS: tuple[ExecutorName, ...] = ("local", "ray")
_MAX_VIEWS = 100
_MAX_VARIANTS = 100_000
_MAX_SIDE = 8192


@dataclass(frozen=True)
class DatasetReport:
    """What a :func:`dataset` call did."""

    output: Path
    #: Variants rendered by this call, and those found finished and skipped (resumed).
    rendered: tuple[str, ...]
    skipped: tuple[str, ...]
    images: int
    seconds: float

    @property
    def manifest(self) -> Path:
        """The dataset's ``manifest.json``."""
        return self.output / "manifest.json"


def _resolve_sources(
    sources: Sequence[Any], seed: int, resolver: ResolverName
) -> list[SceneRecipe]:
    from agrirecipe._scene import Scene, generate

    recipes = []
    for source in sources:
        if isinstance(source, SceneRecipe):
            recipes.append(source)
        elif isinstance(source, Scene):
            recipes.append(source.recipe)
        elif isinstance(source, Path) or (
            isinstance(source, str) and (source.lower().endswith(".json") or Path(source).is_file())
        ):
            recipes.append(Scene.from_file(source).recipe)
        elif isinstance(source, str):
            recipes.append(generate(source, seed=seed, resolver=resolver).recipe)
        else:
            raise ConfigurationError(
                f"dataset source {source!r} is not a prompt, recipe file, Scene or SceneRecipe",
                stage="dataset",
            )
    if not recipes:
        raise ConfigurationError("a dataset needs at least one prompt or recipe", stage="dataset")
    return recipes


def _check_count(name: str, value: int, high: int) -> None:
    if isinstance(value, bool) or not isinstance(value, int) or not 1 <= value <= high:
        raise ConfigurationError(
            f"{name}={value!r} is out of range", stage="dataset", hint=f"an integer 1 to {high}"
        )


def _crop_classes(recipes: Sequence[SceneRecipe]) -> dict[str, int]:
    """Semantic class id of every crop: from 4, in order of first appearance."""
    classes: dict[str, int] = {}
    for recipe in recipes:
        for spec in recipe.fields:
            classes.setdefault(spec.crop, len(SEMANTIC_BASE) + len(classes))
    return classes


def _run_local(
    jobs: Sequence[dict[str, Any]], workers: int, done: Callable[[dict[str, Any]], None]
) -> None:
    if workers == 1:
        for job in jobs:
            done(render_variant(job))
        return
    # "spawn": no Blender or thread state is copied into workers; each child starts clean.
    with ProcessPoolExecutor(max_workers=workers, mp_context=get_context("spawn")) as pool:
        pending: set[Future[dict[str, Any]]] = {pool.submit(render_variant, job) for job in jobs}
        try:
            while pending:
                finished, pending = wait(pending, return_when=FIRST_COMPLETED)
                for future in finished:
                    done(future.result())
        except BrokenProcessPool as exc:
            raise BackendError(
                "a dataset worker process died (out of memory?)",
                stage="dataset",
                hint="fewer --workers, or a lower resolution; rerun to resume",
            ) from exc
        except BaseException:
            for future in pending:  # finished variants stay finished; the rest resume later
                future.cancel()
            raise


def _run_ray(
    jobs: Sequence[dict[str, Any]],
    address: str | None,
    done: Callable[[dict[str, Any]], None],
) -> None:
    try:
        import ray
    except ImportError as exc:
        raise ConfigurationError(
            "the ray executor needs Ray", stage="dataset", hint="pip install 'agrirecipe[ray]'"
        ) from exc
    started_here = not ray.is_initialized()
    if started_here:
        ray.init(address=address, include_dashboard=False, log_to_driver=False)
    try:
        task = ray.remote(num_cpus=1, max_retries=1)(render_variant)
        pending = [task.remote(job) for job in jobs]
        while pending:
            finished, pending = ray.wait(pending, num_returns=1)
            for reference in finished:
                try:
                    record = ray.get(reference)
                except Exception as exc:  # a RayTaskError wrapping the worker's exception
                    cause = getattr(exc, "cause", None)
                    if isinstance(cause, AgrirecipeError):
                        raise cause from exc
                    raise BackendError(
                        f"a Ray task failed: {type(exc).__name__}: {exc}", stage="dataset"
                    ) from exc
                done(record)
    finally:
        if started_here:
            ray.shutdown()


def _progress(total: int, initial: int, enabled: bool) -> Any:
    from tqdm import tqdm

    return tqdm(
        total=total,
        initial=initial,
        unit="variant",
        desc="dataset",
        disable=not enabled,
        dynamic_ncols=True,
    )


def _finished(folder: Path, digest: str) -> dict[str, Any] | None:
    marker = folder / MARKER
    if not marker.is_file():
        return None
    try:
        record: dict[str, Any] = json.loads(marker.read_text("utf-8"))
    except (OSError, json.JSONDecodeError):
        return None
    return record if record.get("digest") == digest else None


def dataset(
    sources: str | Path | Scene | SceneRecipe | Sequence[str | Path | Scene | SceneRecipe],
    output: str | os.PathLike[str],
    *,
    variants: int = 1,
    views: int = 1,
    resolution: tuple[int, int] = (640, 480),
    camera: CameraKind = "random",
    weeds: float | str | None = None,
    vary_conditions: bool = False,
    vary: Sequence[str] = (),
    executor: ExecutorName = "local",
    workers: int | None = None,
    seed: int = 0,
    samples: int | None = None,
    denoise: bool | None = None,
    device: Literal["cpu", "gpu"] = "cpu",
    rigs: CameraRigs | None = None,
    resolver: ResolverName = "auto",
    ray_address: str | None = None,
    timeout_s: float | None = None,
    progress: bool = False,
) -> DatasetReport:
    """Render a synthetic training dataset: ``variants`` per source x ``views`` images each.

    ``sources`` are prompts, recipe files, scenes or recipes. Each variant
    re-seeds the layout (and with ``vary_conditions`` draws the hour, an
    overcast sky, fog and wet soil; ``vary`` names attributes among ``stage``,
    ``season`` and ``health`` to draw where the prompt left them open). Each
    view is a camera of the ``camera`` rig (``robot``, ``drone``, ``overview``,
    or ``random`` per view), posed from the variant's seed. ``weeds`` adds
    weeds (per m², ``"0.5/m2"`` or ``few``/``some``/``many``; None: what the
    prompt says, "with some weeds", else none) as their own class.
    ``executor`` is ``local`` (a process pool of ``workers``, default half the
    cores, each render using two threads, so every core works) or ``ray`` (one
    task of one CPU per variant; the cluster's CPUs set the parallelism;
    ``ray_address``: an existing cluster, None starts one on this machine).
    Outputs are the same bytes whatever the executor and
    worker count, and a rerun skips finished variants. ``samples`` and
    ``denoise`` set the colour render (default 16, off); ``device="gpu"``
    renders on a GPU where Cycles finds one (each variant records its
    ``render_device``; GPU bytes differ from CPU ones); ``timeout_s`` bounds
    one variant's Blender run (default 900 s per view). See the module
    docstring for the folder layout.
    """
    started = time.perf_counter()
    defaults = dataset_defaults()["render"]
    _check_count("variants", variants, _MAX_VARIANTS)
    _check_count("views", views, _MAX_VIEWS)
    if (
        not isinstance(resolution, tuple | list)
        or len(resolution) != 2
        or not all(isinstance(v, int) and 8 <= v <= _MAX_SIDE for v in resolution)
    ):
        raise ConfigurationError(
            f"resolution {resolution!r} is not (width, height)",
            stage="dataset",
            hint=f"two integers from 8 to {_MAX_SIDE}, e.g. (640, 480)",
        )
    if camera not in CAMERA_KINDS:
        raise ConfigurationError(
            f"unknown camera {camera!r}",
            stage="dataset",
            hint="cameras: " + ", ".join(CAMERA_KINDS),
        )
    if device not in ("cpu", "gpu"):
        raise ConfigurationError(
            f"unknown render device {device!r}", stage="dataset", hint="cpu or gpu"
        )
    if executor not in EXECUTORS:
        raise ConfigurationError(
            f"unknown executor {executor!r}", stage="dataset", hint="executors: local, ray"
        )
    cores = os.cpu_count() or 1
    if workers is None:
        # two Blender threads per worker: on 2 cores one worker rendering with both
        # was 1.4x faster than two with one each (bench/bench_dataset.py)
        workers = max(1, cores // 2)
    _check_count("workers", workers, 1024)
    if timeout_s is None:
        timeout_s = float(defaults["timeout_s_per_view"]) * views
    samples = int(defaults["samples"]) if samples is None else samples
    _check_count("samples", samples, 4096)
    denoise = bool(defaults["denoise"]) if denoise is None else denoise
    density = None if weeds is None else parse_weed_density(weeds)
    vary = check_attributes(vary)
    rigs = rigs or CameraRigs.defaults()
    if isinstance(sources, str | Path | SceneRecipe) or not isinstance(sources, Sequence):
        sources = [sources]
    recipes = _resolve_sources(sources, seed, resolver)
    classes = _crop_classes(recipes)
    root = Path(output).resolve()
    if root.exists() and not root.is_dir():
        raise ConfigurationError(f"output {str(root)!r} is not a folder", stage="dataset")
    root.mkdir(parents=True, exist_ok=True)
    remove_stale_temporaries(root)  # half-written files of a killed run (rglob: every folder)

    from agrirecipe import __version__
    from agrirecipe.layout import KERNEL_VERSION

    generator = {"agrirecipe": __version__, "kernel_version": KERNEL_VERSION}
    jobs: list[dict[str, Any]] = []
    for source_index, recipe in enumerate(recipes):
        # Without a density of its own, the dataset takes the prompt's ("with some weeds").
        source_density = density if density is not None else weeds_in_prompt(recipe.prompt)
        for variant in range(variants):
            index = source_index * variants + variant
            layout_seed = variant_seed(seed, source_index, variant)
            varied, drawn = vary_recipe(recipe, vary, stream(layout_seed, "attributes"))
            jobs.append(
                {
                    "name": f"v{index:04d}",
                    # A new version may draw or render differently: not resumed across it.
                    "generator": generator,
                    "output": str(root),
                    "source": source_index,
                    "variant": variant,
                    "variant_seed": layout_seed,
                    "varied": {
                        "seed": layout_seed,
                        "conditions": vary_conditions,
                        "attributes": drawn,
                    },
                    "recipe": varied.model_copy(update={"seed": layout_seed}).model_dump_json(),
                    "views": views,
                    "camera": camera,
                    "rigs": rigs.as_dict(),
                    "resolution": list(resolution),
                    "samples": samples,
                    "denoise": denoise,
                    "device": device,
                    "weeds_per_m2": source_density or 0.0,
                    "vary_conditions": vary_conditions,
                    "vary": list(vary),
                    "crop_classes": classes,
                    # Blender threads per render: the cores shared by the local workers; a
                    # Ray task holds one CPU. Threads never change the bytes rendered.
                    "threads": 1 if executor == "ray" else max(1, cores // workers),
                    "timeout_s": timeout_s,
                }
            )
    records: dict[str, dict[str, Any]] = {}
    pending = []
    for job in jobs:
        record = _finished(root / "variants" / job["name"], job_digest(job))
        if record is None:
            pending.append(job)
        else:
            records[job["name"]] = record
    skipped = tuple(sorted(records))
    bar = _progress(len(jobs), len(records), progress)

    def done(record: dict[str, Any]) -> None:
        records[record["name"]] = record
        bar.update(1)

    try:
        if pending and executor == "ray":
            _run_ray(pending, ray_address, done)
        elif pending:
            _run_local(pending, min(workers, len(pending)), done)
    finally:
        bar.close()
    ordered = [records[job["name"]] for job in jobs]
    source_densities = [jobs[i * variants]["weeds_per_m2"] for i in range(len(recipes))]
    _write_merged(root, ordered, recipes, classes, jobs[0], density, source_densities)
    return DatasetReport(
        output=root,
        rendered=tuple(job["name"] for job in pending),
        skipped=skipped,
        images=sum(len(r["images"]) for r in ordered),
        seconds=time.perf_counter() - started,
    )


def _categories(classes: dict[str, int]) -> list[dict[str, Any]]:
    things = [{"id": SEMANTIC_BASE["weed"], "name": "weed", "supercategory": "weed"}]
    things += [{"id": i, "name": crop, "supercategory": "crop"} for crop, i in classes.items()]
    return things


def _iter_images(records: Sequence[dict[str, Any]]) -> Iterator[dict[str, Any]]:
    for record in records:
        yield from record["images"]


def _write_merged(
    root: Path,
    records: Sequence[dict[str, Any]],
    recipes: Sequence[SceneRecipe],
    classes: dict[str, int],
    first_job: dict[str, Any],
    density: float | None,
    source_densities: Sequence[float],
) -> None:
    """``coco.json``, ``dataset.yaml`` and ``manifest.json`` (last) from the variants."""
    semantic = {**SEMANTIC_BASE, **classes}
    coco_images: list[dict[str, Any]] = []
    coco_annotations: list[dict[str, Any]] = []
    for image_id, image in enumerate(_iter_images(records), start=1):
        coco_images.append(
            {
                "id": image_id,
                "file_name": image["files"]["image"],
                "width": image["width"],
                "height": image["height"],
            }
        )
        for annotation in image["annotations"]:
            coco_annotations.append(
                {
                    "id": len(coco_annotations) + 1,
                    "image_id": image_id,
                    "category_id": annotation["category_id"],
                    "bbox": annotation["bbox"],
                    "area": annotation["area"],
                    "segmentation": annotation["segmentation"],
                    "iscrowd": 0,
                    "instance_id": annotation["instance_id"],
                }
            )
    coco = {
        "info": {"description": "agrirecipe synthetic dataset", "version": "1.0"},
        "images": coco_images,
        "annotations": coco_annotations,
        "categories": _categories(classes),
    }
    write_atomic(root / "coco.json", json.dumps(coco, separators=(",", ":"), sort_keys=True) + "\n")
    names = {0: "weed", **{i - SEMANTIC_BASE["weed"]: crop for crop, i in classes.items()}}
    # No `path:` key: Ultralytics then takes the folder this file is in.
    yolo = ["# YOLO data file (Ultralytics); class = semantic id - 3"]
    yolo += ["train: images", "val: images", "names:"]
    yolo += [f"  {index}: {json.dumps(name)}" for index, name in names.items()]
    write_atomic(root / "dataset.yaml", "\n".join(yolo) + "\n")
    settings = {
        key: first_job[key]
        for key in (
            "views",
            "camera",
            "rigs",
            "resolution",
            "samples",
            "denoise",
            "device",
            "vary_conditions",
            "vary",
        )
    }
    manifest = {
        "format": "agrirecipe-dataset/1",
        "generator": first_job["generator"],
        "settings": {**settings, "weeds_per_m2": density, "renderer": "cycles"},
        "sources": [
            {
                "index": i,
                "prompt": recipe.prompt,
                "fields": [f.id for f in recipe.fields],
                "weeds_per_m2": source_densities[i],
            }
            for i, recipe in enumerate(recipes)
        ],
        "semantic_classes": semantic,
        "instance_ids": "plants.csv row (1-based, header excluded) of the image's variant; "
        "weeds: weeds.csv instance_id (after the crop plants); 0: no plant",
        "depth": "float32 metres along the optical axis; 0 where nothing was hit (sky)",
        "coco": "coco.json",
        "yolo": "dataset.yaml",
        "variants": list(records),
    }
    write_atomic(root / "manifest.json", json.dumps(manifest, indent=1, sort_keys=True) + "\n")
