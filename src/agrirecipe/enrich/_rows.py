"""Stated row geometry -> the field's spacing, size, headland and rotation.

A prompt that says "10 rows of maize, 80 m long, 76 cm apart" gets exactly
that: the field is sized so the layout kernel places 10 rows of 80 m at
0.76 m, and the recipe records the values as stated. Each stated value is
checked against the crop's knowledge: outside the sourced range of
``crops/<crop>.yaml`` it is kept with a warning naming the range; physically
impossible (rows closer than half the narrowest plant, plants closer than a
quarter of the closest sourced spacing, counts that cannot agree) it is a
:class:`~agrirecipe.PromptError` that says why.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from agrirecipe._errors import PromptError
from agrirecipe.knowledge._files import CropFile
from agrirecipe.recipe import AttributeName

__all__ = ["RowPlan", "plan_rows"]

# The unplanted border a stated plot keeps when no headland is stated: at most
# this share of its shorter planted side (a 6 m wide test plot keeps 0.6 m).
_HEADLAND_SHARE = 0.1
# Stated density and in-row spacing may disagree by this much before it is a contradiction
# (a density said rounded: "2,800 trees/ha, 3.5 x 1.0 m" is 2,857 planted); the grid as
# said is kept, with a warning past half a percent.
_AGREE = 0.05
_ROUNDED = 0.005
# Exact factorisations of a tree count are used while their aspect is within this
# factor of the crop's usual field shape.
_MAX_ASPECT_STRETCH = 4.0

_STATED_NAMES: dict[str, AttributeName] = {
    "rows": "rows",
    "beds": "beds",
    "rows_per_bed": "rows_per_bed",
    "row_length_m": "row_length",
    "plants_per_row": "row_length",
    "row_spacing_m": "row_spacing",
    "bed_width_m": "bed_width",
    "alley_m": "row_spacing",
    "in_row_spacing_m": "in_row_spacing",
    "plants_per_ha": "density",
    "plant_count": "plant_count",
    "headland_m": "headland",
    "row_bearing_deg": "row_direction",
}


@dataclass
class RowPlan:
    """What a field's stated geometry makes of it (values the recipe then carries)."""

    row_spacing_m: float
    in_row_spacing_m: float
    rows_per_bed: int
    bed_row_spacing_m: float
    size_m: tuple[float, float]
    headland_m: float
    rotation_deg: float
    stated: list[AttributeName] = field(default_factory=list)
    #: The planted block when stated counts fill less than a stated field ("10 rows in a
    #: 25 x 60 m plot"): width and length inside the headland; None when rows fill it.
    planted_m: tuple[float, float] | None = None
    #: A stated plant count that leaves the last row short ("250 trees in 18 rows"): the
    #: planting positions after it stay empty; None when the rows hold exactly the count.
    plant_count: int | None = None
    warnings: list[str] = field(default_factory=list)

    def agronomy_update(self) -> dict[str, float | int]:
        """The agronomy values the plan replaces (``build_field(agronomy_update=...)``)."""
        return {
            "row_spacing_m": self.row_spacing_m,
            "in_row_spacing_m": self.in_row_spacing_m,
            "rows_per_bed": self.rows_per_bed,
            "bed_row_spacing_m": self.bed_row_spacing_m,
        }


def _error(label: str, message: str, hint: str) -> PromptError:
    return PromptError(f"{label}: {message}", stage="enrich", hint=hint)


def _range_of(value: float, low: float | None, high: float | None) -> str:
    return f"{low:g}-{high:g}" if low is not None and high is not None else f"{value:g}"


