"""The scene recipe: the typed, declarative hub between language and engines.

A :class:`SceneRecipe` is complete: every field has crop, variety, stage,
season, health, asset path, agronomic parameters and geometry. Attributes the
prompt did not state are filled from domain knowledge and listed in
``FieldSpec.inferred``. All models are frozen pydantic v2 models; all lengths
are metres, angles degrees.

Coordinates: right-handed, Z up, X east, Y north. A field is a rectangle whose
south-west corner (before rotation) is ``geometry.origin_m``; it is
``size_m[0]`` wide along X and ``size_m[1]`` long along Y, rotated by
``rotation_deg`` counter-clockwise about its origin. Rows run along the
field's local Y axis.
"""

from __future__ import annotations

import math
import re
from typing import Annotated, Any, Literal, get_args

from pydantic import (
    BaseModel,
    ConfigDict,
    Field,
    ValidationInfo,
    field_validator,
    model_validator,
)

__all__ = [
    "DEFAULT_MAX_PLANTS",
    "GEOMETRY_ATTRIBUTES",
    "SCHEMA_VERSION",
    "Agronomy",
    "AttributeName",
    "Environment",
    "FieldGeometry",
    "FieldSpec",
    "FoliageState",
    "GeometryAttribute",
    "GrowthForm",
    "HealthState",
    "LeafHabit",
    "Placement",
    "PlantingPattern",
    "Relation",
    "RelationKind",
    "SceneRecipe",
    "Season",
    "Stage",
    "Sun",
]

SCHEMA_VERSION = "1.0"
#: Default cap on the nominal number of plants in one recipe (see ``max_plants`` context).
DEFAULT_MAX_PLANTS = 10_000_000

Stage = Literal["Vegetative", "Reproductive", "Maturation"]
Season = Literal["Spring", "Summer", "Fall", "Winter"]
HealthState = Literal["Healthy", "Ill"]
PlantingPattern = Literal[
    "tree_rows", "trellis_rows", "double_rows_on_beds", "ridges", "drilled_rows", "rows"
]
GrowthForm = Literal["tree", "vine", "bush", "row_crop", "leafy_head", "cereal"]
LeafHabit = Literal["deciduous", "evergreen", "perennial", "annual", "biennial"]
FoliageState = Literal[
    "leafless", "budding", "leafy", "flowering", "fruiting", "autumn", "senescent"
]
#: Field geometry a prompt can state (issue 8): rows, spacings, density, direction.
GeometryAttribute = Literal[
    "rows",
    "beds",
    "rows_per_bed",
    "row_length",
    "row_spacing",
    "bed_width",
    "in_row_spacing",
    "density",
    "plant_count",
    "headland",
    "row_direction",
]
GEOMETRY_ATTRIBUTES: tuple[GeometryAttribute, ...] = get_args(GeometryAttribute)
AttributeName = Literal[
    "category", "crop", "variety", "stage", "season", "health", "size", GeometryAttribute
]
RelationKind = Literal["north_of", "south_of", "east_of", "west_of", "next_to", "between"]

_FIELD_ID = r"^[a-z][a-z0-9_]{0,62}$"
Fraction = Annotated[float, Field(ge=0.0, lt=1.0)]
Rgb = tuple[
    Annotated[float, Field(ge=0.0, le=1.0)],
    Annotated[float, Field(ge=0.0, le=1.0)],
    Annotated[float, Field(ge=0.0, le=1.0)],
]
PositiveMetres = Annotated[float, Field(gt=0.0, allow_inf_nan=False)]


class _Frozen(BaseModel):
    model_config = ConfigDict(frozen=True, extra="forbid", allow_inf_nan=False)


class Sun(_Frozen):
    """Sun direction used for the scene's directional light."""

    elevation_deg: float = Field(ge=-90.0, le=90.0, description="Angle above the horizon.")
    azimuth_deg: float = Field(
        ge=0.0, lt=360.0, description="Compass bearing the light comes from, clockwise from north."
    )


