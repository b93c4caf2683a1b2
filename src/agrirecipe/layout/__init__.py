"""Layout: field rectangles packed without overlap, and every plant placed by a seeded kernel.

- :func:`pack_fields` gives each requested field a rectangle (no overlaps, a
  farm track between neighbours, relations such as ``north_of`` honoured).
- :func:`layout_scene` places every plant of a recipe. The placement kernel
  (:func:`place_field`) uses only the standard library; its source
  (:func:`kernel_source`) is inlined into engine scripts together with
  :func:`field_parameters`, so engines place exactly the plants the library does.
"""

from agrirecipe.layout._kernel import (
    KERNEL_MIN_SCALE,
    KERNEL_VERSION,
    PlacementTerms,
    iter_field_plants,
    place_field,
    placement_terms,
    plant_grid,
)
from agrirecipe.layout._layout import (
    FieldPlants,
    Layout,
    field_parameters,
    field_seed,
    kernel_source,
    layout_scene,
    place_field_array,
)
from agrirecipe.layout._packing import DEFAULT_GAP_M, FieldRequest, describe_relation, pack_fields
from agrirecipe.layout._surface import field_ground, ground_colours, ground_source, ground_spec

__all__ = [
    "DEFAULT_GAP_M",
    "KERNEL_MIN_SCALE",
    "KERNEL_VERSION",
    "FieldPlants",
    "FieldRequest",
    "Layout",
    "PlacementTerms",
    "describe_relation",
    "field_ground",
    "field_parameters",
    "field_seed",
    "ground_colours",
    "ground_source",
    "ground_spec",
    "iter_field_plants",
    "kernel_source",
    "layout_scene",
    "pack_fields",
    "place_field",
    "place_field_array",
    "placement_terms",
    "plant_grid",
]
