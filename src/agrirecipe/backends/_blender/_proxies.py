"""Procedural proxy plants: from a field's agronomy to a plan of primitive parts in metres.

The proportions live in ``style.yaml`` (next to this module, with the
colours, camera and sun of Blender scenes); this module validates that file
and resolves it for one :class:`~agrirecipe.recipe.FieldSpec`:
which parts are drawn (foliage state, stage, fruit colour), their size in
metres (canopy width and plant height), and the colours of the materials.
The result is plain JSON-able data that the bpy-side builder
(``scene_builder.py``) turns into meshes, so everything here is testable
without Blender.
"""

from __future__ import annotations

import functools
from importlib import resources
from typing import Annotated, Any, Literal, get_args

import yaml
from pydantic import BaseModel, ConfigDict, Field, ValidationError, model_validator

from agrirecipe._errors import BackendError
from agrirecipe.recipe import FieldSpec, FoliageState, GrowthForm, Stage

__all__ = ["BlenderStyle", "MaterialName", "load_style", "proxy_plan"]

MaterialName = Literal["bark", "foliage", "stem", "ear", "fruit", "blossom"]
_Unit = Annotated[float, Field(ge=0.0, le=1.0)]
_Rgb = tuple[_Unit, _Unit, _Unit]
_Vec = tuple[float, float, float]


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True, allow_inf_nan=False)


class _Colours(_Strict):
    bark: _Rgb
    soil: _Rgb
    ground: _Rgb
    blossom: _Rgb
    sky: _Rgb
    stem_factor: _Unit
    straw: _Rgb
    ear_blend: _Unit


class _Role(_Strict):
    material: MaterialName
    leaf: bool = False
    foliage: tuple[FoliageState, ...] | None = None
    stages: tuple[Stage, ...] | None = None
    needs_fruit_rgb: bool = False


class _Part(_Strict):
    """One line of a growth form: a segment, a blob, or a scatter of blobs."""

    role: str
    shape: Literal["cylinder", "cone", "sphere", "cube"]
    y_unit: Literal["w", "row"] = "w"
    from_: _Vec | None = Field(default=None, alias="from")
    to: _Vec | None = None
    width: float | None = Field(default=None, gt=0.0)
    thickness: float = Field(default=1.0, gt=0.0, le=1.0)
    at: _Vec | None = None
    size: _Vec | None = None
    repeat: int = Field(default=1, ge=1, le=24)
    phase_deg: float = 0.0
    scatter: int | None = Field(default=None, ge=1, le=200)
    band: tuple[float, float] = (-1.0, 1.0)
    diameter_w: float | None = Field(default=None, gt=0.0)
    min_m: float = Field(default=0.0, ge=0.0)
    max_m: float = Field(default=1.0, gt=0.0)
    elongation: float = Field(default=1.0, gt=0.0)

    @model_validator(mode="after")
    def _one_placement(self) -> _Part:
        segment = self.from_ is not None or self.to is not None
        blob = self.at is not None or self.size is not None
        if self.scatter is not None:
            if self.at is None or self.size is None or self.diameter_w is None or segment:
                raise ValueError("a scatter needs at, size and diameter_w (no from/to)")
            low, high = self.band
            if not -1.0 <= low < high <= 1.0:
                raise ValueError("band must be two heights -1 <= low < high <= 1")
            if self.min_m > self.max_m:
                raise ValueError("min_m must not exceed max_m")
        elif segment == blob:
            raise ValueError("a part is either a segment (from, to, width) or a blob (at, size)")
        elif segment and (self.from_ is None or self.to is None or self.width is None):
            raise ValueError("a segment needs from, to and width")
        elif blob and (self.at is None or self.size is None):
            raise ValueError("a blob needs at and size")
        return self


class _Camera(_Strict):
    bearing_deg: float = Field(ge=0.0, lt=360.0)
    elevation_deg: float = Field(gt=5.0, le=90.0)
    lens_mm: float = Field(gt=1.0)
    margin: float = Field(ge=1.0, le=3.0)


class _SunLamp(_Strict):
    strength: float = Field(gt=0.0)
    angle_deg: float = Field(ge=0.0, le=30.0)
    min_elevation_deg: float = Field(ge=0.0, le=45.0)


class _World(_Strict):
    strength: float = Field(ge=0.0)


class BlenderStyle(_Strict):
    """The validated contents of ``style.yaml``: proxies, colours, camera, sun and sky."""

    variants: int = Field(ge=1, le=8)
    colours: _Colours
    foliage_leaf_fraction: dict[FoliageState, _Unit]
    roles: dict[str, _Role]
    growth_forms: dict[GrowthForm, tuple[_Part, ...]]
    camera: _Camera
    sun: _SunLamp
    world: _World

    @model_validator(mode="after")
    def _complete(self) -> BlenderStyle:
        for state in get_args(FoliageState):
            if state not in self.foliage_leaf_fraction:
                raise ValueError(f"foliage_leaf_fraction: no entry for {state!r}")
        for form in get_args(GrowthForm):
            if form not in self.growth_forms:
                raise ValueError(f"growth_forms: no proxy for growth form {form!r}")
        for form, parts in self.growth_forms.items():
            for index, part in enumerate(parts):
                if part.role not in self.roles:
                    raise ValueError(
                        f"growth_forms.{form}[{index}]: unknown role {part.role!r} "
                        f"(roles: {', '.join(sorted(self.roles))})"
                    )
        return self


