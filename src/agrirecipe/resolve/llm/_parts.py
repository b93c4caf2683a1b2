"""The request's parts: mentions of fields, their groups, and the repair of the parts."""

from __future__ import annotations

import itertools
import re
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from agrirecipe.resolve._grammar import NONE
from agrirecipe.resolve.llm._evidence import _collect, _in_size, _readings

if TYPE_CHECKING:
    from agrirecipe.hierarchy import Hierarchy
    from agrirecipe.resolve._lexicon import Item, Lexicon

_PUNCTUATION = ".,;:!?()\"'"


# --- parts of the request --------------------------------------------------------


@dataclass(frozen=True, slots=True)
class _Part:
    """A run of the request's words."""

    first: int  # index of the first word
    last: int  # index of the last word (inclusive)
    text: str  # the words joined by single spaces (as the grammar spells them)
    raw: str  # the original characters of the prompt


def _word_spans(request: str) -> list[tuple[int, int]]:
    """Character spans of the words :func:`prompt_words` returns."""
    spans = []
    for match in re.finditer(r"\S+", request):
        raw = match.group()
        stripped = raw.strip(_PUNCTUATION)
        if stripped:
            start = match.start() + raw.index(stripped)
            spans.append((start, start + len(stripped)))
    return spans


def _make_part(first: int, last: int, words: Sequence[str], request: str) -> _Part:
    spans = _word_spans(request)
    raw = request[spans[first][0] : spans[last][1]]
    return _Part(first, last, " ".join(words[first : last + 1]), raw)


def _parse_parts(answer: str, words: Sequence[str], request: str) -> list[_Part]:
    """The model's parts as word ranges (the grammar guarantees they are runs, in order)."""
    text = answer.strip()
    if not text or text == NONE:
        return []
    parts: list[_Part] = []
    cursor = 0
    for piece in text.split(" | "):
        run = piece.split(" ")
        for start in range(cursor, len(words) - len(run) + 1):
            if list(words[start : start + len(run)]) == run:
                parts.append(_make_part(start, start + len(run) - 1, words, request))
                cursor = start + len(run)
                break
    return parts


@dataclass(slots=True)
class _Group:
    """Consecutive words naming one field: a plant and/or a kind of field, in prompt words."""

    first: int
    last: int
    crop: str | None = None
    variety: str | None = None
    other: str | None = None
    category: str | None = None
    plot: bool = False
    plot_options: tuple[str, ...] = ()
    weak_only: bool = True
    after_join: bool = False
    joins: list[int] = field(default_factory=list)

    @property
    def names_a_plant(self) -> bool:
        return self.crop is not None or self.other is not None


@dataclass(frozen=True, slots=True)
class _Mention:
    """One lexicon item that names a plant or a kind of field."""

    first: int
    last: int
    crop: str | None = None
    variety: str | None = None
    weak: bool = False
    other: str | None = None
    category: str | None = None
    plot: bool = False
    plot_options: tuple[str, ...] = ()
    article: bool = False  # "a", "another", "two": a new field may follow
    definite: bool = False  # "the trees": points back at a field named before


