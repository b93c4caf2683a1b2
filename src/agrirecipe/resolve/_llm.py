"""The "llm" strategy: a local GGUF model reads the prompt under grammars, step by step.

A 270M base model (Gemma 3, the default) is weak, so the strategy is built
around what such a model can do: continue a few-shot document
(``data/llm/fewshot.yaml``) and pick among a few options. Each prompt becomes
a record continued one line at a time, every line under a grammar generated
from the hierarchy and the recipe schema (:mod:`agrirecipe.resolve._grammar`)::

    Request: a healthy Pink Lady apple orchard in summer next to young carrots
    Parts: a healthy Pink Lady apple orchard in summer | young carrots   <- decompose
    Part 1: a healthy Pink Lady apple orchard in summer
    Count: 1                                                              <- per-field
    Crop: Apple                                                              subquery
    Variety: Pink Lady
    Stage: none
    Season: Summer
    Health: Healthy
    Part 2: young carrots
    ...
    Relations: 1 next to 2

1. **Decompose**: the model splits the request into parts; the grammar only
   offers runs of the request's own words, in order, without overlap. It is
   asked where two fields the words name have no joining word ("and", a
   comma, "next to") between them; elsewhere the joining words fix every
   boundary, step 2 would overrule any other answer, and the line is written
   without asking (``narrow=False`` always asks).
2. **Validate and repair the parts** (deterministic): a part naming two plants
   is split between them, a plant no part covers joins the part next to it,
   words naming no plant are merged into a neighbour or, with "all", shared
   by every part; "none" on a request that names a crop is overruled.
3. **Retrieve** each part's candidates from the lexicon (exact and typo
   matches of hierarchy names and aliases, plot nouns, stage/season/health
   words, counts, plants the hierarchy does not hold).
4. **Per-field subquery**: one line per attribute, each a choice among the
   retrieved candidates. The model decides wherever more than one is left
   ("cherry" in "a cherry orchard": Cherry or Tomato; sizes; relations other
   than one "next to" between two parts, which reads one way only); a single
   candidate is written without asking, and with nothing retrieved every
   canonical value plus "none" is offered. The trace says how often the model
   was asked.
5. **Validate the record** (deterministic): "other" is an
   :class:`~agrirecipe.UnknownCropError` listing the nearest known crops; a
   variety of one crop named beside another crop is a contradiction
   (:class:`~agrirecipe.PromptError`); self-relations are dropped.

Why the candidates are narrowed so far, measured on 30 development prompts
(docs in the closing report): offered every canonical value, the model answered
the stage line with the same value whatever the words said (5/17 right; 11/17
with everyday labels such as "young", which is the "always none" baseline),
and dropped named varieties for "none" about half the time. Offered only what
retrieval found, it chooses correctly between readings and can never invent.
``LlmResolver(narrow=False)`` keeps every option open, to measure the model alone.

The model is loaded on first use and kept; the few-shot prefix stays in its KV
cache, so a warm prompt costs only its own tokens. Output is deterministic:
greedy decoding over bit-identical logits whatever ran before (see
:class:`~agrirecipe.localmodels.LlamaCppModel`).
"""

from __future__ import annotations

import functools
import itertools
import re
import threading
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import yaml

from agrirecipe._errors import ConfigurationError, PromptError, UnknownCropError
from agrirecipe.resolve._grammar import (
    ANY_PREFIX,
    NONE,
    OTHER,
    HierarchyGrammars,
    choice_grammar,
    prompt_words,
)
from agrirecipe.resolve._intent import (
    Candidate,
    FieldIntent,
    Hemisphere,
    RelationIntent,
    ResolveContext,
    Resolver,
    SceneIntent,
    SizeIntent,
    TraceStep,
)

if TYPE_CHECKING:
    from agrirecipe.hierarchy import Hierarchy
    from agrirecipe.localmodels import LanguageModel
    from agrirecipe.resolve._lexicon import Item, Lexicon

__all__ = ["MAX_PROMPT_TOKENS", "LlmResolver", "load_examples", "render_examples"]

DATA_DIR = Path(__file__).resolve().parent / "data" / "llm"
#: Longest request the strategy reads, in model tokens.
MAX_PROMPT_TOKENS = 160
#: Most fields one scene may hold (the limit of :class:`SceneIntent`).
MAX_FIELDS = 64
_STATE_KEYS = ("stage", "season", "health")
_PUNCTUATION = ".,;:!?()\"'"
_SOUTHERN = {"Spring": "Fall", "Summer": "Winter", "Fall": "Spring", "Winter": "Summer"}


# --- few-shot examples -----------------------------------------------------------


@functools.lru_cache(maxsize=4)
def load_examples(path: str | Path | None = None) -> tuple[dict[str, Any], ...]:
    """The few-shot examples (``data/llm/fewshot.yaml`` unless ``path`` is given)."""
    source = Path(path) if path is not None else DATA_DIR / "fewshot.yaml"
    try:
        data = yaml.safe_load(source.read_text(encoding="utf-8"))
    except (OSError, yaml.YAMLError) as exc:
        raise ConfigurationError(
            f"cannot read the llm few-shot examples {str(source)!r}: {exc}", stage="llm"
        ) from exc
    examples = data.get("examples") if isinstance(data, dict) else None
    if not isinstance(examples, list) or not examples:
        raise ConfigurationError(
            f"{str(source)!r} holds no 'examples' list",
            stage="llm",
            hint="see agrirecipe/resolve/data/llm/fewshot.yaml for the format",
        )
    return tuple(examples)