def plan_rows(
    stated: dict[str, float],
    crop: CropFile,
    *,
    label: str,
    size_m: tuple[float, float] | None,
    area_m2: float | None,
    default_size_m: tuple[float, float],
    default_headland_m: float,
) -> RowPlan:
    """Turn stated geometry (:meth:`RowSpec.stated`) into the numbers a field is built with.

    ``size_m`` / ``area_m2`` are a size stated beside the rows ("a 0.1 ha plot,
    rows 75 cm apart"); without one, stated counts and lengths decide the size,
    and what they leave open comes from the crop's default field.
    """
    planting = crop.planting
    names: list[AttributeName] = []
    for key in stated:
        name = _STATED_NAMES[key]
        if name not in names:
            names.append(name)
    warnings: list[str] = []

    rows_per_bed = int(stated.get("rows_per_bed", planting.rows_per_bed))
    if "row_spacing_m" in stated and not {"rows_per_bed", "bed_width_m", "beds"} & set(stated):
        # "12 rows on a 3 m grid" of a crop grown in double rows: the rows said, one by one.
        rows_per_bed = 1
    rows = stated.get("rows")
    beds = stated.get("beds")
    if rows is not None and beds is not None and "rows_per_bed" not in stated and rows < beds:
        # "14 beds at 1.52 m centres, 2 rows each": fewer rows than beds are the rows on
        # each bed
        rows_per_bed = int(rows)
        stated = {k: v for k, v in stated.items() if k != "rows"} | {"rows_per_bed": rows}
        names = [_STATED_NAMES["rows_per_bed"] if n == _STATED_NAMES["rows"] else n for n in names]
        warnings.append(
            f"{label}: {rows:g} rows with {beds:g} beds read as {rows:g} rows on each bed"
        )
        rows = None
    elif rows is not None and beds is not None and "rows_per_bed" not in stated:
        if rows % beds:
            raise _error(
                label,
                f"{rows:g} rows cannot share {beds:g} beds evenly",
                "give rows per bed, e.g. '6 beds with two rows per bed'",
            )
        rows_per_bed = int(rows // beds)
    if rows_per_bed > 8:
        raise _error(label, f"{rows_per_bed} rows on one bed is more than 8", "use 1 to 8")
    single_spacing: float | None = None
    if (
        rows is not None
        and rows % rows_per_bed
        and not {"rows_per_bed", "bed_width_m", "beds"} & set(stated)
    ):
        # "next to a row of California Wonder peppers": a crop usually grown in double
        # rows on beds, asked for in a number of rows that fills no whole bed, is planted
        # in single rows as far apart as the rows on its usual beds
        warnings.append(
            f"{label}: {rows:g} row(s) do not fill {crop.crop}'s usual beds of {rows_per_bed} "
            "rows; planted as single rows"
        )
        single_spacing = planting.row_spacing_m.value / rows_per_bed
        rows_per_bed = 1

    # Centre distance of beds (several rows each) or of single rows.
    if rows_per_bed > 1:
        bed_width = stated.get("bed_width_m")
        if (
            bed_width is None
            and {"plants_per_ha", "in_row_spacing_m"} <= set(stated)
            and "row_spacing_m" not in stated
        ):
            # "double rows, 2.25 m in-row, 1,840 plants/ha": the beds are as far apart as
            # that makes
            bed_width = round(
                10_000.0 * rows_per_bed / (stated["plants_per_ha"] * stated["in_row_spacing_m"]),
                4,
            )
        alley = stated.get("alley_m")
        default_rows = planting.bed_row_spacing_m.value
        if bed_width is None and alley is not None:
            # "double rows 1 m apart with 3.75 m alleys": a bed is its rows and one alley
            within = stated.get("row_spacing_m", default_rows if default_rows > 0 else alley / 2)
            bed_width = alley + within * (rows_per_bed - 1)
        if bed_width is None and planting.rows_per_bed > 1:
            bed_width = planting.row_spacing_m.value
        if "row_spacing_m" in stated:
            bed_rows = stated["row_spacing_m"]  # the rows on one bed
            spacing = bed_width if bed_width is not None else bed_rows * rows_per_bed
        else:
            spacing = (
                bed_width if bed_width is not None else planting.row_spacing_m.value * rows_per_bed
            )
            bed_rows = default_rows if default_rows > 0 else spacing / rows_per_bed / 2
            if alley is not None and alley < spacing:
                # "double rows with 3.75 m alleys, ..., 1,840 plants/ha": what the beds'
                # spacing leaves beside the alley is the rows on each bed
                bed_rows = (spacing - alley) / (rows_per_bed - 1)
            # "4 rows per bed on 1.5 m beds": the rows said fit on the bed said.
            bed_rows = min(bed_rows, spacing / rows_per_bed)
    else:
        spacing = (
            stated.get("row_spacing_m")
            or stated.get("bed_width_m")
            or stated.get("alley_m")  # ("4.5 m alleys": single rows, an alley between each two)
            or single_spacing
            or planting.row_spacing_m.value
        )
        if {"plants_per_ha", "in_row_spacing_m"} <= set(stated) and not {
            "row_spacing_m",
            "bed_width_m",
            "alley_m",
        } & set(stated):
            # "80,000 heads per ha, 30 cm in-row": the rows are as far apart as that makes
            spacing = round(10_000.0 / (stated["plants_per_ha"] * stated["in_row_spacing_m"]), 4)
        bed_rows = 0.0
    bed_span = bed_rows * (rows_per_bed - 1)
    if bed_span >= spacing:
        raise _error(
            label,
            f"{rows_per_bed} rows {bed_rows:g} m apart do not fit on a bed every {spacing:g} m",
            "make the beds wider or the rows on them closer",
        )

    in_row = stated.get("in_row_spacing_m")
    density = stated.get("plants_per_ha")
    if density is not None:
        from_density = 10_000.0 * rows_per_bed / (density * spacing)
        if in_row is not None and abs(from_density - in_row) > _AGREE * in_row:
            raise _error(
                label,
                f"{density:,.0f} plants/ha at {spacing:g} m between rows needs a plant every "
                f"{from_density:.3g} m, not every {in_row:g} m",
                "state the density or the in-row spacing, not two that disagree",
            )
        if in_row is None:  # a stated in-row spacing that agrees is kept as said
            in_row = from_density
        elif abs(from_density - in_row) > _ROUNDED * in_row:
            warnings.append(
                f"{label}: {density:,.0f} plants/ha read as said roughly: planted at "
                f"{spacing:g} m x {in_row:g} m as stated "
                f"({10_000.0 * rows_per_bed / (spacing * in_row):,.0f} plants/ha)"
            )
    length_rows = stated.get("row_length_m")
    per_row = stated.get("plants_per_row")
    if in_row is None and per_row is not None and length_rows is not None and per_row > 1:
        in_row = length_rows / (per_row - 1)
    if (
        in_row is None
        and "plant_count" in stated
        and area_m2 is not None
        and size_m is None
        and rows is None
        and beds is None
        and length_rows is None
        and per_row is None
    ):
        # "Royal Gala orchard, 1 ha, 3.4 m rows, 2,900 trees": the trees fill the area
        # said (the field's, headland included) at the rows' spacing
        size_m, beds, in_row = _count_in_area(
            int(stated["plant_count"]),
            area_m2,
            spacing,
            bed_span,
            rows_per_bed,
            default_size_m,
            default_headland_m,
        )
    if in_row is None:
        in_row = planting.in_row_spacing_m.value
    _check_spacing(label, crop, spacing, in_row, rows_per_bed, stated, warnings)

    # Across the rows: a stated count of rows or beds fixes the planted width.
    bed_count: int | None = None
    if rows is not None:
        if rows % rows_per_bed:
            raise _error(
                label,
                f"{rows:g} rows do not fill beds of {rows_per_bed} rows",
                f"ask for a multiple of {rows_per_bed} rows, or say the rows per bed",
            )
        bed_count = int(rows // rows_per_bed)
    elif beds is not None:
        bed_count = int(beds)

    # Along the rows: a stated length, plants per row, or a count of plants.
    count = stated.get("plant_count")
    # (a count that does not fill whole rows leaves the last row short: exactly that many)
    short: int | None = None
    if count is not None and per_row is None and bed_count is None and length_rows is not None:
        # "1,000 tomato plants in 100 m rows": as many rows of that length as the plants fill
        along = math.floor(length_rows / in_row + 1e-9) + 1
        bed_count = max(1, math.ceil(int(count) / (along * rows_per_bed)))
        if bed_count * rows_per_bed * along != int(count):
            short = int(count)
            warnings.append(
                f"{label}: {int(count)} plants do not fill {length_rows:g} m rows evenly; "
                f"planted as {bed_count * rows_per_bed} rows of {along}, the last one short"
            )
    elif count is not None and per_row is None:
        bed_count, per_row = _split_count(
            int(count),
            bed_count,
            rows_per_bed,
            spacing,
            in_row,
            size_m or default_size_m,
            label,
            warnings,
        )
        if bed_count * rows_per_bed * per_row != int(count):
            short = int(count)
    if length_rows is not None:
        usable_l = length_rows
    elif per_row is not None:
        usable_l = (per_row - 0.5) * in_row  # exactly per_row plants, never one more
    else:
        usable_l = None

    usable_w = bed_span + (bed_count - 0.5) * spacing if bed_count is not None else None
    width, length = _outer_size(usable_w, usable_l, size_m, area_m2, default_size_m)
    stated_headland = stated.get("headland_m")
    if stated_headland is not None:
        headland = stated_headland
        if usable_w is None and usable_l is None and size_m is None and area_m2 is None:
            pass  # the default field keeps its size; only the border changes
    elif usable_w is not None or usable_l is not None or size_m is not None or area_m2:
        planted = [v for v in (usable_w, usable_l) if v is not None] or [min(width, length)]
        headland = min(default_headland_m, round(_HEADLAND_SHARE * min(planted), 2))
    else:
        headland = default_headland_m
    planted_m: tuple[float, float] | None = None
    if size_m is not None:
        # "36 m x 60 m: 12 rows on a 3 m grid": the size said is the field; its border
        # narrows to what the rows leave (they are planted whole only if they fit), and
        # "8 beds ... all three are 20 x 50 m": rows that fill less of it are a planted
        # block in its middle, as many as said. A headland said too ("18 rows of 30 m
        # with a 2 m headland all round; the whole plot is 20 x 34 m") stays as said.
        room = [
            (side - planted) / 2
            for side, planted in ((width, usable_w), (length, usable_l))
            if planted is not None
        ]
        least = stated_headland if stated_headland is not None else 0.0
        if room and min(room) >= least - 1e-9:
            headland = min(headland, *room) if stated_headland is None else stated_headland
            inner_w, inner_l = width - 2 * headland, length - 2 * headland
            block = (
                inner_w if usable_w is None else usable_w,
                inner_l if usable_l is None else usable_l,
            )
            spare_w = inner_w - block[0] >= spacing / 2
            spare_l = inner_l - block[1] >= in_row / 2
            if spare_w or spare_l:
                planted_m = (round(block[0], 6), round(block[1], 6))
            usable_w = usable_l = None
    # A stated count or length is planted area: the headland goes around it.
    if usable_w is not None:
        width = usable_w + 2 * headland
    if usable_l is not None:
        length = usable_l + 2 * headland
    if area_m2 is not None and size_m is None and (usable_w is None) != (usable_l is None):
        # "30 ridges on 75 cm centres, ..., 0.5 acre in total": the area said is the
        # whole field's, headland included; the side the rows do not set gives way
        if usable_w is not None:
            length = area_m2 / width
        else:
            width = area_m2 / length
    if width - 2 * headland - bed_span < 0 or length - 2 * headland < 0:
        raise _error(
            label,
            f"a {headland:g} m headland leaves no room for plants in a {width:g} x {length:g} m "
            "field",
            "make the headland narrower or the field larger",
        )
    bearing = stated.get("row_bearing_deg")
    rotation = -bearing if bearing else 0.0
    return RowPlan(
        row_spacing_m=spacing,
        in_row_spacing_m=in_row,
        rows_per_bed=rows_per_bed,
        bed_row_spacing_m=bed_rows if rows_per_bed > 1 else 0.0,
        size_m=(round(width, 6), round(length, 6)),
        headland_m=headland,
        rotation_deg=rotation,
        planted_m=planted_m,
        plant_count=short,
        stated=names,
        warnings=warnings,
    )


def _outer_size(
    usable_w: float | None,
    usable_l: float | None,
    size_m: tuple[float, float] | None,
    area_m2: float | None,
    default_size_m: tuple[float, float],
) -> tuple[float, float]:
    """The field's sides before a headland is added around stated planted sides."""
    if size_m is not None:
        width, length = size_m
    else:
        width, length = default_size_m
        if area_m2 is not None:
            if usable_w is not None:
                return width, area_m2 / usable_w
            if usable_l is not None:
                return area_m2 / usable_l, length
            scale = math.sqrt(area_m2 / (width * length))
            width, length = width * scale, length * scale
    return width, length


def _count_in_area(
    count: int,
    area_m2: float,
    spacing: float,
    bed_span: float,
    rows_per_bed: int,
    default_size_m: tuple[float, float],
    headland_m: float,
) -> tuple[tuple[float, float], float, float]:
    """The field (shaped like the crop's usual one), its beds and the in-row spacing at
    which ``count`` plants fill ``area_m2`` inside the headland, rows ``spacing`` apart."""
    width, length = _outer_size(None, None, None, area_m2, default_size_m)
    inner_w, inner_l = width - 2 * headland_m, length - 2 * headland_m
    if inner_w <= bed_span + spacing / 2 or inner_l <= 0:
        return (width, length), 1.0, inner_l / max(count - 0.5, 0.5)
    beds = max(1, math.floor((inner_w - bed_span) / spacing + 0.5))
    per_row = math.ceil(count / (beds * rows_per_bed))
    return (width, length), float(beds), inner_l / (per_row - 0.5) if per_row > 1 else inner_l


def _split_count(
    count: int,
    bed_count: int | None,
    rows_per_bed: int,
    spacing: float,
    in_row: float,
    shape_m: tuple[float, float],
    label: str,
    warnings: list[str],
) -> tuple[int, int]:
    """Beds and plants per row that hold exactly ``count`` plants, shaped like the field."""
    if bed_count is not None:
        rows = bed_count * rows_per_bed
        per_row = math.ceil(count / rows)
        if rows * per_row != count:
            warnings.append(
                f"{label}: {count} plants do not fill {rows} rows evenly; planted as {rows} rows "
                f"of {per_row}, the last one short"
            )
        return bed_count, per_row
    target = shape_m[0] / shape_m[1]  # width / length of the crop's usual field

    def stretch(beds: int, per_row: int) -> float:
        aspect = (beds * spacing) / max(per_row * in_row, 1e-9)
        return max(aspect / target, target / aspect)

    exact = [
        (beds, count // (beds * rows_per_bed))
        for beds in range(1, count + 1)
        if count % (beds * rows_per_bed) == 0
    ]
    best = min(exact, key=lambda pair: stretch(*pair), default=None)
    if best is not None and stretch(*best) <= _MAX_ASPECT_STRETCH:
        return best
    beds = max(1, round(math.sqrt(count * target * in_row / (spacing * rows_per_bed))))
    per_row = math.ceil(count / (beds * rows_per_bed))
    warnings.append(
        f"{label}: {count} plants make no even block; planted as {beds * rows_per_bed} rows of "
        f"{per_row}, the last one short"
    )
    return beds, per_row


def _check_spacing(
    label: str,
    crop: CropFile,
    spacing: float,
    in_row: float,
    rows_per_bed: int,
    stated: dict[str, float],
    warnings: list[str],
) -> None:
    """Impossible spacings are errors; spacings outside the sourced range are warnings."""
    planting = crop.planting
    canopy = crop.canopy_width_m
    narrowest = min(canopy.range[0] if canopy.range else canopy.value, planting.row_spacing_m.value)
    if rows_per_bed == 1 and spacing < 0.5 * narrowest:
        raise _error(
            label,
            f"rows {spacing:g} m apart are closer than {crop.crop.lower()} plants are wide "
            f"(at least {0.5 * narrowest:g} m)",
            f"{crop.crop} rows are usually {_sourced(planting.row_spacing_m)} apart",
        )
    closest = (
        planting.in_row_spacing_m.range[0]
        if planting.in_row_spacing_m.range
        else (planting.in_row_spacing_m.value)
    )
    if in_row < 0.25 * closest:
        raise _error(
            label,
            f"{crop.crop.lower()} plants {in_row:.3g} m apart in the row cannot grow "
            f"(at least {0.25 * closest:.3g} m)",
            f"{crop.crop} plants are usually {_sourced(planting.in_row_spacing_m)} apart",
        )
    if "row_spacing_m" in stated or "bed_width_m" in stated:
        _warn_range(label, crop, "row spacing", spacing, planting.row_spacing_m, warnings)
    if {"in_row_spacing_m", "plants_per_ha", "plants_per_row"} & set(stated):
        _warn_range(label, crop, "in-row spacing", in_row, planting.in_row_spacing_m, warnings)


def _sourced(value: object) -> str:
    low_high = getattr(value, "range", None)
    number = float(getattr(value, "value", 0.0))
    if low_high:
        return f"{low_high[0]:g}-{low_high[1]:g} m"
    return f"{number:g} m"


def _warn_range(
    label: str, crop: CropFile, what: str, value: float, sourced: object, warnings: list[str]
) -> None:
    low_high = getattr(sourced, "range", None)
    default = float(getattr(sourced, "value", value))
    low, high = (low_high[0], low_high[1]) if low_high else (default, default)
    if low * (1 - 1e-9) <= value <= high * (1 + 1e-9):
        return
    source = getattr(sourced, "source", "est.")
    warnings.append(
        f"{label}: {what} {value:.3g} m is outside the usual {_range_of(default, low, high)} m "
        f"for {crop.crop.lower()} (crops/{crop.crop.lower()}.yaml, source {source}); kept as asked"
    )
