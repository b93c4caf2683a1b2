"""The "rules" strategy: the lexicon plus rapidfuzz for typos, no model.

:class:`LexicalResolver` is the shared base of the lexical strategies: it
reads the prompt with :class:`~agrirecipe.resolve._parse.PromptReader` and
lets subclasses decide how unknown words are read and how the nearest known
crops to an unknown one are found.
"""

from __future__ import annotations

from collections.abc import Sequence

from agrirecipe.resolve._intent import Candidate, ResolveContext, Resolver, SceneIntent, TraceStep
from agrirecipe.resolve._lexicon import (
    Item,
    Lexicon,
    Sense,
    normalise,
    number_value,
)
from agrirecipe.resolve._lexicon_build import build_lexicon
from agrirecipe.resolve._parse import PromptReader

__all__ = ["LexicalResolver", "RulesResolver", "fuzzy_unknown_words", "nearest_by_spelling"]

# Senses a misspelt word may be read together with ("golden delicous", "pink lday").
# ("goldn acre cabbages": "acre" inside a name, never after a number)
_SOFT_KINDS = frozenset({"crop", "variety", "category", "filler", "area_unit"})
_WINDOW = 3


def _is_unknown(item: Item) -> bool:
    return not item.senses and number_value(item.norm) is None and item.norm.isalpha()


def _soft(item: Item) -> bool:
    if not item.senses:
        return item.norm.isalpha()
    return all(sense.kind in _SOFT_KINDS for sense in item.senses) or _filler(item)


def _filler(item: Item) -> bool:
    """A short function word ("in", "the"): never the first or last word of a misspelt name."""
    return (
        len(item.norm) < 4
        and bool(item.senses)
        and all(sense.kind in ("filler", "number", "of") for sense in item.senses)
    )


def fuzzy_unknown_words(items: list[Item], lexicon: Lexicon) -> tuple[list[Item], list[TraceStep]]:
    """Read each unknown word as the lexicon phrase it most likely misspells (rapidfuzz).

    Windows of up to three words around the unknown one are tried, so a typo
    inside a multi-word name ("golden delicous", "cabernet sauvingon") is
    matched as the whole name. Words that stay unknown are left as they are.
    """
    out = list(items)
    steps: list[TraceStep] = []
    index = 0
    while index < len(out):
        if not _is_unknown(out[index]):
            index += 1
            continue
        best: tuple[float, int, int, str, tuple[Sense, ...]] | None = None
        for start in range(max(0, index - _WINDOW + 1), index + 1):
            for end in range(index + 1, min(len(out), start + _WINDOW) + 1):
                window = out[start:end]
                if not all(_soft(w) for w in window):
                    continue
                if (
                    start
                    and number_value(out[start - 1].norm) is not None
                    and any(s.kind == "area_unit" for w in window for s in w.senses)
                ):
                    continue  # ("5 acre fild": a size, then the typo)
                text = " ".join(w.norm for w in window)
                match = lexicon.fuzzy(text)
                if match is None:
                    continue
                phrase, score, senses = match
                words = phrase.split()
                # A function word at either end must be the phrase's own ("nxt to" ->
                # "next to"), not a neighbour swallowed into a guess ("late in the").
                if (_filler(window[0]) and words[0] != window[0].norm) or (
                    _filler(window[-1]) and words[-1] != window[-1].norm
                ):
                    continue
                width = end - start
                if best is None or (score, width) > (best[0], best[2] - best[1]):
                    best = (score, start, end, phrase, senses)
        following = out[index + 1] if index + 1 < len(out) else None
        if best is None and following is not None:
            # ("fontaine potatoes": a variety of the crop said right after it)
            crops = {str(s.value) for s in following.senses if s.kind == "crop"}
            if crops and (variety := lexicon.variety_of(out[index].norm, crops)) is not None:
                best = (variety[1], index, index + 1, variety[0], variety[2])
        if best is None:
            index += 1
            continue
        score, start, end, phrase, senses = best
        tokens = tuple(t for w in out[start:end] for t in w.tokens)
        replaced = Item(tokens, senses, fuzzy_score=score, fuzzy_phrase=phrase)
        steps.append(
            TraceStep(
                stage="normalise",
                subject=replaced.raw,
                detail=f"read as {phrase!r} (typo)",
                candidates=(Candidate(value=phrase, score=round(score, 1), source="fuzzy"),),
            )
        )
        out[start:end] = [replaced]
        index = start + 1
    return out, steps


def nearest_by_spelling(
    context: ResolveContext, name: str, like: Sequence[str], limit: int = 3
) -> tuple[str, ...]:
    """Known crops for an unknown name: the curated ``like`` list, else the closest spellings."""
    if like:
        return tuple(like[:limit])
    from rapidfuzz import fuzz, process

    names: dict[str, str] = {}
    for crop in context.hierarchy.crops.values():
        for phrase in (crop.name, *crop.aliases):
            names.setdefault(normalise(phrase), crop.name)
    ranked = process.extract(normalise(name), list(names), scorer=fuzz.ratio, limit=20)
    result: list[str] = []
    for phrase, _, _ in ranked:
        crop_name = names[str(phrase)]
        if crop_name not in result:
            result.append(crop_name)
    return tuple(result[:limit])


class LexicalResolver(Resolver):
    """Reads prompts with the phrase lexicon; subclasses choose how unknown words are read."""

    name = "rules"
    #: Whether crop and variety names are matched from the lexicon (False: by other means).
    lexicon_has_crop_names = True

    def lexicon(self, context: ResolveContext) -> Lexicon:
        """The lexicon for this context's hierarchy and knowledge base."""
        return build_lexicon(
            context.hierarchy, context.knowledge, crop_names=self.lexicon_has_crop_names
        )

    def read_unknown_words(
        self, items: list[Item], lexicon: Lexicon, context: ResolveContext
    ) -> tuple[list[Item], list[TraceStep]]:
        """Read words the lexicon does not know exactly (default: fuzzy typo matching)."""
        return fuzzy_unknown_words(items, lexicon)

    def nearest_crops(
        self, name: str, like: Sequence[str], context: ResolveContext
    ) -> tuple[str, ...]:
        """The known crops nearest to an unknown one (default: curated list, then spelling)."""
        return nearest_by_spelling(context, name, like)

    def resolve_intent(self, prompt: str, context: ResolveContext) -> SceneIntent:
        """What ``prompt`` asks for, read with the lexicon."""
        reader = PromptReader(
            context,
            self.lexicon(context),
            unknown_words=lambda items, lexicon: self.read_unknown_words(items, lexicon, context),
            nearest_crops=lambda name, like: self.nearest_crops(name, like, context),
            strategy=self.name,
        )
        return reader.read(prompt)


class RulesResolver(LexicalResolver):
    """Deterministic lexicon and rapidfuzz matching over the hierarchy vocabulary; no model."""

    name = "rules"