class Environment(_Frozen):
    """Scene-wide conditions: the dominant season, where on Earth, and the sun."""

    season: Season
    latitude_deg: float = Field(ge=-90.0, le=90.0)
    hemisphere: Literal["north", "south"]
    sun: Sun

    @model_validator(mode="after")
    def _hemisphere_matches_latitude(self) -> Environment:
        expected = "north" if self.latitude_deg >= 0 else "south"
        if self.hemisphere != expected:
            raise ValueError(
                f"hemisphere: {self.hemisphere!r} contradicts latitude_deg "
                f"{self.latitude_deg} (expected {expected!r})"
            )
        return self


class Agronomy(_Frozen):
    """The agronomic parameters a field was laid out and drawn with, and their sources."""

    planting_pattern: PlantingPattern
    growth_form: GrowthForm
    row_spacing_m: PositiveMetres = Field(
        description="Centre-to-centre distance of rows, or of beds/ridges when rows_per_bed > 1."
    )
    rows_per_bed: int = Field(ge=1, le=8, description="Plant rows per bed or ridge.")
    bed_row_spacing_m: float = Field(
        ge=0.0, description="Distance between the rows inside one bed (0 for single rows)."
    )
    in_row_spacing_m: PositiveMetres
    plant_height_m: PositiveMetres = Field(description="Height at this stage, season and health.")
    max_height_m: PositiveMetres
    canopy_width_m: PositiveMetres
    kc_mid: float = Field(ge=0.0, le=2.0, description="FAO-56 mid-season crop coefficient.")
    leaf_habit: LeafHabit
    foliage: FoliageState
    foliage_rgb: Rgb
    fruit_rgb: Rgb | None = None
    disease: str | None = Field(default=None, description="Disease shown when health is Ill.")
    disease_sign: str | None = None
    sources: tuple[str, ...] = Field(
        default=(), description="Source keys of reference/crops.md, or 'est.' for estimates."
    )

    @model_validator(mode="after")
    def _bed_rows_fit(self) -> Agronomy:
        if self.rows_per_bed == 1 and self.bed_row_spacing_m != 0.0:
            raise ValueError("bed_row_spacing_m: must be 0 when rows_per_bed is 1")
        if self.rows_per_bed > 1:
            if self.bed_row_spacing_m <= 0.0:
                raise ValueError("bed_row_spacing_m: must be positive when rows_per_bed > 1")
            span = self.bed_row_spacing_m * (self.rows_per_bed - 1)
            if span >= self.row_spacing_m:
                raise ValueError(
                    f"bed_row_spacing_m: {self.rows_per_bed} rows {self.bed_row_spacing_m} m apart "
                    f"span {span:g} m, wider than the bed spacing row_spacing_m "
                    f"{self.row_spacing_m:g} m"
                )
        if self.plant_height_m > self.max_height_m * 1.5:
            raise ValueError(
                f"plant_height_m: {self.plant_height_m:g} m exceeds max_height_m "
                f"{self.max_height_m:g} m by more than half"
            )
        return self