def _mentions(
    lexicon: Lexicon, request: str, hierarchy: Hierarchy
) -> tuple[list[_Mention], list[int]]:
    """What names a field in the request, in order, and the words that join fields.

    A joining word ("and", a comma, "next to") is where two fields' words are
    best split.
    """
    from agrirecipe.resolve._lexicon import tokenize, vocabulary

    spans = _word_spans(request)

    def word_at(offset: int) -> int:
        for index, (_, end) in enumerate(spans):
            if offset < end:
                return index
        return len(spans) - 1

    found: list[_Mention] = []
    joins: list[int] = []
    items = lexicon.tag(tokenize(request))
    readings = _readings(lexicon, items)
    parts = {str(word) for word in vocabulary()["plant_part_words"]}
    definite_words = {str(word) for word in vocabulary()["definite_words"]}
    for index, item in enumerate(items):
        first, last = word_at(item.start), word_at(item.end - 1)
        if _plants_of_previous(found, first, readings[index]) or (
            item.norm in parts and _part_of_named(found, items, readings, index)
        ):
            continue  # "tomato vines", "tomatoes, fruit ripe": words about a field named
        if item.has("conjunction", "separator") or (
            item.has("relation") and not _in_size(items, index)
        ):
            joins.append(first)
            continue
        if any(s.kind in ("number", "quantity", "other") for s in readings[index]) or (
            item.norm in ("another", "one")
        ):
            found.append(_Mention(first, last, article=True))
            continue
        senses = readings[index]
        crops = [s.value for s in senses if s.kind == "crop"]
        varieties = [s for s in senses if s.kind == "variety" and not (crops and s.weak)]
        if crops:
            found.append(_Mention(first, last, crop=str(crops[0])))
        elif varieties:
            sense = varieties[0]
            found.append(
                _Mention(
                    first, last, crop=str(sense.crop), variety=str(sense.value), weak=sense.weak
                )
            )
        elif any(s.kind == "other_crop" for s in senses):
            other = next(s.value for s in senses if s.kind == "other_crop")
            found.append(_Mention(first, last, other=str(other.name)))
        elif any(s.kind == "category" for s in senses):
            category = next(str(s.value) for s in senses if s.kind == "category")
            found.append(_Mention(first, last, category=category))
        elif any(s.kind == "plot" for s in senses):
            spec = next(s.value for s in senses if s.kind == "plot")
            options = tuple(spec["options"])
            plot_category: str | None = spec["category"]
            if plot_category is None and options:
                categories = {hierarchy.crops[c].category for c in options}
                plot_category = next(iter(categories)) if len(categories) == 1 else None
            definite = index > 0 and items[index - 1].norm in definite_words
            found.append(
                _Mention(
                    first,
                    last,
                    plot=True,
                    plot_options=options,
                    category=plot_category,
                    definite=definite,
                )
            )
    return found, joins


def _plants_of_previous(found: Sequence[_Mention], first: int, senses: Sequence[Any]) -> bool:
    """'tomato vines': a crop alias that also names plants, right after another crop."""
    if not found or found[-1].crop is None or found[-1].last != first - 1:
        return False
    crops = {s.value for s in senses if s.kind == "crop"}
    plants = any(s.kind == "plot" and s.value["individual"] for s in senses)
    return plants and bool(crops) and found[-1].crop not in crops


def _part_of_named(
    found: Sequence[_Mention], items: Sequence[Item], readings: Sequence[Sequence[Any]], index: int
) -> bool:
    """'..., fruit ripe' after a named crop: the crop's fruit, next to a stage or health word."""
    if not any(m.crop is not None for m in found):
        return False
    near = [i for i in (index - 1, index + 1) if 0 <= i < len(items)]
    return any(s.kind in ("stage", "health") for i in near for s in readings[i])


def _fits(group: _Group, mention: _Mention, hierarchy: Hierarchy) -> bool:
    """Whether ``mention`` can describe the same field as ``group``."""
    if mention.other is not None or group.other is not None:
        return False
    if mention.crop is not None:
        if group.crop is not None and group.crop != mention.crop:
            return False
        if mention.variety and group.variety and mention.variety != group.variety:
            return False
        category = hierarchy.crops[mention.crop].category
        if group.category is not None and group.category != category:
            return False
        return not group.plot_options or mention.crop in group.plot_options
    if mention.plot:
        if group.plot:
            return False
        if group.crop is not None and mention.plot_options:
            return group.crop in mention.plot_options
        return group.category is None or mention.category in (None, group.category)
    # a category word
    if group.category is not None and group.category != mention.category:
        return False
    return group.crop is None or hierarchy.crops[group.crop].category == mention.category


def _add(group: _Group, mention: _Mention) -> None:
    group.last = mention.last
    group.crop = group.crop or mention.crop
    group.variety = group.variety or mention.variety
    group.other = group.other or mention.other
    group.category = group.category or mention.category
    group.plot = group.plot or mention.plot
    group.plot_options = group.plot_options or mention.plot_options
    group.weak_only = group.weak_only and (mention.crop is None or mention.weak)


