"""Members of counted fields named again (issue 8): "one still vegetative, the other
tasseling. The young planting is on the south side", "one at 30-inch rows, one at
36-inch rows, the 30-inch plot west of the 36-inch plot", "the 70k plot lies north of the
95k plot", "the Winter Wheat and Spring Wheat plots ..., the winter one much taller", "Two banana
plots ... The western plot has black Sigatoka".

Before the prompt is read, such a reference is written as what it points at: "the
first" / "the second" (the order the members were said in), or the variety's whole name.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence

from agrirecipe.resolve._geometry import number_words
from agrirecipe.resolve._lexicon import Item, number_value, tokenize
from agrirecipe.resolve._links import OPPOSITE

__all__ = ["ORDINAL_WORDS", "counted_plots", "name_members_again", "valued_members"]

#: How the members said in order are named again.
ORDINAL_WORDS = ("the first", "the second", "the third", "the fourth")


def name_members_again(text: str, tag: Callable[[str], Sequence[Item]]) -> str:
    """``text`` with members named again by a word of their variety, their look or their
    measure written as the member itself."""
    return _member_by_its_side(
        _members_by_measure(_members_by_look(_members_by_a_word(text, tag), tag))
    )


# "one still vegetative at about V5, the other tasseling. The young planting is on the
# south side": members said by "one ..." and "the other ...", then one of them named by
# its look and a plot word or "one": that member, as "the first" or "the second"
_MEMBER_SAID = re.compile(r"\b(?i:one|the other)\s+(?P<said>[^,;.:]+)")
_BY_LOOK = re.compile(
    r"\b(?i:the)\s+(?P<word>[A-Za-z][\w-]*)\s+"
    r"(?i:one|field|planting|block|plot|strip|bed|patch|crop|paddock)\b"
    # ("... is on the south side": of two, the side of the other)
    r"(?P<placed>\s+(?i:is|lies|sits)\s+(?:(?i:on|to|at)\s+(?i:the)\s+)?"
    r"(?P<side>(?i:north|south|east|west))(?i:ern)?(?:\s+(?i:side|end))?\b(?!\s+(?i:of)\b))?"
)


# "the Winter Wheat and Spring Wheat plots ..., the winter one much taller": a member
# named by the first word of its variety's name (here a season's word)
_ONE_BY_A_WORD = re.compile(r"\b(?P<the>(?i:the))\s+(?P<word>[A-Za-z]+)\s+(?=(?i:one)\b)")


def _members_by_a_word(text: str, tag: Callable[[str], Sequence[Item]]) -> str:
    """``text`` with "the winter one" written "the Winter Wheat one" when "Winter Wheat",
    a variety whose name begins with that word, was named before it."""

    def rewrite(match: re.Match[str]) -> str:
        word = match.group("word")
        named = re.search(
            rf"\b{re.escape(word)}\s+(?P<next>[A-Za-z]+)", text[: match.start()], re.IGNORECASE
        )
        if named is None:
            return match.group(0)
        variety = f"{word} {named.group('next')}"
        items = [i for i in tag(variety) if i.role != "separator"]
        if len(items) != 1 or not items[0].has("variety"):
            return match.group(0)
        return f"{match.group('the')} {variety} "

    return _ONE_BY_A_WORD.sub(rewrite, text)


# "one at 30-inch rows, one at 36-inch rows, the 30-inch plot west of the 36-inch plot":
# members named again by the measure each was said with
_MEASURE = r"(?P<n>\d+(?:\.\d+)?)\s*-?\s*(?P<unit>inch|inches|in|cm|mm|m|ft|foot|feet)\b"
_BY_MEASURE = re.compile(
    rf"\b(?i:the)\s+{_MEASURE}(?:\s+(?i:rows?|row|spacing))?\s+"
    r"(?i:one|field|plot|block|strip|bed|patch|paddock)\b"
)


def _members_by_measure(text: str) -> str:
    """``text`` with "the 30-inch plot" written "the first" when the members were said
    "one at 30-inch rows, one at 36-inch rows" (each with its own first measure)."""
    said = list(_MEMBER_SAID.finditer(text))
    measures: list[tuple[float, str]] = []
    for member in said:
        found = re.search(_MEASURE, member.group("said"))
        if found is None:
            return text
        measures.append((float(found.group("n")), found.group("unit")[:2].lower()))
    if (
        len(measures) < 2
        or len(measures) > len(ORDINAL_WORDS)
        or len(set(measures)) != len(measures)
    ):
        return text
    start = said[-1].end()

    def rewrite(match: re.Match[str]) -> str:
        key = (float(match.group("n")), match.group("unit")[:2].lower())
        return ORDINAL_WORDS[measures.index(key)] if key in measures else match.group(0)

    return text[:start] + _BY_MEASURE.sub(rewrite, text[start:])


def _members_by_look(text: str, tag: Callable[[str], Sequence[Item]]) -> str:
    def looks(phrase: str) -> set[tuple[str, str]]:
        return {
            (kind, str(sense.value))
            for item in tag(phrase)
            for kind in ("stage", "health")
            for sense in item.senses_of(kind)
        }

    said = list(_MEMBER_SAID.finditer(text))
    members = [looks(m.group("said")) for m in said]
    if len(members) < 2 or len(members) > len(ORDINAL_WORDS) or not all(members):
        return text
    start = said[-1].end()

    def rewrite(match: re.Match[str]) -> str:
        word = looks(match.group("word"))
        fitting = [index for index, m in enumerate(members) if word and word <= m]
        if len(fitting) != 1:
            return match.group(0)
        if match.group("placed") and len(members) == 2:
            other = ORDINAL_WORDS[1 - fitting[0]]
            side = match.group("side").lower()
            return f"{ORDINAL_WORDS[fitting[0]]} is {side} of {other}"
        return ORDINAL_WORDS[fitting[0]] + (match.group("placed") or "")

    # (only after the members are said: "one young, the other ripe")
    return text[:start] + _BY_LOOK.sub(rewrite, text[start:])


# "the 70k plot lies north of the 95k plot": a member named by the number said for it
_VALUED_MEMBER = re.compile(
    r"\b(?i:the)\s+(?P<value>\d[\d,.]*[kK]?)\s+(?i:plot|block|field|strip|bed|parcel)\b"
)
_NUMBER = re.compile(r"\d[\d,.]*[kK]?\b")


def _number_of(text: str) -> float | None:
    """The value of one number as the tokenizer reads it ("70,000", "70k")."""
    tokens = tokenize(text)
    return number_value(tokens[0].norm) if len(tokens) == 1 else None


def valued_members(text: str) -> str:
    """``text`` with "the 70k plot ... the 95k plot" written "the first ... the second"
    when each number was said before for one member, in that order ("one sown at 70,000
    plants/ha and one at 95,000")."""
    references = list(_VALUED_MEMBER.finditer(text))
    values = [_number_of(m.group("value")) for m in references]
    if len(references) < 2 or None in values or len(set(values)) < 2:
        return text
    said = [_number_of(m.group()) for m in _NUMBER.finditer(text[: references[0].start()])]
    order = list(dict.fromkeys(x for x in said if x in values))
    if len(order) != len(set(values)) or len(order) > len(ORDINAL_WORDS):
        return text
    out = text
    for match, value in reversed(list(zip(references, values, strict=True))):
        out = out[: match.start()] + ORDINAL_WORDS[order.index(value)] + out[match.end() :]
    return out


# "Two banana plots 15 m apart on an east-west line ... The western plot has black
# Sigatoka": one of two members named by its side, as the subject of what it has
_BY_ITS_SIDE = re.compile(
    r"\b(?i:the)\s+(?P<side>(?i:north|south|east|west))(?i:ern)?\s+"
    r"(?i:plot|block|field|one|strip|bed|patch)\s+"
    r"(?=(?i:has|have|is|shows|looks|got|was)\b)"
)


def _member_by_its_side(text: str) -> str:
    """``text`` with "The western plot has ..." written "One of them, west of the other,
    has ..." after two plots counted, when no other member is named by a side."""
    sides = list(_BY_ITS_SIDE.finditer(text))
    if len(sides) != 1:
        return text
    counted = counted_plots(text, 2, ("plot", "block", "field", "strip", "bed", "patch"))
    if counted is None or counted.end() > sides[0].start():
        return text
    side = sides[0].group("side").lower()
    opposite = OPPOSITE[f"{side}_of"].removesuffix("_of")
    if re.search(rf"\b(?i:the)\s+{opposite}(?i:ern)?\s", text):
        return text  # ("the western plot ..., the eastern plot ...": both named by side)
    start, end = sides[0].span()
    return f"{text[:start]}one of them, {side} of the other, {text[end:]}"


def counted_plots(text: str, count: int, nouns: Sequence[str]) -> re.Match[str] | None:
    """Where ``text`` first counts ``count`` plots of one of ``nouns`` ("two maize plots",
    "3 wheat strips"), the count in digits or in geometry.yaml's words; None if nowhere."""
    said = "|".join(
        [str(count), *(w for w, v in number_words().items() if v == count and " " not in w)]
    )
    plurals = "|".join(f"{n}s|{n}es" for n in nouns)
    return re.search(rf"\b(?i:{said})\s+(?:[\w-]+\s+){{0,2}}(?i:{plurals})\b", text)
