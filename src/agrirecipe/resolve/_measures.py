"""Which fields a measure said apart from its field belongs to (issue 8).

Rows, spacings and sizes often stand in a clause of their own: "Gala and Fuji, 40 and 36
rows respectively", "(75 cm rows, 33 cm in-row, 40 m long)", "Rows 30 m, ...", "rows 6 m
apart and trees 3 m apart in both", "Regina, same spacing". These helpers tell
:meth:`~agrirecipe.resolve._parse.PromptReader` whether such a measure is the nearest
field's, every listed field's, or the field before's again (the spacings said by
reference to another field are :mod:`agrirecipe.resolve._same_spacing`'s).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterable, Sequence
from dataclasses import replace

from agrirecipe.resolve._geometry import geometry_nouns
from agrirecipe.resolve._lexicon import Item
from agrirecipe.resolve._links import link_norm, listing
from agrirecipe.resolve._member_refs import said_per_plot
from agrirecipe.resolve._mentions import Clause, Mention
from agrirecipe.resolve._shares import HOLDINGS
from agrirecipe.resolve._structure import per_bed, strong_crops
from agrirecipe.resolve._words import SENTENCE_MARKS

__all__ = [
    "after_list_plots",
    "bracketed_by",
    "drop_total_sizes",
    "each_row_long",
    "fields_of_the_list_headed",
    "heads_a_list",
    "in_a_sentence_of_measures",
    "labelled_by",
    "one_bed_each",
    "opens_with_rows",
    "parallel_fields",
    "sentence_fields",
    "sentence_start",
    "share_each_measures",
    "shared_by_all",
    "shared_by_all_after",
]


def _area(item: Item) -> float | None:
    """The area a size says, None for one side alone ("10 m wide")."""
    size = item.data["size"]
    if size.area_m2 is not None:
        return float(size.area_m2)
    if size.width_m is None or size.length_m is None:
        return None
    return float(size.width_m * size.length_m)


def drop_total_sizes(items: Sequence[Item]) -> list[str]:
    """'We farm 40 acres: 25 acres of wheat and 15 of corn': a size said before any crop
    and followed by two or more sizes that add up to it (within 1 %) is the farm's total,
    not one more size of the first field. It becomes a filler word (--explain lists it as
    not used); return its words."""
    sizes = [index for index, item in enumerate(items) if item.role == "size"]
    dropped: list[str] = []
    for position, index in enumerate(sizes):
        later = sizes[position + 1 :]
        if (
            (len(later) < 2 and not _the_farms(items, index))
            or not later
            or any(i.role == "head" for i in items[: later[0]])
        ):
            continue  # (said before any crop: "Spring Wheat 1 ha ..." is the wheat's)
        total, added = _area(items[index]), 0.0
        if total is None:
            continue
        if _the_farms(items, index) and any(
            (area := _area(items[other])) is not None and area < total * 0.99 for other in later
        ):
            # "A 100-acre farm: 50 acres of wheat, the rest maize and potatoes": the farm's
            # size, and the fields in it smaller
            items[index].role = "filler"
            items[index].data["scenery"] = "total"
            dropped.append(items[index].raw)
            continue
        for count, other in enumerate(later, start=1):
            area = _area(items[other])
            if area is None:
                break  # ("..., with a 10 m wide block of Sweet Corn": no area to add)
            added += area
            if count >= 2 and math.isclose(added, total, rel_tol=0.01):
                items[index].role = "filler"
                items[index].data["scenery"] = "total"
                dropped.append(items[index].raw)
                break
            if added > total * 1.01:
                break
    return dropped


def _the_farms(items: Sequence[Item], index: int) -> bool:
    """Whether the size at ``index`` is said of the farm: "a 100-acre farm", "the farm is
    40 ha", "a farm of 12 hectares"."""
    after = items[index + 1].norm if index + 1 < len(items) else ""
    before = [i.norm for i in items[max(0, index - 2) : index]]
    return after in HOLDINGS or (
        len(before) == 2 and before[0] in HOLDINGS and before[1] in ("is", "of", "covers")
    )


def sentence_fields(clauses: Sequence[Clause], position: int) -> list[Mention]:
    """The fields named in the sentence before clause ``position``, each once."""
    start = sentence_start(clauses, position)
    return list({id(m): m for c in clauses[start:position] for m in c.mentions}.values())


