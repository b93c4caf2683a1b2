"""The format of ``crops/<crop>.yaml`` files, validated with pydantic.

Every number is a :class:`Sourced` value: ``{value, source}`` where ``source``
is a key of ``reference/crops.md`` (``F12``, ``AQ``, a page number such as
``"37"``, ``"crops.md C"``) or ``"est."`` for an estimate. Variety entries
override any part of the crop entry (deep merge).
"""

from __future__ import annotations

from typing import Generic, Literal, TypeVar

from pydantic import BaseModel, ConfigDict, Field, field_validator

from agrirecipe.recipe import GrowthForm, LeafHabit, PlantingPattern, Season, Stage

__all__ = ["CropFile", "Sourced"]

T = TypeVar("T")

_RGB = tuple[float, float, float]


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class Sourced(_Strict, Generic[T]):
    """A value with the source it was taken from (or ``"est."``)."""

    value: T
    source: str = Field(min_length=1)
    note: str | None = None
    range: tuple[float, float] | None = None

    @field_validator("source")
    @classmethod
    def _known_source(cls, source: str) -> str:
        allowed_words = {
            "est.",
            "n/a",
            "F11",
            "F12",
            "AQ",
            "crops.md A",
            "crops.md B",
            "crops.md C",
        }
        parts = [part.strip() for part in source.split(",")]
        for part in parts:
            if part not in allowed_words and not part.isdigit():
                raise ValueError(
                    f"unknown source key {part!r}; use F11, F12, AQ, a page number of "
                    "reference/crops.md, 'crops.md A/B/C' or 'est.'"
                )
        return source


class _Planting(_Strict):
    pattern: PlantingPattern
    description: str
    row_spacing_m: Sourced[float]
    in_row_spacing_m: Sourced[float]
    rows_per_bed: int = Field(ge=1, le=8)
    bed_row_spacing_m: Sourced[float]


class _FieldDefaults(_Strict):
    default_size_m: Sourced[tuple[float, float]]
    headland_m: Sourced[float]
    jitter_m: Sourced[float]
    missing_rate: Sourced[float]
    size_variation: Sourced[float]
    yaw_variation_deg: Sourced[float] | None = Field(
        default=None,
        description="How far a plant may turn about its stem; trellised vines keep their "
        "leaf wall along the row. None: any yaw (180).",
    )


class _Disease(_Strict):
    name: str
    sign: str
    source: str
    ill_tint: Literal["chlorotic", "necrotic"]


class _Colours(_Strict):
    foliage_rgb: Sourced[_RGB]
    autumn_rgb: Sourced[_RGB] | None = None
    flower_rgb: Sourced[_RGB] | None = None
    fruit_rgb: Sourced[_RGB] | None = None
    mature_rgb: Sourced[_RGB] | None = Field(
        default=None, description="Colour of the whole plant at maturation (ripe cereals)."
    )


class _SeasonStages(_Strict):
    stages: tuple[Stage, ...] = Field(
        description="Plausible stages in this season, typical first; empty when not grown."
    )
    source: str
    note: str | None = None


class _Flowering(_Strict):
    seasons: tuple[Season, ...] = Field(
        min_length=1,
        description="Seasons in which a reproductive plant shows flowers; outside them it "
        "shows setting or growing fruit.",
    )
    source: str
    note: str | None = None


class CropFile(_Strict):
    """One crop's knowledge after variety overrides are merged in."""

    crop: str
    default_variety: Sourced[str]
    growth_form: GrowthForm
    leaf_habit: LeafHabit
    planting: _Planting
    max_height_m: Sourced[float]
    canopy_width_m: Sourced[float]
    kc_mid: Sourced[float]
    field: _FieldDefaults
    disease: _Disease
    colours: _Colours
    seasons: dict[Season, _SeasonStages]
    stage_height_fraction: dict[Stage, Sourced[float]]
    flowering: _Flowering | None = Field(
        default=None,
        description="When flowers show; when absent, deciduous crops flower in spring and "
        "summer and all others whenever they are reproductive.",
    )

    @field_validator("seasons")
    @classmethod
    def _all_seasons(cls, value: dict[Season, _SeasonStages]) -> dict[Season, _SeasonStages]:
        missing = {"Spring", "Summer", "Fall", "Winter"} - set(value)
        if missing:
            raise ValueError(f"missing seasons: {', '.join(sorted(missing))}")
        return value

    @field_validator("stage_height_fraction")
    @classmethod
    def _all_stages(cls, value: dict[Stage, Sourced[float]]) -> dict[Stage, Sourced[float]]:
        missing = {"Vegetative", "Reproductive", "Maturation"} - set(value)
        if missing:
            raise ValueError(f"missing stages: {', '.join(sorted(missing))}")
        return value