class FieldGeometry(_Frozen):
    """Where a field is: its rectangle and the headland kept free of plants."""

    origin_m: tuple[float, float] = Field(description="South-west corner (x east, y north).")
    size_m: tuple[PositiveMetres, PositiveMetres] = Field(
        description="Width along local X and length along local Y (rows run along Y)."
    )
    rotation_deg: float = Field(default=0.0, ge=-180.0, le=180.0)
    headland_m: float = Field(default=0.0, ge=0.0, allow_inf_nan=False)
    planted_m: tuple[PositiveMetres, PositiveMetres] | None = Field(
        default=None,
        description="Width and length of the planted block, centred inside the headland, "
        "when a stated count of rows or plants fills less than the stated field "
        "('10 rows in a 25 x 60 m plot'); None: the rows fill the field inside its headland.",
    )
    plant_count: int | None = Field(
        default=None,
        ge=1,
        description="The stated number of plants when they do not fill whole rows ('250 trees "
        "in 18 rows'): planting positions after it, in planting order (bed by bed, row by row, "
        "along each row), stay empty, so the last row is short; None: every position of the "
        "grid is planted.",
    )

    def usable_m(self) -> tuple[float, float]:
        """Width and length the rows may fill: inside the headland, and the planted block."""
        width = self.size_m[0] - 2 * self.headland_m
        length = self.size_m[1] - 2 * self.headland_m
        if self.planted_m is not None:
            width, length = min(width, self.planted_m[0]), min(length, self.planted_m[1])
        return width, length

    @property
    def area_m2(self) -> float:
        """Area of the field rectangle."""
        return self.size_m[0] * self.size_m[1]

    def corners_m(self) -> tuple[tuple[float, float], ...]:
        """The four corners in world metres (counter-clockwise from the origin)."""
        ox, oy = self.origin_m
        width, length = self.size_m
        cos_r = math.cos(math.radians(self.rotation_deg))
        sin_r = math.sin(math.radians(self.rotation_deg))
        local = ((0.0, 0.0), (width, 0.0), (width, length), (0.0, length))
        return tuple((ox + u * cos_r - v * sin_r, oy + u * sin_r + v * cos_r) for u, v in local)


#: The most plants one drawn plant may stand for (a field thinned to fit max_plants).
MAX_PLANTS_PER_INSTANCE = 20


class Placement(_Frozen):
    """Seeded variation of plant placement within a field."""

    jitter_m: float = Field(default=0.0, ge=0.0, allow_inf_nan=False)
    missing_rate: Fraction = 0.0
    size_variation: Fraction = Field(default=0.0, description="Relative s.d. of plant scale.")
    yaw_variation_deg: float = Field(default=180.0, ge=0.0, le=180.0)
    plants_per_instance: int = Field(
        default=1,
        ge=1,
        le=MAX_PLANTS_PER_INSTANCE,
        description=(
            "Plants one drawn plant stands for along its row: 1 draws every plant; N draws "
            "every N-th planting position (a dense field thinned to fit max_plants)."
        ),
    )


