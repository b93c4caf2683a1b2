"""The plant meshes of one scene, written beside its outputs in ``assets/``.

Every backend that draws plants (Unreal, Blender, USD) calls
:func:`write_scene_assets` before writing its own file, so an output folder is
complete on its own whichever backends were asked for. The meshes are the plant
library's (:mod:`agrirecipe.plants._library`): the same file names, the same
bytes, ``SCENE_VARIANTS`` shape variants per asset. A file already in the folder
with the right bytes is left alone, so writing a scene again rewrites nothing.

Which variant each plant shows is a pure function of its index in the field
(:func:`plant_variant`, Fibonacci hashing), cheap enough for an engine script to
compute for a million plants and written to ``plants.csv``, so the ground truth
names the exact mesh every instance shows.

A field whose asset the knowledge base does not hold (a crop of a user's own
hierarchy without knowledge) has no mesh: the backends fall back to their
proxies for it.
"""

from __future__ import annotations

import json
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from agrirecipe._errors import AgrirecipeError
from agrirecipe._files import write_atomic
from agrirecipe.hierarchy import AssetKey
from agrirecipe.knowledge import KnowledgeBase, default_knowledge_base
from agrirecipe.plants._library import GENERATOR, asset_file_name, asset_glb, plant_spec
from agrirecipe.plants._shapes import PlantSpec

if TYPE_CHECKING:
    from agrirecipe.plants._mesh import PlantMesh
    from agrirecipe.recipe import FieldSpec, SceneRecipe

__all__ = [
    "ASSETS_FOLDER",
    "SCENE_VARIANTS",
    "FieldAsset",
    "field_assets",
    "plant_variant",
    "plant_variants",
    "unchanged",
    "write_scene_assets",
]

#: The folder of an output directory that holds the scene's plant meshes.
ASSETS_FOLDER = "assets"
#: Shape variants per asset in a scene (the library's default).
SCENE_VARIANTS = 3
# Knuth's multiplicative hash constant (2^32 / golden ratio): consecutive plants spread
# evenly over the variants, with no visible period along a row.
_FIBONACCI = 0x9E3779B1


def plant_variant(index: int, variants: int) -> int:
    """The shape variant of a field's ``index``-th plant (the formula engine scripts inline)."""
    return (((index * _FIBONACCI) & 0xFFFFFFFF) >> 16) % variants


def plant_variants(count: int, variants: int) -> NDArray[np.int32]:
    """:func:`plant_variant` of plants ``0 .. count - 1``, vectorised (identical results)."""
    index = np.arange(count, dtype=np.uint64)
    hashed = ((index * np.uint64(_FIBONACCI)) & np.uint64(0xFFFFFFFF)) >> np.uint64(16)
    return (hashed % np.uint64(variants)).astype(np.int32)


@dataclass(frozen=True, slots=True)
class FieldAsset:
    """The meshes one field's plants are drawn with.

    ``files`` are the ``.glb`` variants relative to the output folder
    (``assets/<Category>/.../SM_..._v<N>.glb``), in variant order; ``scale`` turns
    the catalogue plant into this field's plant (x, y, z; 1 unless the recipe
    states another height or width than the catalogue's).
    """

    field_id: str
    asset_path: str
    files: tuple[str, ...]
    height_m: float
    width_m: float
    scale: tuple[float, float, float]

    @property
    def variants(self) -> int:
        """How many shape variants the field's plants are spread over."""
        return len(self.files)

    def usd_file(self, variant: int) -> str:
        """The USD companion of variant ``variant`` (same folder and name, ``.usdc``)."""
        return self.files[variant].removesuffix(".glb") + ".usdc"


def _key(spec: FieldSpec) -> AssetKey:
    return AssetKey(spec.category, spec.crop, spec.variety, spec.stage, spec.season, spec.health)


def _catalogue_spec(knowledge: KnowledgeBase, key: AssetKey) -> PlantSpec | None:
    try:
        return plant_spec(knowledge, key)
    except AgrirecipeError:
        return None  # not in this knowledge base: the backends draw a proxy