@functools.lru_cache(maxsize=1)
def load_style() -> BlenderStyle:
    """The shipped look of Blender scenes (``style.yaml``), validated once."""
    text = (
        resources.files("agrirecipe.backends._blender")
        .joinpath("style.yaml")
        .read_text(encoding="utf-8")
    )
    try:
        return BlenderStyle.model_validate(yaml.safe_load(text))
    except (yaml.YAMLError, ValidationError) as exc:
        # A broken shipped file is an installation problem, not the user's input.
        raise BackendError(
            f"the Blender scene style (style.yaml) is invalid: {exc}",
            stage="compile",
            hint="reinstall agrirecipe",
        ) from exc


def _scaled(point: _Vec, width_m: float, height_m: float, along_m: float) -> list[float]:
    return [point[0] * width_m, point[1] * along_m, point[2] * height_m]


def _round(values: list[float]) -> list[float]:
    # Six decimals (micrometres) keep scripts short and byte-stable.
    return [round(value, 6) for value in values]


def _blend(a: tuple[float, ...], b: tuple[float, ...], t: float) -> list[float]:
    return [round(x + (y - x) * t, 4) for x, y in zip(a, b, strict=True)]


def _materials(spec: FieldSpec, style: BlenderStyle) -> dict[MaterialName, list[float]]:
    colours = style.colours
    foliage = tuple(spec.agronomy.foliage_rgb)
    materials: dict[MaterialName, list[float]] = {
        "bark": list(colours.bark),
        "foliage": list(foliage),
        "stem": [round(c * colours.stem_factor, 4) for c in foliage],
        "ear": _blend(foliage, colours.straw, colours.ear_blend),
        "blossom": list(colours.blossom),
    }
    if spec.agronomy.fruit_rgb is not None:
        materials["fruit"] = list(spec.agronomy.fruit_rgb)
    return materials


def _shown(role: _Role, spec: FieldSpec, leaf_fraction: float) -> bool:
    agronomy = spec.agronomy
    if role.leaf and leaf_fraction <= 0.0:
        return False
    if role.foliage is not None and agronomy.foliage not in role.foliage:
        return False
    if role.stages is not None and spec.stage not in role.stages:
        return False
    return not (role.needs_fruit_rgb and agronomy.fruit_rgb is None)


def proxy_plan(spec: FieldSpec, style: BlenderStyle | None = None) -> dict[str, Any]:
    """The proxy plant of one field as JSON-able data, every length in metres.

    Lengths are fractions of the canopy width (x, y) and plant height (z), or
    of the in-row spacing (y) for parts with ``y_unit: row``.

    Returns ``{"growth_form", "variants", "parts", "materials"}``: ``parts``
    lists the drawn parts (``kind`` ``"segment"``, ``"blob"`` or
    ``"scatter"``) with their ``role``, ``material`` and placement;
    ``materials`` maps each material used to an sRGB colour. Parts whose role
    is hidden in this field's foliage state or stage are left out (a leafless
    tree keeps only trunk and branches).
    """
    style = style or load_style()
    agronomy = spec.agronomy
    width_m, height_m = agronomy.canopy_width_m, agronomy.plant_height_m
    leaf_fraction = style.foliage_leaf_fraction[agronomy.foliage]
    parts: list[dict[str, Any]] = []
    for part in style.growth_forms[agronomy.growth_form]:
        role = style.roles[part.role]
        if not _shown(role, spec, leaf_fraction):
            continue
        shrink = leaf_fraction if role.leaf else 1.0
        along_m = agronomy.in_row_spacing_m if part.y_unit == "row" else width_m
        entry: dict[str, Any] = {"role": part.role, "material": role.material, "shape": part.shape}
        if part.scatter is not None:
            assert part.at is not None and part.size is not None and part.diameter_w is not None
            diameter = min(max(part.diameter_w * width_m, part.min_m), part.max_m)
            entry.update(
                kind="scatter",
                count=part.scatter,
                at=_round(_scaled(part.at, width_m, height_m, along_m)),
                size=_round(_scaled(part.size, width_m, height_m, along_m)),
                band=list(part.band),
                diameter=round(diameter, 6),
                elongation=part.elongation,
            )
        elif part.from_ is not None:
            assert part.to is not None and part.width is not None
            start = _scaled(part.from_, width_m, height_m, along_m)
            end = _scaled(part.to, width_m, height_m, along_m)
            # Leaves shrink from where they attach, so a budding plant has short leaves.
            end = [s + (e - s) * shrink for s, e in zip(start, end, strict=True)]
            entry.update(
                kind="segment",
                start=_round(start),
                end=_round(end),
                width=round(part.width * width_m * shrink, 6),
                thickness=part.thickness,
            )
        else:
            assert part.at is not None and part.size is not None
            size = [value * shrink for value in _scaled(part.size, width_m, height_m, along_m)]
            entry.update(
                kind="blob",
                at=_round(_scaled(part.at, width_m, height_m, along_m)),
                size=_round(size),
            )
        entry.update(repeat=part.repeat, phase_deg=part.phase_deg)
        parts.append(entry)
    materials = _materials(spec, style)
    used = {entry["material"] for entry in parts}
    return {
        "growth_form": agronomy.growth_form,
        "variants": style.variants,
        "parts": parts,
        "materials": {name: rgb for name, rgb in materials.items() if name in used},
    }
