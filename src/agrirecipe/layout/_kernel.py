# agrirecipe placement kernel (standard library only).
#
# This module's source is inlined verbatim into the generated Unreal Engine and
# Blender scripts, so an engine computes exactly the plant positions the
# library writes into plants.csv. Rules that keep that true:
# - only the standard library (math, random), never an agrirecipe import;
# - no `from __future__` (it must be the first statement of a file), no
#   module-level state besides constants;
# - randomness only from random.Random(seed).random(), whose stream is the
#   same in every CPython (hash() of strings is salted per process: never used);
# - helper names start with `_kernel_` so they cannot clash with script code.
"""Seeded placement of every plant of one field (shared by the library and engine scripts)."""

import math
import random
from collections.abc import Iterator
from typing import Any, NamedTuple

#: Bumped whenever the placement of a given recipe and seed changes.
KERNEL_VERSION = 1
#: Planting patterns the kernel knows; all of them are beds of ``rows_per_bed`` rows.
KERNEL_PATTERNS = (
    "tree_rows",
    "trellis_rows",
    "rows",
    "drilled_rows",
    "double_rows_on_beds",
    "ridges",
)
#: Random numbers drawn per planting position: missing, jitter x, jitter y, yaw, scale.
KERNEL_DRAWS_PER_POSITION = 5
#: Smallest plant scale; size noise is clamped here so no plant is inverted or vanishes.
KERNEL_MIN_SCALE = 0.1
# Uniform noise on [-sqrt(3), sqrt(3)] has unit standard deviation, so
# size_variation is the relative standard deviation of the plant scale.
KERNEL_SQRT3 = math.sqrt(3.0)


def plant_grid(params: dict[str, Any]) -> tuple[int, int, int, float, float]:
    """The nominal planting grid of a field, in field-local metres.

    Returns ``(beds, rows_per_bed, per_row, x_start, y_start)``: ``beds`` beds
    (or single rows) ``row_spacing_m`` apart, each of ``rows_per_bed`` rows
    ``bed_row_spacing_m`` apart, each row ``per_row`` positions
    ``in_row_spacing_m`` apart along local Y. The grid is centred in the field
    minus its headland; ``x_start``/``y_start`` is its first position. The
    count ``beds * rows_per_bed * per_row`` equals ``FieldSpec.drawn_plant_count()``.
    """
    width, length = float(params["size_m"][0]), float(params["size_m"][1])
    headland = float(params["headland_m"])
    row_spacing = float(params["row_spacing_m"])
    rows_per_bed = int(params["rows_per_bed"])
    bed_row_spacing = float(params["bed_row_spacing_m"])
    in_row = float(params["in_row_spacing_m"])
    if params["pattern"] not in KERNEL_PATTERNS:
        raise ValueError(f"unknown planting pattern {params['pattern']!r}")
    if row_spacing <= 0.0 or in_row <= 0.0 or rows_per_bed < 1:
        raise ValueError("row spacings must be positive and rows_per_bed at least 1")
    # Same arithmetic, in the same order, as FieldSpec.drawn_plant_count().
    bed_span = bed_row_spacing * (rows_per_bed - 1)
    inner_w = width - 2 * headland
    inner_l = length - 2 * headland
    planted = params.get("planted_m")  # a planted block smaller than the field, centred
    usable_w = min(inner_w, float(planted[0])) if planted else inner_w
    usable_l = min(inner_l, float(planted[1])) if planted else inner_l
    usable_w -= bed_span
    if usable_w < 0.0 or usable_l < 0.0:
        raise ValueError(f"field {params.get('id')!r} is smaller than its headland")
    beds = math.floor(usable_w / row_spacing + 1e-9) + 1
    per_row = math.floor(usable_l / in_row + 1e-9) + 1
    occupied_w = (beds - 1) * row_spacing + bed_span
    occupied_l = (per_row - 1) * in_row
    x_start = headland + (inner_w - occupied_w) / 2.0
    y_start = headland + (inner_l - occupied_l) / 2.0
    return beds, rows_per_bed, per_row, x_start, y_start


