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
   offers runs of the request's own words, in order, without overlap.
2. **Validate and repair the parts** (deterministic): a part naming two plants
   is split between them, a plant no part covers joins the part next to it,
   words naming no plant are merged into a neighbour or, with "all", shared
   by every part; "none" on a request that names a crop is overruled.
3. **Retrieve** each part's candidates from the lexicon (exact and typo
   matches of hierarchy names and aliases, plot nouns, stage/season/health
   words, counts, plants the hierarchy does not hold).
4. **Per-field subquery**: one line per attribute, each a choice among the
   retrieved candidates. The model decides wherever more than one is left
   ("cherry" in "a cherry orchard": Cherry or Tomato; "Parts"; sizes;
   relations); a single candidate is written without asking, and with nothing
   retrieved every canonical value plus "none" is offered.
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
    numbers: list[str] = field(default_factory=list)
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


def _collect(lexicon: Lexicon, text: str, hemisphere: Hemisphere | None = None) -> _Evidence:
    """Candidates for one run of words (exact lexicon matches, then typo matches)."""
    from agrirecipe.resolve._lexicon import tokenize, vocabulary

    vocab = vocabulary()
    cues = {str(word) for word in vocab["month_cues"]}
    evidence = _Evidence()
    items = lexicon.tag(tokenize(text))
    for index, item in enumerate(items):
        senses: Sequence[Any] = item.senses
        if not senses and len(item.norm) >= 4 and item.norm.isalpha():
            match = lexicon.fuzzy(item.norm)
            if match is not None:
                senses = match[2]
                evidence.weak_varieties |= {
                    (str(s.crop), str(s.value)) for s in senses if s.kind == "variety"
                }
                evidence.candidates.append(
                    Candidate(value=match[0], score=match[1], source="fuzzy")
                )
        previous = items[index - 1] if index else None
        negated = previous is not None and previous.has("negation")
        after_cue = previous is not None and previous.norm in cues
        _add_senses(evidence, item, senses, negated=negated, after_cue=after_cue)
    for month in evidence.states.pop("month", []):
        season = _month_season(int(month), hemisphere, vocab["month_seasons_north"])
        evidence.add_state("season", season)
    return evidence


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
        elif kind in ("number", "quantity") and item.norm.isalpha() and 1 < int(sense.value) < 10:
            evidence.counts.append(int(sense.value))
        elif kind == "distinct":
            evidence.distinct = True
        elif kind == "all":
            evidence.all_words = True
        elif kind in ("area_unit", "length_unit"):
            evidence.units.setdefault(item.norm, (kind, float(sense.value)))
        elif kind == "relation":
            evidence.relations.append(str(sense.value))
        elif kind == "hemisphere":
            evidence.hemisphere = sense.value
        elif kind == "place":
            evidence.place = sense.value
    if item.norm[:1].isdigit():
        evidence.numbers.append(item.norm)


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


@dataclass(frozen=True, slots=True)
class _Mention:
    """Words naming a plant: a crop, one of its varieties, or a typo of either."""

    first: int
    last: int
    crop: str
    variety: str | None


def _mentions(lexicon: Lexicon, request: str) -> tuple[list[_Mention], list[int]]:
    """Every plant the request names, in order, and the words that join fields.

    A joining word ("and", a comma, "next to") is where a part naming two
    plants is best split.
    """
    from agrirecipe.resolve._lexicon import tokenize

    spans = _word_spans(request)

    def word_at(offset: int) -> int:
        for index, (_, end) in enumerate(spans):
            if offset < end:
                return index
        return len(spans) - 1

    found: list[_Mention] = []
    joins: list[int] = []
    for item in lexicon.tag(tokenize(request)):
        if item.has("conjunction", "separator", "relation"):
            joins.append(word_at(item.start))
        senses: Sequence[Any] = item.senses
        if not senses and len(item.norm) >= 4 and item.norm.isalpha():
            match = lexicon.fuzzy(item.norm)
            senses = match[2] if match is not None else ()
        crops = [s.value for s in senses if s.kind == "crop"]
        varieties = [s for s in senses if s.kind == "variety" and not (crops and s.weak)]
        first, last = word_at(item.start), word_at(item.end - 1)
        if crops:
            found.append(_Mention(first, last, str(crops[0]), None))
        elif varieties:
            found.append(_Mention(first, last, str(varieties[0].crop), str(varieties[0].value)))
    return found, joins


def _groups(mentions: Sequence[_Mention]) -> list[list[_Mention]]:
    """Consecutive mentions of one crop, with at most one variety, name one field."""
    groups: list[list[_Mention]] = []
    for mention in mentions:
        current = groups[-1] if groups else None
        if current is not None and current[0].crop == mention.crop:
            named = {m.variety for m in current if m.variety is not None}
            if mention.variety is None or not named or mention.variety in named:
                current.append(mention)
                continue
        groups.append([mention])
    return groups