def field_assets(
    recipe: SceneRecipe,
    *,
    knowledge: KnowledgeBase | None = None,
    variants: int = SCENE_VARIANTS,
) -> dict[str, FieldAsset | None]:
    """Per field id, its meshes, or None when the knowledge base has no plant for it."""
    kb = knowledge or default_knowledge_base()
    assets: dict[str, FieldAsset | None] = {}
    for spec in recipe.fields:
        key = _key(spec)
        plant = _catalogue_spec(kb, key)
        if plant is None:
            assets[spec.id] = None
            continue
        files = tuple(
            f"{ASSETS_FOLDER}/{asset_file_name(kb, key, variant)}" for variant in range(variants)
        )
        agronomy = spec.agronomy
        across = round(agronomy.canopy_width_m / plant.width_m, 6)
        assets[spec.id] = FieldAsset(
            field_id=spec.id,
            asset_path=kb.hierarchy.asset_path(key),
            files=files,
            height_m=plant.height_m,
            width_m=plant.width_m,
            scale=(across, across, round(agronomy.plant_height_m / plant.height_m, 6)),
        )
    return assets


def _mesh(knowledge: KnowledgeBase, key: AssetKey, variant: int) -> tuple[PlantMesh, bytes]:
    path = knowledge.hierarchy.asset_path(key)
    mesh, data, _ = asset_glb(plant_spec(knowledge, key), key, path, variant)
    return mesh, data


def unchanged(path: Path, data: bytes) -> bool:
    """Whether ``path`` already holds exactly ``data`` (then it is not rewritten)."""
    try:
        return path.stat().st_size == len(data) and path.read_bytes() == data
    except OSError:
        return False


def write_scene_assets(
    recipe: SceneRecipe,
    directory: str | Path,
    *,
    knowledge: KnowledgeBase | None = None,
    usd: bool = False,
    variants: int = SCENE_VARIANTS,
) -> list[Path]:
    """Write the meshes ``recipe`` uses into ``directory/assets`` (``.glb``; ``.usdc`` too).

    Files already there with the same content are kept as they are. Returns every
    mesh file of the scene (written or kept), and writes ``assets/scene_assets.json``
    listing, per field, its asset and files.
    """
    kb = knowledge or default_knowledge_base()
    folder = Path(directory)
    assets = field_assets(recipe, knowledge=kb, variants=variants)
    by_path = {a.asset_path: (a, spec) for spec in recipe.fields if (a := assets[spec.id])}
    files: list[Path] = []
    for asset, spec in by_path.values():
        key = _key(spec)
        for variant, relative in enumerate(asset.files):
            mesh, data = _mesh(kb, key, variant)
            target = folder / relative
            if not unchanged(target, data):
                write_atomic(target, data)
            files.append(target)
            if usd:
                from agrirecipe.plants._usd import write_usd_asset

                usd_target = folder / asset.usd_file(variant)
                write_usd_asset(usd_target, mesh, name=Path(relative).stem)
                files.append(usd_target)
    index = {
        "generator": GENERATOR,
        "variants": variants,
        "fields": {
            field_id: None
            if asset is None
            else {"asset_path": asset.asset_path, "files": list(asset.files), "scale": asset.scale}
            for field_id, asset in assets.items()
        },
    }
    listing = folder / ASSETS_FOLDER / "scene_assets.json"
    text = json.dumps(index, indent=1, sort_keys=True) + "\n"
    if not unchanged(listing, text.encode()):
        write_atomic(listing, text)
    return files


def asset_files(assets: Sequence[FieldAsset | None]) -> list[str]:
    """Every distinct mesh file of ``assets``, in order (a helper for manifests)."""
    seen: dict[str, None] = {}
    for asset in assets:
        if asset is not None:
            seen.update(dict.fromkeys(asset.files))
    return list(seen)