def _words_text(text: str) -> str:
    return " ".join(prompt_words(text))


def _part_block(index: int, part: Mapping[str, Any], suffix: str = "") -> str:
    """The record of one part, line for line as :class:`LlmResolver` writes it."""
    text = _words_text(str(part["text"]))
    crop = str(part["crop"])
    lines = [f"Part {index}: {text}{suffix}", f"Count: {part.get('count', 1)}", f"Crop: {crop}"]
    if crop == OTHER:
        lines.append(f"Name: {part['name']}")
        return "\n".join(lines) + "\n"
    if crop.startswith(ANY_PREFIX):
        lines.append(f"Different: {part.get('different', 'no')}")
    else:
        lines.append(f"Variety: {part.get('variety', NONE)}")
    lines += [f"{key.capitalize()}: {part.get(key, NONE)}" for key in _STATE_KEYS]
    if re.search(r"\d", text):
        lines.append(f"Size: {part.get('size', NONE)}")
    return "\n".join(lines) + "\n"


def render_examples(examples: Sequence[Mapping[str, Any]]) -> str:
    """The few-shot document: one record per example, a blank line after each."""
    blocks = []
    for example in examples:
        lines = [f"Request: {example['request']}\n"]
        parts = example["parts"]
        if parts == NONE:
            lines.append(f"Parts: {NONE}\n")
        else:
            lines.append("Parts: " + " | ".join(_words_text(str(p["text"])) for p in parts) + "\n")
            fields = [part for part in parts if not part.get("shared")]
            suffix = "".join(f" + {_words_text(str(p['text']))}" for p in parts if p.get("shared"))
            lines += [_part_block(i, part, suffix) for i, part in enumerate(fields, start=1)]
            if len(fields) > 1:
                lines.append(f"Relations: {example.get('relations', NONE)}\n")
        blocks.append("".join(lines))
    return "\n".join(blocks) + "\n"


# --- retrieval over the lexicon --------------------------------------------------


@dataclass(slots=True)
class _Evidence:
    """What the lexicon finds in a run of words: the candidates of one part."""

    crops: dict[str, str] = field(default_factory=dict)  # crop -> words as typed
    varieties: dict[tuple[str, str], str] = field(default_factory=dict)  # (crop, variety) -> words
    weak_varieties: set[tuple[str, str]] = field(default_factory=set)
    categories: dict[str, str] = field(default_factory=dict)
    plot_options: list[str] = field(default_factory=list)
    plot_category: str | None = None
    noun: str | None = None
    other: dict[str, tuple[str, ...]] = field(default_factory=dict)  # unknown plant -> nearest
    states: dict[str, list[str]] = field(default_factory=dict)  # "stage" -> ["Vegetative"]
    counts: list[int] = field(default_factory=list)
    distinct: bool = False
    all_words: bool = False
    sizes: list[str] = field(default_factory=list)  # "50 x 100 m", "2 ha"
    units: dict[str, tuple[str, float]] = field(default_factory=dict)  # word -> (kind, factor)
    relations: list[str] = field(default_factory=list)
    hemisphere: tuple[str, float] | None = None
    place: tuple[str, float] | None = None
    candidates: list[Candidate] = field(default_factory=list)

    @property
    def names_a_plant(self) -> bool:
        return bool(self.crops or self.varieties or self.other)

    @property
    def names_a_field(self) -> bool:
        return self.names_a_plant or bool(
            self.categories or self.plot_options or self.plot_category
        )

    def add_state(self, key: str, value: str) -> None:
        values = self.states.setdefault(key, [])
        if value not in values:
            values.append(value)


_FIELD_SENSES = ("crop", "variety", "category", "plot", "other_crop")


def _collect(lexicon: Lexicon, text: str, hemisphere: Hemisphere | None = None) -> _Evidence:
    """Candidates for one run of words (exact lexicon matches, then typo matches)."""
    from agrirecipe.resolve._lexicon import tokenize, vocabulary

    vocab = vocabulary()
    cues = {str(word) for word in vocab["month_cues"]}
    evidence = _Evidence()
    items = lexicon.tag(tokenize(text))
    readings = _readings(lexicon, items, evidence.candidates)
    for index, (item, senses) in enumerate(zip(items, readings, strict=True)):
        previous = items[index - 1] if index else None
        negated = previous is not None and previous.has("negation")
        after_cue = previous is not None and previous.norm in cues
        kept = [s for s in senses if not (_in_size(items, index) and s.kind == "relation")]
        _add_senses(evidence, item, kept, negated=negated, after_cue=after_cue)
        if item.norm in (":", ".", ";"):
            evidence.counts.clear()  # "three fields: ..." announces the fields that follow
        elif _counts_fields(items, readings, index):
            evidence.counts += [
                int(s.value) for s in senses if s.kind in ("number", "quantity") and s.value > 1
            ]
            if item.norm.isdigit() and int(item.norm) > 1:
                evidence.counts.append(int(item.norm))
    _promote_weak_varieties(evidence, items, readings)
    evidence.sizes = _size_options(items, readings)
    for month in evidence.states.pop("month", []):
        season = _month_season(int(month), hemisphere, vocab["month_seasons_north"])
        evidence.add_state("season", season)
    return evidence


