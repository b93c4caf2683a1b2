"""Fields named by a label: "Block A: Jonagored apples, ... Block B, north of A: pears".

Engineers name plots by letter or number and then place the others against the
label. Before the prompt is read, each label that introduces a field ("Block A:",
"Plot 2 -") is dropped, and each later reference to it ("north of A", "beside plot
2") becomes a definite reference to the crop named after the label ("north of the
Jonagored apples"), which the reader already resolves to that field.

A compass position used as a label ("the east plot is Bintje, the west plot
Fontane") is moved after what it names ("Bintje in the eastern block"), where the
reader places fields by a trailing direction.
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

__all__ = [
    "drop_list_numbers",
    "open_ordered_lists",
    "place_compass_members",
    "place_leading_directions",
    "place_trailing_directions",
    "place_walked_orders",
    "resolve_labels",
]

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
_NAMING = ("crop", "variety", "category")


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
        and all(i.has(*_NAMING) for i in items)
    ]
    if len(found) < 2:
        return text
    for match in reversed(found):
        lead = match.group("lead")
        lead = ", " if lead.strip().lower() == "and" else lead  # ("..., and field B: pears")
        said = f"{lead}{match.group('noun')} {match.group('label')}: {match.group('crop')}"
        text = text[: match.start()] + said + text[match.end() :]
    return text


def resolve_labels(text: str, tag: Callable[[str], Sequence[Item]]) -> tuple[str, list[str]]:
    """``text`` with field labels dropped and references to them spelled out.

    ``tag`` reads a phrase into lexicon items. Returns the new text and one note per
    label ("Block A = Jonagored apples"). Text with fewer than two labels that name
    crops is returned unchanged.
    """
    text = _crops_in_labels(text, tag)
    text = _PLACED_THEN_MEASURED.sub(r"\g<head> \g<rest>, \g<where>", text)
    text = _NAME_PLACED_THEN_MEASURED.sub(r"\g<name>: \g<rest>, \g<where>\g<end>", text)
    text = name_members_again(text, tag)
    text = _PLURAL_LABELS.sub(_one_noun_each, valued_members(_numbered_members(text, tag)))
    text = _BETWEEN_BARE_LABELS.sub(lambda m: f"{m.group('head')}{_one_noun_each(m)}", text)
    text = _PLACED_THEN_NAMED.sub(r"\g<head>, \g<where>, is", text)
    text = _PLACED_THEN_MARKED.sub(_placed_then_marked, text)
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
            if first and first[0].has(*_NAMING):
                definitions.append(match)
        definitions.sort(key=lambda m: m.start())
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
            + rf"\b(?=\s+(?i:{_SUBJECT_VERBS})\b)"
        )
        out, said = subject.subn("the " + phrase.replace("\\", "\\\\"), out)
        count += said
        # a label never referenced is still a name, not another field ("Plot 2: ...")
        notes.append(f"{label} = {phrase}" + ("" if count else " (a label only)"))
    return out, notes


# "plot 2 is 10 m west of plot 1 and is wheat": a label placed first and named after
# "and is" defines its field, like "plot 2, 10 m west of plot 1, is wheat"
_PLACED_THEN_NAMED = re.compile(
    rf"(?P<head>\b{_LABEL})\s+(?i:is|lies|sits)\s+"
    rf"(?P<where>[^;.,:]*?\b(?i:{_BEFORE_REFERENCE})\s+(?:(?i:the)\s+)?{_LABEL})"
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
    rf"(?P<where>{_CLOSE}(?i:north|south|east|west)\s+"
    r"(?i:of)\s+[^,:;.]+?)\s*:\s*(?P<rest>\d(?:[^.;:]|\.(?=\d))*?)\s*(?P<end>[;!?]|\.(?!\d)|$)"
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
        if first and first[0].has(*_NAMING):
            return f"{match.group('order')}: "
        return match.group(0)

    return _ORDER.sub(colon, text)


# "2 plots: (1) wheat ..., 1 ha; (2) a 1 ha maize plot ...": the numbers of a list
_LIST_NUMBER = re.compile(r"(?:(?<=^)|(?<=[:;,.!?]\s)|(?<=\n))\(?(?P<n>[1-9]|[a-h])\)\s+")


def drop_list_numbers(text: str) -> str:
    """``text`` without the numbers of a list ("(1) wheat ...; (2) maize ...", "a) ...
    b) ..."): two or more, in order from 1 (or a), each opening its item. They count
    no fields and name none."""
    matches = list(_LIST_NUMBER.finditer(text))
    order = [m.group("n") for m in matches]
    if len(order) < 2 or order not in (
        [str(i) for i in range(1, len(order) + 1)],
        [chr(ord("a") + i) for i in range(len(order))],
    ):
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
        words = [item.raw for item in tag(clause) if item.has(*_NAMING)]
        if words:
            return " ".join(words)
    return ""


# "top half corn bottom half wheat": the next side's part, said after a field's words
_SIDE_PART = (
    r"\s+(?:(?i:the)\s+)?(?i:north|south|east|west|top|bottom|upper|lower)(?i:ern)?\s+"
    r"(?i:plot|block|field|one|part|half|strip|parcel|section|paddock|area)\b"
)
# "the east plot is Bintje with late blight, ...": a field named by its compass position
_LEADING = re.compile(
    r"(?<!in )(?<!on )(?<!of )(?<!at )(?<!to )"
    r"(?:\b(?i:the)\s+|(?:^|(?<=[,;.:]\s)))(?P<side>(?i:north|south|east|west|top|bottom|upper|lower))(?i:ern)?\s+"
    r"(?P<noun>(?i:plot|block|field|one|part|half|strip|parcel|section|paddock|area))\b\s*"
    r"(?:(?i:is|are|has|holds|gets|grows|has got)\s+|[:\-–—]\s*)?"
    # (the rest runs to a mark, past a decimal point or a thousands comma: "drilled in
    # 12.5 cm rows", "at 80,000 plants/ha"; or to the next side's plot: "the south block
    # is Grande Naine and the north block is Lady Finger")
    r"(?P<rest>(?!(?i:of|to|and|with|in|on|at|is|are)\b)[^\s,;.:()]"
    r"(?:(?!\s+(?i:and|but|while|whereas)\s+(?:(?i:the)\s+)?"
    r"(?i:north|south|east|west|top|bottom|upper|lower)(?i:ern)?\s)"
    # ("top half corn bottom half wheat": to the next side's part, said without a mark)
    rf"(?!{_SIDE_PART})"
    r"[^,;.:()]|[.,](?=\d))*)"
)
_NEXT_SIDE = re.compile(_SIDE_PART)


# "the western block at 2.75 m between rows", "the eastern one at 3 m": a member named by
# its side, then its measures (to a mark, past a decimal point)
_SIDE_MEMBER = re.compile(
    r"\b(?i:the)\s+(?P<side>(?i:north|south|east|west))(?i:ern)?\s+"
    r"(?P<noun>(?i:block|plot|field|strip|one|half|part|section|parcel|bed))\s+"
    r"(?P<rest>(?i:at|with|on|of)\s+\d(?:[^,;.:()]|[.,](?=\d))*)"
)


# "Upper block (north): Riesling": a block named by where it is, then its compass side
_SIDE_IN_BRACKETS = re.compile(
    r"\b(?i:upper|lower|top|bottom|left|right|front|back|near|far)\s+"
    r"(?P<noun>(?i:plot|block|field|strip|parcel|section|paddock|area))\s*"
    r"\(\s*(?P<side>(?i:north|south|east|west))(?i:ern)?(?:\s+(?i:side|end|half))?\s*\)"
    r"(?=\s*[:\-–—])"
)


def place_leading_directions(text: str) -> str:
    """``text`` with "the east plot is X" written "X in the eastern block", and "X in the
    north orchard" written "X in the north block" (where X is, not one more field)."""
    text = _SIDE_IN_BRACKETS.sub(lambda m: f"{m.group('side').lower()} {m.group('noun')}", text)
    for _ in range(_MAX_UNMARKED_SIDES):
        # (again after each, for the next side's part said without a mark)
        placed = _LEADING.sub(_placed_on_its_side, text)
        if placed == text:
            break
        text = placed
    if len({m.group("side").lower() for m in _SIDE_MEMBER.finditer(text)}) >= 2:
        # "the western block at 2.75 m between rows, the eastern block at 3 m": members
        # told apart by their sides, each said after its measures
        text = _SIDE_MEMBER.sub(
            lambda m: (
                f"the {m.group('noun')} {m.group('rest').rstrip()} on the "
                f"{m.group('side').lower()} side"
            ),
            text,
        )
    return _IN_SIDE_PLOT.sub(lambda m: f"{m.group('at')} the {m.group('side').lower()} block", text)


