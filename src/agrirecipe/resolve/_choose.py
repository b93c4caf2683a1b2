"""The *choose* stage: a crop for every generic field (seeded, honouring categories,
distinctness and season), different varieties for "different" fields of one crop, and
the season of fields that state none.

Every choice is a :class:`TraceStep` naming what it chose from and the seed, so
``--explain`` shows why a generic "fruit orchard" became a cherry orchard.
"""

from __future__ import annotations

import random
from collections import Counter
from collections.abc import Sequence

from agrirecipe._errors import PromptError
from agrirecipe.recipe import Season
from agrirecipe.resolve._intent import FieldIntent, ResolveContext, SceneIntent, TraceStep

__all__ = ["choose_crops", "distinct_varieties", "scene_season_of"]

_SEASONS: tuple[Season, ...] = ("Spring", "Summer", "Fall", "Winter")


def _season_hint(intent: SceneIntent, field: FieldIntent) -> Season | None:
    if field.season is not None:
        return field.season
    if intent.season is not None:
        return intent.season
    stated = [f.season for f in intent.fields if f.season is not None]
    return Counter(stated).most_common(1)[0][0] if stated else None


def choose_crops(intent: SceneIntent, context: ResolveContext, steps: list[TraceStep]) -> list[str]:
    """A crop for every field: the named one, or a seeded choice for a generic field."""
    rng = random.Random(context.seed)
    hierarchy, knowledge = context.hierarchy, context.knowledge
    chosen: list[str | None] = [f.crop for f in intent.fields]
    for index, field in enumerate(intent.fields):
        if field.crop is not None:
            continue
        if field.crop_options:
            pool = list(field.crop_options)
        elif field.category is not None:
            pool = list(hierarchy.categories[field.category].crops)
        else:
            pool = list(hierarchy.crops)
        if field.distinct_group is not None:
            taken = {
                chosen[j]
                for j, other in enumerate(intent.fields)
                if j != index and other.distinct_group == field.distinct_group
            }
            pool = [crop for crop in pool if crop not in taken]
            if not pool:
                size = sum(1 for f in intent.fields if f.distinct_group == field.distinct_group)
                kind = field.category.lower() if field.category else "crops"
                raise PromptError(
                    f"asked for {size} different {kind}, but the asset hierarchy does not "
                    "hold that many",
                    stage="resolve",
                    path=f"fields[{index}]",
                    hint="ask for fewer different crops",
                )
        season = _season_hint(intent, field)
        preferred = pool
        if season is not None:
            preferred = [
                crop
                for crop in pool
                if (stages := knowledge.plausible_stages(crop, season))
                and (field.stage is None or field.stage in stages)
            ] or pool
        unused = [crop for crop in preferred if crop not in chosen] or preferred
        crop = rng.choice(unused)
        chosen[index] = crop
        steps.append(
            TraceStep(
                stage="choose",
                subject=field.text,
                detail=f"generic field: chose {crop} from {', '.join(unused)} "
                f"(seed {context.seed}"
                + (f"; crops plausible in {season} first)" if season else ")"),
            )
        )
    return [crop for crop in chosen if crop is not None]


def distinct_varieties(
    intent: SceneIntent, crops: Sequence[str], context: ResolveContext, steps: list[TraceStep]
) -> list[str | None]:
    """Different varieties for "different" fields of one named crop ("two different apple
    orchards"): the default variety first, then seeded choices among those not yet used.

    Returns a variety per field, None where the field's own or default variety stands.
    """
    rng = random.Random(context.seed)
    chosen: list[str | None] = [None] * len(intent.fields)
    groups: dict[tuple[int, str], list[int]] = {}
    for index, field in enumerate(intent.fields):
        if field.distinct_group is not None:
            groups.setdefault((field.distinct_group, crops[index]), []).append(index)
    for (_, crop), members in groups.items():
        if len(members) < 2:
            continue
        used = {intent.fields[i].variety for i in members if intent.fields[i].variety}
        names = [v.name for v in context.hierarchy.crop(crop).varieties]
        default = context.knowledge.default_variety(crop)
        for index in members:
            if intent.fields[index].variety is not None:
                continue
            unused = [v for v in names if v not in used]
            if not unused:
                break  # more fields than varieties: the rest keep the default
            variety = default if default in unused else rng.choice(unused)
            used.add(variety)
            chosen[index] = variety
            steps.append(
                TraceStep(
                    stage="choose",
                    subject=intent.fields[index].text,
                    detail=f"different {crop} fields: variety {variety} "
                    f"(not yet used of {', '.join(names)}; seed {context.seed})",
                )
            )
    return chosen


def scene_season_of(
    intent: SceneIntent, crops: Sequence[str], context: ResolveContext
) -> tuple[Season, str]:
    """The season of fields that state none: a scene shows one moment.

    The season stated for other fields; else the season in which the most stated
    stages are plausible (the first such field's typical season on a tie); else Summer.
    """
    stated = [f.season for f in intent.fields if f.season is not None]
    if stated:
        return Counter(stated).most_common(1)[0][0], "as the other fields"
    knowledge = context.knowledge
    staged = [
        (crops[i], f.variety or knowledge.default_variety(crops[i]), f.stage)
        for i, f in enumerate(intent.fields)
        if f.stage is not None
    ]
    if not staged:
        return "Summer", "scene default"
    crop, variety, stage = staged[0]
    typical = knowledge.typical_season(crop, stage, variety)
    order: list[Season] = [typical] + [s for s in _SEASONS if s != typical]

    def fits(season: Season) -> int:
        return sum(s in knowledge.plausible_stages(c, season, v) for c, v, s in staged)

    best = max(order, key=fits)  # max keeps the first of equals: the typical season
    return best, f"typical for the stated stage{'s' if len(staged) > 1 else ''}"