def _readings(
    lexicon: Lexicon, items: Sequence[Item], candidates: list[Candidate] | None = None
) -> list[Sequence[Any]]:
    """Each item's senses; unknown words are read as typos of a phrase when close enough.

    Two neighbouring words are tried together first ("granny smtih" -> "granny
    smith"), then the unknown word alone ("aples" -> "apples").
    """
    readings: list[Sequence[Any]] = [item.senses for item in items]
    index = 0
    while index < len(items):
        item = items[index]
        if item.senses or len(item.norm) < 4 or not item.norm.isalpha():
            index += 1
            continue
        pairs = []
        if index > 0 and items[index - 1].norm.isalpha() and not items[index - 1].has("filler"):
            pairs.append((index - 1, f"{items[index - 1].norm} {item.norm}"))
        if index + 1 < len(items) and items[index + 1].norm.isalpha():
            pairs.append((index, f"{item.norm} {items[index + 1].norm}"))
        for first, phrase in pairs:
            match = lexicon.fuzzy(phrase)
            if match is not None and " " in match[0]:
                readings[first], readings[first + 1] = match[2], ()
                break
        else:
            match = lexicon.fuzzy(item.norm)
            if match is not None:
                readings[index] = match[2]
        if match is not None and candidates is not None:
            candidates.append(Candidate(value=match[0], score=match[1], source="fuzzy"))
        index += 1
    return readings


def _in_size(items: Sequence[Item], index: int) -> bool:
    """Whether the item at ``index`` joins two sides of a size ("50 by 100", "50 m by 100 m")."""
    if not items[index].has("dimension_joiner") or index == 0:
        return False
    previous = items[index - 1]
    if previous.has("length_unit") and index >= 2:
        previous = items[index - 2]
    return _is_number(previous)


def _is_number(item: Item | None) -> bool:
    return item is not None and (item.norm[:1].isdigit() or item.has("number", "fraction"))


def _counts_fields(items: Sequence[Item], readings: Sequence[Sequence[Any]], index: int) -> bool:
    """Whether the number at ``index`` counts fields ("two fields", "3 tomato plots")."""
    item = items[index]
    if not (item.norm.isdigit() or item.has("number", "quantity")):
        return False
    for later in range(index + 1, min(index + 4, len(items))):
        kinds = {s.kind for s in readings[later]}
        if kinds & set(_FIELD_SENSES):
            return True
        if kinds & {"area_unit", "length_unit", "number", "conjunction", "separator", "relation"}:
            return False
    return False


def _promote_weak_varieties(
    evidence: _Evidence, items: Sequence[Item], readings: Sequence[Sequence[Any]]
) -> None:
    """A weak variety word next to its crop's name is a variety ("Sonata strawberries")."""
    for index, senses in enumerate(readings):
        for sense in senses:
            if sense.kind != "variety" or (sense.crop, sense.value) not in evidence.weak_varieties:
                continue
            neighbours = [readings[j] for j in (index - 1, index + 1) if 0 <= j < len(items)]
            if any(s.kind == "crop" and s.value == sense.crop for n in neighbours for s in n):
                evidence.weak_varieties.discard((sense.crop, sense.value))


def _size_options(items: Sequence[Item], readings: Sequence[Sequence[Any]]) -> list[str]:
    """The sizes the words can state: ``"50 x 100 m"`` or ``"2 ha"``, numbers as written."""
    options: list[str] = []
    pending: list[str] = []
    sided: tuple[str, str] | None = None  # "100 m" waiting for "by 200 m"
    for item, senses in zip(items, readings, strict=True):
        kinds = {s.kind: s for s in senses}
        if item.norm[:1].isdigit():
            pending.append(item.norm)
        elif "fraction" in kinds:
            pending.append(f"{float(kinds['fraction'].value):g}")
        elif "number" in kinds and item.norm not in ("a", "an") and item.norm.isalpha():
            pending.append(str(kinds["number"].value))
        elif "area_unit" in kinds and pending:
            options.append(f"{pending[-1]} {_unit_word(item)}")
            pending, sided = [], None
        elif "length_unit" in kinds and pending:
            if len(pending) >= 2:
                options.append(f"{pending[-2]} x {pending[-1]} {_unit_word(item)}")
            elif sided is not None and sided[1] == _unit_word(item):
                square = f"{sided[0]} x {sided[0]} {_unit_word(item)}"
                if square in options:  # "40 m wide and 80 m long" is one rectangle
                    options.remove(square)
                options.append(f"{sided[0]} x {pending[-1]} {_unit_word(item)}")
                sided = None
            else:
                sided = (pending[-1], _unit_word(item))
            pending = []
        elif "side" in kinds and sided is not None:
            # "a 100 m long field": one side only reads as a square (as the lexical reader)
            options.append(f"{sided[0]} x {sided[0]} {sided[1]}")
        elif not (kinds.keys() & {"dimension_joiner", "filler"}):
            pending = []
    return list(dict.fromkeys(options))


def _unit_word(item: Item) -> str:
    """A unit as one word of a size option: "m2", not the tokens "m 2"."""
    return item.norm.replace(" ", "")