def _repair_parts(
    parts: Sequence[_Part], words: Sequence[str], request: str, lexicon: Lexicon
) -> tuple[list[_Part], list[_Part], list[str]]:
    """Deterministic checks of the model's decomposition, and the repairs they imply.

    Returns the field parts, the shared parts ("all in autumn", read with every
    field) and a description of each repair. Afterwards every field part holds
    one group of plant mentions, or none for a generic field ("an orchard").
    """
    repairs: list[str] = []
    mentions, joins = _mentions(lexicon, request)
    groups = _groups(mentions)

    def groups_in(first: int, last: int) -> list[list[_Mention]]:
        return [g for g in groups if first <= g[0].first and g[-1].last <= last]

    # A part naming several plants is split between them.
    spans: list[list[int]] = []
    for part in parts:
        first = part.first
        inside = groups_in(part.first, part.last)
        for left, right in itertools.pairwise(inside):
            between = [j for j in joins if left[-1].last < j < right[0].first]
            cut = between[0] if between else left[-1].last + 1
            spans.append([first, cut - 1])
            first = cut
        spans.append([first, part.last])
    if len(spans) > len(parts):
        repairs.append("parts naming several plants were split between them")
    # A plant no part covers joins the part next to it when that part names no
    # other crop, or becomes a part of its own.
    for group in groups:
        first, last = group[0].first, group[-1].last
        if any(a <= first and last <= b for a, b in spans):
            continue
        touching = [s for s in spans if s[0] <= last + 1 and first - 1 <= s[1]]
        target = next(
            (s for s in touching if all(g[0].crop == group[0].crop for g in groups_in(*s))), None
        )
        words_text = " ".join(words[first : last + 1])
        if target is not None:
            target[0], target[1] = min(target[0], first), max(target[1], last)
            repairs.append(f"{words_text!r} joined the part next to it")
        else:
            spans.append([first, last])
            repairs.append(f"{words_text!r} names a plant no part covered; made it a part")
    spans.sort()
    # Parts naming neither a plant nor a field: shared ("all in autumn") or merged.
    kept: list[list[int]] = []
    leading: list[int] | None = None
    shared: list[_Part] = []
    for span in spans:
        part = _make_part(span[0], span[1], words, request)
        evidence = _collect(lexicon, part.raw)
        if evidence.names_a_field:
            if leading is not None and not kept:
                span[0] = min(span[0], leading[0])
                leading = None
            kept.append(span)
        elif evidence.all_words:
            shared.append(part)
            repairs.append(f"{part.text!r} applies to every field")
        elif kept:
            kept[-1][1] = max(kept[-1][1], span[1])
            repairs.append(f"{part.text!r} merged into the part before it")
        else:
            leading = span if leading is None else [leading[0], span[1]]
            repairs.append(f"{part.text!r} merged into the part after it")
    if not kept:
        whole = _make_part(0, len(words) - 1, words, request)
        if _collect(lexicon, whole.raw).names_a_field:
            repairs.append("the model found no field, but the request names a crop or field")
            kept, shared = [[0, len(words) - 1]], []
    merged: list[list[int]] = []
    for span in sorted(kept):
        if merged and span[0] <= merged[-1][1]:
            merged[-1][1] = max(merged[-1][1], span[1])
        else:
            merged.append(span)
    return [_make_part(a, b, words, request) for a, b in merged], shared, repairs


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
        record = _Record(model, self.prefix, request)

        # 1. decompose, 2. validate and repair
        answer = record.answer("Parts:", grammars.parts_grammar(words), max_tokens=2 * size + 24)
        model_parts = _parse_parts(answer, words, request)
        trace.append(
            TraceStep(
                stage="decompose",
                subject="request",
                detail="model parts: " + (" | ".join(p.text for p in model_parts) or NONE),
            )
        )
        parts, shared, repairs = _repair_parts(model_parts, words, request, lexicon)
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

        # 3-5. one subquery per part
        fields: list[FieldIntent] = []
        first_field: list[int] = []
        for number, part in enumerate(parts, start=1):
            evidence = _collect(lexicon, f"{part.raw} {shared_raw}".strip(), hemisphere)
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

        relations: list[RelationIntent] = []
        if len(parts) > 1:
            kinds = list(dict.fromkeys(scene.relations)) if self.narrow else None
            if kinds == []:
                record.write(f"Relations: {NONE}\n")
            else:
                answer = record.answer(
                    "Relations:", grammars.relations_grammar(len(parts), kinds), max_tokens=48
                )
                record.write(f"Relations:{answer}")
                relations = _parse_relations(answer, first_field, grammars.relation_kinds)
                trace.append(TraceStep(stage="llm", subject="relations", detail=answer.strip()))

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
            values["different"] = record.choose("Different", options)
        else:
            options = self._variety_options(hierarchy, crop, evidence)
            values["variety"] = record.choose(
                "Variety", options, grammars.variety_grammar(crop, options)
            )
        for key in _STATE_KEYS:
            allowed = grammars.values(key)
            found = [v for v in evidence.states.get(key, []) if v in allowed]
            # With nothing retrieved the model is not asked: offered every value,
            # it named one for 90% of the parts that state none (measured).
            options = (found or [NONE]) if self.narrow else [*allowed, NONE]
            values[key] = record.choose(
                key.capitalize(), options, grammars.state_grammar(key, options)
            )
        if re.search(r"\d", part.text):
            numbers = list(dict.fromkeys(evidence.numbers))
            if numbers and evidence.units:
                answer = record.answer(
                    "Size:", grammars.size_grammar(numbers, list(evidence.units)), max_tokens=24
                )
                record.write(f"Size:{answer}")
                values["size"] = answer.strip()
            else:
                record.write(f"Size: {NONE}\n")
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
                **states,
            )
            for _ in range(count)
        ]
    variety = values.get("variety", NONE)
    _check_contradiction(crop, variety, evidence, part)
    mention = evidence.varieties.get((crop, variety)) or evidence.crops.get(crop)
    return [
        FieldIntent(
            text=part.raw,
            mention=mention,
            noun=evidence.noun,
            crop=crop,
            variety=None if variety == NONE else variety,
            size=size,
            **states,
        )
        for _ in range(count)
    ]


def _parse_size(answer: str, evidence: _Evidence) -> SizeIntent | None:
    """``"50 x 100 m"`` or ``"2 ha"`` (numbers and units are the part's own words)."""
    if not answer or answer == NONE:
        return None
    *numbers_text, unit = answer.split(" ")
    kind, factor = evidence.units.get(unit, ("length_unit", 1.0))
    numbers = [float(t) for t in numbers_text if t != "x"]
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