#: How many sides' parts said one after another without a mark are read.
_MAX_UNMARKED_SIDES = 4


def _placed_on_its_side(match: re.Match[str]) -> str:
    """ "the east plot is X" as "X in the eastern block"; "the top field is X" as "X in the
    top field", a zone read with the farm's other zones ("...; below it maize; and at the
    bottom, carrots")."""
    side = match.group("side")
    rest = match.group("rest").rstrip()
    # ("top half corn bottom half wheat": the next side's part begins)
    mark = "," if _NEXT_SIDE.match(match.string, match.end()) else ""
    if side.lower() in _OPPOSITE_SIDES:
        return f"{rest} in the {side.lower()}ern block{mark}"
    return f"{rest} in the {side} {match.group('noun')}{mark}"


# "Durondeau pears in the north orchard", "Cos on the north beds": where the pears are
_IN_SIDE_PLOT = re.compile(
    r"\b(?P<at>(?i:in|on))\s+(?i:the)\s+(?P<side>(?i:north|south|east|west))(?i:ern)?\s+"
    r"(?i:orchard|vineyard|paddock|grove|plantation|patch|strip|beds|rows|terraces)\b"
    r"(?!\s+(?i:of|is|has|are|with)\b)"
)


# "The north block has downy mildew, the south block is clean": two members told apart
# by their side, described, not named
_COMPASS_MEMBER = re.compile(
    # "the north block has ...", "in the west plot the leaves are ..."
    r"\b(?P<at>(?i:in)\s+)?(?P<the>(?i:the))\s+(?P<side>(?i:north|south|east|west))(?i:ern)?\s+"
    r"(?i:block|plot|field|one|strip|vineyard|orchard|half|bed|paddock|grove|patch)\b"
    r"(?=(?(at)\s*|\s+(?i:has|is|shows|looks|was|carries|got|has got|with)\b)(?P<rest>[^,;.]*))"
)
_OPPOSITE_SIDES = {"north": "south", "south": "north", "east": "west", "west": "east"}


