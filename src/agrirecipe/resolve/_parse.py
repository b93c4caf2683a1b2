"""The lexical reader: a prompt to a :class:`SceneIntent`, shared by the rules, embedding
and hybrid strategies.

Strategies differ in how they read words the lexicon does not know exactly
(typos, unseen names) and how they find the crops nearest to an unknown one:
they pass those two functions in. Everything else (decomposition, attribute
attachment, months and hemispheres, counts, refinements, relations, and the
errors for what cannot be honoured) is the same reading of the same words.

The reading, in order (:meth:`PromptReader.read`; each pass lives in the module
named for what it reads, its words in the data file beside it):

====  ==========================================  ===============================
step  pass                                        module (data)
====  ==========================================  ===============================
1     texting forms become words; value lists     ``_casual`` (casual.yaml),
      and counts said once; labels, members       ``_lists`` (value_lists.yaml),
      named again, walks and sides said in        ``_labels``, ``_sides``,
      other words; plots said to touch; counts    ``_members``, ``_side_phrases``,
      of a crop's rows or plants                  ``_neighbours``, ``_counted_crops``
2     words, numbers and marks                    ``_lexicon.tokenize``
3     stated row geometry (and measures no        ``_geometry`` (geometry.yaml)
      recipe holds, as not used)
4     zones of a farm                             ``_zones`` (zones.yaml)
5     phrases and their senses; visual cues,      ``_lexicon``, built by
      scenery and purpose words                   ``_lexicon_build`` (vocabulary.yaml,
                                                  cues.yaml, scenery.yaml, ...)
6     typos and unseen names                      the strategy's reader
7     each phrase's role; a season, stage or      ``_scan``, ``_retractions``,
      health taken back; purposes; latitudes,     ``_purposes``, ``_sizes``
      heights and sizes
7b    what single words are in their place        ``_words``, ``_numbers``,
      (numbers that count no fields, labels,      ``_looks``, ``_plot_words``
      negations, colours and looks, plot words    (vocabulary.yaml
      of no field)                                ``reader_words``)
8     scenery-only prompts, unknown crops         ``_refusals``
9     clauses and mentions; contradictions        ``_decompose`` (data in
      inside a noun phrase                        ``_mentions``),
                                                  ``_contradictions``
10    weak variety names; mentions taken back    ``_weak_varieties``,
      (corrections, alternatives, choices left    ``_retractions``,
      open, negations); counts, shared            ``_counts``, ``_structure``,
      attributes; the members a plural lists;     ``_refinements``, ``_listing``,
                                                  ``_listed_members``,
      descriptions of plants named;               ``_descriptions``, ``_own_crop``,
      back-references (and where a mention is     ``_coreference``,
      placed); plots said with a field;           ``_back_references``,
      list headings, titles and comparison        ``_placed_members``,
      headings; summaries of fields; lists said   ``_appositives``, ``_headings``,
      again as their fields; plots counted        ``_titles``, ``_comparisons``,
      after the only crop named                   ``_summaries``,
                                                  ``_restated_lists``,
                                                  ``_plots_of_the_crop``
11    head-less clauses' words to their fields    ``_loose`` (signs in
      (which fields a measure is said of)         ``_loose_owners``),
                                                  ``_measures``
12    fields of each mention, their attributes    ``_fields``
      (stated, else visual cues), sizes, rows
13    relations between fields (words between     ``_relations``, ``_links``;
      mentions; rows and orders; directions       ``_rows``; ``_placements``;
      said around a field; scenery, and           ``_landmarks``,
      relations said of scenery); zone order      ``_scenery_links``; ``_zones``
====  ==========================================  ===============================
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable, Sequence

from agrirecipe._errors import PromptError
from agrirecipe.resolve._appositives import merge_appositive_plots
from agrirecipe.resolve._casual import count_said_after_crop, end_reciprocals, expand_casual
from agrirecipe.resolve._comparisons import drop_compared_headings
from agrirecipe.resolve._coreference import merge_coreferences
from agrirecipe.resolve._counted_crops import hoist_counted_crops
from agrirecipe.resolve._counts import (
    apply_plural_counts,
    count_a_list_after_it,
    count_plots_of_a_list,
    share_count_over_a_list,
    take_the_lower_count,
)
from agrirecipe.resolve._decompose import MentionBuilder, decompose, resolve_weak_varieties
from agrirecipe.resolve._descriptions import dissolve_plant_parts
from agrirecipe.resolve._fields import (
    FieldReading,
    describe_intent,
    give_respectively,
    plot_of_the_plants,
)
from agrirecipe.resolve._geometry import find_geometry
from agrirecipe.resolve._headings import (
    drop_joint_headings,
    drop_list_headings,
    drop_plural_headings,
    fill_counted_lists,
    lend_heading_category,
    lend_heading_crop,
    name_counted_plots,
)
from agrirecipe.resolve._in_turn import say_in_turn
from agrirecipe.resolve._intent import (
    Hemisphere,
    ResolveContext,
    SceneIntent,
    TraceStep,
)
from agrirecipe.resolve._labels import drop_list_numbers, open_ordered_lists, resolve_labels
from agrirecipe.resolve._lexicon import (
    Item,
    Lexicon,
    Sense,
    Token,
    reader_words,
    tokenize,
    vocabulary,
)
from agrirecipe.resolve._likewise import share_likewise
from agrirecipe.resolve._links import ARTICLES
from agrirecipe.resolve._lists import fill_gapped_counts, spread_value_lists
from agrirecipe.resolve._loose import attach_loose
from agrirecipe.resolve._measures import (
    drop_total_sizes,
    share_each_measures,
)
from agrirecipe.resolve._mentions import Clause, Mention
from agrirecipe.resolve._named_in_order import name_counted_in_order
from agrirecipe.resolve._neighbours import (
    name_the_placed_plot,
    place_around_a_centre,
    place_by_cover,
    place_divided_plots,
    place_flanks,
    place_neighbouring_plots,
)
from agrirecipe.resolve._orders import complete_orders, drop_placed_neighbours, past_a_row_end
from agrirecipe.resolve._placed_members import measures_after_a_placed_reference
from agrirecipe.resolve._placements import predicate_of_the_placed
from agrirecipe.resolve._plots_of_the_crop import count_the_crop
from agrirecipe.resolve._purposes import purpose_diseases
from agrirecipe.resolve._refinements import apply_refinements
from agrirecipe.resolve._refusals import (
    EXAMPLES,
    NearestCrops,
    reject_no_crop,
    reject_other_crops,
    reject_scenery,
    reject_unknown_names,
)
from agrirecipe.resolve._relations import read_relations
from agrirecipe.resolve._restated_lists import drop_restated_lists
from agrirecipe.resolve._retractions import (
    apply_corrections,
    correct_placements,
    drop_alternatives,
    drop_corrected_words,
    drop_free_choices,
    drop_negated,
)
from agrirecipe.resolve._same_spacing import parallel_spacing, same_spacing
from agrirecipe.resolve._scan import assign_roles
from agrirecipe.resolve._short_names import name_short_forms
from agrirecipe.resolve._side_phrases import place_sides, place_split_halves
from agrirecipe.resolve._sides import (
    place_compass_members,
    place_leading_directions,
    place_trailing_directions,
    place_walked_orders,
)
from agrirecipe.resolve._sizes import read_heights, read_latitude, read_sizes
from agrirecipe.resolve._structure import (
    apply_each_side,
    raise_conflicts,
    share_counted_fields,
    share_leading_attributes,
    share_trailing_attributes,
)
from agrirecipe.resolve._summaries import (
    drop_announced_plots,
    drop_counted_summaries,
    drop_forward_summaries,
    drop_restated_counts,
    drop_single_plot_counts,
    drop_trailing_summaries,
    spread_counted_totals,
)
from agrirecipe.resolve._titles import drop_titles
from agrirecipe.resolve._weak_varieties import promote_weak_varieties
from agrirecipe.resolve._words import read_words
from agrirecipe.resolve._zones import (
    find_zones,
    lone_side,
    zone_owners,
    zone_relations,
)

__all__ = ["NOTHING_FOUND", "NearestCrops", "PromptReader", "UnknownWords"]

#: How the message of the error for a prompt that names no field begins.
NOTHING_FOUND = "no crop or field found in the prompt"

#: Reads unknown words in place (typos, unseen names); returns the new items and trace steps.
UnknownWords = Callable[[list[Item], Lexicon], tuple[list[Item], list[TraceStep]]]
#: The known crops nearest to a name the hierarchy does not hold, best first.

#: The most fields one recipe holds (SceneRecipe.fields).
_MAX_FIELDS = 64


def _scenery_placed_by(container: Item, clauses: Sequence[Clause]) -> bool:
    """Whether the container word ("the farm") only places the sky said right before it
    ("The sky over the farm this evening"): the scene's backdrop, not fields."""
    for clause in clauses:
        if container in clause.items:
            before = [i for i in clause.items if i.end <= container.start]
            while before and before[-1].norm in ARTICLES:
                before.pop()
            return (
                len(before) >= 2
                and before[-1].norm in _OVER
                and before[-2].data.get("scenery") == "sky"
            )
    return False