def _month_season(month: int, hemisphere: Hemisphere | None, table: Mapping[str, Any]) -> str:
    season = next(str(name) for name, months in table.items() if month in months)
    return _SOUTHERN[season] if hemisphere == "south" else season


def _add_senses(
    evidence: _Evidence, item: Item, senses: Sequence[Any], *, negated: bool, after_cue: bool
) -> None:
    for sense in senses:
        kind = sense.kind
        if kind == "crop":
            evidence.crops.setdefault(sense.value, item.raw)
            evidence.candidates.append(Candidate(value=sense.value, score=100, source="lexicon"))
        elif kind == "variety":
            key = (str(sense.crop), str(sense.value))
            evidence.varieties.setdefault(key, item.raw)
            if sense.weak:
                evidence.weak_varieties.add(key)
            evidence.candidates.append(
                Candidate(value=f"{sense.crop}/{sense.value}", score=100, source="lexicon")
            )
        elif kind == "category":
            evidence.categories.setdefault(sense.value, item.raw)
        elif kind == "plot":
            spec = sense.value
            evidence.noun = evidence.noun or str(spec["noun"])
            evidence.plot_options += [c for c in spec["options"] if c not in evidence.plot_options]
            evidence.plot_category = evidence.plot_category or spec["category"]
        elif kind == "other_crop":
            evidence.other.setdefault(sense.value.name, tuple(sense.value.like))
        elif kind in ("stage", "season"):
            evidence.add_state(kind, str(sense.value))
        elif kind == "month" and (after_cue or not sense.weak):
            evidence.states.setdefault("month", []).append(str(sense.value))
        elif kind == "health":
            evidence.add_state(
                "health", "Healthy" if negated and sense.value == "Ill" else sense.value
            )
        elif kind == "distinct":
            evidence.distinct = True
        elif kind == "all":
            evidence.all_words = True
        elif kind in ("area_unit", "length_unit"):
            evidence.units.setdefault(_unit_word(item), (kind, float(sense.value)))
        elif kind == "relation" or (kind == "relation_trailer" and sense.value == "next_to"):
            # "next to", "side by side" (the model reads trailing directions backwards);
            # "on either side of" is a "between" whose order the model decides
            evidence.relations.append("between" if sense.value == "flanks" else str(sense.value))
        elif kind == "hemisphere":
            evidence.hemisphere = sense.value
        elif kind == "place":
            evidence.place = sense.value


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


# --- the record ------------------------------------------------------------------


class _Record:
    """The few-shot document being continued for one prompt."""

    def __init__(self, model: LanguageModel, prefix: str, request: str) -> None:
        self.model = model
        self.text = prefix + f"Request: {request}\n"
        self.asked = 0

    def write(self, text: str) -> None:
        self.text += text

    def answer(self, label: str, grammar: str, *, max_tokens: int) -> str:
        """The model's continuation of ``label`` under ``grammar`` (not yet written)."""
        self.asked += 1
        return self.model.complete(self.text + label, grammar=grammar, max_tokens=max_tokens)

    def choose(self, label: str, options: Sequence[str], grammar: str | None = None) -> str:
        """Write ``label: <option>``; the model picks when there is more than one option.

        ``grammar`` must accept exactly `` <option>\\n`` for the options (default:
        :func:`choice_grammar` of them).
        """
        unique = list(dict.fromkeys(options))
        if len(unique) == 1:
            choice = unique[0]
        else:
            longest = max(len(option) for option in unique)
            choice = self.answer(
                f"{label}:", grammar or choice_grammar(unique), max_tokens=longest + 4
            ).strip()
        self.write(f"{label}: {choice}\n")
        return choice


# --- the strategy ----------------------------------------------------------------