def place_compass_members(text: str, tag: Callable[[str], Sequence[Item]]) -> str:
    """``text`` with "the north block has X, the south block is Y" written "one to the
    north has X, the other to the south is Y" when X and Y name no crop (two members of a
    counted plot, told apart by side; "the east plot is Bintje" is left to name a field)."""
    matches = list(_COMPASS_MEMBER.finditer(text))
    if len(matches) != 2:
        return text
    first, second = matches
    sides = first.group("side").lower(), second.group("side").lower()
    if _OPPOSITE_SIDES[sides[0]] != sides[1]:
        return text
    if any(item.has(*_NAMING) for m in matches for item in tag(m.group("rest"))):
        return text
    one = "One" if (first.group("at") or first.group("the"))[0].isupper() else "one"
    other = "The other" if (second.group("at") or second.group("the"))[0].isupper() else "the other"
    return (
        text[: first.start()]
        + f"{one} to the {sides[0]}"
        + text[first.end() : second.start()]
        + f"{other} to the {sides[1]}"
        + text[second.end() :]
    )


# "the top field", "the bottom plot": north and south, as zones read them
_SIDES = {
    "north": "north",
    "south": "south",
    "east": "east",
    "west": "west",
    "top": "north",
    "upper": "north",
    "bottom": "south",
    "lower": "south",
}


# "carrots north, potatoes south": a compass word alone after what it places
_TRAILING = re.compile(
    r"\b(?P<word>[A-Za-z][\w'-]*)\s+(?P<side>(?i:north|south|east|west))\b(?=\s*(?:[,.;]|$))"
)
#: Words after which a compass word is a direction, not a place ("rows running north").
_NOT_PLACED = frozenset(
    {
        "run",
        "runs",
        "running",
        "facing",
        "face",
        "faces",
        "going",
        "heading",
        "looking",
        "look",
        "due",
        "to",
        "the",
        "of",
        "from",
        "towards",
        "toward",
        "pointing",
        "lying",
        "aligned",
        "oriented",
        "orientated",
        "far",
        "up",
        "down",
        "back",
        "out",
        "and",
    }
)


# "two apple blocks: Granny (west) and Fuji (east)": a side in brackets after a field
_BRACKETED_SIDE = re.compile(
    r"\(\s*(?P<side>(?i:north|south|east|west))(?i:ern)?(?:\s+(?i:side|end|half))?\s*\)"
)