class FieldSpec(_Frozen):
    """One planted field: what grows (flat attributes), how, and where."""

    id: str = Field(pattern=_FIELD_ID, description="Identifier safe for engines: [a-z][a-z0-9_]*")
    label: str = Field(min_length=1, max_length=200)
    category: str = Field(min_length=1)
    crop: str = Field(min_length=1)
    variety: str = Field(min_length=1)
    stage: Stage
    season: Season
    health: HealthState
    asset_path: str = Field(min_length=1)
    agronomy: Agronomy
    geometry: FieldGeometry
    placement: Placement = Placement()
    stated: tuple[AttributeName, ...] = Field(
        default=(), description="Attributes the prompt stated."
    )
    inferred: tuple[AttributeName, ...] = Field(
        default=(), description="Attributes filled from domain knowledge."
    )

    @field_validator("asset_path")
    @classmethod
    def _asset_path_is_unreal_object_path(cls, value: str) -> str:
        if not re.fullmatch(r"/[A-Za-z_][\w/]*\.[A-Za-z_]\w*", value):
            raise ValueError(
                f"{value!r} is not an Unreal object path such as '/Game/Dir/SM_X.SM_X' "
                "(no file extension)"
            )
        return value

    @model_validator(mode="after")
    def _field_holds_a_plant(self) -> FieldSpec:
        width, length = self.geometry.size_m
        headland = self.geometry.headland_m
        usable_w, usable_l = self.geometry.usable_m()
        agronomy = self.agronomy
        bed_span = agronomy.bed_row_spacing_m * (agronomy.rows_per_bed - 1)
        # One plant needs its canopy, or at least half the spacing it was planted at
        # (a single stated row of maize 0.75 m wide is a real plot).
        need_w = min(agronomy.canopy_width_m, agronomy.row_spacing_m / 2)
        need_l = min(agronomy.canopy_width_m, agronomy.in_row_spacing_m / 2)
        if usable_w < max(need_w, bed_span) or usable_l < need_l:
            raise ValueError(
                f"geometry.size_m: a {width:g} x {length:g} m field with a {headland:g} m "
                f"headland is too small for one {self.crop} plant (needs at least "
                f"{2 * headland + max(need_w, bed_span):g} x {2 * headland + need_l:g} m)"
            )
        overlap = set(self.stated) & set(self.inferred)
        if overlap:
            raise ValueError(f"stated: {sorted(overlap)} cannot be both stated and inferred")
        if self.geometry.plant_count is not None and self.placement.plants_per_instance != 1:
            raise ValueError(
                "placement.plants_per_instance: a field of a stated plant count draws every "
                "plant (plants_per_instance 1)"
            )
        return self

    def _grid(self, plants_per_instance: int = 1) -> tuple[int, int]:
        """Beds (or single rows) across the field and positions along each row, every
        ``plants_per_instance``-th planting position drawn (the kernel's grid)."""
        agronomy = self.agronomy
        bed_span = agronomy.bed_row_spacing_m * (agronomy.rows_per_bed - 1)
        usable_w, usable_l = self.geometry.usable_m()
        usable_w -= bed_span
        beds = math.floor(usable_w / agronomy.row_spacing_m + 1e-9) + 1
        in_row = agronomy.in_row_spacing_m * plants_per_instance
        per_row = math.floor(usable_l / in_row + 1e-9) + 1
        return beds, per_row

    @property
    def nominal_plant_count(self) -> int:
        """Planting positions of the field's agronomy, before missing plants are removed
        (at most the stated ``geometry.plant_count``)."""
        beds, per_row = self._grid()
        grid = beds * self.agronomy.rows_per_bed * per_row
        limit = self.geometry.plant_count
        return grid if limit is None else min(grid, limit)

    def drawn_plant_count(self, plants_per_instance: int | None = None) -> int:
        """Positions the layout kernel draws: every ``plants_per_instance``-th planting
        position along each row (the field's own ``placement.plants_per_instance`` by
        default); equal to :attr:`nominal_plant_count` when every plant is drawn."""
        stride = (
            self.placement.plants_per_instance
            if plants_per_instance is None
            else plants_per_instance
        )
        beds, per_row = self._grid(stride)
        grid = beds * self.agronomy.rows_per_bed * per_row
        limit = self.geometry.plant_count
        return grid if limit is None else min(grid, limit)

    @property
    def bed_count(self) -> int:
        """Beds or ridges across the field (equal to :attr:`row_count` for single rows)."""
        return self._grid()[0]

    @property
    def row_count(self) -> int:
        """Plant rows in the field, every row of every bed counted."""
        return self._grid()[0] * self.agronomy.rows_per_bed

    @property
    def row_length_m(self) -> float:
        """Length of the planted rows: the field's length inside its headland (or the
        planted block's, when it is shorter)."""
        return self.geometry.usable_m()[1]

    @property
    def plants_per_ha(self) -> float:
        """Nominal planting density of the row pattern (plants per hectare)."""
        agronomy = self.agronomy
        return (
            10_000.0 * agronomy.rows_per_bed / (agronomy.row_spacing_m * agronomy.in_row_spacing_m)
        )

    @property
    def row_bearing_deg(self) -> float:
        """Direction the rows run, degrees clockwise from north in [0, 180)."""
        return round((-self.geometry.rotation_deg) % 180.0, 9) % 180.0


class Relation(_Frozen):
    """A spatial relation stated in the prompt, honoured by the field packer."""

    kind: RelationKind
    subject: str = Field(pattern=_FIELD_ID)
    objects: tuple[Annotated[str, Field(pattern=_FIELD_ID)], ...] = Field(
        min_length=1, max_length=2
    )

    @model_validator(mode="after")
    def _arity(self) -> Relation:
        expected = 2 if self.kind == "between" else 1
        if len(self.objects) != expected:
            raise ValueError(f"objects: {self.kind!r} takes {expected} field id(s)")
        if self.subject in self.objects:
            raise ValueError(f"objects: a field cannot be {self.kind} itself")
        return self