class LlmResolver(Resolver):
    """Resolve prompts with a local GGUF model, under grammars generated from the hierarchy.

    ``model`` is a :class:`~agrirecipe.localmodels.LanguageModel`, a path to a
    GGUF file, or None for the default (``AGRIRECIPE_GGUF``, else Gemma 3 270M
    from its PyPI package). ``narrow=False`` offers every crop, variety and
    state at every step (the model alone decides; for measurement).
    ``examples`` replaces the few-shot file.
    """

    name = "llm"

    def __init__(
        self,
        model: LanguageModel | str | Path | None = None,
        *,
        narrow: bool = True,
        examples: str | Path | None = None,
    ) -> None:
        self._model_arg = model
        self._model: LanguageModel | None = None
        self.narrow = narrow
        self._examples_path = examples
        self._grammars: dict[int, HierarchyGrammars] = {}
        self._lock = threading.Lock()

    @property
    def model(self) -> LanguageModel:
        """The language model (created on first use; its weights load on the first call)."""
        with self._lock:
            if self._model is None:
                from agrirecipe.localmodels import LlamaCppModel, default_language_model

                arg = self._model_arg
                if arg is None:
                    self._model = default_language_model()
                elif isinstance(arg, str | Path):
                    self._model = LlamaCppModel(arg)
                else:
                    self._model = arg
            return self._model

    @functools.cached_property
    def prefix(self) -> str:
        """The rendered few-shot document every record continues."""
        return render_examples(load_examples(self._examples_path))

    def grammars(self, hierarchy: Hierarchy) -> HierarchyGrammars:
        """The grammars for ``hierarchy`` (built once per hierarchy object)."""
        cached = self._grammars.get(id(hierarchy))
        if cached is None or cached.hierarchy is not hierarchy:
            cached = HierarchyGrammars(hierarchy)
            self._grammars[id(hierarchy)] = cached
        return cached

    def choose(self, question: str, candidates: Sequence[str]) -> str:
        """The candidate the model picks to answer ``question``; always one of ``candidates``.

        For strategies that combine, e.g. ``choose('Which crop is "cherry" in
        "cherry tomatoes beside the pears"?', ["Tomato", "Cherry"])``.
        """
        options = list(dict.fromkeys(candidates))
        if not options:
            raise ConfigurationError("choose() needs at least one candidate", stage="llm")
        if len(options) == 1:
            return options[0]
        prompt = _choice_prefix() + f"Question: {question}\nOptions: {', '.join(options)}\nAnswer:"
        longest = max(len(option) for option in options)
        answer = self.model.complete(
            prompt, grammar=choice_grammar(options), max_tokens=longest + 4
        )
        return answer.strip()

    # --- resolution ---

    def resolve_intent(self, prompt: str, context: ResolveContext) -> SceneIntent:
        """What ``prompt`` asks for, read by the language model under grammars."""
        from agrirecipe.resolve._lexicon import build_lexicon

        request = " ".join(prompt.split())
        words = prompt_words(request)
        if not words:
            raise PromptError(
                "the prompt is empty",
                stage="resolve",
                hint="describe the fields, e.g. 'a Gala apple orchard next to a carrot field'",
            )
        grammars = self.grammars(context.hierarchy)
        lexicon = build_lexicon(context.hierarchy, context.knowledge)
        model = self.model
        counter = getattr(model, "count_tokens", None)
        size = int(counter(request)) if callable(counter) else len(words)
        if size > MAX_PROMPT_TOKENS:
            raise PromptError(
                f"the prompt is {size} tokens; the llm resolver reads at most {MAX_PROMPT_TOKENS}",
                stage="resolve",
                hint="shorten the request or use resolver='hybrid'",
            )
        scene = _collect(lexicon, request)
        hemisphere = _hemisphere(scene, context)
        trace: list[TraceStep] = []
        warm = getattr(model, "warm", None)
        if callable(warm):
            warm(self.prefix)  # the few-shot prefix, from the on-disk cache after the first run
        record = _Record(model, self.prefix, request)

        # 1. decompose, 2. validate and repair. The model is asked only where two
        # fields have no joining word between them: elsewhere the joining words fix
        # every boundary and its answer would be overruled (a third of the strategy's
        # time went to that answer; docs/EVALUATION.md).
        groups = _field_groups(lexicon, request, context.hierarchy)
        model_parts: list[_Part] | None = None
        if _boundary_open(*groups) or not self.narrow:
            answer = record.answer(
                "Parts:", grammars.parts_grammar(words), max_tokens=2 * size + 24
            )
            model_parts = _parse_parts(answer, words, request)
            detail = "model parts: " + (" | ".join(p.text for p in model_parts) or NONE)
        elif len(groups[0]) > 1:
            detail = "parts fixed by the joining words (the model is not asked)"
        else:
            detail = "at most one field named: one part (the model is not asked)"
        trace.append(TraceStep(stage="decompose", subject="request", detail=detail))
        parts, shared, repairs = _repair_parts(model_parts, words, request, lexicon, groups)
        trace += [TraceStep(stage="validate", subject="parts", detail=r) for r in repairs]
        if not parts:
            if scene.other:
                raise _unknown(*next(iter(scene.other.items())), context.hierarchy)
            raise PromptError(
                f"{prompt.strip()!r} does not ask for crops or fields",
                stage="resolve",
                hint="name crops (e.g. 'apples', 'carrots'), varieties or kinds of field; "
                "known crops: " + ", ".join(context.hierarchy.crops),
            )
        shown = sorted([*parts, *shared], key=lambda p: p.first)
        record.write("Parts: " + " | ".join(p.text for p in shown) + "\n")
        suffix = "".join(f" + {p.text}" for p in shared)
        shared_raw = " ".join(p.raw for p in shared)
        _check_adjacent_names(lexicon, request)
        _check_plots(lexicon, request, context.hierarchy)

        # 3-5. one subquery per part
        fields: list[FieldIntent] = []
        first_field: list[int] = []
        common = _collect(lexicon, shared_raw, hemisphere) if shared_raw else None
        for number, part in enumerate(parts, start=1):
            evidence = _collect(lexicon, part.raw, hemisphere)
            if common is not None:
                for key, stated in common.states.items():
                    evidence.states.setdefault(key, list(stated))  # the part's own words win
            record.write(f"Part {number}: {part.text}{suffix}\n")
            values = self._read_part(record, grammars, part, evidence)
            trace.append(
                TraceStep(
                    stage="retrieve",
                    subject=part.text,
                    detail=_describe(evidence),
                    candidates=tuple(evidence.candidates[:8]),
                )
            )
            trace.append(
                TraceStep(
                    stage="llm",
                    subject=part.text,
                    detail="; ".join(f"{k}: {v}" for k, v in values.items()),
                )
            )
            first_field.append(len(fields))
            fields += _field_intents(values, part, evidence, context.hierarchy)
            if len(fields) > MAX_FIELDS:
                raise PromptError(
                    f"the request asks for {len(fields)} or more fields; a scene holds at most "
                    f"{MAX_FIELDS}",
                    stage="resolve",
                    hint="ask for fewer fields",
                )

        relations: list[RelationIntent] = []
        if len(parts) > 1:
            kinds = list(dict.fromkeys(scene.relations)) if self.narrow else None
            if kinds == []:
                record.write(f"Relations: {NONE}\n")
            elif kinds == ["next_to"] and len(parts) == 2 and len(scene.relations) == 1:
                # one "next to" between two fields reads one way only (it is symmetric)
                record.write("Relations: 1 next to 2\n")
                relations = _parse_relations(" 1 next to 2", first_field, ["next_to"])
            else:
                answer = record.answer(
                    "Relations:", grammars.relations_grammar(len(parts), kinds), max_tokens=48
                )
                record.write(f"Relations:{answer}")
                relations = _parse_relations(answer, first_field, grammars.relation_kinds)
                trace.append(TraceStep(stage="llm", subject="relations", detail=answer.strip()))
            relations += _between_counted(scene, relations, first_field, len(fields))
        elif len(fields) > 1 and "next_to" in scene.relations:
            # "two different fruits side by side": one counted part's fields in a row
            relations = [
                RelationIntent(kind="next_to", subject=b, objects=(a,))
                for a, b in itertools.pairwise(range(len(fields)))
            ]

        trace.append(
            TraceStep(
                stage="llm",
                subject="model",
                detail=f"asked {record.asked} time(s); every other line had one candidate",
            )
        )
        seasons = {f.season for f in fields if f.season is not None}
        return SceneIntent(
            prompt=prompt,
            fields=tuple(fields),
            relations=tuple(relations),
            season=next(iter(seasons)) if len(seasons) == 1 else None,
            hemisphere=hemisphere if scene.hemisphere or scene.place else None,
            latitude_deg=(scene.place or scene.hemisphere or (None, None))[1],
            place=scene.place[0] if scene.place else None,
            trace=tuple(trace),
            resolver=self.name,
        )

    def _read_part(
        self,
        record: _Record,
        grammars: HierarchyGrammars,
        part: _Part,
        evidence: _Evidence,
    ) -> dict[str, str]:
        """The part's record, one line per attribute, each a choice among its candidates."""
        hierarchy = grammars.hierarchy
        values: dict[str, str] = {}
        if self.narrow:
            counts = [str(n) for n in dict.fromkeys(evidence.counts)] or ["1"]
        else:
            counts = [str(n) for n in range(1, 10)]
        values["count"] = record.choose("Count", counts)
        crop_options = self._crop_options(grammars, evidence)
        crop = record.choose("Crop", crop_options, grammars.crop_grammar(crop_options))
        values["crop"] = crop
        if crop == OTHER:
            answer = record.answer(
                "Name:", grammars.span_grammar(prompt_words(part.text)), max_tokens=48
            )
            record.write(f"Name:{answer}")
            values["name"] = answer.strip()
            return values
        if crop.startswith(ANY_PREFIX):
            options = ["yes"] if evidence.distinct and self.narrow else ["yes", "no"]
            if values["count"] == "1" and self.narrow:
                options = ["no"]  # one field differs from no other
            values["different"] = record.choose("Different", options)
        else:
            options = self._variety_options(hierarchy, crop, evidence)
            values["variety"] = record.choose(
                "Variety", options, grammars.variety_grammar(crop, options)
            )
        count = int(values["count"])
        for key in _STATE_KEYS:
            allowed = grammars.values(key)
            found = [v for v in evidence.states.get(key, []) if v in allowed]
            if self.narrow and len(found) > 1:
                if len(found) != count:
                    raise PromptError(
                        f"{part.raw!r} states two different {key} values: {' and '.join(found)}",
                        stage="resolve",
                        hint=f"state one {key} per field",
                    )
                # "two fields, one healthy and one with blight": one value per field.
                values[f"{key} per field"] = "|".join(found)
                record.write(f"{key.capitalize()}: {found[0]}\n")
                values[key] = found[0]
                continue
            # With nothing retrieved the model is not asked: offered every value,
            # it named one for 90% of the parts that state none (measured).
            options = (found or [NONE]) if self.narrow else [*allowed, NONE]
            values[key] = record.choose(
                key.capitalize(), options, grammars.state_grammar(key, options)
            )
        if re.search(r"\d", part.text) or (evidence.sizes and self.narrow):
            options = evidence.sizes if self.narrow else [*evidence.sizes, NONE]
            values["size"] = record.choose("Size", options or [NONE])
        return values

    def _crop_options(self, grammars: HierarchyGrammars, evidence: _Evidence) -> list[str]:
        """The crop line's options: retrieved crops, else generic categories, else everything."""
        everything = list(grammars.crop_options())
        if not self.narrow:
            return everything
        crops = list(evidence.crops)
        crops += [crop for crop, _ in evidence.varieties if crop not in crops]
        if len(evidence.plot_options) == 1 and evidence.plot_options[0] not in crops:
            crops.append(evidence.plot_options[0])  # "a vineyard" can only be grapes
        options = list(crops)
        if not evidence.names_a_plant:
            categories = list(evidence.categories)
            if evidence.plot_category:
                categories.append(evidence.plot_category)
            categories += [grammars.hierarchy.crops[c].category for c in evidence.plot_options]
            options += [ANY_PREFIX + c for c in dict.fromkeys(categories)]
        if evidence.other:
            options.append(OTHER)
        return options or everything

    def _variety_options(self, hierarchy: Hierarchy, crop: str, evidence: _Evidence) -> list[str]:
        """The variety line's options: the crop's varieties the words name (or all, unnarrowed).

        A variety named outright must be chosen: "none" stays open only when
        every reading is weak ("golden", "cherry") or a typo match.
        """
        if not self.narrow:
            return [*(v.name for v in hierarchy.crops[crop].varieties), NONE]
        named = [v for c, v in evidence.varieties if c == crop]
        strong = [v for v in named if (crop, v) not in evidence.weak_varieties]
        return strong if strong else [*named, NONE]


