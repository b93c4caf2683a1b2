"""The plant asset library: a mesh per catalogue asset and shape variant, and a manifest.

``build_library`` walks the catalogue (crop x variety x stage x season x health),
turns each knowledge-base entry into a :class:`PlantSpec` (height, canopy width,
foliage state and colours for that stage, season and health) and writes
``<Category>/<Crop>/<Variety>/<Stage>/<Season>/<Health>/SM_..._v<N>.glb`` for each
variant, the folders of the hierarchy's asset paths. ``manifest.json`` lists every
file with its asset path, bounds, triangle count and the parameters it was built
from. Seeds come from the asset path and variant number, so the same inputs give
byte-identical files whatever the order or the number of worker processes.
"""

from __future__ import annotations

import functools
import hashlib
import json
from collections.abc import Callable, Iterable, Sequence
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

from agrirecipe import __version__
from agrirecipe._errors import ConfigurationError
from agrirecipe._files import write_atomic
from agrirecipe.hierarchy import AssetKey
from agrirecipe.knowledge import KnowledgeBase, default_knowledge_base
from agrirecipe.plants._gltf import glb_bytes
from agrirecipe.plants._mesh import PlantMesh
from agrirecipe.plants._shapes import PlantSpec, draw

__all__ = [
    "AssetFile",
    "asset_file_name",
    "asset_glb",
    "asset_seed",
    "build_library",
    "plant_mesh",
    "plant_spec",
]

_DATA = Path(__file__).with_name("data") / "shapes.yaml"
GENERATOR = f"agrirecipe {__version__} plants"
MAX_VARIANTS = 16


@functools.cache
def _shapes() -> dict[str, Any]:
    data: dict[str, Any] = yaml.safe_load(_DATA.read_text("utf-8"))
    return data


def _rgb(value: Any) -> tuple[float, float, float]:
    r, g, b = (float(c) for c in value)
    return (r, g, b)


def plant_spec(knowledge: KnowledgeBase, key: AssetKey) -> PlantSpec:
    """What the plant of catalogue asset ``key`` looks like, from the knowledge base."""
    shapes = _shapes()
    entry = knowledge.lookup(key)
    agronomy = entry.agronomy
    crop_file = knowledge.crop_file(key.crop, key.variety)
    crop_shape = shapes["crops"].get(key.crop)
    if crop_shape is None:
        archetype = shapes["growth_forms"][agronomy.growth_form]
        template = next(
            c for c in shapes["crops"].values() if c["archetype"] == archetype
        )  # a crop of a custom hierarchy: the numbers of a crop of its archetype
        crop_shape = dict(template)
    params = {k: v for k, v in crop_shape.items() if k != "varieties"}
    override = (crop_shape.get("varieties") or {}).get(key.variety, {})
    params.update(override)
    # Leaf colour of the healthy plant; an ill plant shows its disease on a share of leaves.
    healthy = knowledge.agronomy(
        AssetKey(key.category, key.crop, key.variety, key.stage, key.season, "Healthy")
    )
    ill_rgb = None
    if key.health != "Healthy":
        ill_rgb = _rgb(shapes["colours"][crop_file.disease.ill_tint])
    colours = crop_file.colours
    return PlantSpec(
        archetype=str(params["archetype"]),
        height_m=agronomy.plant_height_m,
        width_m=agronomy.canopy_width_m,
        in_row_m=agronomy.in_row_spacing_m,
        foliage=agronomy.foliage,
        stage=key.stage,
        leaf_rgb=healthy.foliage_rgb,
        ill_rgb=ill_rgb,
        flower_rgb=colours.flower_rgb.value if colours.flower_rgb else None,
        fruit_rgb=agronomy.fruit_rgb,
        mature_rgb=colours.mature_rgb.value if colours.mature_rgb else None,
        params=params,
        colours={k: _rgb(v) for k, v in shapes["colours"].items()},
        ill_share=float(shapes["ill_share"]),
    )


def asset_seed(asset_path: str, variant: int) -> int:
    """The shape seed of one variant of an asset (stable across processes)."""
    digest = hashlib.sha256(f"{asset_path}#{variant}".encode()).digest()
    return int.from_bytes(digest[:8], "little")


def plant_mesh(knowledge: KnowledgeBase, key: AssetKey, variant: int = 0) -> PlantMesh:
    """The mesh of one catalogue asset's shape variant."""
    path = knowledge.hierarchy.asset_path(key)
    return draw(plant_spec(knowledge, key), asset_seed(path, variant))


def asset_file_name(knowledge: KnowledgeBase, key: AssetKey, variant: int) -> str:
    """The file of a variant, relative to the library: the asset path's folders."""
    path = knowledge.hierarchy.asset_path(key)
    folders, _, name = path.rpartition("/")
    relative = folders.split("/", 3)[-1] if folders.count("/") >= 3 else folders.lstrip("/")
    return f"{relative}/{name.split('.')[0]}_v{variant}.glb"


@dataclass(frozen=True, slots=True)
class AssetFile:
    """One written variant, as listed in the manifest."""

    asset_path: str
    file: str
    variant: int
    triangles: int
    bounds_m: tuple[tuple[float, float, float], tuple[float, float, float]]
    bytes: int
    spec: dict[str, Any]


