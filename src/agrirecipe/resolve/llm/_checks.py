"""Deterministic checks of the request and of the record, and the unknown-plant error."""

from __future__ import annotations

import itertools
from collections.abc import Sequence
from typing import TYPE_CHECKING

from agrirecipe._errors import PromptError, UnknownCropError
from agrirecipe.resolve._grammar import NONE
from agrirecipe.resolve.llm._evidence import _Evidence
from agrirecipe.resolve.llm._parts import _Part

if TYPE_CHECKING:
    from agrirecipe.hierarchy import Hierarchy
    from agrirecipe.resolve._lexicon import Lexicon


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
    from agrirecipe.resolve._numbers import numbers_that_count_no_fields
    from agrirecipe.resolve._retractions import apply_corrections
    from agrirecipe.resolve._scan import assign_roles
    from agrirecipe.resolve._sizes import read_sizes
    from agrirecipe.resolve._structure import raise_conflicts

    items = lexicon.tag(tokenize(request))
    assign_roles(items)
    # ("A wheat strip at 12.5 cm ...": a measure the geometry left in the request, no count)
    numbers_that_count_no_fields(items)
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
