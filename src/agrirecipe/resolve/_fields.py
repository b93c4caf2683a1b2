"""Fields from mentions: how many each mention stands for, and each field's attributes.

The last part of the prompt reader (:class:`~agrirecipe.resolve._parse.PromptReader`
inherits :class:`FieldReading`): a mention is expanded into its fields ("three
carrot fields" -> three), scene-wide words are shared out, and every field
becomes a :class:`FieldIntent` from its words: stage, season, health (stated,
else from visual cues), size and stated row geometry.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any, cast

from agrirecipe._errors import PromptError
from agrirecipe.recipe import HealthState, Season, Stage
from agrirecipe.resolve._attributes import health_of, single_size, single_value, values_of
from agrirecipe.resolve._cues import apply_cues
from agrirecipe.resolve._geometry import row_spec
from agrirecipe.resolve._intent import (
    Candidate,
    FieldIntent,
    Hemisphere,
    ResolveContext,
    RowSpec,
    SizeIntent,
    TraceStep,
)
from agrirecipe.resolve._lexicon import Item
from agrirecipe.resolve._mentions import Mention

__all__ = [
    "ATTRIBUTE_ROLES",
    "FieldDraft",
    "FieldReading",
    "describe_intent",
    "give_respectively",
    "plot_of_the_plants",
]

#: The largest side a planting grid said like a size can have ("4.5 x 2.5 m").
_GRID_MAX_M = 12.0
#: Stated spacings that leave no room for a grid said like a size.
_SPACED = frozenset(
    {"row_spacing_m", "in_row_spacing_m", "bed_width_m", "alley_m", "plants_per_ha"}
)

#: Roles of the words that describe a field (not name it).
ATTRIBUTE_ROLES = (
    "stage",
    "season",
    "month",
    "health",
    "negation",
    "size",
    "geometry",
    "cue",
    "zone",
    "same_size",
    "same_spacing",
    "all",
)


@dataclass
class FieldDraft:
    """A field being assembled from its mention, its refinement and scene-wide words."""

    mention: Mention
    items: list[Item]
    interpretations: list[tuple[str, str | None, bool]] | None
    category: str | None
    plot: dict[str, Any] | None
    group: int | None = None
    sub: Mention | None = None
    #: Which of its mention's fields this is, and how many the mention stands for.
    place: tuple[int, int] = (0, 1)


class FieldReading:
    """Mentions -> fields -> :class:`FieldIntent` (mixed into the prompt reader)."""

    context: ResolveContext
    crop_categories: dict[str, str]
    trace: list[TraceStep]
    warnings: list[str]

    def _expand(self, mentions: Sequence[Mention]) -> list[FieldDraft]:
        fields: list[FieldDraft] = []
        groups: dict[int, int] = {}
        next_group = 0
        for mention in mentions:
            count = max(mention.count or 1, len(mention.refinements))
            members: list[FieldDraft] = []
            for index in range(count):
                sub = (
                    mention.refinements[index] if index < len(mention.refinements) else mention.rest
                )
                members.append(self._member(mention, sub))
                members[-1].place = (index, count)
            if mention.distinct and count > 1:
                if mention.distinct_crops:
                    _check_distinct(mention, members)
                for member in members:
                    member.group = next_group
                next_group += 1
            if mention.other and fields:
                group = next((f.group for f in fields if f.group is not None), None)
                if group is None:
                    group, next_group = next_group, next_group + 1
                for member in fields + members:
                    if member.group is None or member.group == group:
                        member.group = group
                    else:
                        groups[member.group] = group
            fields.extend(members)
        for member in fields:
            while member.group is not None and member.group in groups:
                member.group = groups[member.group]
        return fields

    def _member(self, mention: Mention, sub: Mention | None) -> FieldDraft:
        interpretations = mention.interpretations
        category, plot = mention.category, mention.plot
        items = list(mention.items)
        if sub is not None:
            if sub.interpretations is not None:
                crops = {c for c, _, _ in interpretations or ()}
                narrowed = [i for i in sub.interpretations if not crops or i[0] in crops]
                interpretations = narrowed or sub.interpretations
            category = sub.category or category
            if sub.plot is not None and sub.plot["narrows"]:
                plot = sub.plot
            items = (
                [i for i in items if i.role not in ATTRIBUTE_ROLES]
                + sub.items
                + [i for i in items if i.role in ATTRIBUTE_ROLES]
            )
        return FieldDraft(mention, items, interpretations, category, plot, sub=sub)

    def _apply_scene_items(
        self,
        scene_items: Sequence[Item],
        fields: Sequence[FieldDraft],
        hemisphere: Hemisphere | None,
    ) -> Season | None:
        if not scene_items:
            return None
        # a measure only reaches the scene when it was said of every field ("each")
        says_all = any(i.role in ("all", "geometry") for i in scene_items)
        seasons = values_of(scene_items, ("season", "month"), hemisphere)
        if len(set(seasons)) > 1:
            raise PromptError(
                "the scene is said to be in " + " and ".join(sorted(set(seasons))),
                stage="resolve",
                hint="a scene shows one moment: state one season (fields may differ if "
                "each says its own)",
            )
        if says_all:
            # "cabbages with lesions, and onions, all healthy": what a field says of
            # itself wins over what is said of all ("all fruiting and starting to
            # ripen" is still said whole)
            own_roles = [{own.role for own in member.items} for member in fields]
            for item in scene_items:
                if item.role not in ("season", "month", "all"):
                    for member, roles in zip(fields, own_roles, strict=True):
                        if item.role not in ("health", "stage") or item.role not in roles:
                            member.items.append(item)
            for member in fields:
                own = values_of(member.items, ("season", "month"), hemisphere)
                if own and seasons and own[0] != seasons[0]:
                    raise PromptError(
                        f"{member.mention.text!r} is said to be in {own[0]} but all fields "
                        f"in {seasons[0]}",
                        stage="resolve",
                        hint="state the season once for all fields or per field",
                    )
        return cast(Season, seasons[0]) if seasons else None

    def _field_intent(
        self,
        member: FieldDraft,
        hemisphere: Hemisphere | None,
        scene_season: Season | None = None,
    ) -> FieldIntent:
        text = member.mention.text
        if member.sub is not None and member.sub is not member.mention and member.sub.items:
            text = f"{text} ({member.sub.text})"
        stage: Stage | None = single_value(member.items, ("stage",), "stage", text, hemisphere)  # type: ignore[assignment]
        season: Season | None = single_value(
            member.items, ("season", "month"), "season", text, hemisphere
        )  # type: ignore[assignment]
        health: HealthState | None = health_of(member.items, text)
        # a season said for the whole scene ("Frosty blue April morning") beats a cue
        stage, said_season, health = self._cues(member, text, stage, season or scene_season, health)
        season = season if said_season == scene_season and season is None else said_season
        sizes = [item.data["size"] for item in member.items if item.role == "size"]
        rows = row_spec(member.items, text)
        interpretations = member.interpretations or []
        strong = [i for i in interpretations if not i[2]] or []
        crop = variety = None
        if strong:
            crop = strong[0][0]
            varieties = {v for c, v, _ in strong if c == crop and v is not None}
            variety = varieties.pop() if len(varieties) == 1 else None
            self._trace_choice(member, crop, variety, strong)
        plot = member.plot or {}
        options: tuple[str, ...] = tuple(plot.get("options", ()))
        category = member.category
        if category is None and not strong:
            category = plot.get("category")  # "a vineyard, a vegetable garden"
        if category is not None:
            options = tuple(o for o in options if self.crop_categories.get(o) == category)
        if crop is None and any(
            i.data["cue"].deciduous_only for i in member.items if "cue" in i.data
        ):
            # "an orchard, bare branches white with hoarfrost": a tree that drops its leaves
            deciduous = tuple(
                o for o in options if self.context.knowledge.crop_file(o).leaf_habit == "deciduous"
            )
            options = deciduous or options
        if crop is None and len(options) == 1:
            crop = options[0]
        index, count = member.place
        said_of_all = [i for i in member.mention.items if i.role == "size"]
        if (
            count > 1
            and len(sizes) == len(said_of_all) == count
            and len({s.text for s in sizes}) == count
        ):
            # "two apple orchards, 100 x 50 m and 60 x 40 m", "Two orange blocks -
            # conventional 7.2 x 3.8 m and super-high-density 3.7 x 1.2 m": one each, in order
            sizes = [sizes[index]]
        sizes, rows, fitting = self._planting_grid(sizes, rows, (crop,) if crop else options, text)
        if crop is None and fitting:
            # "a fruit tree block (3.5 m x 1 m)": the crops that grid fits
            options = tuple(o for o in options if o in fitting)
            crop = options[0] if len(options) == 1 else None
        size = single_size(sizes, text)
        heads = [h for h in member.mention.heads if h.role in ("head", "plot")]
        mention_words = " ".join(h.raw for h in heads) or None
        noun = plot.get("noun") if plot else None
        return FieldIntent(
            text=text,
            mention=mention_words,
            noun=noun,
            category=category if crop is None else self.crop_categories.get(crop),
            crop=crop,
            variety=variety,
            stage=stage,
            season=season,
            health=health,
            size=size,
            rows=rows,
            generic=crop is None,
            crop_options=options if crop is None else (),
            distinct_group=member.group,
        )

    def _planting_grid(
        self,
        sizes: list[SizeIntent],
        rows: RowSpec | None,
        crops: Sequence[str],
        text: str,
    ) -> tuple[list[SizeIntent], RowSpec | None, tuple[str, ...]]:
        """'Cripps Pink 3.4 x 1.0 m, 18 rows', 'Savoy cabbage, 60 x 40 cm': two lengths
        that fit the crop's row and plant spacing, and no field, are its planting grid
        (rows that far apart, plants that far apart in the row), not the field's size.
        Of several crops the field may be, the grid need fit only some: those are
        returned (empty when no grid was read)."""
        spaced = _SPACED & rows.stated().keys() if rows is not None else set()
        density = rows.plants_per_ha if rows is not None and spaced == {"plants_per_ha"} else None
        if not crops or (spaced and density is None):
            return sizes, rows, ()
        for size in sizes:
            width, length = size.width_m, size.length_m
            if width is None or length is None or max(width, length) > _GRID_MAX_M:
                continue
            if density is not None and abs(density * width * length / 10_000 - 1) > 0.02:
                continue  # "3 m by 3 m, 1,111 plants per hectare": the grid the density is
            fitting = tuple(crop for crop in crops if self._fits_grid(crop, width, length))
            if fitting:
                said = rows.stated() if rows is not None else {}
                grid = RowSpec(
                    **said,
                    row_spacing_m=width,
                    in_row_spacing_m=length,
                    text="; ".join(t for t in (rows.text if rows else "", size.text) if t),
                )
                self.trace.append(
                    TraceStep(
                        stage="decompose",
                        subject=size.text,
                        detail=f"the planting grid of {text!r} (rows {width:g} m apart, "
                        f"plants {length:g} m apart), not its size",
                    )
                )
                return [s for s in sizes if s is not size], grid, fitting
        return sizes, rows, ()

    def _fits_grid(self, crop: str, row: float, plant: float) -> bool:
        planting = self.context.knowledge.crop_file(crop).planting
        rows_low, rows_high = planting.row_spacing_m.range or (planting.row_spacing_m.value,) * 2
        plants_low, plants_high = (
            planting.in_row_spacing_m.range or (planting.in_row_spacing_m.value,) * 2
        )
        return rows_low / 2 <= row <= rows_high * 2 and plants_low / 2 <= plant <= plants_high * 2

    def _cues(
        self,
        member: FieldDraft,
        text: str,
        stage: Stage | None,
        season: Season | None,
        health: HealthState | None,
    ) -> tuple[Stage | None, Season | None, HealthState | None]:
        """Fill unstated attributes from what the field looks like ("curled leaves")."""
        strong = [i for i in member.interpretations or [] if not i[2]]
        deciduous = (
            self.context.knowledge.crop_file(strong[0][0]).leaf_habit == "deciduous"
            if strong
            else None
        )
        reading = apply_cues(
            [i for i in member.items if "cue" in i.data],
            {"stage": stage, "season": season, "health": health},
            deciduous=deciduous,
            field_text=text,
        )
        self.warnings.extend(reading.warnings)
        for used in reading.used:
            self.trace.append(TraceStep(stage="normalise", subject=text, detail=f"cue {used}"))
        values = reading.values
        return (
            cast(Stage | None, stage or values.get("stage")),
            cast(Season | None, season or values.get("season")),
            cast(HealthState | None, health or values.get("health")),
        )

    def _trace_choice(
        self,
        member: FieldDraft,
        crop: str,
        variety: str | None,
        strong: Sequence[tuple[str, str | None, bool]],
    ) -> None:
        candidates: list[Candidate] = []
        for head in member.mention.heads:
            score = head.fuzzy_score if head.fuzzy_score is not None else 100.0
            source = head.data.get("source", "fuzzy" if head.fuzzy_score is not None else "lexicon")
            for c, v, _ in strong:
                value = f"{c}/{v}" if v else c
                if all(x.value != value for x in candidates):
                    candidates.append(Candidate(value=value, score=score, source=source))
        self.trace.append(
            TraceStep(
                stage="normalise",
                subject=member.mention.text,
                detail=f"crop {crop}" + (f", variety {variety}" if variety else ""),
                candidates=tuple(candidates),
            )
        )


def _check_distinct(mention: Mention, members: Sequence[FieldDraft]) -> None:
    """'three different fruit crops, all of them apples': 'different' crops named the same.

    Two members are the same when both are fixed to one crop and their varieties
    do not tell them apart ("two different fruits: Gala and Fuji" are different).
    """
    fixed: dict[str, list[str | None]] = {}
    for member in members:
        strong = {(c, v) for c, v, weak in member.interpretations or () if not weak}
        crops = {c for c, _ in strong}
        if len(crops) == 1:
            named = {v for _, v in strong}
            fixed.setdefault(crops.pop(), []).append(named.pop() if len(named) == 1 else None)
    for crop, varieties in fixed.items():
        if len(varieties) > 1 and (None in varieties or len(set(varieties)) < len(varieties)):
            raise PromptError(
                f"{mention.text!r} asks for {len(members)} different crops, but the prompt "
                f"makes {len(varieties)} of them {crop}",
                stage="resolve",
                hint="name a different crop for each field, or drop 'different' to have "
                f"several {crop.lower()} fields",
            )


def describe_intent(intent: FieldIntent) -> str:
    parts = [intent.variety or "", intent.crop or f"any {intent.category or 'crop'}"]
    words = " ".join(p for p in parts if p)
    stated = [
        f"{name}={value}"
        for name, value in (
            ("stage", intent.stage),
            ("season", intent.season),
            ("health", intent.health),
        )
        if value is not None
    ]
    if intent.size is not None:
        stated.append(f"size={intent.size.text}")
    if intent.crop_options:
        stated.append("options=" + "/".join(intent.crop_options))
    if intent.distinct_group is not None:
        stated.append(f"distinct group {intent.distinct_group}")
    return words + (f" ({', '.join(stated)})" if stated else "")


def _share(item: Item) -> tuple[int, int, int] | None:
    """An item's place in a "respectively" list: (index, how many, the list's start)."""
    if item.role == "geometry":
        shares = [m.share for m in item.data["geometry"] if m.share is not None]
        return shares[0] if shares else None
    share = item.data.get("share") if item.role == "size" else None
    return cast(tuple[int, int, int], share) if share is not None else None


def give_respectively(fields: Sequence[FieldDraft]) -> None:
    """'Gala and Fuji blocks, 3.4 m and 3.5 m row spacing respectively', '..., 30x40m and
    30x60m resp.': each value of a "respectively" list goes to one of the fields named up
    to the last field that holds the list, in order (the first value to the first)."""
    lists: dict[int, list[Item]] = {}
    holders: dict[int, int] = {}
    for position, field in enumerate(fields):
        for item in field.items:
            share = _share(item)
            if share is not None:
                if item not in lists.setdefault(share[2], []):
                    lists[share[2]].append(item)
                holders[share[2]] = position
    for start, items in lists.items():
        count = cast(tuple[int, int, int], _share(items[0]))[1]
        named = fields[: holders[start] + 1]
        if len(named) < count:
            raise PromptError(
                f"{' '.join(i.raw for i in items)!r} gives {count} values 'respectively', "
                f"but only {len(named)} field(s) are named before it",
                stage="resolve",
                hint="name one field for each value, e.g. 'Gala and Fuji blocks, 3.4 m and "
                "3.5 m row spacing respectively'",
            )
        for field in fields:
            field.items[:] = [i for i in field.items if i not in items]
        for item in items:
            index = cast(tuple[int, int, int], _share(item))[0]
            named[len(named) - count + index].items.append(item)


def plot_of_the_plants(mentions: Sequence[Mention], tag: Callable[[str], list[Item]]) -> None:
    """'fruit trees at 5 m spacing', 'fruit-tree rows at 5 m': the plants' word that a
    spacing took ("trees at 5 m") still says the plot with the category before it ("fruit
    trees": trees, not bananas), for a field that names no crop and no plot."""
    for mention in mentions:
        if mention.plot is not None or mention.has_crop:
            continue
        items = mention.items
        for head, after in itertools.pairwise(items):
            if head.role != "head" or "geometry" not in after.data or not after.raw.strip():
                continue
            words = after.raw.replace("-", " ").split()
            said = tag(f"{head.norm} {words[0]}")
            plots = [s.value for s in said[0].senses if s.kind == "plot"] if len(said) == 1 else []
            if len(plots) == 1 and plots[0]["narrows"]:
                mention.plot = plots[0]
                break