def after_list_plots(clauses: Sequence[Clause], position: int) -> bool:
    """Whether the sentence so far named the plots of a list ("... in adjacent strips")."""
    return any(
        i.data.get("list_plots")
        for clause in clauses[sentence_start(clauses, position) : position + 1]
        for i in clause.items
    )


def opens_with_rows(clauses: Sequence[Clause], position: int) -> bool:
    """Whether a measure clause opens a sentence with the rows' or beds' word after two or
    more fields ("...; Walla Walla, 20 rows at 35 cm. Rows 30 m, ..."): every field's rows."""
    clause = clauses[position]
    if clause.mentions or not clause.items or clause.items[0].role != "geometry":
        return False
    if (
        position > 0
        and clause.link is not None
        and clause.link.norm in (",", "and")
        and _only_measures(clause)
        and _only_measures(clauses[position - 1])
    ):
        # ("... Beds on 1.2 m centres, 2 rows a bed, 25 cm plant spacing": the measures
        # go on in the sentence the rows' word opened)
        return opens_with_rows(clauses, position - 1)
    named = {id(m): m for c in clauses[:position] for m in c.mentions}.values()
    if clause.link is None or (
        clause.link.norm not in SENTENCE_MARKS and not _closes_one_crop(clauses, position, named)
    ):
        return False
    first = clause.items[0].tokens[0].norm
    fields = sum(max(len({id(r) for r in m.refinements}), m.count or 1) for m in named)
    return first in geometry_nouns() and fields >= 2


def _closes_one_crop(clauses: Sequence[Clause], position: int, named: Iterable[Mention]) -> bool:
    """'Walla Walla and Stuttgarter onion plots, ..., Stuttgarter plot east of the Walla
    Walla one, rows NE-SW': a last clause after a comma, once fields of one crop are
    placed against each other."""
    crops = {frozenset(strong_crops(m)) for m in named}
    previous = clauses[position - 1] if position else None
    # ("Bibb lettuce and Stuttgarter onions, two 0.25 ha plots each with ..., the onions
    # south of the lettuce, rows E-W": the way the rows run, after fields said of "each",
    # is every field's, whatever the crops; not "Gala west of wheat, rows NE-SW")
    bearing = _measure_keys(clauses[position].items) == {"row_bearing_deg"} and any(
        i.role == "all" for c in clauses[:position] for i in (*c.items, *c.loose)
    )
    return (
        _clause_is_last(clauses, position)
        and (bearing or (len(crops) == 1 and bool(next(iter(crops)))))
        and previous is not None
        and previous.link is not None
        and previous.link.role == "relation"
    )


def _clause_is_last(clauses: Sequence[Clause], position: int) -> bool:
    """Whether no clause after ``position`` says anything."""
    return all(not c.items and not c.mentions for c in clauses[position + 1 :])


def shared_by_all(clauses: Sequence[Clause], position: int) -> bool:
    """Whether a measure clause continues a run of measures that began with "each" or
    "both" ("both 10 rows at 3.8 m, a tree every 1.2 m, rows running NW-SE")."""
    index = position
    while index > 0:
        clause = clauses[index]
        # ("Both blocks: 15 rows of 80 m, ...": a colon after "both" opens the run)
        if clause.link is None or not (listing(clause.link) or clause.link.norm == ":"):
            return False
        previous = clauses[index - 1]
        # ("Two maize fields, both with 12 m headlands: one 200 x 150 m, rows N-S": a
        # member named after "both" ends the run; its measures are its own)
        if previous.mentions or previous.refinement is not None:
            return False
        # ("Each block is 40 rows x 150 m, rows 2.5 m apart": the "each" clause lent its
        # words to every field, and the measures after it go with them)
        if (
            any(i.role == "all" for i in (*previous.loose, *previous.items))
            or any(
                t.norm in ("each", "both")
                for i in previous.loose
                # ("30-inch ridges, 2 rows each, 20 ridges": rows on each ridge)
                if i.role == "geometry"
                and not per_bed(i)
                and not each_row_long(clauses, index - 1, i)
                for t in i.tokens
            )
            # "8 rows per block, 5 m between rows": measures said per plot
            or said_per_plot(previous.items)
        ):
            return True
        index -= 1
    return False