class PlacementTerms(NamedTuple):
    """The numbers the placement formulas use, read once from a field's parameters."""

    row_spacing: float
    bed_row_spacing: float
    in_row: float
    origin_x: float
    origin_y: float
    rotation_rad: float
    cos_r: float
    sin_r: float
    jitter: float
    missing_rate: float
    size_variation: float
    yaw_max_rad: float
    plant_height: float


def placement_terms(params: dict[str, Any]) -> PlacementTerms:
    """:class:`PlacementTerms` of one field (trigonometry done here, once, with :mod:`math`)."""
    rotation = math.radians(float(params["rotation_deg"]))
    return PlacementTerms(
        row_spacing=float(params["row_spacing_m"]),
        bed_row_spacing=float(params["bed_row_spacing_m"]),
        in_row=float(params["in_row_spacing_m"]),
        origin_x=float(params["origin_m"][0]),
        origin_y=float(params["origin_m"][1]),
        rotation_rad=rotation,
        cos_r=math.cos(rotation),
        sin_r=math.sin(rotation),
        jitter=float(params["jitter_m"]),
        missing_rate=float(params["missing_rate"]),
        size_variation=float(params["size_variation"]),
        yaw_max_rad=math.radians(float(params["yaw_variation_deg"])),
        plant_height=float(params["plant_height_m"]),
    )


def iter_field_plants(
    params: dict[str, Any],
) -> Iterator[tuple[float, float, float, float, float, float]]:
    """Yield every plant of one field as ``(x, y, z, yaw_rad, scale, height_m)``.

    World metres, right-handed, Z up, ground at z = 0. Positions run bed by
    bed, row by row within a bed, then along the row (local Y). Each nominal
    position draws five numbers from ``random.Random(params["seed"])`` (missing,
    jitter x, jitter y, yaw, scale) whether or not the plant is missing, so the
    stream never depends on earlier outcomes. The first position is never
    missing, so no field is left empty.
    """
    beds, rows_per_bed, per_row, x_start, y_start = plant_grid(params)
    # Plain locals: attribute look-ups in the loop below would cost a third of its time.
    (
        row_spacing,
        bed_row_spacing,
        in_row,
        origin_x,
        origin_y,
        rotation,
        cos_r,
        sin_r,
        jitter,
        missing_rate,
        size_variation,
        yaw_max,
        plant_height,
    ) = placement_terms(params)
    draw = random.Random(int(params["seed"])).random
    sqrt3 = KERNEL_SQRT3
    min_scale = KERNEL_MIN_SCALE
    # A stated count that does not fill whole rows: the positions after it stay empty.
    limit = params.get("plant_count")
    last = beds * rows_per_bed * per_row if limit is None else int(limit)
    for bed in range(beds):
        for row in range(rows_per_bed):
            local_x = x_start + bed * row_spacing + row * bed_row_spacing
            for step in range(per_row):
                if (bed * rows_per_bed + row) * per_row + step >= last:
                    return
                local_y = y_start + step * in_row
                u_missing, u_x, u_y, u_yaw, u_scale = draw(), draw(), draw(), draw(), draw()
                # A field keeps its first plant: a tiny plot is never left empty.
                if u_missing < missing_rate and (bed or row or step):
                    continue
                px = local_x + (2.0 * u_x - 1.0) * jitter
                py = local_y + (2.0 * u_y - 1.0) * jitter
                scale = 1.0 + size_variation * ((2.0 * u_scale - 1.0) * sqrt3)
                if scale < min_scale:
                    scale = min_scale
                yield (
                    origin_x + (px * cos_r - py * sin_r),
                    origin_y + (px * sin_r + py * cos_r),
                    0.0,
                    rotation + (2.0 * u_yaw - 1.0) * yaw_max,
                    scale,
                    plant_height * scale,
                )


def place_field(params: dict[str, Any]) -> list[tuple[float, float, float, float, float, float]]:
    """Every plant of one field: a list of ``(x, y, z, yaw_rad, scale, height_m)``.

    ``params`` is one dict of :func:`agrirecipe.layout.field_parameters`. The
    result depends only on ``params`` (deterministic across processes and
    machines).
    """
    return list(iter_field_plants(params))
