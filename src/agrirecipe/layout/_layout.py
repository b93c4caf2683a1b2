"""Every plant of a recipe, placed by the shared kernel (fast numpy path, identical results).

:func:`field_parameters` turns a recipe into one JSON-able dict per field: all
that :func:`~agrirecipe.layout._kernel.place_field` needs. Engine scripts embed
those dicts and the kernel's source (:func:`kernel_source`); the library runs
the same computation vectorised with numpy. The numpy path reproduces the
kernel bit for bit: it starts numpy's Mersenne Twister from the exact state of
``random.Random(seed)`` (the legacy ``RandomState.random_sample`` builds a
double from two 32-bit words exactly like ``random.random``), draws the same
numbers in the same order, and evaluates the same IEEE-754 expressions with the
same grouping. Trigonometry is only done on scalars with :mod:`math`, as in the
kernel. The tests compare the two paths for equality, not closeness.
"""

from __future__ import annotations

import hashlib
import inspect
import random
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from agrirecipe._errors import RecipeValidationError
from agrirecipe.layout import _kernel
from agrirecipe.recipe import FieldSpec, SceneRecipe

__all__ = [
    "FieldPlants",
    "Layout",
    "field_parameters",
    "field_seed",
    "kernel_source",
    "layout_scene",
    "place_field_array",
]

FloatArray = NDArray[np.float64]


def field_seed(recipe_seed: int, field_id: str) -> int:
    """The 64-bit kernel seed of one field: stable across processes (SHA-256, not ``hash()``)."""
    digest = hashlib.sha256(f"agrirecipe/layout/{recipe_seed}/{field_id}".encode()).digest()
    return int.from_bytes(digest[:8], "big")


def _parameters(spec: FieldSpec, recipe_seed: int) -> dict[str, Any]:
    geometry, agronomy, placement = spec.geometry, spec.agronomy, spec.placement
    # ("250 trees in 18 rows": the stated count, the last row short)
    counted = {} if geometry.plant_count is None else {"plant_count": geometry.plant_count}
    return {
        **counted,
        "id": spec.id,
        "seed": field_seed(recipe_seed, spec.id),
        "origin_m": [geometry.origin_m[0], geometry.origin_m[1]],
        "size_m": [geometry.size_m[0], geometry.size_m[1]],
        "rotation_deg": geometry.rotation_deg,
        "headland_m": geometry.headland_m,
        "planted_m": list(geometry.planted_m) if geometry.planted_m is not None else None,
        "pattern": agronomy.planting_pattern,
        "row_spacing_m": agronomy.row_spacing_m,
        "rows_per_bed": agronomy.rows_per_bed,
        "bed_row_spacing_m": agronomy.bed_row_spacing_m,
        # (a thinned field draws every N-th planting position: each stands for N plants)
        "in_row_spacing_m": agronomy.in_row_spacing_m * placement.plants_per_instance,
        "plants_per_instance": placement.plants_per_instance,
        "plant_height_m": agronomy.plant_height_m,
        "jitter_m": placement.jitter_m,
        "missing_rate": placement.missing_rate,
        "size_variation": placement.size_variation,
        "yaw_variation_deg": placement.yaw_variation_deg,
    }


def field_parameters(recipe: SceneRecipe) -> list[dict[str, Any]]:
    """One JSON-able dict per field, in recipe order: the kernel's whole input.

    Each dict carries the field's ``"id"`` and its ``"seed"`` (:func:`field_seed`).
    """
    return [_parameters(spec, recipe.seed) for spec in recipe.fields]


def kernel_source() -> str:
    """The placement kernel's source text, to inline verbatim into engine scripts.

    Executing it in a fresh namespace defines ``place_field``,
    ``iter_field_plants`` and ``plant_grid`` (standard library only).
    """
    return inspect.getsource(_kernel)