_SENTENCE_ENDS = frozenset({".", "!", ";"})


def _ends_a_sentence(clause: Clause) -> bool:
    """Whether the clause begins a new sentence ("...; fruit ready", "... . Rows ...")."""
    link = clause.link
    return link is not None and link.norm in _SENTENCE_ENDS


def sentence_start(clauses: Sequence[Clause], position: int) -> int:
    """The index of the clause that begins the sentence clause ``position`` is in."""
    start = position
    while start > 0 and not _ends_a_sentence(clauses[start]):
        start -= 1
    return start


def _only_measures(clause: Clause) -> bool:
    """A clause of row measures and words that say nothing of a field ("Tall spindle")."""
    return not clause.mentions and all(
        i.role in ("geometry", "filler", "all", "unknown")
        or (i.role == "number" and i.norm in ("a", "an"))
        for i in clause.items
    )


def in_a_sentence_of_measures(clauses: Sequence[Clause], position: int) -> bool:
    """Whether a clause of measures lies in a sentence that names no field."""
    clause = clauses[position]
    if not any(i.role == "geometry" for i in clause.items):
        return False
    index = position
    while True:
        current = clauses[index]
        if not _only_measures(current):
            return False
        if _ends_a_sentence(current):
            return True
        if current.link is None or index == 0:
            return False
        index -= 1


def _measure_keys(items: Sequence[Item]) -> frozenset[str]:
    """The geometry keys a field's (or a clause's) words state ("row_spacing_m", ...)."""
    return frozenset(g.key for i in items if i.role == "geometry" for g in i.data["geometry"])


def parallel_fields(clauses: Sequence[Clause], position: int) -> list[Mention]:
    """'10 rows of beef tomatoes north of 10 rows of cherry tomatoes, 1.6 m between
    rows': the fields of the sentence, when each states the same measures, so what
    follows them in that sentence is about all of them ([] otherwise)."""
    # "Two vineyard blocks: Chardonnay ... and Cabernet ...": the members, not their host
    fields = list(
        {
            id(f): f for m in sentence_fields(clauses, position) for f in (m.refinements or [m])
        }.values()
    )
    if any(f.clause > position for f in fields):
        return []  # a member named later takes what comes before it
    end = position + 1
    while end < len(clauses) and not _ends_a_sentence(clauses[end]):
        if any(all(m is not f for f in fields) for m in clauses[end].mentions):
            return []  # a field named later in the sentence takes what comes before it
        end += 1
    if len(fields) < 2 or any((m.count or 1) > 1 or m.refinements for m in fields):
        return []
    keys = [_measure_keys(m.items) for m in fields]
    if not all(k == keys[0] for k in keys):
        return []
    if keys[0]:
        return fields
    # "a Navel block next to a blood orange block, 6 m between rows": blocks of one crop
    # that state no measures anywhere before share the run of measures said after them
    crops = [strong_crops(m) for m in fields]
    run = position
    while run > 0 and _only_measures(clauses[run - 1]) and not _ends_a_sentence(clauses[run]):
        run -= 1
    measured_before = any(i.role == "geometry" for c in clauses[:run] for i in (*c.items, *c.loose))
    return fields if crops[0] and all(c == crops[0] for c in crops) and not measured_before else []


#: Words after a size that make it every listed field's ("1 ha each").
_EACH_SIZE = ("each", "both")


