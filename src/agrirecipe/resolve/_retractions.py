"""Mentions the text takes back: corrections, alternatives, choices left open, negations.

- *Corrections*: "cherry tomatoes? no, I mean cherry trees" keeps the trees; "cabage
  patch kid lol jk, just a cabbage field" keeps the field; "summer... jk make it autumn"
  keeps the autumn.
- *Alternatives*: "a field of wheat or maize" is one field, of the first named.
- *Choices left open*: "some fruit fields pls, whatever fruit u like" is no more fields.
- *Negations*: "no apples, just pears" asks for no apples; "the kitchen garden's gone"
  for no garden.
- *Placements corrected*: "peppers b4 the onions... i mean west of them" places the
  peppers west of the onions (:func:`correct_placements`, on the text).

Each pass removes the mentions it reads from their clauses and returns their texts,
which the reader lists in its trace. The words are data (``corrections``,
``negations`` and ``reader_words.free_choice`` and ``gone`` in vocabulary.yaml).
"""

from __future__ import annotations

import itertools
import re
from collections.abc import Sequence

from agrirecipe.resolve._lexicon import Item, reader_words
from agrirecipe.resolve._mentions import Clause, Mention
from agrirecipe.resolve._structure import first_word, names_a_variety

_PLACE = (
    r"(?:before|after|next to|beside|behind|in front of|past|beyond|by|near|"
    r"(?:just |right |directly )?(?:north|south|east|west)\s+of)"
)
#: "peppers b4 the onions (sturon)... i mean west of them": a placement said again in
#: other words, pointing back at what the first one named.
_PLACE_CORRECTED = re.compile(
    rf"\b(?i:{_PLACE})\s+(?P<what>[^.,;:!?()]*?(?:\s*\([^)]*\))?)\s*"
    r"(?:\.{2,}|…|,|-+|–|—)?\s*(?i:i mean|i meant|or rather|rather|sorry|no)\s*,?\s+"
    r"(?P<place>(?i:(?:just |right |directly )?(?:north|south|east|west)\s+of|next to|beside|"
    r"behind|in front of))\s+(?i:them|it|those|that|these)\b"
)


def correct_placements(text: str) -> str:
    """``text`` with "X b4 the onions... i mean west of them" written "X west of the
    onions": the placement said last, of what the first one named."""
    return _PLACE_CORRECTED.sub(lambda m: f"{m.group('place')} {m.group('what')}", text)


__all__ = [
    "apply_corrections",
    "correct_placements",
    "drop_alternatives",
    "drop_corrected_words",
    "drop_free_choices",
    "drop_negated",
]

#: Words that may stand between a negation and what it negates ("no any apples").
_ANY = frozenset({"any", "a", "an", "the", "some"})
#: Words between a negation and the plots it denies ("and no other plots", "no more
#: fields"): the fields named so far are all there are.
_OTHER = frozenset({"other", "more", "further", "extra", "additional", "else"})


def apply_corrections(clauses: Sequence[Clause]) -> list[str]:
    """Drop the mention a correction ("no, I mean ...") replaces; return what was dropped."""
    dropped: list[str] = []
    for position, clause in enumerate(clauses):
        if not clause.mentions:
            continue
        first_head = clause.mentions[0].heads[0]
        corrected = any(
            item.role == "correction" and item.start < first_head.start
            for item in clause.mentions[0].items
        ) or _correction_before(clauses, position)
        if not corrected:
            continue
        for earlier in reversed(clauses[:position]):
            if earlier.mentions:
                new, old = clause.mentions[0], earlier.mentions[-1]
                if (
                    not new.has_crop
                    and new.category is None
                    and new.plot is not None
                    and old.has_crop
                    and len(clause.mentions) == 1
                ):
                    # "the Valencia groove (sorry, grove)": only the plot word is
                    # corrected; the crop named stays
                    plots = [h for h in old.heads if h.role == "plot"]
                    old.heads = [h for h in old.heads if h.role != "plot"] + new.heads
                    old.items = [i for i in old.items if i not in plots] + [
                        i for i in new.items if i.role != "correction"
                    ]
                    old.plot = new.plot
                    clause.mentions = []
                    dropped.append(" ".join(h.raw for h in plots) or new.text)
                    break
                dropped.append(earlier.mentions.pop().text)
                while earlier.mentions and earlier.mentions[-1].continued:
                    dropped.append(earlier.mentions.pop().text)
                break
    return dropped


#: What a word said again after a correction replaces: a time of year (a season or a
#: month), a stage or a health.
_REPLACED = {"season": "time", "month": "time", "stage": "stage", "health": "health"}


