"""Training examples: development prompts with the records the finetuned strategy asks.

The llm strategy does not ask for JSON: it continues a plain-text record one
line at a time, each line under a grammar (see :mod:`agrirecipe.resolve.llm`).
The finetuned strategy asks the same lines, each reading only what it depends
on (a *local* record: the request, then one part's lines; or the request, then
the parts' words and the relations line). A prompt therefore gives one
training example per part, plus one for its relations when it has several
parts, filled from the prompt's ground truth and rendered by the strategy's
own :func:`~agrirecipe.resolve.llm.render_local`, so the fine-tuned model
learns exactly the lines the grammars accept::

    Request: Bing cherries ready for harvest in summer      <- context (no loss)
    Part 1: Bing cherries ready for harvest in summer       <- context
    Count: 1                                                <- " 1" is learnt
    Crop: Cherry                                            <- " Cherry" is learnt
    ...

The request is normalised and split into parts the way the strategy does it
without a model (texting forms expanded, stated row geometry taken out, parts
cut at the joining words). Each line's value is the truth's, and it must be one
of the options the strategy would offer there (the same narrowing); a prompt
whose truth cannot be written that way is skipped with a reason, so the
examples never teach an answer the grammar forbids. Skipped: invalid prompts,
truths that allow several crops ("an orchard"), ranges of field counts and
extra fields, parts whose boundaries the model would decide.

``limit`` bounds the prompts used (the development set has grown past 20,000
prompts; about 700 keep a training run within the hour the issue allows): the
``dev`` prompts are read in a seeded order until that many gave examples. The
split into training and held-out examples is seeded and by prompt id, so a
prompt's examples are all on one side. Only the ``dev`` split of the benchmark
is read; blind sets are never trained on.
"""

from __future__ import annotations

import hashlib
import json
import random
import re
from collections import Counter
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from agrirecipe._errors import AgrirecipeError
from agrirecipe.resolve._grammar import NONE

if TYPE_CHECKING:
    from agrirecipe.evaluation import BenchmarkPrompt
    from agrirecipe.hierarchy import Hierarchy
    from agrirecipe.knowledge import KnowledgeBase

__all__ = ["ExampleSet", "TrainingExample", "build_examples", "split_examples", "write_examples"]

_STATE_KEYS = ("stage", "season", "health")


@dataclass(frozen=True, slots=True)
class TrainingExample:
    """One local record of a development prompt: ``context`` is given, ``target`` is learnt."""

    prompt_id: str
    context: str  # "Request: <normalised request>\n"
    target: str  # the record's lines after the request (one part's, or the relations')


@dataclass(frozen=True, slots=True)
class ExampleSet:
    """The examples built from a benchmark, and why the other prompts were skipped."""

    examples: tuple[TrainingExample, ...]
    skipped: dict[str, int]

    @property
    def prompts(self) -> int:
        """How many prompts gave the examples."""
        return len({example.prompt_id for example in self.examples})

    @property
    def digest(self) -> str:
        """SHA-256 of the examples (recorded with the adapter: the exact training data)."""
        payload = json.dumps([[e.prompt_id, e.context, e.target] for e in self.examples])
        return hashlib.sha256(payload.encode("utf-8")).hexdigest()


class _SkipError(AgrirecipeError):
    """The prompt's truth cannot be written as a record the grammars accept (never escapes:
    :func:`build_examples` counts it as the reason the prompt was skipped)."""


def build_examples(
    prompts: Iterable[BenchmarkPrompt] | None = None,
    *,
    hierarchy: Hierarchy | None = None,
    knowledge: KnowledgeBase | None = None,
    limit: int | None = None,
    seed: int = 0,
) -> ExampleSet:
    """Local records for the ``dev`` prompts (default: every shipped benchmark prompt file).

    With ``limit``, the prompts are read in an order shuffled by ``seed`` until
    ``limit`` of them gave examples; the rest are counted as not read.
    """
    from agrirecipe.hierarchy import default_hierarchy
    from agrirecipe.knowledge import default_knowledge_base
    from agrirecipe.resolve._lexicon_build import build_lexicon
    from agrirecipe.resolve.llm import LlmResolver

    if prompts is None:
        from agrirecipe.evaluation import load_benchmark

        prompts = load_benchmark().prompts
    hierarchy = hierarchy or default_hierarchy()
    knowledge = knowledge or default_knowledge_base()
    lexicon = build_lexicon(hierarchy, knowledge)
    strategy = LlmResolver()  # for its narrowing only; no model is loaded
    grammars = strategy.grammars(hierarchy)
    examples: list[TrainingExample] = []
    skipped: Counter[str] = Counter()
    items = list(prompts)
    if limit is not None:
        items.sort(key=lambda item: item.id)
        random.Random(seed).shuffle(items)
    used = 0
    for item in items:
        if item.split != "dev":
            skipped["not in the dev split"] += 1
            continue
        if limit is not None and used >= limit:
            skipped[f"not read (the limit of {limit} prompts was reached)"] += 1
            continue
        try:
            examples += _examples(item, lexicon, strategy, grammars)
        except _SkipError as reason:
            skipped[str(reason)] += 1
        else:
            used += 1
    return ExampleSet(examples=tuple(examples), skipped=dict(sorted(skipped.items())))


