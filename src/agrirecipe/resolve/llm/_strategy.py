"""The llm strategy: :class:`LlmResolver` and the record it continues for one prompt."""

from __future__ import annotations

import functools
import itertools
import re
import threading
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from agrirecipe._errors import ConfigurationError, PromptError
from agrirecipe.resolve._casual import expand_casual
from agrirecipe.resolve._geometry import GeometryMatch, merge_geometry, strip_geometry
from agrirecipe.resolve._grammar import (
    ANY_PREFIX,
    NONE,
    OTHER,
    HierarchyGrammars,
    choice_grammar,
    prompt_words,
)
from agrirecipe.resolve._intent import (
    FieldIntent,
    RelationIntent,
    ResolveContext,
    Resolver,
    SceneIntent,
    TraceStep,
)
from agrirecipe.resolve.llm._answers import _between_counted, _field_intents, _parse_relations
from agrirecipe.resolve.llm._checks import _check_adjacent_names, _check_plots, _unknown
from agrirecipe.resolve.llm._evidence import _collect, _describe, _Evidence, _hemisphere
from agrirecipe.resolve.llm._examples import (
    _STATE_KEYS,
    _choice_prefix,
    load_examples,
    render_examples,
)
from agrirecipe.resolve.llm._parts import (
    _boundary_open,
    _field_groups,
    _parse_parts,
    _Part,
    _repair_parts,
    _word_spans,
)

if TYPE_CHECKING:
    from agrirecipe.hierarchy import Hierarchy
    from agrirecipe.localmodels import LanguageModel

__all__ = ["MAX_FIELDS", "MAX_PROMPT_TOKENS", "LlmResolver"]

#: Longest request the strategy reads, in model tokens.
MAX_PROMPT_TOKENS = 160
#: Most fields one scene may hold (the limit of :class:`SceneIntent`).
MAX_FIELDS = 64


# --- the record ------------------------------------------------------------------


class _Record:
    """The few-shot document being continued for one prompt."""

    def __init__(self, model: LanguageModel, prefix: str, request: str) -> None:
        self.model = model
        self.text = prefix + f"Request: {request}\n"
        self.asked = 0

    def write(self, text: str) -> None:
        self.text += text

    def start_part(self, number: int, text: str, suffix: str) -> None:
        """Open part ``number``'s lines: its words, then the words every part shares."""
        self.write(f"Part {number}: {text}{suffix}\n")

    def context(self, label: str) -> str:
        """What the model reads before answering ``label``: the whole record so far."""
        return self.text + label

    def answer(self, label: str, grammar: str, *, max_tokens: int) -> str:
        """The model's continuation of ``label`` under ``grammar`` (not yet written)."""
        self.asked += 1
        return self.model.complete(self.context(label), grammar=grammar, max_tokens=max_tokens)

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


class _LocalRecord(_Record):
    """A record whose questions read only the lines they depend on (the finetuned strategy's).

    A part's line reads the request and that part's own lines; the parts line
    reads the request; the relations line reads the request and the parts' words
    (``Part 1: ...`` without the shared words or the answers). The full record
    repeats the request's words two or three times before the relations
    question, and evaluating it was nearly all of a prompt's time (about 5 ms a
    token on two cores): the local contexts are a third to a half as long, and
    the request they start with stays in the KV cache between questions.
    Rendered for training by :func:`~agrirecipe.resolve.llm.render_local`.
    """

    def __init__(self, model: LanguageModel, prefix: str, request: str) -> None:
        super().__init__(model, prefix, request)
        self.head = self.text
        self.parts: list[str] = []
        self.block = ""

    def write(self, text: str) -> None:
        super().write(text)
        self.block += text

    def start_part(self, number: int, text: str, suffix: str) -> None:
        self.parts.append(f"Part {number}: {text}\n")
        self.block = ""
        super().start_part(number, text, suffix)

    def context(self, label: str) -> str:
        if label == "Parts:":
            return self.head + label
        if label == "Relations:":
            return self.head + "".join(self.parts) + label
        return self.head + self.block + label


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
    #: Whether each question reads only the lines it depends on (:class:`_LocalRecord`)
    #: instead of the whole record; the few-shot document is written as whole records.
    local_records = False

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
        from agrirecipe.resolve._lexicon_build import build_lexicon

        # Texting forms are words; stated row geometry is read by its own reader and
        # given back to the field named before it (the model never sees "10 rows" as
        # a count of fields).
        stripped, geometry = strip_geometry(" ".join(expand_casual(prompt).split()))
        request = " ".join(stripped.split())
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
        record = (_LocalRecord if self.local_records else _Record)(model, self.prefix, request)

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
            record.start_part(number, part.text, suffix)
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

        fields = _attach_geometry(fields, parts, first_field, stripped, request, geometry)
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


def _attach_geometry(
    fields: list[FieldIntent],
    parts: Sequence[_Part],
    first_field: Sequence[int],
    stripped: str,
    request: str,
    geometry: Sequence[tuple[int, GeometryMatch]],
) -> list[FieldIntent]:
    """Give each stated geometry to the fields of the part named nearest before it."""
    if not geometry or not parts:
        return fields
    spans = _word_spans(request)
    starts = [spans[part.first][0] for part in parts]
    by_part: dict[int, list[GeometryMatch]] = {}
    for position, match in geometry:
        at = len(" ".join(stripped[:position].split()))  # the same place in the request
        before = [index for index, start in enumerate(starts) if start <= at]
        by_part.setdefault(before[-1] if before else 0, []).append(match)
    result = list(fields)
    ends = [*first_field[1:], len(fields)]
    for index, matches in by_part.items():
        spec = merge_geometry(matches, parts[index].raw)
        for number in range(first_field[index], ends[index]):
            result[number] = result[number].model_copy(update={"rows": spec})
    return result
