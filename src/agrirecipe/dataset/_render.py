"""Render one variant: plan it, run Blender in a child process, write its images and labels.

:func:`render_variant` is the unit of work an executor runs (a process-pool
worker or a Ray task). Its input is a plain JSON-able job and everything it
writes depends on that job only: the same job gives the same bytes on any
worker. It writes the variant's ``variant.json`` last: a variant whose
``variant.json`` exists (with the same job digest) is finished.
"""

from __future__ import annotations

import hashlib
import io
import json
import shutil
from importlib import resources
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from agrirecipe._errors import ConfigurationError
from agrirecipe._files import write_atomic
from agrirecipe.dataset._config import CameraRigs, DroneRig, OverviewRig, RobotRig
from agrirecipe.dataset._labels import (
    SEMANTIC_BASE,
    coco_rle,
    decode_labels,
    fog,
    instance_regions,
    read_label_exr,
)
from agrirecipe.dataset._plan import (
    plan_conditions,
    plan_views,
    plan_weeds,
    stream,
    weeds_csv,
)
from agrirecipe.recipe import SceneRecipe

__all__ = ["MARKER", "job_digest", "render_variant"]

#: The file a finished variant's folder holds; written last.
MARKER = "variant.json"
_RENDER_FOLDER = ".render"
# Plant indices travel through float32 AOVs, exact up to 2**24.
_MAX_FIELD_PLANTS = 2**24


def job_digest(job: dict[str, Any]) -> str:
    """SHA-256 of what decides a variant's outputs (not where, nor how many threads)."""
    decisive = {k: v for k, v in job.items() if k not in ("output", "threads", "timeout_s")}
    return hashlib.sha256(json.dumps(decisive, sort_keys=True).encode()).hexdigest()


def _passes_source() -> str:
    source = resources.files("agrirecipe.dataset").joinpath("_bpy_passes.py").read_text("utf-8")
    # Drop the header comment and docstring: the build script has its own.
    return source.split('"""', 2)[2]


def _rigs(data: dict[str, Any]) -> CameraRigs:
    return CameraRigs(
        robot=RobotRig(**data["robot"]),
        drone=DroneRig(**data["drone"]),
        overview=OverviewRig(**data["overview"]),
        sensor_width_mm=data["sensor_width_mm"],
        clip_start_m=data["clip_start_m"],
        clip_end_m=data["clip_end_m"],
    )


def _png_bytes(array: NDArray[np.uint8]) -> bytes:
    """A PNG of an 8-bit array: (h, w, 3) as RGB, (h, w) as greyscale; no metadata."""
    from PIL import Image

    buffer = io.BytesIO()
    Image.fromarray(array).save(buffer, format="PNG", compress_level=6)
    return buffer.getvalue()


def _npy_bytes(array: NDArray[Any]) -> bytes:
    buffer = io.BytesIO()
    np.save(buffer, array, allow_pickle=False)
    return buffer.getvalue()


def _read_rgb(path: Path) -> NDArray[np.uint8]:
    from PIL import Image

    with Image.open(path) as image:
        return np.asarray(image.convert("RGB"), dtype=np.uint8)