def place_field_array(
    params: dict[str, Any],
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
    """:func:`place_field` vectorised: ``(xyz (n, 3), yaw_rad, scale, height_m)``, bit-identical."""
    beds, rows_per_bed, per_row, x_start, y_start = _kernel.plant_grid(params)
    terms = _kernel.placement_terms(params)
    count = beds * rows_per_bed * per_row
    limit = params.get("plant_count")  # a stated count: the positions after it stay empty
    if limit is not None:
        count = min(count, int(limit))
    draws = _random_stream(int(params["seed"]), count * _kernel.KERNEL_DRAWS_PER_POSITION)
    draws = draws.reshape(count, _kernel.KERNEL_DRAWS_PER_POSITION)
    kept = draws[:, 0] >= terms.missing_rate  # the kernel skips u_missing < missing_rate
    if count:
        kept[0] = True  # ... except at the first position (no field is left empty)
    u_x, u_y, u_yaw, u_scale = (draws[kept, column] for column in range(1, 5))
    del draws

    # local_x = x_start + bed * row_spacing + row * bed_row_spacing, in that order.
    bed_index = np.arange(beds, dtype=np.float64)[:, None]
    row_index = np.arange(rows_per_bed, dtype=np.float64)[None, :]
    row_x = ((x_start + bed_index * terms.row_spacing) + row_index * terms.bed_row_spacing).ravel()
    step_y = y_start + np.arange(per_row, dtype=np.float64) * terms.in_row
    local_x = np.repeat(row_x, per_row)[:count][kept]
    local_y = np.tile(step_y, beds * rows_per_bed)[:count][kept]

    px = local_x + (2.0 * u_x - 1.0) * terms.jitter
    py = local_y + (2.0 * u_y - 1.0) * terms.jitter
    xyz = np.zeros((px.shape[0], 3), dtype=np.float64)
    xyz[:, 0] = terms.origin_x + (px * terms.cos_r - py * terms.sin_r)
    xyz[:, 1] = terms.origin_y + (px * terms.sin_r + py * terms.cos_r)
    yaw = terms.rotation_rad + (2.0 * u_yaw - 1.0) * terms.yaw_max_rad
    scale = 1.0 + terms.size_variation * ((2.0 * u_scale - 1.0) * _kernel.KERNEL_SQRT3)
    scale = np.maximum(scale, _kernel.KERNEL_MIN_SCALE)
    height = terms.plant_height * scale
    return xyz, yaw, scale, height


def _random_stream(seed: int, size: int) -> FloatArray:
    """``[random.Random(seed).random() for _ in range(size)]``, computed by numpy."""
    _version, internal, _gauss = random.Random(seed).getstate()
    state = np.random.RandomState()
    key = np.array(internal[:624], dtype=np.uint32)
    state.set_state(("MT19937", key, int(internal[624]), 0, 0.0))
    return state.random_sample(size)


@dataclass(frozen=True, eq=False)
class FieldPlants:
    """The plants of one field: world metres, right-handed, Z up (arrays are read-only)."""

    field_id: str
    spec: FieldSpec
    #: Positions, shape (n, 3).
    xyz: FloatArray
    #: Rotation about Z, radians, counter-clockwise seen from above.
    yaw_rad: FloatArray
    #: Uniform scale of the plant relative to its asset.
    scale: FloatArray
    #: Plant height, metres (``agronomy.plant_height_m * scale``).
    height_m: FloatArray

    @property
    def plant_count(self) -> int:
        """Plants present (nominal positions minus missing plants)."""
        return int(self.xyz.shape[0])

    @property
    def nominal_plant_count(self) -> int:
        """Positions drawn before missing plants were removed (every planting position,
        or every ``plants_per_instance``-th one of a thinned field)."""
        return self.spec.drawn_plant_count()

    @property
    def plants_per_instance(self) -> int:
        """Plants each drawn plant stands for (1 unless the field was thinned)."""
        return self.spec.placement.plants_per_instance

    def attributes(self) -> dict[str, str | int | float | list[str]]:
        """The field described in flat JSON-able values, for ground-truth outputs.

        What the field is (the five attributes, asset, agronomy summary), where
        (headland, rotation, area) and how many plants it holds; ``fields.geojson``
        and the USD field prims carry exactly these.
        """
        spec, agronomy, geometry = self.spec, self.spec.agronomy, self.spec.geometry
        return {
            "field_id": spec.id,
            "label": spec.label,
            "category": spec.category,
            "crop": spec.crop,
            "variety": spec.variety,
            "stage": spec.stage,
            "season": spec.season,
            "health": spec.health,
            "asset_path": spec.asset_path,
            "planting_pattern": agronomy.planting_pattern,
            "growth_form": agronomy.growth_form,
            "row_spacing_m": agronomy.row_spacing_m,
            "in_row_spacing_m": agronomy.in_row_spacing_m,
            "rows_per_bed": agronomy.rows_per_bed,
            "plant_height_m": agronomy.plant_height_m,
            "foliage": agronomy.foliage,
            "headland_m": geometry.headland_m,
            "rotation_deg": geometry.rotation_deg,
            "area_m2": round(geometry.area_m2, 6),
            "nominal_plant_count": self.nominal_plant_count,
            "plant_count": self.plant_count,
            "plants_per_instance": self.plants_per_instance,
            "stated": list(spec.stated),
            "inferred": list(spec.inferred),
        }

    def __repr__(self) -> str:
        return (
            f"FieldPlants({self.field_id!r}, {self.spec.variety} {self.spec.crop}, "
            f"{self.plant_count:,} of {self.nominal_plant_count:,} positions planted)"
        )


@dataclass(frozen=True, eq=False)
class Layout:
    """Every plant of every field of a recipe, in recipe order."""

    recipe: SceneRecipe
    fields: tuple[FieldPlants, ...]

    @property
    def plant_count(self) -> int:
        """Plants in all fields."""
        return sum(field.plant_count for field in self.fields)

    def field(self, field_id: str) -> FieldPlants:
        """The plants of the field with this id."""
        for plants in self.fields:
            if plants.field_id == field_id:
                return plants
        raise RecipeValidationError(
            f"no field {field_id!r} in this layout",
            stage="layout",
            hint="fields: " + ", ".join(plants.field_id for plants in self.fields),
        )

    def __repr__(self) -> str:
        return f"Layout({len(self.fields)} field(s), {self.plant_count:,} plants)"


def layout_scene(recipe: SceneRecipe) -> Layout:
    """Place every plant of ``recipe`` (deterministic in the recipe and its seed)."""
    placed = []
    for spec, params in zip(recipe.fields, field_parameters(recipe), strict=True):
        xyz, yaw, scale, height = place_field_array(params)
        for array in (xyz, yaw, scale, height):
            array.flags.writeable = False
        placed.append(
            FieldPlants(
                field_id=spec.id, spec=spec, xyz=xyz, yaw_rad=yaw, scale=scale, height_m=height
            )
        )
    return Layout(recipe=recipe, fields=tuple(placed))