# --- helpers ---------------------------------------------------------------------


@functools.lru_cache(maxsize=1)
def _choice_prefix() -> str:
    data = yaml.safe_load((DATA_DIR / "choose.yaml").read_text(encoding="utf-8"))
    blocks = [
        f"Question: {ex['question']}\nOptions: {', '.join(ex['options'])}\nAnswer: {ex['answer']}\n"
        for ex in data["examples"]
    ]
    return "\n".join(blocks) + "\n"


def _hemisphere(scene: _Evidence, context: ResolveContext) -> Hemisphere | None:
    if context.latitude_deg is not None:
        return "south" if context.latitude_deg < 0 else "north"
    location = scene.place or scene.hemisphere
    if location is None:
        return None
    return "south" if location[1] < 0 else "north"


def _describe(evidence: _Evidence) -> str:
    found = [
        *evidence.crops,
        *(f"{c}/{v}" for c, v in evidence.varieties),
        *(ANY_PREFIX + c for c in evidence.categories),
        *(f"{OTHER}: {name}" for name in evidence.other),
        *(f"{key}: {'/'.join(v)}" for key, v in evidence.states.items()),
    ]
    return "retrieved " + (", ".join(found) if found else "nothing")


def _field_intents(
    values: Mapping[str, str], part: _Part, evidence: _Evidence, hierarchy: Hierarchy
) -> list[FieldIntent]:
    """Validate a part's record and turn it into one FieldIntent per counted field."""
    crop = values["crop"]
    if crop == OTHER:
        name = values.get("name") or part.text
        nearest = evidence.other.get(name) or next(iter(evidence.other.values()), ())
        raise _unknown(name, nearest, hierarchy)
    count = int(values.get("count", "1"))
    states: dict[str, Any] = {
        key: None if values.get(key, NONE) == NONE else values[key] for key in _STATE_KEYS
    }
    per_field = [
        {
            key: values[f"{key} per field"].split("|")[index]
            for key in _STATE_KEYS
            if f"{key} per field" in values
        }
        for index in range(count)
    ]
    size = _parse_size(values.get("size", NONE), evidence)
    if crop.startswith(ANY_PREFIX):
        category = crop[len(ANY_PREFIX) :]
        options = tuple(c for c in evidence.plot_options if hierarchy.crops[c].category == category)
        distinct = values.get("different") == "yes" and count > 1
        return [
            FieldIntent(
                text=part.raw,
                mention=evidence.categories.get(category),
                noun=evidence.noun,
                category=category,
                generic=True,
                crop_options=options,
                distinct_group=0 if distinct else None,
                size=size,
                **{**states, **per_field[index]},
            )
            for index in range(count)
        ]
    variety = values.get("variety", NONE)
    _check_contradiction(crop, variety, evidence, part)
    distinct = evidence.distinct and count > 1
    if distinct and evidence.categories and variety == NONE:
        # "three different fruit crops, all of them apples"
        raise PromptError(
            f"{part.raw!r} asks for {count} different crops, but names only {crop}",
            stage="resolve",
            hint="name a different crop for each field, or drop 'different' to have "
            f"several {crop.lower()} fields",
        )
    mention = evidence.varieties.get((crop, variety)) or evidence.crops.get(crop)
    return [
        FieldIntent(
            text=part.raw,
            mention=mention,
            noun=evidence.noun,
            crop=crop,
            variety=None if variety == NONE else variety,
            size=size,
            # "two different apple orchards": different varieties of the crop
            distinct_group=0 if distinct else None,
            **{**states, **per_field[index]},
        )
        for index in range(count)
    ]