@dataclass(frozen=True, slots=True)
class _Job:
    """One variant to write; plain data, so it crosses to a worker process."""

    spec: PlantSpec
    key: AssetKey
    asset_path: str
    variant: int
    file: Path
    relative: str


def asset_glb(
    spec: PlantSpec, key: AssetKey, asset_path: str, variant: int
) -> tuple[PlantMesh, bytes, dict[str, Any]]:
    """One variant's mesh, its ``.glb`` bytes and the parameters it was built from."""
    mesh = draw(spec, asset_seed(asset_path, variant))
    summary: dict[str, Any] = {
        "crop": key.crop,
        "variety": key.variety,
        "stage": key.stage,
        "season": key.season,
        "health": key.health,
        "archetype": spec.archetype,
        "height_m": round(spec.height_m, 4),
        "canopy_width_m": round(spec.width_m, 4),
        "foliage": spec.foliage,
    }
    data = glb_bytes(
        mesh,
        # The file's own name: importers that name assets after the mesh (Unreal's
        # Interchange) keep the variants apart.
        name=f"{asset_path.rsplit('.', 1)[-1]}_v{variant}",
        generator=GENERATOR,
        extras={"asset_path": asset_path, "variant": variant, **summary},
    )
    return mesh, data, summary


def _build_one(job: _Job) -> AssetFile:
    spec, path, variant = job.spec, job.asset_path, job.variant
    mesh, data, summary = asset_glb(spec, job.key, path, variant)
    budget = int(_shapes()["budgets"][spec.archetype])
    if mesh.triangle_count > budget:
        raise ConfigurationError(
            f"{path} variant {variant} has {mesh.triangle_count} triangles, over the "
            f"{spec.archetype} budget of {budget}",
            stage="plants",
            hint="lower the leaf or fruit counts in plants/data/shapes.yaml",
        )
    write_atomic(job.file, data)
    size = len(data)
    low, high = mesh.bounds
    return AssetFile(
        asset_path=path,
        file=job.relative,
        variant=variant,
        triangles=mesh.triangle_count,
        bounds_m=(
            (round(low[0], 4), round(low[1], 4), round(low[2], 4)),
            (round(high[0], 4), round(high[1], 4), round(high[2], 4)),
        ),
        bytes=size,
        spec=summary,
    )


def build_library(
    output: str | Path,
    *,
    knowledge: KnowledgeBase | None = None,
    crops: Sequence[str] | None = None,
    variants: int = 3,
    workers: int = 1,
    progress: Callable[[int, int], None] | None = None,
) -> list[AssetFile]:
    """Write the plant meshes of the catalogue (or of ``crops``) and ``manifest.json``.

    ``variants`` shape variants per asset (1-16); ``workers`` processes (the files
    are the same for any number). Returns what was written, in catalogue order.
    """
    if (
        isinstance(variants, bool)
        or not isinstance(variants, int)
        or not 1 <= variants <= MAX_VARIANTS
    ):
        raise ConfigurationError(
            f"variants must be a whole number from 1 to {MAX_VARIANTS}, got {variants!r}",
            stage="plants",
        )
    if isinstance(workers, bool) or not isinstance(workers, int) or workers < 1:
        raise ConfigurationError(
            f"workers must be a positive whole number, got {workers!r}", stage="plants"
        )
    kb = knowledge or default_knowledge_base()
    for crop in crops or ():
        kb.hierarchy.crop(crop)  # an unknown crop: the hierarchy's error, listing the known ones
    keys = [k for k in kb.hierarchy.assets() if not crops or k.crop in crops]
    root = Path(output)
    jobs = []
    for key in keys:
        spec, path = plant_spec(kb, key), kb.hierarchy.asset_path(key)
        for variant in range(variants):
            relative = asset_file_name(kb, key, variant)
            jobs.append(_Job(spec, key, path, variant, root / relative, relative))
    results: list[AssetFile] = []
    mapper: Iterable[AssetFile]
    if workers == 1:
        mapper = map(_build_one, jobs)
        for done, result in enumerate(mapper, 1):
            results.append(result)
            if progress is not None:
                progress(done, len(jobs))
    else:
        with ProcessPoolExecutor(max_workers=workers) as pool:
            for done, result in enumerate(pool.map(_build_one, jobs, chunksize=8), 1):
                results.append(result)
                if progress is not None:
                    progress(done, len(jobs))
    manifest = {
        "generator": GENERATOR,
        "hierarchy": kb.hierarchy.digest(),
        "knowledge": kb.digest(),
        "variants": variants,
        "assets": [
            {
                "asset_path": r.asset_path,
                "file": r.file,
                "variant": r.variant,
                "triangles": r.triangles,
                "bounds_m": [list(r.bounds_m[0]), list(r.bounds_m[1])],
                "bytes": r.bytes,
                **r.spec,
            }
            for r in results
        ],
    }
    write_atomic(root / "manifest.json", json.dumps(manifest, indent=1, sort_keys=True) + "\n")
    return results
