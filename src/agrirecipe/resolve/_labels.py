"""Fields named by a label: "Block A: Jonagored apples, ... Block B, north of A: pears".

Engineers name plots by letter or number and then place the others against the
label. Before the prompt is read, each label that introduces a field ("Block A:",
"Plot 2 -") is dropped, and each later reference to it ("north of A", "beside plot
2") becomes a definite reference to the crop named after the label ("north of the
Jonagored apples"), which the reader already resolves to that field.

Compass positions used as labels are :mod:`agrirecipe.resolve._sides`'.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence

from agrirecipe.resolve._lexicon import Item, tokenize, vocabulary
from agrirecipe.resolve._members import (
    ORDINAL_WORDS,
    counted_plots,
    name_members_again,
    valued_members,
)

__all__ = ["NAMING", "drop_list_numbers", "open_ordered_lists", "resolve_labels"]

_NOUNS = r"(?:block|plot|field|parcel|area|section|strip|zone|bay|compartment|trial plot)"
# "Field one: Russet potatoes ... Field two, south of field one: Fontane": a number word
# as a label (always after its noun, like a number)
_WORD_LABELS = r"(?i:one|two|three|four|five|six|seven|eight|nine|ten)"
#: A label's mark ("B", "2", "two") and a label with its noun ("plot B").
_MARK = rf"(?:[A-H]|\d{{1,2}}|{_WORD_LABELS})"
_LABEL = rf"(?i:{_NOUNS})\s+{_MARK}"
#: How close a side is said ("directly east of").
_CLOSE = r"(?:(?i:directly|just|immediately|right|due)\s+)?"


def _said(label: str) -> str:
    """A pattern for a label as written: a letter in capitals ("north of B", never the
    article "a"), a number word in any case ("field one")."""
    return re.escape(label) if _letter(label) or label.isdigit() else f"(?i:{re.escape(label)})"


def _letter(label: str) -> bool:
    """A label that is one letter (referred to with or without its noun: "north of B")."""
    return len(label) == 1 and label.isalpha()


# "Block A:", "plot 2 -", "Field B," : a label that introduces what follows it.
_DEFINITION = re.compile(
    rf"\b(?i:{_NOUNS})\s+(?P<label>[A-H]|\d{{1,2}}|{_WORD_LABELS})\b\s*"
    rf"(?P<mark>[:,(\-–—=]|(?i:is|has|sits|lies|stands|goes)\b)"
)
# "plot 2 Kordia cherries" among labels defined with a mark
_LOOSE_DEFINITION = re.compile(
    rf"\b(?i:{_NOUNS})\s+(?P<label>[A-H]|\d{{1,2}}|{_WORD_LABELS})\b(?P<mark>)\s+(?=[A-Za-z])"
)
# "A = Roma, B = San Marzano": a bare letter given a crop by an equals sign
_BARE_DEFINITION = re.compile(r"(?<![\w=])(?P<label>[A-H])\s*(?P<mark>=)(?!=)")
# "A: Agria potatoes, 2 ha. B: Red Baron onions": a bare letter opening a sentence, then a
# colon
_SENTENCE_DEFINITION = re.compile(r"(?:^|(?<=[.;!?]\s))(?P<label>[A-H])\s*(?P<mark>:)")
# "A is north of B": a label as the subject of a placing verb
_SUBJECT_VERBS = (
    r"(?:is|sits|lies|are|stands|goes|runs|borders|adjoins|touches|shows|has|have|looks|"
    r"gets|got|carries|suffers)"
)
# "A west of B", "plot 2 next to plot 1": a label placed by a relation word right after it
_PLACING = r"(?:(?:north|south|east|west)(?:-?(?:east|west))?\s+of|next\s+to|beside|alongside)"
# What a reference to a label follows: a relation word, or the label's noun.
_BEFORE_REFERENCE = (
    r"(?:of|to|from|beside|besides|by|and|than|next to|alongside|between|put|place|with)"
)

# "Block 2, south of block 1: Riesling": a label after a relation word is referred to,
# not defined
_REFERRED = re.compile(rf"\b(?i:{_BEFORE_REFERENCE})\s+(?:(?i:the)\s+)?$")

#: What comes before a label that opens a sentence.
_SENTENCE_START = re.compile(r"(?:^|[.;:!?])\s*$")
#: The items a crop phrase keeps ("Jonagored apples"): crop, variety and category words.
#: The senses of a word that name what a field grows.
NAMING = ("crop", "variety", "category")


# "Iceberg lettuce in field A, Red Express cabbage in field B": a crop put in a labelled
# plot (after a mark or "and": the crop's words only)
_CROP_IN_LABEL = re.compile(
    rf"(?P<lead>(?:^|[,;:.]\s*|\b(?i:and)\s+))(?P<crop>[A-Za-z][\w'’-]*(?:\s+[A-Za-z][\w'’-]*){{0,3}}?)"
    rf"\s+(?i:in|on)\s+(?P<noun>(?i:{_NOUNS}))\s+(?P<label>[A-H]|\d{{1,2}})\b"
)


def _crops_in_labels(text: str, tag: Callable[[str], Sequence[Item]]) -> str:
    """``text`` with "Iceberg lettuce in field A, Red Express cabbage in field B" written
    "field A: Iceberg lettuce, field B: Red Express cabbage" (two or more such)."""
    found = [
        m
        for m in _CROP_IN_LABEL.finditer(text)
        if (items := [i for i in tag(m.group("crop")) if i.role != "separator"])
        and all(i.has(*NAMING) for i in items)
    ]
    if len(found) < 2:
        return text
    for match in reversed(found):
        lead = match.group("lead")
        lead = ", " if lead.strip().lower() == "and" else lead  # ("..., and field B: pears")
        said = f"{lead}{match.group('noun')} {match.group('label')}: {match.group('crop')}"
        text = text[: match.start()] + said + text[match.end() :]
    return text


# "Plot register: P1 Imperator carrots, P2 Danvers carrots, ...": a capital and a number
# as one word, the code of a plot (never a count of fields)
_CODE = re.compile(r"(?<![\w-])(?P<letter>[A-Z])(?P<number>\d{1,2})(?![\w-]|\.\d)")
_ITEM_OPENING = re.compile(r"(?:^|[,;:.(]|\n)\s*$")


def _code_labels(text: str) -> str:
    """``text`` with plot codes written as numbered plots ("P2 Danvers" -> "plot 2
    Danvers") when two or more codes of one letter each open an item of a list."""
    openers: dict[str, set[str]] = {}
    for match in _CODE.finditer(text):
        if _ITEM_OPENING.search(text[: match.start()]):
            openers.setdefault(match.group("letter"), set()).add(match.group("number"))
    letters = {letter for letter, numbers in openers.items() if len(numbers) >= 2}
    if not letters:
        return text
    return _CODE.sub(
        lambda m: f"plot {m.group('number')}" if m.group("letter") in letters else m.group(0),
        text,
    )


def resolve_labels(text: str, tag: Callable[[str], Sequence[Item]]) -> tuple[str, list[str]]:
    """``text`` with field labels dropped and references to them spelled out.

    ``tag`` reads a phrase into lexicon items. Returns the new text and one note per
    label ("Block A = Jonagored apples"). Text with fewer than two labels that name
    crops is returned unchanged.
    """
    text = _crops_in_labels(_code_labels(text), tag)
    text = _SIZED_THEN_NAMED.sub(_sized_then_named, text)
    text = _BRACKETED_THEN_NAMED.sub(r"\g<head>: ", text)
    text = _PLACED_THEN_MEASURED.sub(r"\g<head> \g<rest>, \g<where>", text)
    text = _NAME_PLACED_THEN_MEASURED.sub(r"\g<name>: \g<rest>, \g<where>\g<end>", text)
    text = name_members_again(text, tag)
    text = _PLURAL_LABELS.sub(_one_noun_each, valued_members(_numbered_members(text, tag)))
    text = _BETWEEN_BARE_LABELS.sub(lambda m: f"{m.group('head')}{_one_noun_each(m)}", text)
    text = _PLACED_THEN_NAMED.sub(r"\g<head>, \g<where>, is", text)
    text = _PLACED_THEN_MARKED.sub(_placed_then_marked, text)
    text = _PLACED_THEN_IS.sub(r"\g<head>, \g<where>: ", text)
    definitions = sorted(
        [
            *(m for m in _DEFINITION.finditer(text) if not _REFERRED.search(text[: m.start()])),
            *_BARE_DEFINITION.finditer(text),
            *_SENTENCE_DEFINITION.finditer(text),
        ],
        key=lambda m: m.start(),
    )
    # ("Plot 2 sits between plots 1 and 3": a label as the subject of a placing verb,
    # naming no crop after it, is referred to, not defined)
    subjects = [
        m
        for m in definitions
        if m.group("mark").isalpha() and not _crop_phrase(text[m.end() :], tag)
    ]
    definitions = [m for m in definitions if m not in subjects]
    if definitions or subjects:
        # "Plot 1 is Gala apples, plot 2 Kordia cherries, and plot 3 is ...": with other
        # labels defined, a label right before a crop's name defines it too
        defined = {m.group("label").upper() for m in definitions}
        taken = [(m.start(), m.end()) for m in definitions]
        for match in _LOOSE_DEFINITION.finditer(text):
            if match.group("label").upper() in defined or any(
                a <= match.start() < b for a, b in taken
            ):
                continue
            first = tag(text[match.end() :].split(",")[0])
            if first and first[0].has(*NAMING):
                definitions.append(match)
        definitions.sort(key=lambda m: m.start())
    if not definitions and not subjects:
        # "Plot A carrots; plot B onions, north of A; plot C lettuce, east of A": labels
        # with no mark at all, before crops, when the text places fields against them
        loose = [
            m
            for m in _LOOSE_DEFINITION.finditer(text)
            if not _REFERRED.search(text[: m.start()])
            and (first := tag(text[m.end() :].split(",")[0]))
            and first[0].has(*NAMING)
        ]
        labels = {m.group("label") for m in loose}
        if len(labels) >= 2 and any(
            re.search(rf"\b(?i:{_BEFORE_REFERENCE})\s+(?:(?i:the)\s+)?{_said(label)}\b", text)
            for label in labels
        ):
            definitions = loose
    names: dict[str, str] = {}
    for match in definitions:
        label = match.group("label").upper()
        phrase = _crop_phrase(text[match.end() :], tag)
        if phrase and label not in names:
            names[label] = phrase
    if len(names) < 2 and not (
        # "Field 4, the one over the ditch: Russet spuds": one label opening a sentence
        len(definitions) == 1
        and names
        and definitions[0].group("mark") != "="
        and _SENTENCE_START.search(text[: definitions[0].start()])
    ):
        return text, []
    notes: list[str] = []
    # Drop the definitions (last first, so offsets stay valid), keeping their mark.
    out = text
    first_said: dict[str, re.Match[str]] = {}
    for match in definitions:
        first_said.setdefault(match.group("label").upper(), match)
    for match in reversed(definitions):
        mark = match.group("mark")
        label = match.group("label").upper()
        if first_said[label] is not match and label in names:
            # "Plot A: Fontane, plot B: Agria ... plot B is clean": a label said again
            # with "is" is the field it named, not a new definition
            again = "the " + names[label] + (" " + mark if mark.isalpha() else mark)
            out = out[: match.start()] + again + out[match.end() :]
            continue
        keep = "" if mark in ":-–—=" or mark.isalpha() else mark
        out = out[: match.start()] + keep + out[match.end() :]
    opening = out[: definitions[0].start()].rstrip()
    if definitions[0].re is _SENTENCE_DEFINITION and opening.endswith("."):
        # "Plots for the farm map. A: Agria potatoes, ... B: ...": the sentence before the
        # labels introduces the fields they list
        out = opening[:-1] + ":" + out[len(opening) :]
    for label, phrase in names.items():
        noun = rf"(?i:{_NOUNS})\s+"
        # "north of A", "beside block A" (a capital letter); "beside plot 2" (a number
        # only after its noun)
        pattern = re.compile(
            rf"(?P<before>\b(?i:{_BEFORE_REFERENCE})\s+)(?:(?i:the)\s+)?"
            + (rf"(?:{noun})?" if _letter(label) else noun)
            + _said(label)
            + r"\b"
        )
        template = "\\g<before>the " + phrase.replace("\\", "\\\\")
        replaced, count = pattern.subn(template, out)
        out = replaced
        # "A is north of B, and D sits between A and C"; "Plot 2 sits between ..." (a
        # number only after its noun)
        subject = re.compile(
            r"(?:^|(?<=[.;,:]\s)|(?<=\b(?i:and)\s))"
            + (rf"(?:{noun})?" if _letter(label) else noun)
            + _said(label)
            + rf"\b(?=\s+(?:(?i:{_SUBJECT_VERBS})|{_CLOSE}(?i:{_PLACING}))\b)"
        )
        out, said = subject.subn("the " + phrase.replace("\\", "\\\\"), out)
        count += said
        # a label never referenced is still a name, not another field ("Plot 2: ...")
        notes.append(f"{label} = {phrase}" + ("" if count else " (a label only)"))
    return out, notes


# "plot 2 is 10 m west of plot 1 and is wheat": a label placed first and named after
# "and is" defines its field, like "plot 2, 10 m west of plot 1, is wheat" (also against
# a letter said bare: "Block B sits immediately east of A and is Williams pears")
_PLACED_THEN_NAMED = re.compile(
    rf"(?P<head>\b{_LABEL})\s+(?i:is|lies|sits)\s+"
    rf"(?P<where>[^;.,:]*?\b(?i:{_BEFORE_REFERENCE})\s+(?:(?i:the)\s+)?(?:{_LABEL}|[A-H]))"
    r"\s+(?i:and)\s+(?i:is)\b"
)

# "Plot B directly east of A = Nantes carrots": a label placed against another, then
# named after "=" or ":" (the other's noun left out), like "plot B, directly east of
# plot A: Nantes carrots" (not a bare "A = ..." defining plot A)
_PLACED_THEN_MARKED = re.compile(
    rf"(?P<head>\b(?P<noun>(?i:{_NOUNS}))\s+{_MARK})\s*,?\s+(?P<where>{_CLOSE}"
    r"(?:(?i:north|south|east|west)\s+(?i:of)|(?i:next to|beside|alongside))\s+(?:(?i:the)\s+)?)"
    rf"(?P<other>(?i:{_NOUNS})\s+)?(?P<ref>{_MARK})\s*(?:=|:)\s*"
    r"(?=[A-Za-z])"
)


# "Plot B, directly south of A, is Regina, 40 by 80 m": a label placed against another
# between commas, then named after "is", like "Plot B, directly south of A: Regina, ..."
_PLACED_THEN_IS = re.compile(
    rf"(?P<head>\b{_LABEL})\s*,\s+(?P<where>{_CLOSE}"
    r"(?:(?i:north|south|east|west)\s+(?i:of)|(?i:next to|beside|alongside))\s+(?:(?i:the)\s+)?"
    rf"(?:(?i:{_NOUNS})\s+)?{_MARK})\s*,\s*(?i:is|has)\s+(?=[A-Za-z])"
)


def _placed_then_marked(match: re.Match[str]) -> str:
    other = match.group("other") or f"{match.group('noun')} "
    return f"{match.group('head')}, {match.group('where')}{other}{match.group('ref')}: "


# "plot 2 east of plot 1 at 70,000 plants/ha on 90 cm rows": what follows the label
# placed against another is said of the label's own plot, as in "plot 2 at 70,000
# plants/ha on 90 cm rows, east of plot 1"
_PLACED_THEN_MEASURED = re.compile(
    rf"(?P<head>\b{_LABEL})\s+(?P<where>{_CLOSE}"
    rf"(?i:north|south|east|west)\s+(?i:of)\s+(?:(?i:the)\s+)?{_LABEL})\s+"
    rf"(?P<rest>(?i:at|on|with)\s+\d[^;.:]*?)(?=\s*(?:[;:]|\.(?!\d)|,\s*{_LABEL}\b|$))"
)

# "Kordia: 10 rows, .... Regina, north of the Kordia block: 12 rows, ...": a name that
# opens its sentence, placed, then measured after a colon, as in "Regina: 12 rows, ...,
# north of the Kordia block" (the measures the name's, not the block's it is placed by)
_NAME_PLACED_THEN_MEASURED = re.compile(
    rf"(?:^|(?<=[.;!?]\s))(?!(?i:{_NOUNS})\b)(?P<name>[A-Z][\w'-]*(?:\s+[A-Z][\w'-]*)?)\s*,\s*"
    rf"(?P<where>(?:(?i:to\s+the)\s+)?{_CLOSE}(?i:north|south|east|west)\s+"
    r"(?i:of)\s+[^,:;.]+?)\s*:\s*(?P<rest>\d(?:[^.;:]|\.(?=\d))*?)\s*(?P<end>[;!?]|\.(?!\d)|$)"
)

# "Field A, 3 ha: Agria potatoes, healthy. Field B (2.5 ha): Winter Wheat": a label with
# its size, then what it grows, as in "Field A: Agria potatoes, healthy, 3 ha" (the size
# the label's field's, never a second size of the field before)
_SIZE = (
    r"\d+(?:\.\d+)?\s*(?:m\s*)?(?i:x|by|×)\s*\d+(?:\.\d+)?\s*(?i:m|ft|metres|meters)\b"
    r"|\d+(?:\.\d+)?\s*(?:(?i:ha|hectares?|acres?|ac|m2|sq\.?\s*m)\b|m²)"
)
_SIZED_THEN_NAMED = re.compile(
    rf"(?P<head>\b{_LABEL})\s*(?:,\s*(?P<size>{_SIZE})|\(\s*(?P<bracketed>{_SIZE})\s*\))"
    r"\s*[:\-–—]\s*(?P<rest>(?:[^.;!?]|\.(?=\d))+?)\s*(?P<end>[;!?]|\.(?!\d)|$)"
)


def _sized_then_named(match: re.Match[str]) -> str:
    size = match.group("size") or match.group("bracketed")
    return f"{match.group('head')}: {match.group('rest')}, {size}{match.group('end')}"


# "Strip 1 (west end) dent corn, strip 2 flint corn": a label with a bracket, then what
# it grows, as in "Strip 1 (west end): dent corn" (the bracket the label's own)
_BRACKETED_THEN_NAMED = re.compile(
    rf"(?:^|(?<=[.;,!?]\s))(?P<head>{_LABEL}\s*\([^()]*\))\s+(?=[A-Za-z])"
)

# "between plots 1 and 3", "blocks A and C": one noun for two labels
_PLURAL_LABELS = re.compile(
    rf"\b(?P<noun>(?i:{_NOUNS}))s\s+(?P<a>[A-H]|\d{{1,2}}|{_WORD_LABELS})\s+(?P<and>(?i:and|&|or))\s+"
    rf"(?P<b>[A-H]|\d{{1,2}}|{_WORD_LABELS})\b"
)


# "Plot 2 lies between 1 and 3": the labels it lies between, said without their noun
_BETWEEN_BARE_LABELS = re.compile(
    rf"\b(?P<head>(?P<noun>(?i:{_NOUNS}))\s+(?:[A-H]|\d{{1,2}})\s+(?:[a-z]+\s+){{0,2}}"
    rf"(?i:between)\s+)(?P<a>[A-H]|\d{{1,2}})\s+(?P<and>(?i:and|&))\s+(?P<b>[A-H]|\d{{1,2}})\b"
    rf"(?!\s*(?:m|cm|ha|ft|in|%|rows|beds)\b)"
)


def _one_noun_each(match: re.Match[str]) -> str:
    noun = match.group("noun")
    return f"{noun} {match.group('a')} {match.group('and')} {noun} {match.group('b')}"


# "three strips side by side, west to east wheat, maize, potatoes": an order said right
# before the list it orders
_ORDER = re.compile(
    r"\b(?P<order>(?i:from\s+)?(?i:west|east|north|south|left|right|top|bottom)\s+(?i:to)\s+"
    r"(?i:west|east|north|south|left|right|top|bottom))\s+(?=[A-Za-z])"
)


def open_ordered_lists(text: str, tag: Callable[[str], Sequence[Item]]) -> str:
    """``text`` with a colon after an order said right before a crop's name ("west to east
    wheat, maize, potatoes" is "west to east: wheat, maize, potatoes"), as the reader
    reads a heading; an order said of anything else ("rows run west to east in both") is
    left."""

    def colon(match: re.Match[str]) -> str:
        following = text[match.end() :].split(",")[0].split(".")[0]
        first = tag(following)
        if first and first[0].has(*NAMING):
            return f"{match.group('order')}: "
        return match.group(0)

    return _ORDER.sub(colon, text)


# "2 plots: (1) wheat ..., 1 ha; (2) a 1 ha maize plot ...": the numbers of a list
_LIST_NUMBER = re.compile(r"(?:(?<=^)|(?<=[:;,.!?]\s)|(?<=\n))\(?(?P<n>[1-9]|[a-h])\)\s+")


#: "plots are (a) Albion strawberries, ripe (b) California Wonder ...": a list's marks in
#: full brackets, wherever they stand
_BRACKETED_NUMBER = re.compile(r"(?:(?<=^)|(?<=\s))\((?P<n>[1-9]|[a-h])\)\s+")


def _in_order(marks: Sequence[str]) -> bool:
    return len(marks) >= 2 and marks in (
        [str(i) for i in range(1, len(marks) + 1)],
        [chr(ord("a") + i) for i in range(len(marks))],
    )


def drop_list_numbers(text: str) -> str:
    """``text`` without the numbers of a list ("(1) wheat ...; (2) maize ...", "a) ...
    b) ..."): two or more, in order from 1 (or a), each opening its item. They count
    no fields and name none. Marks in full brackets inside a sentence ("plots are (a)
    Albion strawberries, ripe (b) ...") end the item before them: a colon before the
    first, a semicolon before the others."""
    bracketed = list(_BRACKETED_NUMBER.finditer(text))
    if _in_order([m.group("n") for m in bracketed]) and any(
        not re.search(r"[:;,.!?]\s*$", text[: m.start()]) and m.start() > 0 for m in bracketed
    ):
        for at, match in reversed(list(enumerate(bracketed))):
            before = text[: match.start()].rstrip()
            joined = not before or before[-1] in ":;,.!?"
            mark = "" if joined else (": " if at == 0 else "; ")
            text = before + mark + (" " if joined and before else "") + text[match.end() :]
        return text
    matches = list(_LIST_NUMBER.finditer(text))
    if not _in_order([m.group("n") for m in matches]):
        return text
    for match in reversed(matches):
        text = text[: match.start()] + text[match.end() :]
    return text


# "plot 1 at 70,000 plants/ha, plot 2 at 100,000": two members told apart by number
_MEMBER_LABEL = re.compile(
    r"\b(?P<noun>(?i:plot|block|field|strip|bed|parcel|grove|orchard|vineyard|paddock))\s+"
    r"(?P<label>[1-4]|[A-D]|(?i:one|two|three|four)(?!\s+(?i:ha|hectares?|acres?|m|metres?|meters?)\b))"
    r"\b(?P<colon>\s*[:=])?"
)
# "plot one ..., plot two ...": a member's number said as a word
_LABEL_WORDS = {"ONE": "1", "TWO": "2", "THREE": "3", "FOUR": "4"}


def _member_label(match: re.Match[str]) -> str:
    """The label of a member ("plot 2", "Field B", "plot two"), as a digit or capital."""
    label = match.group("label").upper()
    return _LABEL_WORDS.get(label, label)


# "Field B, east of A": a letter label referred to without its noun
_BARE_MEMBER = re.compile(
    rf"\b(?i:{_BEFORE_REFERENCE})\s+(?P<at>(?:(?i:the)\s+)?)(?P<label>[AB])\b(?!\s*[:=])"
)


def _numbered_members(text: str, tag: Callable[[str], Sequence[Item]]) -> str:
    """``text`` with the two members of "two maize plots" called "plot 1" and "plot 2"
    written "one" and "the other" where first named, "the first" and "the second" after
    ("plot 1: Gala", a label that names a crop, is left to :func:`resolve_labels`;
    "Field A: 200 x 150 m, rows N-S. Field B, east of A: 0.8 ha" names none, so A and
    B are the two members)."""
    matches = list(_MEMBER_LABEL.finditer(text))
    plants = frozenset(str(w) for w in vocabulary()["descriptive_heads"])
    if any(
        m.group("colon")
        # ("block 1: 30 rows of vines" names the plants of the blocks counted, no crop)
        and set(_crop_phrase(text[m.end() :], tag).lower().split()) - plants
        for m in matches
    ):
        return text
    labels = [_member_label(m) for m in matches]
    members = len(set(labels))
    if not 2 <= members <= len(ORDINAL_WORDS) or set(labels) not in (
        {str(n) for n in range(1, members + 1)},
        {chr(ord("A") + n) for n in range(members)},
    ):
        return text
    noun = matches[0].group("noun").lower()
    if any(m.group("noun").lower() != noun for m in matches):
        return text
    counted = counted_plots(text, members, (noun,))
    if counted is None or counted.end() > matches[0].start():
        return text
    # "two plots ... plot 1 ..., plot 2 ...": one and the other where first named; the
    # members in order otherwise ("Strip 2 sits south of strip 1 and strip 3 south of
    # strip 2", "grove 2 south of grove 1")
    by_order = members > 2 or labels[0] not in "1A"
    if by_order and any(_crop_phrase(text[m.end() :], tag) for m in matches):
        return text  # ("plot 1 Cos, plot 2 Iceberg, plot 3 Lollo Rosso": labels defined)
    if labels[0] == "A":
        matches = sorted(
            [*matches, *(m for m in _BARE_MEMBER.finditer(text) if m.start() > matches[0].end())],
            key=lambda m: m.start(),
        )
    out = text
    for match in reversed(matches):
        label = _member_label(match)
        first_said = all(_member_label(m) != label for m in matches if m.start() < match.start())
        if by_order:
            word = ORDINAL_WORDS[int(label) - 1 if label.isdigit() else ord(label) - ord("A")]
        elif first_said:
            word = "one" if label in "1A" else "the other"
        else:
            word = "the first" if label in "1A" else "the second"
        start = match.start("at") if "at" in match.groupdict() else match.start()
        out = out[:start] + word + out[match.end("label") :]
    return out


def _crop_phrase(following: str, tag: Callable[[str], Sequence[Item]]) -> str:
    """The crop words after a label: of its first phrase, or of the first phrase of its
    sentence that names a crop ("Block B, just south of A, is Pinot Noir")."""
    sentence = re.split(r"[.;]", following, maxsplit=1)[0]
    for clause in sentence.split(","):
        if not tokenize(clause):
            continue
        words = [item.raw for item in tag(clause) if item.has(*NAMING)]
        if words:
            return " ".join(words)
    return ""
