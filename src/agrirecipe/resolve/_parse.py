"""The lexical reader: a prompt to a :class:`SceneIntent`, shared by the rules, embedding
and hybrid strategies.

Strategies differ in how they read words the lexicon does not know exactly
(typos, unseen names) and how they find the crops nearest to an unknown one:
they pass those two functions in. Everything else (decomposition, attribute
attachment, months and hemispheres, counts, refinements, relations, and the
errors for what cannot be honoured) is the same reading of the same words.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any, cast

from agrirecipe._errors import PromptError, UnknownCropError
from agrirecipe.recipe import HealthState, Season, Stage
from agrirecipe.resolve._attributes import (
    health_of,
    single_size,
    single_value,
    values_of,
)
from agrirecipe.resolve._casual import expand_casual
from agrirecipe.resolve._cues import apply_cues
from agrirecipe.resolve._decompose import (
    Clause,
    Mention,
    MentionBuilder,
    decompose,
    resolve_weak_varieties,
)
from agrirecipe.resolve._geometry import find_geometry, row_spec
from agrirecipe.resolve._intent import (
    Candidate,
    FieldIntent,
    Hemisphere,
    ResolveContext,
    SceneIntent,
    TraceStep,
)
from agrirecipe.resolve._lexicon import (
    Item,
    Lexicon,
    OtherCrop,
    Sense,
    Token,
    tokenize,
    vocabulary,
)
from agrirecipe.resolve._relations import coordinated, read_relations
from agrirecipe.resolve._scan import assign_roles, read_latitude, read_sizes
from agrirecipe.resolve._structure import (
    apply_corrections,
    apply_each_side,
    apply_plural_counts,
    apply_refinements,
    dissolve_plant_parts,
    merge_coreferences,
    promote_weak_varieties,
    raise_conflicts,
    share_leading_attributes,
    share_trailing_attributes,
)
from agrirecipe.resolve._zones import find_zones, zone_relations

__all__ = ["NOTHING_FOUND", "NearestCrops", "PromptReader", "UnknownWords"]

#: How the message of the error for a prompt that names no field begins.
NOTHING_FOUND = "no crop or field found in the prompt"

#: Reads unknown words in place (typos, unseen names); returns the new items and trace steps.
UnknownWords = Callable[[list[Item], Lexicon], tuple[list[Item], list[TraceStep]]]
#: The known crops nearest to a name the hierarchy does not hold, best first.
NearestCrops = Callable[[str, Sequence[str]], tuple[str, ...]]

_EXAMPLES = (
    "'a healthy Pink Lady apple orchard in summer', "
    "'two carrot fields next to a wheat field', 'some fruit and vegetable fields'"
)
#: The most fields one recipe holds (SceneRecipe.fields).
_MAX_FIELDS = 64
_ATTRIBUTE_ROLES = (
    "stage",
    "season",
    "month",
    "health",
    "negation",
    "size",
    "geometry",
    "cue",
    "zone",
    "all",
)


@dataclass
class _Field:
    """A field being assembled from its mention, its refinement and scene-wide words."""

    mention: Mention
    items: list[Item]
    interpretations: list[tuple[str, str | None, bool]] | None
    category: str | None
    plot: dict[str, Any] | None
    group: int | None = None
    sub: Mention | None = None


class PromptReader:
    """Reads prompts for one hierarchy and knowledge base with one strategy's word readers."""

    def __init__(
        self,
        context: ResolveContext,
        lexicon: Lexicon,
        *,
        unknown_words: UnknownWords,
        nearest_crops: NearestCrops,
        strategy: str,
    ) -> None:
        self.context = context
        self.lexicon = lexicon
        self.unknown_words = unknown_words
        self.nearest_crops = nearest_crops
        self.strategy = strategy
        self.crop_categories = {c.name: c.category for c in context.hierarchy.crops.values()}
        self.trace: list[TraceStep] = []
        self.warnings: list[str] = []

    # --- the whole reading ---

    def read(self, prompt: str) -> SceneIntent:
        """What ``prompt`` asks for."""
        if not isinstance(prompt, str) or not prompt.strip():
            raise PromptError(
                "the prompt is empty",
                stage="resolve",
                hint=f"describe the fields you want, e.g. {_EXAMPLES}",
            )
        text = expand_casual(prompt)
        tokens = tokenize(text)
        spans = [(m.first, m.last, Sense("geometry", m)) for m in find_geometry(tokens)]
        claimed = [False] * len(tokens)
        for first, last, _ in spans:
            claimed[first:last] = [True] * (last - first)
        spans += [(z.first, z.last, Sense("zone", z.zone)) for z in find_zones(tokens, claimed)]
        items = self._tag(tokens, sorted(spans, key=lambda span: span[0]))
        items, steps = self.unknown_words(items, self.lexicon)
        self.trace.extend(steps)
        assign_roles(items)
        prompt_latitude, latitude_text, items = read_latitude(text, items)
        items = read_sizes(items)
        self._reject_scenery(items)
        self._reject_other_crops(items)
        builder = MentionBuilder(self.crop_categories)
        clauses = decompose(items, builder)
        promote_weak_varieties(clauses, builder)
        apply_plural_counts(clauses, int(vocabulary()["plural_fields"]))
        for dropped in apply_corrections(clauses):
            self.trace.append(
                TraceStep(stage="decompose", subject=dropped, detail="replaced by a correction")
            )
        raise_conflicts(clauses)
        for dissolved in dissolve_plant_parts(clauses):
            self.trace.append(
                TraceStep(
                    stage="decompose", subject=dissolved, detail="the named fields' own fruit"
                )
            )
        share_leading_attributes(clauses)
        share_trailing_attributes(clauses)
        mentions = apply_refinements(clauses, self.crop_categories)
        mentions = merge_coreferences(clauses, mentions, builder)
        apply_each_side(clauses)
        scene_items = self._attach_loose(clauses, mentions)
        for mention in mentions:
            for sub in (mention, *mention.refinements):
                resolve_weak_varieties(sub)
        latitude, hemisphere, place = self._place(items, prompt_latitude, latitude_text)
        if not mentions:
            mentions = self._container_fields(items, clauses)
        self._reject_unknown_names(items, mentions)
        fields = self._expand(mentions)
        if len(fields) > _MAX_FIELDS:
            raise PromptError(
                f"the prompt asks for {len(fields)} fields; a scene holds at most {_MAX_FIELDS}",
                stage="resolve",
                hint="ask for fewer fields, or larger ones",
            )
        members: dict[int, list[int]] = {}
        for index, member in enumerate(fields):
            members.setdefault(id(member.mention), []).append(index)
            if member.sub is not None and member.sub is not member.mention:
                members.setdefault(id(member.sub), []).append(index)
        relations = read_relations(clauses, members, self.trace, self.warnings)
        said = {(r.kind, r.subject, r.objects) for r in relations}
        relations += [
            r
            for r in zone_relations([f.items for f in fields])
            if (r.kind, r.subject, r.objects) not in said
        ]
        scene_season = self._apply_scene_items(scene_items, fields, hemisphere)
        intents = [self._field_intent(f, hemisphere) for f in fields]
        for index, intent in enumerate(intents):
            self.trace.append(
                TraceStep(
                    stage="decompose",
                    subject=f"field {index + 1}",
                    detail=f"{intent.text!r} -> " + _describe(intent),
                )
            )
        scenery = sorted({i.raw for i in items if "scenery" in i.data and i.role == "filler"})
        if scenery:
            self.trace.append(
                TraceStep(
                    stage="decompose",
                    subject="not used",
                    detail="scenery and purpose, not fields: "
                    + ", ".join(repr(w) for w in scenery),
                )
            )
        ignored = sorted({i.raw for i in items if i.role == "non_agricultural"})
        if ignored:
            self.warnings.append(
                "ignored " + ", ".join(repr(w) for w in ignored) + ": agrirecipe builds crop "
                "fields, not other scenery"
            )
        return SceneIntent(
            prompt=prompt,
            fields=tuple(intents),
            relations=tuple(relations),
            season=scene_season,
            hemisphere=hemisphere,
            latitude_deg=latitude,
            place=place,
            warnings=tuple(self.warnings),
            trace=tuple(self.trace),
            resolver=self.strategy,
        )

    def _tag(self, tokens: Sequence[Token], spans: Sequence[tuple[int, int, Sense]]) -> list[Item]:
        """The lexicon's items, with each span read before it (a stated geometry such as
        "76 cm apart", a zone such as "along the top") as one item."""
        items: list[Item] = []
        index = 0
        for first, last, sense in spans:
            items.extend(self.lexicon.tag(tokens[index:first]))
            items.append(Item(tuple(tokens[first:last]), (sense,)))
            index = last
        items.extend(self.lexicon.tag(tokens[index:]))
        return items

    # --- unknown and non-agricultural requests ---

    def _reject_scenery(self, items: Sequence[Item]) -> None:
        """ "a parking lot with trees": non-agricultural scenery with plants in general only.

        Such a prompt names no crop, category, field or farm: the plant words in it
        (trees, grass, bushes) are the scenery's, not a request for a crop field.
        """
        scenery = [item for item in items if item.role == "non_agricultural"]
        if not scenery:
            return
        generic = {str(word) for word in vocabulary()["generic_vegetation"]}
        for item in items:
            if item.role in ("head", "weak_variety", "container"):
                return
            if item.role in ("plot", "other_crop") and item.norm not in generic:
                return
        raise PromptError(
            f"{scenery[0].raw!r} is not an agricultural scene, and the prompt names no crop "
            "or field",
            stage="resolve",
            hint="agrirecipe builds crop fields, orchards, vineyards and farms; name a crop, "
            f"a variety or a kind of field, e.g. {_EXAMPLES}",
        )

    def _reject_other_crops(self, items: Sequence[Item]) -> None:
        for item in items:
            if item.role != "other_crop":
                continue
            other: OtherCrop = item.senses_of("other_crop")[0].value
            if other.variety_of is not None:
                names = [v.name for v in self.context.hierarchy.crop(other.variety_of).varieties]
                article = "an" if other.variety_of[0] in "AEIOU" else "a"
                raise UnknownCropError(
                    f"{item.raw!r} is {article} {other.variety_of} variety the asset hierarchy "
                    "does not hold",
                    requested=item.raw,
                    nearest=_by_spelling(item.raw, names),
                    stage="resolve",
                    hint=f"{other.variety_of} varieties: " + ", ".join(names),
                )
            nearest = self.nearest_crops(other.name, other.like)
            raise UnknownCropError(
                f"{item.raw!r} is not a crop of the asset hierarchy ({other.name} is unknown)",
                requested=item.raw,
                nearest=nearest,
                stage="resolve",
            )

    def _reject_unknown_names(self, items: Sequence[Item], mentions: Sequence[Mention]) -> None:
        """Unknown words where a crop or variety name belongs are unknown crops, not fillers."""
        position = {id(item): index for index, item in enumerate(items)}
        for mention in mentions:
            for sub in (mention, *mention.refinements):
                plots = [h for h in sub.heads if h.role == "plot"]
                named = sub.has_crop or sub.category is not None
                if plots and not named:
                    word = _word_before(items, position.get(id(plots[0])))
                    word = word or _word_after_of(items, position.get(id(plots[0])))
                    if word is not None:
                        self._unknown_crop(word.raw)
                crops = [h for h in sub.heads if h.role == "head" and h.senses_of("crop")]
                if crops and not any(h.senses_of("variety") for h in sub.heads):
                    word = _word_before(items, position.get(id(crops[0])))
                    if word is not None and word.tokens[0].capitalised and position[id(word)] > 0:
                        crop = str(crops[0].senses_of("crop")[0].value)
                        varieties = [v.name for v in self.context.hierarchy.crop(crop).varieties]
                        raise UnknownCropError(
                            f"{word.raw!r} is not one of the {crop} varieties of the hierarchy",
                            requested=f"{word.raw} {crops[0].raw}",
                            nearest=_by_spelling(word.raw, varieties),
                            stage="resolve",
                            hint=f"{crop} varieties: " + ", ".join(varieties),
                        )

    def _unknown_crop(self, word: str) -> None:
        nearest = self.nearest_crops(word, ())
        raise UnknownCropError(
            f"{word!r} is not a crop of the asset hierarchy",
            requested=word,
            nearest=nearest,
            stage="resolve",
        )

    def _container_fields(self, items: Sequence[Item], clauses: Sequence[Clause]) -> list[Mention]:
        """No field named: "a mixed farm" stands for a few fields; anything else is an error."""
        non_agricultural = [item.raw for item in items if item.role == "non_agricultural"]
        if non_agricultural:
            raise PromptError(
                f"{non_agricultural[0]!r} is not an agricultural scene",
                stage="resolve",
                hint=f"agrirecipe builds fields of crops, e.g. {_EXAMPLES}",
            )
        containers = [item for item in items if item.role == "container"]
        if not containers:
            words = [i.raw for i in items if i.role == "unknown"]
            detail = (
                f" (did not understand {', '.join(repr(w) for w in words[:5])})" if words else ""
            )
            raise PromptError(
                f"{NOTHING_FOUND}{detail}",
                stage="resolve",
                hint="name a crop, a variety or a kind of field, e.g. " + _EXAMPLES,
            )
        mention = Mention(items=[i for c in clauses for i in c.loose], clause=0)
        mention.heads.append(containers[0])
        mention.count = int(vocabulary()["containers"]["default_fields"])
        numbers = [i for i in mention.items if i.role in ("number", "quantity")]
        if numbers and numbers[-1].norm not in ("a", "an"):
            mention.count = int(float(numbers[-1].data["value"]))
        mention.distinct = True
        for clause in clauses:
            clause.loose = []
        self.trace.append(
            TraceStep(
                stage="decompose",
                subject=containers[0].raw,
                detail=f"no crop named: {mention.count} fields of different crops",
            )
        )
        return [mention]

    # --- structure ---

    def _attach_loose(self, clauses: Sequence[Clause], mentions: Sequence[Mention]) -> list[Item]:
        """Give each head-less clause's attributes to its field(s); return scene-wide items."""
        scene: list[Item] = []
        for position, clause in enumerate(clauses):
            _detach_trailing_all(clause)
            if position and mentions:
                _apply_group_words(clause.loose, coordinated(clauses, position))
            attributes = [i for i in clause.loose if i.role in _ATTRIBUTE_ROLES]
            if not attributes or not mentions:
                continue
            before = [m for c in clauses[:position] for m in c.mentions]
            refined = clauses[position - 1].refined_parent if position else None
            after = [m for c in clauses[position + 1 :] for m in c.mentions]
            says_all = any(i.role == "all" for i in attributes)
            seasons = [i for i in attributes if i.role in ("season", "month")]
            others = [i for i in attributes if i.role not in ("season", "month", "all")]
            if says_all:
                scene.extend(attributes)
                continue
            if not before or (len(mentions) > 1 and not after):
                # Opening words ("In autumn, ...") or closing words after several fields:
                # a time of year belongs to the whole scene.
                scene.extend(seasons)
                seasons = []
            if (
                before
                and not after
                and len(before) > 1
                and any(_says_all_plants(i) for i in others)
            ):
                # "A next to B, young plants": closing words about "the plants" describe all.
                for target in before:
                    target.items.extend(others)
                continue
            targets: list[Mention] = []
            forward = after[0] if after else None
            next_link = clauses[position + 1].link if position + 1 < len(clauses) else None
            starts_bare = (
                position + 1 < len(clauses)
                and bool(clauses[position + 1].items)
                and clauses[position + 1].items[0].role not in ("number", "quantity", "filler")
            )
            if not before or (
                next_link is not None
                and next_link.role == "conjunction"
                and forward is not None
                and forward.clause == position + 1
                and starts_bare
            ):
                targets = [forward] if forward is not None else []
            elif refined is not None and refined.refinements:
                targets = [refined.refinements[-1]]
            else:
                targets = coordinated(clauses, position)
            # Rows and spacings describe one plot: the nearest field named ("each" shares them).
            geometry = [i for i in others if i.role == "geometry"]
            others = [i for i in others if i.role != "geometry"]
            for target in targets:
                target.items.extend(seasons + others)
            if geometry and targets:
                targets[-1].items.extend(geometry)
        return scene

    def _place(
        self, items: Sequence[Item], prompt_latitude: float | None, latitude_text: str | None
    ) -> tuple[float | None, Hemisphere | None, str | None]:
        place = next((i for i in items if i.role == "place"), None)
        hemisphere_item = next((i for i in items if i.role == "hemisphere"), None)
        latitude: float | None = None
        name: str | None = None
        if prompt_latitude is not None:
            latitude, name = prompt_latitude, latitude_text
        elif place is not None:
            name, latitude = place.data["value"]
        elif hemisphere_item is not None:
            latitude = float(hemisphere_item.data["value"][1])
            name = hemisphere_item.raw
        if self.context.latitude_deg is not None:
            if latitude is not None and (latitude < 0) != (self.context.latitude_deg < 0):
                self.warnings.append(
                    f"the prompt says {name!r} but latitude_deg={self.context.latitude_deg:g} "
                    "was given; the argument wins"
                )
            latitude = self.context.latitude_deg
        hemisphere: Hemisphere | None = None
        if latitude is not None:
            hemisphere = "south" if latitude < 0 else "north"
            self.trace.append(
                TraceStep(
                    stage="normalise",
                    subject=name or "latitude_deg",
                    detail=f"latitude {latitude:g}, {hemisphere}ern hemisphere",
                )
            )
        return latitude, hemisphere, name

    # --- fields ---

    def _expand(self, mentions: Sequence[Mention]) -> list[_Field]:
        fields: list[_Field] = []
        groups: dict[int, int] = {}
        next_group = 0
        for mention in mentions:
            count = max(mention.count or 1, len(mention.refinements))
            members: list[_Field] = []
            for index in range(count):
                sub = (
                    mention.refinements[index] if index < len(mention.refinements) else mention.rest
                )
                members.append(self._member(mention, sub))
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

    def _member(self, mention: Mention, sub: Mention | None) -> _Field:
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
                [i for i in items if i.role not in _ATTRIBUTE_ROLES]
                + sub.items
                + [i for i in items if i.role in _ATTRIBUTE_ROLES]
            )
        return _Field(mention, items, interpretations, category, plot, sub=sub)

    def _apply_scene_items(
        self, scene_items: Sequence[Item], fields: Sequence[_Field], hemisphere: Hemisphere | None
    ) -> Season | None:
        if not scene_items:
            return None
        says_all = any(i.role == "all" for i in scene_items)
        seasons = values_of(scene_items, ("season", "month"), hemisphere)
        if len(set(seasons)) > 1:
            raise PromptError(
                "the scene is said to be in " + " and ".join(sorted(set(seasons))),
                stage="resolve",
                hint="a scene shows one moment: state one season (fields may differ if "
                "each says its own)",
            )
        if says_all:
            for item in scene_items:
                if item.role not in ("season", "month", "all"):
                    for member in fields:
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

    def _field_intent(self, member: _Field, hemisphere: Hemisphere | None) -> FieldIntent:
        text = member.mention.text
        for sub in member.mention.refinements or []:
            if any(item in member.items for item in sub.items):
                text = f"{text} ({sub.text})"
        stage: Stage | None = single_value(member.items, ("stage",), "stage", text, hemisphere)  # type: ignore[assignment]
        season: Season | None = single_value(
            member.items, ("season", "month"), "season", text, hemisphere
        )  # type: ignore[assignment]
        health: HealthState | None = health_of(member.items, text)
        stage, season, health = self._cues(member, text, stage, season, health)
        sizes = [item.data["size"] for item in member.items if item.role == "size"]
        size = single_size(sizes, text)
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
        if category is not None:
            options = tuple(o for o in options if self.crop_categories.get(o) == category)
        if crop is None and len(options) == 1:
            crop = options[0]
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

    def _cues(
        self,
        member: _Field,
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
        member: _Field,
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


# --- helpers ---


_ALL_PLANTS = frozenset({"plants", "trees", "vines", "crops", "bushes"})


def _says_all_plants(item: Item) -> bool:
    """'young plants', 'healthy trees': an attribute phrase about the plants in general."""
    words = item.norm.split()
    return len(words) > 1 and words[-1] in _ALL_PLANTS


def _detach_trailing_all(clause: Clause) -> None:
    """'cherry trees and apple trees both carrying ripe fruit': after the last field of a
    clause, "both"/"all" and the words after it describe every field, not only that one."""
    if not clause.mentions:
        return
    mention = clause.mentions[-1]
    last_head = max(h.start for h in mention.heads)
    marker = next(
        (
            i
            for i in sorted(mention.items, key=lambda i: i.start)
            if i.role == "all" and i.start > last_head
        ),
        None,
    )
    if marker is None:
        return
    moved = [i for i in mention.items if i.start >= marker.start and i not in mention.heads]
    if not any(i.role in _ATTRIBUTE_ROLES for i in moved if i is not marker):
        return
    mention.items = [i for i in mention.items if i not in moved]
    clause.loose = [*clause.loose, *moved]


def _apply_group_words(loose: Sequence[Item], group: Sequence[Mention]) -> None:
    """Words about the fields listed just before: "grains and veggies: two of each" counts
    each of them; "five fields, each a different crop" makes them different crops."""
    roles = [i.role for i in loose if i.role != "filler"]
    if (
        len(roles) >= 2
        and roles[0] == "number"
        and roles[-1] == "all"
        and (roles[1:-1] in ([], ["of"]))
    ):
        number = next(i for i in loose if i.role == "number")
        count = float(number.data.get("value", 1))
        if count == int(count) and 1 <= count <= 64:
            for mention in group:
                if mention.count is None or mention.count == 1:
                    mention.count = int(count)
    if any(i.role == "distinct" for i in loose):
        for mention in group:
            if (mention.count or 1) > 1:
                mention.distinct = True
                mention.distinct_crops = not mention.has_crop


def _check_distinct(mention: Mention, members: Sequence[_Field]) -> None:
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


def _word_before(items: Sequence[Item], index: int | None) -> Item | None:
    if index is None or index == 0:
        return None
    word = items[index - 1]
    return word if word.role == "unknown" else None


def _word_after_of(items: Sequence[Item], index: int | None) -> Item | None:
    if index is None or index + 2 >= len(items):
        return None
    if items[index + 1].role == "of" and items[index + 2].role == "unknown":
        return items[index + 2]
    return None


def _by_spelling(word: str, names: Sequence[str], limit: int = 3) -> tuple[str, ...]:
    from rapidfuzz import fuzz, process

    matches = process.extract(word, list(names), scorer=fuzz.WRatio, limit=limit)
    return tuple(str(m[0]) for m in matches)


def _describe(intent: FieldIntent) -> str:
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