def share_each_measures(clauses: Sequence[Clause]) -> None:
    """'The Hamlin block ..., Washington Navel the west half: 150 trees each at 7 m x 4 m':
    a measure said with "each" by the last of a list is every listed field's."""
    for position, clause in enumerate(clauses):
        for mention in clause.mentions[-1:]:
            ordered = sorted(mention.items, key=lambda i: i.start)
            # (the word after it in the clause: "gala half an acre each")
            in_clause = sorted(clause.items, key=lambda i: i.start)
            following: list[Item | None] = [
                next((b for b in in_clause if b.start >= a.end), None) for a in ordered
            ]
            sizes = [
                a
                for a, b in zip(ordered, following, strict=True)
                if a.role == "size"
                and (
                    (b is not None and b.role == "all" and b.norm in _EACH_SIZE)
                    # "Cos, iceberg and Lollo in three plots of 10 x 25 m": each plot's
                    or bool(a.data.get("of_each_plot"))
                )
            ]
            if sizes:
                # "wheat north of maize north of potatoes 1 ha each": every field's size
                for other in sentence_fields(clauses, position):
                    if other is not mention and not any(i.role == "size" for i in other.items):
                        other.items.extend(sizes)
            # "150 trees each at 7 m x 4 m": the whole measure, said for every one
            measures = [i for i in mention.items if i.role == "geometry"]
            said_each = [i for i in measures if not per_bed(i) and _said_of_each(i)]
            if not said_each or _of_each_row(measures, said_each):
                # "Fontane, Agria and Bintje in three 9-row strips": each plot's rows
                measures = [i for i in measures if i.data.get("of_each_plot")]
            if not measures:
                continue
            for other in sentence_fields(clauses, position):
                if other is not mention:
                    said = _measure_keys(other.items)
                    other.items.extend(i for i in measures if not _measure_keys([i]) & said)


#: Plot words after "per" that say a measure of every field ("150 trees per block").
_PER_PLOT = frozenset({"block", "plot", "field", "orchard", "vineyard", "strip", "grove"})


def _said_of_each(item: Item) -> bool:
    """Whether a measure is said with "each" or "both", or "per block" ("one block each
    of apples, pears and cherries, 150 trees per block")."""
    words = [t.norm for t in item.tokens]
    return any(w in ("each", "both") for w in words) or any(
        a == "per" and b in _PER_PLOT for a, b in itertools.pairwise(words)
    )


def _of_each_row(measures: Sequence[Item], said_each: Sequence[Item]) -> bool:
    """'Tomato rows - 20 rows, 50 m each, 1.5 m between rows': a length said "each" after
    the field's own count of rows is each row's, not each field's."""
    own = [i for i in measures if all(i is not e for e in said_each)]
    if all(
        _measure_keys([i]) == {"rows", "row_length_m"} and _each_before_a_length(i)
        for i in said_each
    ):
        return True  # "40 rows, each 500 ft long": the count in the same measure
    return all(_measure_keys([i]) <= {"row_length_m"} for i in said_each) and "rows" in (
        _measure_keys(own)
    )


def _each_before_a_length(item: Item) -> bool:
    """Whether "each" in the measure stands right before a number ("rows, each 500 ft")."""
    words = [t.norm for t in item.tokens]
    return any(a == "each" and b[:1].isdigit() for a, b in itertools.pairwise(words))


def each_row_long(clauses: Sequence[Clause], position: int, item: Item) -> bool:
    """'20 rows, 50 m each': a row length said "each" right after a count of rows is the
    length of each of those rows, not a measure of each field."""
    keys = _measure_keys([item])
    if "row_length_m" not in keys or not any(t.norm == "each" for t in item.tokens):
        return False
    if keys == {"rows", "row_length_m"}:
        # "40 rows, each 500 ft long": "each" before the length, in the same measure (not
        # "8 rows of 60 m each", each field's)
        return _each_before_a_length(item)
    if keys != {"row_length_m"}:
        return False
    said = [*clauses[position].items]
    if position:
        said += clauses[position - 1].items
    return any(
        g.key == "rows"
        for i in said
        if i.role == "geometry" and i is not item
        for g in i.data["geometry"]
    )


def bracketed_by(clauses: Sequence[Clause], position: int) -> Mention | None:
    """The field a bracket of measures follows ("two lettuce plots (10 rows each, ...)"),
    when clause ``position`` lies inside that bracket; None otherwise."""
    for index in range(position, 0, -1):
        clause = clauses[index]
        if clause.mentions or clause.link is None or clause.link.norm == ")":
            return None
        if clause.link.norm == "(":
            before = clauses[index - 1].mentions
            return before[-1] if before else None
    return None


def labelled_by(clauses: Sequence[Clause], position: int) -> Mention | None:
    """The field a sentence opens as a label ("Tomato plots: 10 rows each, 1.5 m apart.")
    when clause ``position`` is one of the measures after its colon, and the sentence
    names no field after them (else the label heads that list); None otherwise."""
    for clause in clauses[position:]:
        if clause.index > position and link_norm(clause) in (".", "!", "?", ";"):
            break
        if clause.mentions:
            return None
    for index in range(position, 0, -1):
        clause = clauses[index]
        if clause.mentions or clause.link is None or clause.link.norm not in (",", ":"):
            return None
        if clause.link.norm == ":":
            label = clauses[index - 1]
            opens = label.link is None or label.link.norm in (".", "!", "?", ";")
            return label.mentions[-1] if opens and len(label.mentions) == 1 else None
    return None