def split_examples(
    examples: Sequence[TrainingExample], *, heldout_fraction: float, seed: int
) -> tuple[list[TrainingExample], list[TrainingExample]]:
    """A seeded split by prompt id into (train, held-out) examples: a prompt's examples are
    all on one side, the same side every time; ``heldout_fraction`` of the prompts are held out."""
    ids = sorted({example.prompt_id for example in examples})
    random.Random(seed).shuffle(ids)
    count = round(len(ids) * heldout_fraction)
    if heldout_fraction > 0 and len(ids) > 1:
        count = max(1, count)
    heldout = set(ids[:count])
    order = {prompt_id: index for index, prompt_id in enumerate(ids)}
    ordered = sorted(examples, key=lambda e: (order[e.prompt_id], e.context, e.target))
    return (
        [e for e in ordered if e.prompt_id not in heldout],
        [e for e in ordered if e.prompt_id in heldout],
    )


def write_examples(examples: Sequence[TrainingExample], path: str | Path) -> None:
    """Write examples as JSON lines (for inspection; the trainer rebuilds them)."""
    with Path(path).open("w", encoding="utf-8") as handle:
        for example in examples:
            record = {"id": example.prompt_id, "context": example.context}
            record["target"] = example.target
            handle.write(json.dumps(record, ensure_ascii=False) + "\n")


# --- one prompt ------------------------------------------------------------------


def _examples(
    item: BenchmarkPrompt, lexicon: Any, strategy: Any, grammars: Any
) -> list[TrainingExample]:
    from agrirecipe.resolve._casual import expand_casual
    from agrirecipe.resolve._geometry import strip_geometry
    from agrirecipe.resolve._grammar import prompt_words
    from agrirecipe.resolve.llm import render_local
    from agrirecipe.resolve.llm._evidence import _collect, _hemisphere
    from agrirecipe.resolve.llm._parts import _boundary_open, _field_groups, _repair_parts

    if item.invalid:
        raise _SkipError("invalid prompt (an error, not a record)")
    if item.field_count is not None or item.extra_field is not None:
        raise _SkipError("a range of field counts or an extra field")
    if not item.fields:
        raise _SkipError("no truth fields")
    for field in item.fields:
        if field.crop is None or len(field.crop) != 1:
            raise _SkipError("the truth allows several crops")
    stripped, _ = strip_geometry(" ".join(expand_casual(item.prompt).split()))
    request = " ".join(stripped.split())
    words = prompt_words(request)
    hierarchy = grammars.hierarchy
    groups = _field_groups(lexicon, request, hierarchy)
    if _boundary_open(*groups):
        raise _SkipError("the model would decide the part boundaries")
    parts, shared, _ = _repair_parts(None, words, request, lexicon, groups)
    if not parts:
        raise _SkipError("no part names a plant")
    hemisphere = _hemisphere(_collect(lexicon, request), _NoLatitude())  # type: ignore[arg-type]
    shared_raw = " ".join(p.raw for p in shared)
    common = _collect(lexicon, shared_raw, hemisphere) if shared_raw else None
    owners = _assign_fields(item, parts, lexicon, hemisphere)
    rendered_parts: list[tuple[int, dict[str, Any]]] = []
    for part, fields in zip(parts, owners, strict=True):
        evidence = _collect(lexicon, part.raw, hemisphere)
        if common is not None:
            for key, stated in common.states.items():
                evidence.states.setdefault(key, list(stated))
        rendered_parts.append(
            (part.first, _part_values(part, fields, evidence, strategy, grammars))
        )
    rendered_parts += [(p.first, {"text": p.text, "shared": True}) for p in shared]
    rendered_parts.sort(key=lambda pair: pair[0])
    example: dict[str, Any] = {
        "request": request,
        "parts": [values for _, values in rendered_parts],
    }
    if len(parts) > 1:
        example["relations"] = _relations(item, owners)
    return [
        TrainingExample(prompt_id=item.id, context=context, target=target)
        for context, target in render_local(example)
    ]


