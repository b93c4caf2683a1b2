"""Changing the fields an instruction names: "make the pears ill", "the carrots in
autumn", "the apples Gala", "rows 50 cm apart", "the wheat field 2 ha"."""

from __future__ import annotations

import math
from collections import Counter
from typing import TYPE_CHECKING, Any

from pydantic import ValidationError

from agrirecipe._errors import AgrirecipeError, PromptError
from agrirecipe.edit._common import read_words, targets_of, validated
from agrirecipe.edit._words import Instruction, fields_list, matching_fields
from agrirecipe.enrich import build_environment, build_field
from agrirecipe.recipe import (
    GEOMETRY_ATTRIBUTES,
    AttributeName,
    FieldGeometry,
    FieldSpec,
    SceneRecipe,
)

if TYPE_CHECKING:
    from agrirecipe.resolve._intent import FieldIntent, ResolveContext, SceneIntent

__all__ = ["change_fields"]

# Stated row values that decide the field's size (the others keep it).
_SIZING = frozenset({"rows", "beds", "row_length_m", "plant_count", "plants_per_row"})


def change_fields(
    recipe: SceneRecipe, words: Instruction, context: ResolveContext, resolver: str
) -> SceneRecipe:
    intent = read_words(words.rest, context, resolver)
    targets = targets_of(recipe, words, intent)
    wishes: dict[str, tuple[FieldIntent, SceneIntent]] = {}
    if intent is not None and not words.named:
        for field in intent.fields:
            for spec in matching_fields(field, recipe):
                wishes[spec.id] = (field, intent)
    if not targets:
        targets = _implied_targets(recipe, words, context, resolver)
    for spec in targets:
        if spec.id not in wishes:
            read = read_words(f"a {spec.crop} field, {words.rest}", context, resolver)
            if read is None:
                raise _nothing_to_change(words)
            wishes[spec.id] = (read.fields[0], read)
    changed: dict[str, FieldSpec] = {}
    warnings = list(recipe.warnings)
    for spec in targets:
        wish, read = wishes[spec.id]
        new_spec, notes = _changed_field(spec, wish, read, context)
        changed[spec.id] = new_spec
        warnings.extend(notes)
    fields = tuple(changed.get(f.id, f) for f in recipe.fields)
    data: dict[str, Any] = {"fields": fields, "warnings": tuple(dict.fromkeys(warnings))}
    seasons = [f.season for f in fields]
    season = Counter(seasons).most_common(1)[0][0] if seasons else recipe.environment.season
    if season != recipe.environment.season:
        data["environment"] = build_environment(season, recipe.environment.latitude_deg)
    return validated(recipe, data, context)


def _implied_targets(
    recipe: SceneRecipe, words: Instruction, context: ResolveContext, resolver: str
) -> list[FieldSpec]:
    """Fields an instruction points at without naming them: the only one, or every
    field for a season (a scene shows one moment), else the instruction is ambiguous."""
    if len(recipe.fields) == 1:
        return list(recipe.fields)
    probe = read_words(f"a {recipe.fields[0].crop} field, {words.rest}", context, resolver)
    if probe is None:
        raise _nothing_to_change(words)
    field = probe.fields[0]
    said = {
        name
        for name in ("variety", "stage", "health", "size", "rows")
        if getattr(field, name) is not None
    }
    if (field.season is not None or probe.season is not None) and not said:
        return list(recipe.fields)
    raise PromptError(
        f"{words.text!r} does not say which field to change",
        stage="edit",
        hint="name it by crop, kind or id (or say 'all fields'); the fields are: "
        + fields_list(recipe),
    )


def _nothing_to_change(words: Instruction) -> PromptError:
    return PromptError(
        f"{words.text!r} names nothing to change",
        stage="edit",
        hint="say what to change, e.g. 'make the pears ill', 'the carrots in autumn', "
        "'the apples Gala', 'rows 50 cm apart', 'the wheat field 2 ha'",
    )