def heads_a_list(clauses: Sequence[Clause], position: int) -> bool:
    """Whether a measure clause begins a run of measures that a colon ends, before a list
    of two or more fields ("rows east-west, 2.0 m between rows and 1.1 m between vines:
    Riesling (20 rows) on the north side, Pinot Noir (16 rows) on the south side")."""
    return fields_of_the_list_headed(clauses, position) >= 2


def fields_of_the_list_headed(clauses: Sequence[Clause], position: int) -> int:
    """How many fields the list after a run of measures ended by a colon names (see
    :func:`heads_a_list`); 0 when the measure clause heads no such list."""
    index = position
    while index < len(clauses) and not clauses[index].mentions:
        clause = clauses[index]
        if index > position and (clause.link is None or not listing(clause.link)):
            return 0
        if not clause.items or any(
            i.role not in ("geometry", "filler", "all", "of") for i in clause.items
        ):
            return 0
        index += 1
    if index >= len(clauses) or index == position:
        return 0
    opening = clauses[index]
    # ("three 1.5 m beds, 4 rows per bed, 30 cm in-row - Cos, Lollo, Iceberg": or a dash)
    if opening.link is None or opening.link.norm not in (":", "-", "–", "—"):
        return 0
    listed = [opening]
    seen = {h.norm for m in opening.mentions for h in m.heads if h.role == "head"}
    for clause in clauses[index + 1 :]:
        if clause.link is not None and clause.link.norm in SENTENCE_MARKS:
            break
        heads = {h.norm for m in clause.mentions for h in m.heads if h.role == "head"}
        if heads & seen:
            break  # ("..., onions on the middle bed": a member named again)
        if clause.mentions and clause.link is not None and listing(clause.link):
            listed.append(clause)
            seen |= heads
    return len(listed) if len(listed) >= 2 else 0


def one_bed_each(geometry: Sequence[Item], members: int) -> list[Item]:
    """'three 1.5 m beds: lettuce, onions and carrots': a count of beds said before a
    list of as many fields is one bed for each of them. Returns the measures so read."""
    read: list[Item] = []
    for item in geometry:
        matches = item.data.get("geometry", ())
        if not any(m.key == "beds" and m.value == members for m in matches):
            read.append(item)
            continue
        one = [replace(m, value=1.0) if m.key == "beds" else m for m in matches]
        read.append(replace(item, data={**item.data, "geometry": one}))
    return read


def shared_by_all_after(clauses: Sequence[Clause], position: int) -> bool:
    """Whether a measure clause begins a run of measures that ends with "in both" or "in
    each" ("rows 6 m apart and trees 3 m apart in both")."""
    index = position + 1
    while index < len(clauses):
        clause = clauses[index]
        if clause.link is None or not listing(clause.link) or clause.mentions:
            return False
        if clause.link.norm in SENTENCE_MARKS:
            return False  # "..., 20 rows; all rows 40 m": a new sentence for every field
        if not clause.items or any(
            i.role not in ("geometry", "filler", "all")
            and not (i.role == "number" and i.norm in ("a", "an"))  # "and a 6 m headland"
            for i in clause.items
        ):
            return False
        alls = [i for i in clause.items if i.role == "all"]
        if alls:
            # ("cherry tomatoes, 10 rows at 1.5 m, and beef tomatoes, 10 rows at 1.8 m,
            # both 0.5 m in-row": "both" said before a measure of its own, after a run
            # that says again what an earlier field said for itself, is about that
            # measure only; so is "in each" after one: "one with ... trees every 0.6 m,
            # the other with ... trees every 1.5 m, 10 rows in each")
            run = _measure_keys([i for c in clauses[position:index] for i in c.items])
            start = sentence_start(clauses, position)
            said_before = _measure_keys([i for c in clauses[start:position] for i in c.items])
            return not run & said_before
        index += 1
    return False