def _parse_size(answer: str, evidence: _Evidence) -> SizeIntent | None:
    """``"50 x 100 m"`` or ``"2 ha"`` (numbers and units are the part's own words)."""
    if not answer or answer == NONE:
        return None
    *numbers_text, unit = answer.split(" ")
    kind, factor = evidence.units.get(unit, ("length_unit", 1.0))
    try:
        numbers = [float(t) for t in numbers_text if t != "x"]
    except ValueError:
        return None  # not a size the words state; the grammar only offers those
    if any(n <= 0 for n in numbers):
        raise PromptError(
            f"a field cannot measure {answer}", stage="resolve", hint="sizes must be positive"
        )
    if len(numbers) == 2 and kind == "length_unit":
        return SizeIntent(width_m=numbers[0] * factor, length_m=numbers[1] * factor, text=answer)
    if len(numbers) == 1 and kind == "area_unit":
        return SizeIntent(area_m2=numbers[0] * factor, text=answer)
    return None


def _parse_relations(
    answer: str, first_field: Sequence[int], kinds: Sequence[str]
) -> list[RelationIntent]:
    """``"1 next to 2, 3 between 1 and 2"`` -> relations between the parts' first fields."""
    relations: list[RelationIntent] = []
    for piece in answer.strip().split(", "):
        between = re.fullmatch(r"(\d) between (\d) and (\d)", piece)
        if between:
            subject, *objects = (first_field[int(g) - 1] for g in between.groups())
            if len({subject, *objects}) == 3:
                relations.append(
                    RelationIntent(
                        kind="between", subject=subject, objects=tuple(objects), text=piece
                    )
                )
            continue
        match = re.fullmatch(r"(\d) ([a-z ]+) (\d)", piece)
        if match is None:
            continue
        kind = match.group(2).replace(" ", "_")
        subject, target = (first_field[int(match.group(i)) - 1] for i in (1, 3))
        if kind in kinds and subject != target:
            relations.append(
                RelationIntent.model_validate(
                    {"kind": kind, "subject": subject, "objects": (target,), "text": piece}
                )
            )
    return relations


