"""Fields an edit brings in: "add a wheat field south of the orchard" (placed beside
the field named, moving nothing) and "replace the carrots with potatoes" (the same
plot, another crop)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from agrirecipe._errors import PromptError
from agrirecipe.edit._change import change_fields
from agrirecipe.edit._common import describe, read_words, targets_of, validated, warnings_without
from agrirecipe.edit._place import place_block
from agrirecipe.edit._words import Instruction, fields_list, matching_fields, unmatched
from agrirecipe.enrich import build_field
from agrirecipe.recipe import FieldSpec, Relation, SceneRecipe

if TYPE_CHECKING:
    from agrirecipe.resolve._intent import ResolveContext, SceneIntent

__all__ = ["add_fields", "replace_fields"]


def replace_fields(
    recipe: SceneRecipe, words: Instruction, context: ResolveContext, resolver: str
) -> SceneRecipe:
    """ "replace the carrots with potatoes": the same plots, a new crop. When the new
    words name no other crop ("turn the pears to flowering") it is a change."""
    from agrirecipe.resolve._pipeline import plot_noun

    assert words.replacement is not None
    wanted = read_words(words.replacement, context, resolver)
    intent = read_words(words.rest, context, resolver)
    targets = targets_of(recipe, words, intent)
    if not targets and len(recipe.fields) == 1:
        targets = list(recipe.fields)
    crops = {t.crop for t in targets}
    same_crop = wanted is not None and all(f.crop in crops for f in wanted.fields if not f.generic)
    if wanted is None or (same_crop and not any(f.generic for f in wanted.fields)):
        joined = f"{words.rest} {words.replacement}"
        return change_fields(
            recipe,
            Instruction(
                text=words.text,
                action="change",
                rest=joined,
                named=words.named,
                everything=words.everything,
                pronoun=words.pronoun,
            ),
            context,
            resolver,
        )
    if not targets:
        raise PromptError(
            f"{words.text!r} names no field of the scene to replace",
            stage="edit",
            hint="name it by crop, kind or id; the fields are: " + fields_list(recipe),
        )
    if len(wanted.fields) != 1 or wanted.fields[0].crop is None:
        raise PromptError(
            f"{words.text!r}: say the one crop that takes the fields' place",
            stage="edit",
            hint="e.g. 'replace the carrots with Bintje potatoes'",
        )
    wish = wanted.fields[0]
    crop = wish.crop
    assert crop is not None
    knowledge = context.knowledge
    used = {f.id for f in recipe.fields} - {t.id for t in targets}
    renamed: dict[str, str] = {}
    replaced: dict[str, FieldSpec] = {}
    for spec in targets:
        noun = plot_noun(crop, knowledge)
        variety = wish.variety or knowledge.default_variety(crop)
        season = wish.season or wanted.season or spec.season
        stage = wish.stage or knowledge.typical_stage(crop, season, variety)
        health = wish.health or "Healthy"
        stem = f"{crop.lower().replace(' ', '_')}_{noun}"
        number = 1
        while f"{stem}_{number}" in used:
            number += 1
        new_id = f"{stem}_{number}"
        used.add(new_id)
        renamed[spec.id] = new_id
        said = {
            "variety": wish.variety,
            "stage": wish.stage,
            "health": wish.health,
        }
        stated = ["crop"] + [name for name, value in said.items() if value is not None]
        stated += [name for name in ("season", "size") if name in spec.stated]
        if wish.season or wanted.season:
            stated.append("season")
        names = ("variety", "stage", "season", "health", "size")
        inferred = [name for name in names if name not in stated]
        label = f"{variety} {crop.lower()} {noun}"
        labels = {f.label for f in recipe.fields} | {f.label for f in replaced.values()}
        suffix = 1
        while label in labels:
            suffix += 1
            label = f"{variety} {crop.lower()} {noun} {suffix}"
        replaced[spec.id] = build_field(
            hierarchy=context.hierarchy,
            knowledge=knowledge,
            field_id=new_id,
            label=label,
            crop=crop,
            variety=variety,
            stage=stage,
            season=season,
            health=health,
            geometry=spec.geometry,
            stated=tuple(dict.fromkeys(stated)),  # type: ignore[arg-type]
            inferred=tuple(inferred),  # type: ignore[arg-type]
        )
    fields = tuple(replaced.get(f.id, f) for f in recipe.fields)
    relations = tuple(
        Relation(
            kind=r.kind,
            subject=renamed.get(r.subject, r.subject),
            objects=tuple(renamed.get(o, o) for o in r.objects),
        )
        for r in recipe.relations
    )
    warnings = warnings_without(recipe, renamed)
    return validated(
        recipe, {"fields": fields, "relations": relations, "warnings": warnings}, context
    )


def add_fields(
    recipe: SceneRecipe, words: Instruction, context: ResolveContext, resolver: str
) -> SceneRecipe:
    from agrirecipe.resolve._intent import RelationIntent

    intent = read_words(words.rest, context, resolver)
    if intent is None:
        raise PromptError(
            f"{words.text!r} names no field to add",
            stage="edit",
            hint="name a crop or a kind of field, e.g. 'add a wheat field south of the orchard'",
        )
    objects = {o for r in intent.relations for o in r.objects}
    subjects = {r.subject for r in intent.relations}
    anchors: dict[int, list[FieldSpec]] = {}
    for index, field in enumerate(intent.fields):
        if index in objects and index not in subjects:
            found = matching_fields(field, recipe)
            if not found:
                raise unmatched(describe(field), recipe)
            anchors[index] = found
    for field_id in words.named:  # "add a wheat field south of carrot_field_1"
        anchors.setdefault(-1, []).append(recipe.field(field_id))
    new_index = [i for i in range(len(intent.fields)) if i not in anchors]
    if not new_index:
        raise PromptError(
            f"{words.text!r} names no new field", stage="edit", hint="name the crop to add"
        )
    renumber = {old: new for new, old in enumerate(new_index)}
    inner = tuple(
        RelationIntent(
            kind=r.kind,
            subject=renumber[r.subject],
            objects=tuple(renumber[o] for o in r.objects),
            text=r.text,
        )
        for r in intent.relations
        if r.subject in renumber and all(o in renumber for o in r.objects)
    )
    own_seasons = [intent.fields[i].season for i in new_index]
    sub = intent.model_copy(
        update={
            "fields": tuple(intent.fields[i] for i in new_index),
            "relations": inner,
            "season": intent.season or recipe.environment.season,
        }
    )
    block = _built(sub, context, recipe.resolver)
    block = _unclashed(block, recipe, own_seasons, intent.season is None)
    outer = [
        r for r in intent.relations if r.subject in renumber and not set(r.objects) <= set(renumber)
    ]
    anchor: list[FieldSpec] = []
    side: str | None = None
    relations = list(recipe.relations) + list(block.relations)
    if outer:
        side = outer[0].kind
        anchor = anchors[outer[0].objects[0]]
        for relation in outer:
            targets = [anchors[o] for o in relation.objects if o in anchors]
            for found in targets:
                if len(found) > 1:
                    raise PromptError(
                        f"{words.text!r}: {len(found)} fields fit "
                        + ", ".join(f.id for f in found),
                        stage="edit",
                        hint="name the one you mean by its id",
                    )
            relations.append(
                Relation(
                    kind=relation.kind,
                    subject=block.fields[renumber[relation.subject]].id,
                    objects=tuple(found[0].id for found in targets),
                )
            )
    elif -1 in anchors:
        anchor, side = anchors[-1], "next_to"
        relations.extend(
            Relation(kind="next_to", subject=block.fields[0].id, objects=(spec.id,))
            for spec in anchor[:1]
        )
    dx, dy = place_block(
        [f.geometry for f in block.fields], recipe.fields, anchor=anchor, side=side
    )
    moved = tuple(
        f.model_copy(
            update={
                "geometry": f.geometry.model_copy(
                    update={"origin_m": (f.geometry.origin_m[0] + dx, f.geometry.origin_m[1] + dy)}
                )
            }
        )
        for f in block.fields
    )
    return validated(
        recipe,
        {
            "fields": recipe.fields + moved,
            "relations": tuple(dict.fromkeys(relations)),
            "warnings": tuple(dict.fromkeys(recipe.warnings + block.warnings)),
        },
        context,
    )


def _built(intent: SceneIntent, context: ResolveContext, resolver: str) -> SceneRecipe:
    from agrirecipe.resolve._pipeline import build_recipe

    recipe, _steps = build_recipe(intent, context, resolver=resolver)
    return recipe


def _unclashed(
    block: SceneRecipe,
    recipe: SceneRecipe,
    own_seasons: Sequence[str | None],
    season_from_scene: bool,
) -> SceneRecipe:
    """New fields with ids and labels the scene does not use yet; a season taken from
    the scene is marked inferred, as generate() marks it."""
    used_ids = {f.id for f in recipe.fields}
    used_labels = {f.label for f in recipe.fields}
    renamed: dict[str, str] = {}
    fields: list[FieldSpec] = []
    for spec, own in zip(block.fields, own_seasons, strict=True):
        stem, _, number = spec.id.rpartition("_")
        count = int(number) if number.isdigit() else 1
        new_id = spec.id
        while new_id in used_ids:
            count += 1
            new_id = f"{stem}_{count}"
        used_ids.add(new_id)
        renamed[spec.id] = new_id
        label = spec.label
        n = 1
        while label in used_labels:
            n += 1
            label = f"{spec.label} {n}"
        used_labels.add(label)
        update: dict[str, Any] = {"id": new_id, "label": label}
        if own is None and season_from_scene and "season" in spec.stated:
            update["stated"] = tuple(a for a in spec.stated if a != "season")
            update["inferred"] = (*spec.inferred, "season")
        fields.append(spec.model_copy(update=update))
    relations = tuple(
        Relation(
            kind=r.kind,
            subject=renamed[r.subject],
            objects=tuple(renamed[o] for o in r.objects),
        )
        for r in block.relations
    )
    warnings = tuple(_renamed_warning(w, renamed) for w in block.warnings)
    return block.model_copy(
        update={"fields": tuple(fields), "relations": relations, "warnings": warnings}
    )


def _renamed_warning(warning: str, renamed: dict[str, str]) -> str:
    head, colon, tail = warning.partition(":")
    if colon and head in renamed:
        return f"{renamed[head]}:{tail}"
    return warning