class _NoLatitude:
    """The part of a resolve context :func:`_hemisphere` reads: no latitude was passed."""

    latitude_deg = None


def _assign_fields(
    item: BenchmarkPrompt, parts: Sequence[Any], lexicon: Any, hemisphere: Any
) -> list[list[Any]]:
    """The truth fields each part describes: matched by the one crop the part's words name."""
    from agrirecipe.resolve.llm._evidence import _collect

    if len(parts) == 1:
        return [list(item.fields)]
    owners: list[list[Any]] = [[] for _ in parts]
    taken: set[int] = set()
    for index, part in enumerate(parts):
        evidence = _collect(lexicon, part.raw, hemisphere)
        crops = set(evidence.crops) | {crop for crop, _ in evidence.varieties}
        if len(crops) != 1:
            raise _SkipError("a part names no crop or several")
        crop = next(iter(crops))
        for number, field in enumerate(item.fields):
            if number not in taken and field.crop == (crop,):
                owners[index].append(field)
                taken.add(number)
        if not owners[index]:
            raise _SkipError("a part's crop is not in the truth")
    if len(taken) != len(item.fields):
        raise _SkipError("a truth field matches no part")
    return owners


def _part_values(
    part: Any, fields: Sequence[Any], evidence: Any, strategy: Any, grammars: Any
) -> dict[str, Any]:
    """One part's lines (the fewshot.yaml shape), each checked against the strategy's options."""
    first = fields[0]
    keys = ("crop", "variety", *_STATE_KEYS)
    if any(
        f.allowed(k) != first.allowed(k) or (k in f.inferred) != (k in first.inferred)
        for f in fields
        for k in keys
    ):
        raise _SkipError("one part's fields differ")
    counts = [str(n) for n in dict.fromkeys(evidence.counts)] or ["1"]
    count = str(len(fields))
    if count not in counts:
        raise _SkipError("the field count is not among the numbers the words give")
    crop = first.crop[0]
    if crop not in strategy._crop_options(grammars, evidence):
        raise _SkipError("the crop is not among the retrieved options")
    variety = first.variety[0] if first.variety and len(first.variety) == 1 else NONE
    if first.variety and len(first.variety) > 1:
        raise _SkipError("the truth allows several varieties")
    if variety not in strategy._variety_options(grammars.hierarchy, crop, evidence):
        raise _SkipError("the variety is not among the retrieved options")
    values: dict[str, Any] = {"text": part.text, "count": int(count), "crop": crop}
    values["variety"] = variety
    for key in _STATE_KEYS:
        allowed = first.allowed(key)
        truth = NONE if allowed is None or key in first.inferred else allowed[0]
        if allowed is not None and len(allowed) > 1:
            raise _SkipError(f"the truth allows several {key} values")
        found = [v for v in evidence.states.get(key, []) if v in grammars.values(key)]
        if len(found) > 1:
            raise _SkipError(f"a part states several {key} values")
        options = found or [NONE]
        if truth not in options:
            raise _SkipError(f"the {key} is not among the retrieved options")
        values[key] = truth
    if re.search(r"\d", part.text) or evidence.sizes:
        if len(evidence.sizes) > 1:
            raise _SkipError("a part states several sizes")
        values["size"] = evidence.sizes[0] if evidence.sizes else NONE
        if not re.search(r"\d", part.text):
            raise _SkipError("a size line the record renderer would not write")
    return values


def _relations(item: BenchmarkPrompt, owners: Sequence[Sequence[Any]]) -> str:
    """The truth's relations over part numbers (``1 next to 2, 3 between 1 and 2``)."""
    if not item.relations:
        return NONE
    part_of: dict[str, int] = {}
    for number, fields in enumerate(owners, start=1):
        for field in fields:
            if field.ref is not None:
                part_of[field.ref] = number
    rendered = []
    for relation in item.relations:
        try:
            subject = part_of[relation.subject]
            objects = [part_of[ref] for ref in relation.objects]
        except KeyError as exc:
            raise _SkipError("a relation names a field no part holds") from exc
        if relation.kind == "between":
            rendered.append(f"{subject} between {objects[0]} and {objects[1]}")
        else:
            rendered.append(f"{subject} {relation.kind.replace('_', ' ')} {objects[0]}")
    return ", ".join(rendered)