def _between_counted(
    scene: _Evidence,
    relations: Sequence[RelationIntent],
    first_field: Sequence[int],
    field_count: int,
) -> list[RelationIntent]:
    """ "A between two fields of B": one part counted twice holds both sides."""
    if "between" not in scene.relations or any(r.kind == "between" for r in relations):
        return []
    if len(first_field) != 2:
        return []
    ends = [*first_field[1:], field_count]
    sizes = [end - start for start, end in zip(first_field, ends, strict=True)]
    if sorted(sizes) != [1, 2]:
        return []
    single = first_field[sizes.index(1)]
    pair = first_field[sizes.index(2)]
    return [RelationIntent(kind="between", subject=single, objects=(pair, pair + 1))]


def _check_adjacent_names(lexicon: Lexicon, request: str) -> None:
    """A variety written right before another crop's name ("Granny Smith bananas")."""
    from agrirecipe.resolve._lexicon import tokenize

    items = lexicon.tag(tokenize(request))
    for left, right in itertools.pairwise(items):
        if request[left.end : right.start].strip():
            continue
        varieties = [s for s in left.senses if s.kind == "variety" and not s.weak]
        crops = {s.value for s in right.senses if s.kind == "crop"}
        if (
            varieties
            and crops
            and not left.has("crop")
            and not any(v.crop in crops for v in varieties)
        ):
            variety = varieties[0]
            crop = sorted(crops)[0]
            raise PromptError(
                f"{left.raw!r} is a variety of {variety.crop}, not of {crop} "
                f"(in {left.raw + ' ' + right.raw!r})",
                stage="resolve",
                hint=f"name a {crop} variety, or ask for {variety.value} {variety.crop}",
            )


def _check_plots(lexicon: Lexicon, request: str, hierarchy: Hierarchy) -> None:
    """A plot that cannot hold the crop written into it ("a vineyard of cabbages").

    The same reading of the words as the lexical strategies', so that a
    correction ("..., no, I mean ...") still takes the contradiction back.
    """
    from agrirecipe.resolve._decompose import MentionBuilder, decompose
    from agrirecipe.resolve._lexicon import tokenize
    from agrirecipe.resolve._scan import assign_roles, read_sizes
    from agrirecipe.resolve._structure import apply_corrections, raise_conflicts

    items = lexicon.tag(tokenize(request))
    assign_roles(items)
    builder = MentionBuilder({c.name: c.category for c in hierarchy.crops.values()})
    clauses = decompose(read_sizes(items), builder)
    apply_corrections(clauses)
    raise_conflicts(clauses)


def _check_contradiction(crop: str, variety: str, evidence: _Evidence, part: _Part) -> None:
    """A variety of another crop named beside this crop ("a Gala pear orchard")."""
    if variety != NONE or crop not in evidence.crops:
        return
    for (other_crop, other_variety), words in evidence.varieties.items():
        if other_crop != crop and (other_crop, other_variety) not in evidence.weak_varieties:
            raise PromptError(
                f"{words!r} is a variety of {other_crop}, not of {crop} (in {part.raw!r})",
                stage="resolve",
                hint=f"name a {crop} variety, or ask for {other_variety} {other_crop}",
            )


def _unknown(name: str, nearest: Sequence[str], hierarchy: Hierarchy) -> UnknownCropError:
    """The error for a plant the hierarchy does not hold, with the nearest known crops."""
    known = tuple(c for c in nearest if c in hierarchy.crops)
    if not known:
        from rapidfuzz import process

        names = {a: c.name for c in hierarchy.crops.values() for a in (c.name, *c.aliases)}
        matches = process.extract(name, list(names), limit=10)
        known = tuple(dict.fromkeys(names[str(m[0])] for m in matches))[:3]
    return UnknownCropError(
        f"{name!r} is not a crop of the hierarchy", requested=name, nearest=known, stage="resolve"
    )