def render_variant(job: dict[str, Any]) -> dict[str, Any]:
    """Render one variant described by ``job`` (see :func:`agrirecipe.dataset.dataset`);
    return its record (the contents of its ``variant.json``)."""
    from agrirecipe._scene import Scene
    from agrirecipe.backends.annotations import write_plants_csv
    from agrirecipe.backends.blender import (
        RenderSettings,
        _cached_assets,
        blender_script,
        run_bpy_child,
    )

    root = Path(job["output"])
    name = job["name"]
    folder = root / "variants" / name
    recipe = SceneRecipe.model_validate_json(job["recipe"])
    scene = Scene(recipe)
    layout = scene.layout
    counts = [plants.plant_count for plants in layout.fields]
    if max(counts) > _MAX_FIELD_PLANTS:
        raise ConfigurationError(
            f"a field of {max(counts):,} plants is too large for the label render",
            stage="dataset",
            hint=f"at most {_MAX_FIELD_PLANTS:,} plants per field (float32 AOVs hold exact "
            "integers up to 2**24): split the field",
        )
    offsets = [int(v) for v in np.cumsum([0, *counts[:-1]])]
    plant_total = int(sum(counts))
    seed = int(job["variant_seed"])
    resolution = (int(job["resolution"][0]), int(job["resolution"][1]))
    views = plan_views(
        recipe,
        count=int(job["views"]),
        camera=job["camera"],
        rigs=_rigs(job["rigs"]),
        resolution=resolution,
        rng=stream(seed, "views"),
    )
    conditions = plan_conditions(
        recipe, vary=bool(job["vary_conditions"]), rng=stream(seed, "conditions")
    )
    weeds = plan_weeds(
        recipe,
        density_per_m2=float(job["weeds_per_m2"]),
        first_id=plant_total + 1,
        rng=stream(seed, "weeds"),
    )
    write_atomic(folder / "recipe.json", recipe.model_dump_json(indent=2) + "\n")
    write_plants_csv(layout, folder / "plants.csv")
    write_atomic(folder / "weeds.csv", weeds_csv(weeds))

    work = folder / _RENDER_FOLDER
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    blender_job = {
        "output_dir": str(work),
        "resolution": list(resolution),
        "threads": int(job["threads"]),
        "cycles_seed": seed % (2**31),
        "samples": int(job["samples"]),
        "denoise": bool(job["denoise"]),
        "device": job["device"],
        "weeds": weeds,
        "conditions": conditions,
        "views": views,
    }
    settings = RenderSettings(resolution=resolution, samples=int(job["samples"]))
    script = (
        blender_script(scene, settings, verbose=False, assets_root=_cached_assets(scene))
        + "\n\n# --- dataset passes: agrirecipe.dataset._bpy_passes, inlined verbatim ---\n"
        + _passes_source().rstrip()
        + "\n\n\nif __name__ == '__main__':\n"
        + f"    JOB = json.loads({json.dumps(blender_job, sort_keys=True)!r})\n"
        + "    render_dataset_views(AGRIRECIPE_REPORT, JOB, SCENE)\n"
    )
    path = work / "dataset_build.py"
    path.write_text(script, encoding="utf-8")
    timeout = job.get("timeout_s")
    run_bpy_child(path, timeout_s=None if timeout is None else float(timeout))
    cameras = {c["name"]: c for c in json.loads((work / "cameras.json").read_text("utf-8"))}
    device = (work / "device.txt").read_text("utf-8").strip()

    crop_classes = job["crop_classes"]
    field_classes = [int(crop_classes[spec.crop]) for spec in recipe.fields]
    images = []
    for view in views:
        stem = f"{name}_{view['name']}"
        labels = decode_labels(
            read_label_exr(work / f"{view['name']}.labels.exr"),
            field_offsets=offsets,
            field_classes=field_classes,
            weed_first_id=plant_total + 1,
        )
        rgb = _read_rgb(work / f"{view['name']}.rgb.png")
        if conditions["fog_visibility_m"] is not None:
            rgb = fog(
                rgb,
                labels.depth_m,
                visibility_m=float(conditions["fog_visibility_m"]),
                colour=conditions["fog_rgb"],
            )
        files = {
            "image": f"images/{stem}.png",
            "depth": f"depth/{stem}.npy",
            "semantic": f"semantic/{stem}.png",
            "instance": f"instance/{stem}.npy",
            "yolo": f"labels/{stem}.txt",
        }
        write_atomic(root / files["image"], _png_bytes(rgb))
        write_atomic(root / files["depth"], _npy_bytes(labels.depth_m))
        write_atomic(root / files["semantic"], _png_bytes(labels.semantic))
        write_atomic(root / files["instance"], _npy_bytes(labels.instance))
        annotations = _annotations(labels.instance, labels.semantic, offsets, recipe, weeds)
        write_atomic(root / files["yolo"], _yolo(annotations, resolution))
        camera = cameras[view["name"]]
        images.append(
            {
                "name": stem,
                "view": view["name"],
                "width": resolution[0],
                "height": resolution[1],
                "files": files,
                "camera": {
                    **{k: v for k, v in view.items() if k not in ("name",)},
                    "K": camera["K"],
                    "world_to_camera": camera["world_to_camera"],
                    "location_m": camera["location_m"],
                    "lens_mm": camera["lens_mm"],
                    "shift": camera["shift"],
                    "sensor_fit": camera["sensor_fit"],
                    "convention": "OpenCV: x right, y down, z forward; K in pixels",
                },
                "conditions": conditions,
                "annotations": annotations,
            }
        )
    record = {
        "name": name,
        "digest": job_digest(job),
        "source": job["source"],
        "variant": job["variant"],
        "variant_seed": seed,
        "varied": job["varied"],
        "plant_count": plant_total,
        "render_device": device,
        "weed_count": len(weeds["instance_id"]),
        "weeds_per_m2": float(job["weeds_per_m2"]),
        "files": {
            "recipe": f"variants/{name}/recipe.json",
            "plants": f"variants/{name}/plants.csv",
            "weeds": f"variants/{name}/weeds.csv",
        },
        "images": images,
    }
    shutil.rmtree(work, ignore_errors=True)
    write_atomic(folder / MARKER, json.dumps(record, indent=1, sort_keys=True) + "\n")
    return record


def _annotations(
    instance: NDArray[np.uint32],
    semantic: NDArray[np.uint8],
    offsets: list[int],
    recipe: SceneRecipe,
    weeds: dict[str, Any],
) -> list[dict[str, Any]]:
    """One annotation per visible plant or weed, in instance id order."""
    height, width = instance.shape
    first_weed = int(weeds["instance_id"][0]) if weeds["instance_id"] else None
    annotations = []
    for instance_id, (x0, y0, x1, y1, mask) in instance_regions(instance).items():
        ys, xs = np.nonzero(mask)
        category = int(semantic[y0 + ys[0], x0 + xs[0]])
        if first_weed is not None and instance_id >= first_weed:
            field_id = weeds["field_id"][instance_id - first_weed]
        else:
            index = int(np.searchsorted(offsets, instance_id - 1, side="right")) - 1
            field_id = recipe.fields[index].id
        annotations.append(
            {
                "instance_id": instance_id,
                "category_id": category,
                "field_id": field_id,
                "bbox": [x0, y0, x1 - x0, y1 - y0],
                "area": int(ys.size),
                "segmentation": coco_rle(mask, origin=(x0, y0), size=(height, width)),
            }
        )
    return annotations


def _yolo(annotations: list[dict[str, Any]], resolution: tuple[int, int]) -> str:
    """YOLO boxes: ``class cx cy w h`` normalised; class = semantic id - 3 (weed 0, crops 1..)."""
    width, height = resolution
    lines = []
    for annotation in annotations:
        x, y, w, h = annotation["bbox"]
        lines.append(
            f"{annotation['category_id'] - SEMANTIC_BASE['weed']} "
            f"{(x + w / 2) / width:.6f} {(y + h / 2) / height:.6f} "
            f"{w / width:.6f} {h / height:.6f}"
        )
    return "".join(line + "\n" for line in lines)