#: Words that set the sky over the place named after them ("the sky over the farm").
_OVER = frozenset({"over", "above", "across", "behind", "beyond"})


#: "Nothing is planted this year", "no crops at the moment": a farm that grows nothing.
_NOTHING_PLANTED = re.compile(
    r"\b(?:nothing|no crops?|no crop at all)(?: (?:is|s|was|has been|got|at all))? "
    r"(?:planted|growing|grown|sown|in the ground|this year|at the moment|right now)\b"
)


def _listed_after_a_colon(items: Sequence[Item], container: Item) -> list[Item]:
    """The words after the first colon that follows ``container`` up to the end of its
    sentence (what a farm is said to hold), or [] when no colon follows it."""
    after = [i for i in items if i.start >= container.end]
    colon = next((k for k, i in enumerate(after) if i.norm == ":"), None)
    if colon is None or any(i.norm in (".", "!", "?", ";") for i in after[:colon]):
        return []
    listed: list[Item] = []
    for item in after[colon + 1 :]:
        if item.norm in (".", "!", "?", ";"):
            break
        listed.append(item)
    return listed


class PromptReader(FieldReading):
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
                hint=f"describe the fields you want, e.g. {EXAMPLES}",
            )
        text = drop_list_numbers(
            fill_gapped_counts(spread_value_lists(correct_placements(expand_casual(prompt))))
        )

        def tag(phrase: str) -> list[Item]:
            return self.lexicon.tag(tokenize(phrase))

        # "pinot nero & cabernet, ..., pinot north": a variety named again by its first word
        text = name_short_forms(text, self._variety_names(), tag)
        text, labels = resolve_labels(end_reciprocals(text, tag), tag)
        text = place_compass_members(open_ordered_lists(text, tag), tag)
        text = place_around_a_centre(text, tag)
        text = place_trailing_directions(place_leading_directions(place_split_halves(text)))
        text = place_walked_orders(place_neighbouring_plots(place_divided_plots(text)))
        text = name_the_placed_plot(text, tag)
        text = place_by_cover(place_sides(place_flanks(text, tag)))
        text = hoist_counted_crops(count_said_after_crop(text, tag), tag)
        for note in labels:
            self.trace.append(TraceStep(stage="decompose", subject="label", detail=note))
        tokens = tokenize(text)
        spans: list[tuple[int, int, tuple[Sense, ...]]] = []
        unused: list[tuple[int, int]] = []
        for match in find_geometry(tokens, unused):
            if spans and spans[-1][:2] == (match.first, match.last):  # "20 rows at 5 m"
                spans[-1] = (match.first, match.last, (*spans[-1][2], Sense("geometry", match)))
            else:
                spans.append((match.first, match.last, (Sense("geometry", match),)))
        # "0.76 m bed tops", "sown 3 cm deep": measures no recipe holds, listed as not used
        spans += [(first, last, (Sense("scenery", "measures"),)) for first, last in unused]
        claimed = [False] * len(tokens)
        for first, last, _ in spans:
            claimed[first:last] = [True] * (last - first)
        spans += [(z.first, z.last, (Sense("zone", z.zone),)) for z in find_zones(tokens, claimed)]
        items = self._tag(tokens, sorted(spans, key=lambda span: span[0]))
        items, steps = self.unknown_words(items, self.lexicon)
        self.trace.extend(steps)
        assign_roles(items)
        self._note(drop_corrected_words(items), "replaced by a correction")
        purpose_diseases(items, text)
        prompt_latitude, latitude_text, items = read_latitude(text, items)
        items = read_sizes(read_heights(items))
        self._note(
            drop_total_sizes(items), "the sizes after it add up to it: a total, not a field's size"
        )
        read_words(items, text)
        reject_scenery(items)
        reject_other_crops(items, self.context.hierarchy, self.nearest_crops)
        builder = MentionBuilder(self.crop_categories)
        clauses = decompose(items, builder)
        promote_weak_varieties(clauses, builder)
        predicate_of_the_placed(clauses)
        measures_after_a_placed_reference(clauses)
        self._note(drop_free_choices(clauses), "left to the reader's choice: no field of its own")
        apply_plural_counts(clauses, int(vocabulary()["plural_fields"]))
        take_the_lower_count(clauses)
        share_count_over_a_list(clauses)
        count_a_list_after_it(clauses)
        count_plots_of_a_list(clauses)
        self._note(apply_corrections(clauses), "replaced by a correction")
        self._note(
            drop_alternatives(clauses),
            "an alternative to the crop before it: one field, of the first named",
        )
        raise_conflicts(clauses)
        self._note(drop_negated(clauses), "negated: not a field")
        self._note(
            dissolve_plant_parts(clauses, self.crop_categories), "the named fields' own fruit"
        )
        share_leading_attributes(clauses)
        share_trailing_attributes(clauses)
        share_likewise(clauses)
        mentions = apply_refinements(clauses, self.crop_categories, builder)
        mentions = name_counted_in_order(clauses, mentions)
        mentions = lend_heading_category(clauses, share_counted_fields(mentions))
        mentions = drop_forward_summaries(
            clauses, drop_joint_headings(clauses, mentions, self.crop_categories)
        )
        mentions = drop_compared_headings(clauses, mentions)
        mentions = merge_coreferences(clauses, mentions, builder)
        mentions = merge_appositive_plots(clauses, mentions)
        mentions = drop_list_headings(clauses, mentions, self.crop_categories)
        mentions = drop_counted_summaries(clauses, mentions)
        mentions = fill_counted_lists(clauses, mentions)
        mentions = drop_titles(clauses, mentions, self.crop_categories)
        mentions = drop_trailing_summaries(clauses, drop_plural_headings(clauses, mentions))
        mentions = drop_restated_lists(clauses, mentions, self.crop_categories)
        mentions = drop_announced_plots(clauses, drop_restated_counts(clauses, mentions))
        mentions = spread_counted_totals(clauses, drop_single_plot_counts(clauses, mentions))
        mentions = lend_heading_crop(clauses, name_counted_plots(clauses, mentions))
        mentions = count_the_crop(clauses, mentions)
        apply_each_side(clauses)
        for clause in clauses:
            # "... and there's a duck pond in the middle": the zone of scenery, not a field
            if not clause.mentions and any(i.scenery for i in clause.loose):
                clause.loose = [i for i in clause.loose if i.role != "zone"]
        say_in_turn(clauses)
        scene_items = attach_loose(clauses, mentions)
        share_each_measures(clauses)
        for mention in mentions:
            for sub in (mention, *mention.refinements):
                resolve_weak_varieties(sub)
        latitude, hemisphere, place = self._place(items, prompt_latitude, latitude_text)
        if not mentions:
            mentions = self._container_fields(items, clauses)
        reject_unknown_names(items, mentions, self.context.hierarchy, self.nearest_crops)
        reject_no_crop(items, mentions)
        plot_of_the_plants(mentions, tag)
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
        owned = zone_owners(items, [f.items for f in fields])
        zoned = [r for r in zone_relations(owned) if (r.kind, r.subject, r.objects) not in said]
        relations = drop_placed_neighbours(relations, zoned) + zoned
        relations = relations or lone_side(tokens, claimed, owned)
        relations += complete_orders(relations, owned)
        relations += past_a_row_end(relations, owned)
        scene_season = self._apply_scene_items(scene_items, fields, hemisphere)
        give_respectively(fields)
        intents = [self._field_intent(f, hemisphere, scene_season) for f in fields]
        for index in range(1, len(intents)):  # "... & same size of romaine"
            if intents[index].size is None and any(
                i.role == "same_size" or (i.role == "same_spacing" and "again" in i.norm)
                for i in fields[index].items
            ):
                intents[index] = intents[index].model_copy(update={"size": intents[index - 1].size})
            same = [i for i in fields[index].items if i.role == "same_spacing"]
            if same:
                intents[index] = same_spacing(intents[index], intents[index - 1], same)
        for index, field in enumerate(fields):
            others = [(intents[j], f.items) for j, f in enumerate(fields) if j != index]
            intents[index] = parallel_spacing(
                intents[index], field.items, others, self._spacing_ranges(intents[index].crop)
            )
        for index, intent in enumerate(intents):
            self.trace.append(
                TraceStep(
                    stage="decompose",
                    subject=f"field {index + 1}",
                    detail=f"{intent.text!r} -> " + describe_intent(intent),
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

    def _variety_names(self) -> list[str]:
        """The hierarchy's variety names and aliases."""
        return [
            name
            for crop in self.context.hierarchy.crops.values()
            for variety in crop.varieties
            for name in (variety.name, *variety.aliases)
        ]

    def _note(self, subjects: Iterable[str], detail: str) -> None:
        """Record in the trace what one reading pass did to each of these words."""
        self.trace.extend(TraceStep(stage="decompose", subject=s, detail=detail) for s in subjects)

    def _tag(
        self, tokens: Sequence[Token], spans: Sequence[tuple[int, int, tuple[Sense, ...]]]
    ) -> list[Item]:
        """The lexicon's items, with each span read before it (a stated geometry such as
        "76 cm apart", a zone such as "along the top") as one item."""
        items: list[Item] = []
        index = 0
        for first, last, senses in spans:
            items.extend(self.lexicon.tag(tokens[index:first]))
            items.append(Item(tuple(tokens[first:last]), senses))
            index = last
        items.extend(self.lexicon.tag(tokens[index:]))
        return items

    def _spacing_ranges(self, crop: str | None) -> dict[str, tuple[float, float]]:
        """The sourced ranges of ``crop``'s row and in-row spacing, by recipe key."""
        if crop is None or crop not in self.context.hierarchy.crops:
            return {}
        planting = self.context.knowledge.crop_file(crop).planting
        said = {
            "row_spacing_m": planting.row_spacing_m,
            "in_row_spacing_m": planting.in_row_spacing_m,
        }
        return {k: v.range for k, v in said.items() if v.range is not None}

    # --- unknown and non-agricultural requests ---

    def _container_fields(self, items: Sequence[Item], clauses: Sequence[Clause]) -> list[Mention]:
        """No field named: "a mixed farm" stands for a few fields; anything else is an error."""
        non_agricultural = [item.raw for item in items if item.role == "non_agricultural"]
        if non_agricultural:
            raise PromptError(
                f"{non_agricultural[0]!r} is not an agricultural scene",
                stage="resolve",
                hint=f"agrirecipe builds fields of crops, e.g. {EXAMPLES}",
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
                hint="name a crop, a variety or a kind of field, e.g. " + EXAMPLES,
            )
        scenery = [i.raw for i in items if i.scenery]
        if scenery and all(
            c.norm in reader_words("only_a_scene") or _scenery_placed_by(c, clauses)
            for c in containers
        ):
            # "a drone survey scene over the yard: two tractors, a sprayer and the shed"
            raise PromptError(
                f"{NOTHING_FOUND}: only scenery ({', '.join(repr(w) for w in scenery[:5])})",
                stage="resolve",
                hint="name a crop, a variety or a kind of field, e.g. " + EXAMPLES,
            )
        said = " ".join(i.norm for i in items)
        if _NOTHING_PLANTED.search(said):
            # "Our farm has a farmhouse, two barns, ... Nothing is planted this year."
            raise PromptError(
                f"{NOTHING_FOUND}: the prompt says nothing is grown",
                stage="resolve",
                hint="name a crop, a variety or a kind of field, e.g. " + EXAMPLES,
            )
        listed = _listed_after_a_colon(items, containers[0])
        if listed and all(not i.has("crop", "variety", "category", "plot") for i in listed):
            # "Describe our farm for the drone survey: farmhouse, two sheds, gravel lanes,
            # a pond ...": what the farm holds, said, is scenery alone
            named = [i.raw for i in listed if i.scenery or i.role == "non_agricultural"]
            raise PromptError(
                f"{NOTHING_FOUND}: the {containers[0].raw} holds only scenery"
                + (f" ({', '.join(repr(w) for w in named[:5])})" if named else ""),
                stage="resolve",
                hint="name a crop, a variety or a kind of field, e.g. " + EXAMPLES,
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


# --- helpers ---
