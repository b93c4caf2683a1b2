"""The crop asset hierarchy: categories, crops, varieties and the catalogue of asset paths."""

from agrirecipe.hierarchy._hierarchy import (
    AssetKey,
    Category,
    Crop,
    Hierarchy,
    Variety,
    default_hierarchy,
    load_hierarchy,
    pascal_case,
)

__all__ = [
    "AssetKey",
    "Category",
    "Crop",
    "Hierarchy",
    "Variety",
    "default_hierarchy",
    "load_hierarchy",
    "pascal_case",
]