def drop_corrected_words(items: Sequence[Item]) -> list[str]:
    """'bananas, summer... jk make it autumn': a time of year, stage or health said right
    after a correction (only filler or a comma between) replaces the one said last before it; that
    one becomes filler. Returns the words dropped."""
    dropped: list[str] = []
    for index, item in enumerate(items):
        if item.role != "correction":
            continue
        said = next(
            (i for i in items[index + 1 :] if i.role != "filler" and i.norm not in (",", ":")),
            None,
        )
        if said is None or said.role not in _REPLACED:
            continue
        replaced = next(
            (i for i in reversed(items[:index]) if _REPLACED.get(i.role) == _REPLACED[said.role]),
            None,
        )
        if replaced is not None:
            replaced.role = "filler"
            dropped.append(replaced.raw)
    return dropped


def _correction_before(clauses: Sequence[Clause], position: int) -> bool:
    """A correction word alone in the clause right before ("no, I mean, ..."), or ending
    it after the field it takes back ("cabage patch kid lol jk, just a cabbage field")."""
    if position == 0:
        return False
    previous = clauses[position - 1]
    if not previous.mentions:
        return any(i.role == "correction" for i in previous.loose)
    last = previous.mentions[-1]
    head = max(h.start for h in last.heads)
    return any(i.role == "correction" and i.start > head for i in last.items)


def drop_alternatives(clauses: Sequence[Clause]) -> list[str]:
    """'grain field, wheat or corn idc', 'a field of wheat or maize': crops said as
    alternatives ask for one field, of the first named. Returns the texts dropped."""
    dropped: list[str] = []
    for before, clause in itertools.pairwise(clauses):
        if clause.link is None or clause.link.norm != "or" or len(clause.mentions) != 1:
            continue
        if not before.mentions:
            continue
        first, other = before.mentions[-1], clause.mentions[0]
        head = min(other.heads, key=lambda h: h.start)
        if (
            first.has_crop
            and other.has_crop
            and (first.count or 1) == 1
            and other.count is None
            and not other.refinements
            and not any(h.role == "plot" for h in other.heads)
            and all(i.role == "filler" for i in clause.items if i.end <= head.start)
        ):
            clause.mentions.remove(other)
            dropped.append(other.text)
    return dropped


def drop_free_choices(clauses: Sequence[Clause]) -> list[str]:
    """'some fruit fields pls, whatever fruit u like', '3 fields, any vegetables': a crop
    or kind left to the reader's choice, after the fields it is for, is no field of its
    own; a kind gives those fields their category when they name none. Returns the
    texts dropped."""
    dropped: list[str] = []
    choices = reader_words("free_choice")
    earlier: list[Mention] = []
    for clause in clauses:
        for mention in list(clause.mentions):
            first = first_word(mention)
            if (
                earlier
                and first is not None
                and first.norm in choices
                # ("wheat and any vegetable": a member of a list, a field)
                and not (clause.link is not None and clause.link.role == "conjunction")
                and clause.mentions[0] is mention
                and mention.count is None
                and not names_a_variety(mention)
                and not any(h.role == "plot" for h in mention.heads)
                # (the kind of the fields before, or what they leave open; "wheat, any
                # vegetable" lists two)
                and (
                    (mention.category is None and not mention.has_crop)
                    or (
                        not earlier[-1].has_crop
                        and earlier[-1].category in (None, mention.category)
                    )
                )
            ):
                owner = earlier[-1]
                if owner.category is None:
                    owner.category = mention.category
                clause.mentions.remove(mention)
                dropped.append(mention.text)
                continue
            earlier.append(mention)
    return dropped


def drop_negated(clauses: Sequence[Clause]) -> list[str]:
    """'no crops or anything', 'no apples, just pears': a negated mention asks for no field.

    A mention whose head follows a negation word ("no", "not", "without", with
    at most an article or "any" between) is removed from its clause. Returns
    the texts dropped.
    """
    dropped: list[str] = []
    for clause in clauses:
        for mention in list(clause.mentions):
            head = min(mention.heads, key=lambda h: h.start)
            before = [i for i in clause.items if i.end <= head.start]
            while before and before[-1].norm in _ANY:
                before.pop()
            if before and before[-1].norm in _OTHER and not mention.has_crop:
                before.pop()
            if (before and before[-1].role == "negation") or _gone(clause, mention):
                clause.mentions.remove(mention)
                dropped.append(mention.text)
    return dropped


#: Words between a field and "gone" that say it is no more ("the kitchen garden's gone").
_BE = frozenset({"s", "is", "are", "has", "have", "was", "were", "been", "now", "all"})


def _gone(clause: Clause, mention: Mention) -> bool:
    """Whether a field named of no variety is said to be gone, ending its clause: "The
    kitchen garden's gone, the whole place is one field of Jalapeños now" (not "leaves
    gone brown")."""
    head = max(h.end for h in mention.heads)
    after = [i.norm for i in clause.items if i.start >= head]
    while after and after[0] in _BE:
        after.pop(0)
    return (
        not names_a_variety(mention)
        and len(after) >= 1
        and " ".join(after) in reader_words("gone")
        and len(clause.mentions) == 1
    )
