"""The reader's working data: clauses, the field mentions they hold, and the crops a
head can name.

A *clause* is the items between two boundaries (separators, conjunctions,
relation words); a *mention* is one field request being read inside it, with
its heads (crop, variety, category, plot words), attributes and count. An
*interpretation* is one (crop, variety, weak) reading a head allows; heads that
name one field must share one (:func:`combine_interpretations`).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

from agrirecipe._errors import PromptError
from agrirecipe.resolve._lexicon import Item

__all__ = [
    "PRE_HEAD",
    "Clause",
    "Interpretation",
    "Mention",
    "combine_interpretations",
    "head_interpretations",
    "named_crops",
    "split_clauses",
]

_BOUNDARIES = ("separator", "conjunction", "relation", "between", "trailer")
# Roles that may stand right before a head as part of its noun phrase.
PRE_HEAD = (
    "number",
    "quantity",
    "distinct",
    "other",
    "stage",
    "health",
    "negation",
    "weak_variety",
    "size",
    "geometry",
    "cue",
    "zone",
    "same_size",
    "same_spacing",
    "filler",
    "unknown",
    "reference",
    "container",
    "season",
)

Interpretation = tuple[str, str | None, bool]  # (crop, variety or None, weak)


@dataclass
class Mention:
    """A field request being read: heads, attributes, count, refinements."""

    items: list[Item] = field(default_factory=list)
    heads: list[Item] = field(default_factory=list)
    interpretations: list[Interpretation] | None = None
    category: str | None = None
    plot: dict[str, Any] | None = None
    count: int | None = None
    #: The count is only a plural's default ("plots"): a longer list after it wins.
    implied_count: bool = False
    #: A vague amount ("several", "lots of"): a count only of fields, not of plants.
    quantity: int | None = None
    distinct: bool = False
    #: "three different vegetables" asks for different crops; "two different apple
    #: orchards" (a crop already named) for different fields of that crop.
    distinct_crops: bool = False
    other: bool = False
    #: A contradiction in the mention's own words ("a vineyard of cabbages"), raised
    #: unless a correction ("..., no, I mean ...") drops the mention.
    conflict: PromptError | None = None
    #: The phrase goes on in the next mention ("a vineyard | of cabbages").
    continued: bool = False
    clause: int = 0
    refinements: list[Mention] = field(default_factory=list)
    #: Attribute words another mention of a list lent it ("ripe wheat and maize"):
    #: its own words said later replace them ("..., maize still green").
    borrowed: list[Item] = field(default_factory=list)
    rest: Mention | None = None
    is_refinement: bool = False
    #: A member held open before one said by its place ("The middle one has blight"):
    #: the others said later ("the other two look fine") fill it.
    unsaid: bool = False

    @property
    def text(self) -> str:
        """The mention's words as typed."""
        ordered = sorted(self.items, key=lambda item: item.start)
        return " ".join(item.raw for item in ordered)

    @property
    def has_crop(self) -> bool:
        """Whether a crop was named (a strong interpretation exists)."""
        return bool(self.interpretations) and any(
            not weak for _, _, weak in self.interpretations or ()
        )

    def attributes(self, role: str) -> list[Item]:
        """This mention's items of one attribute role."""
        return [item for item in self.items if item.role == role]


@dataclass
class Clause:
    """Items between two boundaries, with the boundary before it."""

    items: list[Item]
    link: Item | None
    index: int
    mentions: list[Mention] = field(default_factory=list)
    loose: list[Item] = field(default_factory=list)
    refined_parent: Mention | None = None
    #: The member this clause named once it became a refinement of ``refined_parent``.
    refinement: Mention | None = None
    #: The fields a crop named again in this clause was said of, when it was more than
    #: one ("..., peppers fruiting and ripe": both pepper fields).
    said_of: list[Mention] = field(default_factory=list)

    @property
    def named(self) -> list[Mention]:
        """The mentions of the clause, or the member it refined ("imperator" in "two
        carrot plots, imperator on the north side"), for relations to point at."""
        return self.mentions or ([self.refinement] if self.refinement is not None else [])

    @property
    def headless(self) -> bool:
        """No mention in this clause."""
        return not self.mentions


def split_clauses(items: Sequence[Item]) -> list[Clause]:
    """Cut the items at separators, conjunctions and relation words."""
    clauses: list[Clause] = []
    current: list[Item] = []
    link: Item | None = None
    for item in items:
        if item.role in _BOUNDARIES:
            clauses.append(Clause(current, link, len(clauses)))
            current, link = [], item
        else:
            current.append(item)
    clauses.append(Clause(current, link, len(clauses)))
    return clauses


def head_interpretations(item: Item) -> list[Interpretation]:
    result: list[Interpretation] = []
    for sense in item.senses:
        if sense.kind == "crop":
            result.append((str(sense.value), None, False))
        elif sense.kind == "variety" and sense.crop is not None:
            # a weak name promoted to its clause's head ("west to east: Lollo, then ...")
            # names its variety wherever the field is merged
            # ("grove outside Valencia, navel trees": "navel" made the head of its plot)
            weak = sense.weak and not (
                item.data.get("promoted")
                or (item.role == "head" and not item.has("crop", "category"))
            )
            result.append((sense.crop, str(sense.value), weak))
    return result


def combine_interpretations(
    left: list[Interpretation] | None, right: list[Interpretation]
) -> list[Interpretation] | None:
    """Interpretations both sides allow; None when they cannot be the same field."""
    if left is None:
        return list(right)
    if not right:
        return list(left)
    combined: list[Interpretation] = []
    for crop_a, variety_a, weak_a in left:
        for crop_b, variety_b, weak_b in right:
            if crop_a != crop_b:
                continue
            if variety_a and variety_b and variety_a != variety_b:
                continue
            entry = (crop_a, variety_a or variety_b, weak_a and weak_b)
            if entry not in combined:
                combined.append(entry)
    return combined or None


def named_crops(interpretations: Sequence[Interpretation] | None) -> list[str]:
    crops: list[str] = []
    for crop, _, weak in interpretations or ():
        if not weak and crop not in crops:
            crops.append(crop)
    return crops