def place_trailing_directions(text: str) -> str:
    """``text`` with "carrots north, potatoes south" written "carrots in the north,
    potatoes in the south" (two or more such places, not all the same), and likewise
    "Granny (west) and Fuji (east)"."""
    sides = {m.group("side").lower() for m in _BRACKETED_SIDE.finditer(text)}
    if len(sides) >= 2:
        # ("Zone 1 (north end): Bing cherries": a zone before its field, as "At the top:")
        text = _BRACKETED_SIDE.sub(
            lambda m: (
                f"at the {m.group('side').lower()} end"
                if text[m.end() :].lstrip().startswith(":")
                else f"in the {m.group('side').lower()}"
            ),
            text,
        )
    matches = [m for m in _TRAILING.finditer(text) if m.group("word").lower() not in _NOT_PLACED]
    if len(matches) < 2 or len({m.group("side").lower() for m in matches}) < 2:
        return text
    for match in reversed(matches):
        start, end = match.span("side")
        text = f"{text[:start]}in the {match.group('side')}{text[end:]}"
    return text


#: The side words a walk across the farm starts and ends at, with the side opposite.
_WALK_SIDES = {
    "bottom": "top",
    "top": "bottom",
    "north": "south",
    "south": "north",
    "east": "west",
    "west": "east",
    "left": "right",
    "right": "left",
}
_SIDE = "|".join(_WALK_SIDES)
# "Starting at the bottom of the farm by the road and working up to the top: onions,
# then carrots, then potatoes", "from the bottom of the farm up to the top: ...": an
# order said as a walk from one side to the opposite one
_WALKED = re.compile(
    rf"\b(?:(?i:starting|beginning|start|begin)\s+(?i:at|from)|(?i:from))\s+(?i:the)\s+"
    rf"(?P<start>(?i:{_SIDE}))(?:\s+(?i:end|side|edge))?\b"
    r"(?P<between>[^:;.,!?]{0,60}?)"
    r"\s+(?:(?i:and)\s+)?(?:(?i:working|going|moving|heading|walking|coming|running)\s+)?"
    r"(?:(?i:up|down|across|over|along|back)\s+)?(?i:to|towards|toward)\s+(?i:the)\s+"
    rf"(?P<end>(?i:{_SIDE}))(?:\s+(?i:end|side|edge))?\b"
)


def place_walked_orders(text: str) -> str:
    """``text`` with "starting at the bottom ... and working up to the top" written
    "from bottom to top" (an order of the fields named after it), when the walk ends at
    the side opposite where it starts."""

    def order(match: re.Match[str]) -> str:
        start, end = match.group("start").lower(), match.group("end").lower()
        if _WALK_SIDES[start] != end:
            return match.group(0)
        return f"from {start} to {end}"

    text = _WALKED.sub(order, text)
    # "Top to bottom on our hillside farm in Madeira: ...": the place said first, so the
    # order stands right before the list it orders
    text = _ORDER_THEN_PLACE.sub(
        lambda m: (
            f"{m.group('place')}, {m.group('order').lower()}:"
            if _WALK_SIDES[m.group("a").lower()] == m.group("b").lower()
            else m.group(0)
        ),
        text,
    )
    return _EACH_FURTHER.sub(
        lambda m: f", laid out {_WALK_SIDES[m.group('side').lower()]} to {m.group('side').lower()}",
        text,
    )


_ORDER_THEN_PLACE = re.compile(
    rf"(?:^|(?<=[.;!?]\s))(?P<order>(?:(?i:from)\s+)?(?P<a>(?i:{_SIDE}))\s+(?i:to)\s+"
    rf"(?P<b>(?i:{_SIDE})))\s+(?P<place>(?i:on|at|in|across)\s+[^:;.,]{{1,60}}?)\s*:"
)


# "first the Hamlin grove, then the Navel, then the Moro, each one further north": the
# fields in the order named, from the opposite side to that one
_EACH_FURTHER = re.compile(
    r",?\s*\b(?i:each|every)\s+(?:(?i:one|block|field|plot|strip|orchard|grove)\s+)?"
    r"(?i:further|farther|a bit further|a little further)\s+(?P<side>(?i:north|south|east|west))\b"
    r"(?:\s+(?i:than the last|again))?"
)