class SceneRecipe(_Frozen):
    """A complete, validated description of an agricultural scene."""

    schema_version: Literal["1.0"] = "1.0"
    prompt: str = Field(description="The request this recipe was generated from.")
    seed: int = Field(ge=0, lt=2**63)
    units: Literal["metres"] = "metres"
    resolver: str = Field(default="manual", description="Strategy that produced the recipe.")
    environment: Environment
    fields: tuple[FieldSpec, ...] = Field(min_length=1, max_length=64)
    relations: tuple[Relation, ...] = ()
    warnings: tuple[str, ...] = ()

    @model_validator(mode="after")
    def _scene_is_consistent(self, info: ValidationInfo) -> SceneRecipe:
        ids = [f.id for f in self.fields]
        for index, field_id in enumerate(ids):
            if field_id in ids[:index]:
                raise ValueError(f"fields[{index}].id: duplicate field id {field_id!r}")
        for index, relation in enumerate(self.relations):
            for name in (relation.subject, *relation.objects):
                if name not in ids:
                    raise ValueError(
                        f"relations[{index}]: unknown field id {name!r} (fields: {', '.join(ids)})"
                    )
        for i, first in enumerate(self.fields):
            for j in range(i + 1, len(self.fields)):
                if _rectangles_overlap(first.geometry, self.fields[j].geometry):
                    raise ValueError(
                        f"fields[{j}].geometry: field {self.fields[j].id!r} overlaps "
                        f"field {first.id!r}"
                    )
        context: Any = info.context or {}
        cap = int(context.get("max_plants", DEFAULT_MAX_PLANTS))
        total = 0
        for index, spec in enumerate(self.fields):
            drawn = spec.drawn_plant_count()
            total += drawn
            if total > cap:
                width, length = spec.geometry.size_m
                per_ha = drawn / max(width * length / 10_000.0, 1e-9)
                room_ha = max(cap - (total - drawn), 0) / per_ha
                stride = spec.placement.plants_per_instance
                drawn_so = f", every {stride} plants drawn as one" if stride > 1 else ""
                raise ValueError(
                    f"fields[{index}].geometry.size_m: the scene would hold {total:,} plants "
                    f"by field {spec.id!r}, more than the cap of {cap:,}; at its spacings "
                    f"({per_ha:,.0f} plants/ha{drawn_so}) at most {room_ha:.2f} ha of it fit "
                    "(make fields smaller or raise max_plants)"
                )
        return self

    @property
    def nominal_plant_count(self) -> int:
        """Planting positions in all fields before missing plants are removed."""
        return sum(f.nominal_plant_count for f in self.fields)

    @property
    def drawn_plant_count(self) -> int:
        """Positions the layout draws in all fields (a thinned field draws every N-th)."""
        return sum(f.drawn_plant_count() for f in self.fields)

    def field(self, field_id: str) -> FieldSpec:
        """The field with this id."""
        for spec in self.fields:
            if spec.id == field_id:
                return spec
        from agrirecipe._errors import RecipeValidationError

        raise RecipeValidationError(
            f"no field {field_id!r} in this recipe",
            hint="fields: " + ", ".join(f.id for f in self.fields),
        )


def _rectangles_overlap(a: FieldGeometry, b: FieldGeometry) -> bool:
    """Separating-axis test on two (rotated) rectangles; touching edges do not overlap."""
    poly_a, poly_b = a.corners_m(), b.corners_m()
    for poly in (poly_a, poly_b):
        for k in range(4):
            x1, y1 = poly[k]
            x2, y2 = poly[(k + 1) % 4]
            axis = (y1 - y2, x2 - x1)
            proj_a = [axis[0] * x + axis[1] * y for x, y in poly_a]
            proj_b = [axis[0] * x + axis[1] * y for x, y in poly_b]
            tolerance = 1e-6 * math.hypot(*axis)
            if max(proj_a) <= min(proj_b) + tolerance or max(proj_b) <= min(proj_a) + tolerance:
                return False
    return True