def _changed_field(
    spec: FieldSpec, wish: FieldIntent, read: SceneIntent, context: ResolveContext
) -> tuple[FieldSpec, list[str]]:
    """``spec`` with the attributes ``wish`` states; the rest kept or, when it followed
    from a changed attribute (the stage of a new season), inferred again."""
    from agrirecipe.enrich import plan_rows

    knowledge = context.knowledge
    if wish.crop is not None and wish.crop != spec.crop:
        raise PromptError(
            f"{spec.label} is {spec.crop.lower()}; an edit does not turn it into "
            f"{wish.crop.lower()}",
            stage="edit",
            path=spec.id,
            hint=f"remove it and add a {wish.crop.lower()} field in its place",
        )
    stated: list[AttributeName] = list(spec.stated)
    inferred: list[AttributeName] = list(spec.inferred)

    def state(name: AttributeName) -> None:
        if name not in stated:
            stated.append(name)
        if name in inferred:
            inferred.remove(name)

    variety = wish.variety or spec.variety
    season = wish.season or read.season or spec.season
    if variety != spec.variety or wish.variety is not None:
        state("variety")
    if season != spec.season or wish.season is not None or read.season is not None:
        state("season")
    stage = wish.stage
    if stage is not None:
        state("stage")
    elif "stage" in spec.stated or (season == spec.season and variety == spec.variety):
        stage = spec.stage
    else:
        stage = knowledge.typical_stage(spec.crop, season, variety)
    health = wish.health or spec.health
    if wish.health is not None:
        state("health")
    geometry = spec.geometry
    update: dict[str, float | int] | None = None
    if set(GEOMETRY_ATTRIBUTES) & set(spec.stated):  # spacings said before stay as said
        kept = spec.agronomy
        update = {
            name: getattr(kept, name)
            for name in ("row_spacing_m", "in_row_spacing_m", "rows_per_bed", "bed_row_spacing_m")
        }
    notes: list[str] = []
    if wish.rows is not None:
        values = wish.rows.stated()
        sizing = bool(_SIZING & set(values))
        plan = plan_rows(
            values,
            knowledge.crop_file(spec.crop, variety),
            label=spec.label,
            size_m=None if sizing else geometry.size_m,
            area_m2=None,
            default_size_m=geometry.size_m,
            default_headland_m=geometry.headland_m,
        )
        for name in plan.stated:
            state(name)
        update = plan.agronomy_update()
        geometry = geometry.model_copy(
            update={
                "size_m": plan.size_m,
                "headland_m": plan.headland_m,
                "planted_m": plan.planted_m,
                "plant_count": plan.plant_count,
                "rotation_deg": plan.rotation_deg
                if "row_bearing_deg" in values
                else geometry.rotation_deg,
            }
        )
        notes.extend(f"{spec.id}: {w}" for w in plan.warnings)
    if wish.size is not None:
        geometry = _resized(geometry, wish.size.width_m, wish.size.length_m, wish.size.area_m2)
        state("size")
    try:
        new = build_field(
            hierarchy=context.hierarchy,
            knowledge=knowledge,
            field_id=spec.id,
            label=spec.label.replace(spec.variety, variety, 1),
            crop=spec.crop,
            variety=variety,
            stage=stage,
            season=season,
            health=health,
            geometry=geometry,
            placement=spec.placement,
            stated=stated,
            inferred=inferred,
            agronomy_update=update,
        )
    except (ValidationError, AgrirecipeError) as exc:
        raise PromptError(
            f"{spec.label} cannot be made {variety} {spec.crop.lower()}, {stage}, {season}, "
            f"{health}: {exc}",
            stage="edit",
            path=spec.id,
        ) from exc
    if {"stage", "season"} & set(new.stated):
        reason = knowledge.implausibility(spec.crop, variety, stage, season, health)
        if reason is not None:
            notes.append(f"{spec.id}: {reason} (kept as asked)")
    return new, notes


def _resized(
    geometry: FieldGeometry, width: float | None, length: float | None, area: float | None
) -> FieldGeometry:
    """The field at a stated size ("50 by 100 m", or an area at the same proportions)."""
    if width is None or length is None:
        assert area is not None
        old_width, old_length = geometry.size_m
        scale = math.sqrt(area / (old_width * old_length))
        width, length = round(old_width * scale, 2), round(old_length * scale, 2)
    headland = min(geometry.headland_m, round(0.1 * min(width, length), 2))
    return geometry.model_copy(update={"size_m": (width, length), "headland_m": headland})