def _groups(
    mentions: Sequence[_Mention], joins: Sequence[int], hierarchy: Hierarchy
) -> list[_Group]:
    """Mentions of one field, grouped: a new group starts where a mention cannot fit.

    A kind of field named after a joining word and an article or number starts
    a field of its own ("... and a 1 ha field of carrots"); a second kind of
    field with neither is more words about the same one ("tomato plants",
    "the trees have scab", "five fields of different crops").
    """
    groups: list[_Group] = []
    article = False
    for mention in mentions:
        if mention.article:
            article = True
            continue
        current = groups[-1] if groups else None
        after_join = current is not None and any(current.last < j < mention.first for j in joins)
        generic = mention.crop is None and mention.other is None
        if current is not None:
            fits = _fits(current, mention, hierarchy)
            opens = generic and current.names_a_plant and after_join and article
            if fits and not opens:
                _add(current, mention)
                article = False
                continue
            # "a wheat field, fruit trees in bloom": a kind of field after a joining
            # word is a field of its own.
            own = (
                bool(mention.plot_options)
                and current.crop not in mention.plot_options  # "Gala orchard, trees in bloom"
                and not mention.definite
                and any(
                    current.last < j <= mention.first  # a comma counts as the next word's
                    for j in joins
                )
            )
            if not fits and mention.plot and not article and current.other is None and not own:
                current.last = mention.last
                continue
        group = _Group(mention.first, mention.first, after_join=after_join)
        _add(group, mention)
        groups.append(group)
        article = False
    # A weak reading alone ("golden" in "wheat, golden and ripe") names no field
    # when another field is named.
    strong = [g for g in groups if not (g.crop is not None and g.weak_only)]
    return strong if strong else groups


def _field_groups(
    lexicon: Lexicon, request: str, hierarchy: Hierarchy
) -> tuple[list[_Group], list[int]]:
    """The fields the words name (grouped mentions) and the joining words' indexes."""
    mentions, joins = _mentions(lexicon, request, hierarchy)
    return _groups(mentions, joins, hierarchy), joins


def _boundary_open(groups: Sequence[_Group], joins: Sequence[int]) -> bool:
    """Whether two neighbouring fields have no joining word between them, so the model
    must decide where one field's words end ("apples with scab carrots young")."""
    return any(
        not any(left.last < j < right.first for j in joins)
        for left, right in itertools.pairwise(groups)
    )


def _repair_parts(
    parts: Sequence[_Part] | None,
    words: Sequence[str],
    request: str,
    lexicon: Lexicon,
    fields: tuple[Sequence[_Group], Sequence[int]],
) -> tuple[list[_Part], list[_Part], list[str]]:
    """Check the model's decomposition against the fields the words name; repair it.

    Every part must hold exactly one field's words. The model's boundaries are
    kept where they fall between two fields (that is where it decides which
    field the words in between describe); elsewhere a part is split at the
    first joining word. ``parts`` is None when the model was not asked (no
    boundary was open). Returns the field parts, the shared parts ("..., all
    in autumn", read with every field) and a description of each repair.
    """
    groups, joins = fields
    if not groups:
        return [], [], []
    asked = parts is not None
    parts = parts or []
    model_ends = {p.last for p in parts}
    cuts: list[int] = []  # index of the first word of each part after the first
    repairs: list[str] = []
    for left, right in itertools.pairwise(groups):
        # A joining word between two fields ("and", "next to", a comma) is the
        # boundary; where there is none, the model decides where the words in
        # between belong. (Preferring the model's boundary over a joining word
        # lost 2 multi-field prompts of the benchmark and won none.)
        between = [j for j in joins if left.last < j < right.first]
        chosen = [e + 1 for e in model_ends if left.last <= e < right.first]
        cut = between[0] if between else min(chosen) if chosen else left.last + 1
        if asked and cut not in chosen:
            repairs.append(f"boundary moved to before {words[cut]!r}")
        cuts.append(cut)
    bounds = [0, *cuts, len(words)]
    spans = [[bounds[i], bounds[i + 1] - 1] for i in range(len(groups))]
    # Words after the last field, after a comma or with "all", describe every field.
    shared: list[_Part] = []
    tail_joins = [j for j in joins if j > groups[-1].last]
    if len(groups) > 1 and tail_joins:
        start = tail_joins[0]
        tail = _make_part(start, len(words) - 1, words, request) if start < len(words) else None
        if tail is not None and _collect(lexicon, tail.raw).states:
            spans[-1][1] = start - 1
            shared.append(tail)
            repairs.append(f"{tail.text!r} describes every field")
    model = [(p.first, p.last) for p in parts]
    final = [_make_part(a, b, words, request) for a, b in spans if a <= b]
    if asked and [(p.first, p.last) for p in final] != model and not repairs:
        repairs.append("parts aligned with the fields the words name")
    return final, shared, repairs
