"""Procedural plant meshes for the asset catalogue (issue 9).

``build_library`` writes a glTF binary mesh per catalogue asset and shape variant
with a manifest; ``plant_mesh`` gives one asset's mesh in memory. The shapes come
from the knowledge base (height, canopy width, foliage, colours) and
``plants/data/shapes.yaml`` (one archetype and its numbers per crop).
"""

from agrirecipe.plants._gltf import glb_bytes, write_glb
from agrirecipe.plants._ground_asset import (
    GROUND_FOLDER,
    ground_file,
    ground_mesh,
    has_relief,
    write_ground_assets,
)
from agrirecipe.plants._library import (
    AssetFile,
    asset_file_name,
    build_library,
    plant_mesh,
    plant_spec,
)
from agrirecipe.plants._mesh import Material, PlantMesh, Primitive
from agrirecipe.plants._scene import (
    ASSETS_FOLDER,
    SCENE_VARIANTS,
    FieldAsset,
    field_assets,
    plant_variant,
    plant_variants,
    write_scene_assets,
)
from agrirecipe.plants._shapes import ARCHETYPES, PlantSpec
from agrirecipe.plants._sheet import contact_sheet

__all__ = [
    "ARCHETYPES",
    "ASSETS_FOLDER",
    "GROUND_FOLDER",
    "SCENE_VARIANTS",
    "AssetFile",
    "FieldAsset",
    "Material",
    "PlantMesh",
    "PlantSpec",
    "Primitive",
    "asset_file_name",
    "build_library",
    "contact_sheet",
    "field_assets",
    "glb_bytes",
    "ground_file",
    "ground_mesh",
    "has_relief",
    "plant_mesh",
    "plant_spec",
    "plant_variant",
    "plant_variants",
    "write_glb",
    "write_ground_assets",
    "write_scene_assets",
]
