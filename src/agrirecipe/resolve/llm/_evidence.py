"""Retrieval over the lexicon: the candidates a run of the request's words offers."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from agrirecipe.resolve._grammar import ANY_PREFIX, OTHER
from agrirecipe.resolve._intent import Candidate, Hemisphere, ResolveContext

if TYPE_CHECKING:
    from agrirecipe.resolve._lexicon import Item, Lexicon

_SOUTHERN = {"Spring": "Fall", "Summer": "Winter", "Fall": "Spring", "Winter": "Summer"}


# --- retrieval over the lexicon --------------------------------------------------


@dataclass(slots=True)
class _Evidence:
    """What the lexicon finds in a run of words: the candidates of one part."""

    crops: dict[str, str] = field(default_factory=dict)  # crop -> words as typed
    varieties: dict[tuple[str, str], str] = field(default_factory=dict)  # (crop, variety) -> words
    weak_varieties: set[tuple[str, str]] = field(default_factory=set)
    categories: dict[str, str] = field(default_factory=dict)
    plot_options: list[str] = field(default_factory=list)
    plot_category: str | None = None
    noun: str | None = None
    other: dict[str, tuple[str, ...]] = field(default_factory=dict)  # unknown plant -> nearest
    states: dict[str, list[str]] = field(default_factory=dict)  # "stage" -> ["Vegetative"]
    counts: list[int] = field(default_factory=list)
    distinct: bool = False
    all_words: bool = False
    sizes: list[str] = field(default_factory=list)  # "50 x 100 m", "2 ha"
    units: dict[str, tuple[str, float]] = field(default_factory=dict)  # word -> (kind, factor)
    relations: list[str] = field(default_factory=list)
    hemisphere: tuple[str, float] | None = None
    place: tuple[str, float] | None = None
    candidates: list[Candidate] = field(default_factory=list)

    @property
    def names_a_plant(self) -> bool:
        return bool(self.crops or self.varieties or self.other)

    @property
    def names_a_field(self) -> bool:
        return self.names_a_plant or bool(
            self.categories or self.plot_options or self.plot_category
        )

    def add_state(self, key: str, value: str) -> None:
        values = self.states.setdefault(key, [])
        if value not in values:
            values.append(value)


_FIELD_SENSES = ("crop", "variety", "category", "plot", "other_crop")


def _collect(lexicon: Lexicon, text: str, hemisphere: Hemisphere | None = None) -> _Evidence:
    """Candidates for one run of words (exact lexicon matches, then typo matches)."""
    from agrirecipe.resolve._lexicon import tokenize, vocabulary

    vocab = vocabulary()
    cues = {str(word) for word in vocab["month_cues"]}
    evidence = _Evidence()
    items = lexicon.tag(tokenize(text))
    readings = _readings(lexicon, items, evidence.candidates)
    for index, (item, senses) in enumerate(zip(items, readings, strict=True)):
        previous = items[index - 1] if index else None
        negated = previous is not None and previous.has("negation")
        after_cue = previous is not None and previous.norm in cues
        kept = [s for s in senses if not (_in_size(items, index) and s.kind == "relation")]
        _add_senses(evidence, item, kept, negated=negated, after_cue=after_cue)
        if item.norm in (":", ".", ";"):
            evidence.counts.clear()  # "three fields: ..." announces the fields that follow
        elif _counts_fields(items, readings, index):
            evidence.counts += [
                int(s.value) for s in senses if s.kind in ("number", "quantity") and s.value > 1
            ]
            if item.norm.isdigit() and int(item.norm) > 1:
                evidence.counts.append(int(item.norm))
    _promote_weak_varieties(evidence, items, readings)
    evidence.sizes = _size_options(items, readings)
    for month in evidence.states.pop("month", []):
        season = _month_season(int(month), hemisphere, vocab["month_seasons_north"])
        evidence.add_state("season", season)
    return evidence


def _readings(
    lexicon: Lexicon, items: Sequence[Item], candidates: list[Candidate] | None = None
) -> list[Sequence[Any]]:
    """Each item's senses; unknown words are read as typos of a phrase when close enough.

    Two neighbouring words are tried together first ("granny smtih" -> "granny
    smith"), then the unknown word alone ("aples" -> "apples").
    """
    readings: list[Sequence[Any]] = [item.senses for item in items]
    index = 0
    while index < len(items):
        item = items[index]
        if item.senses or len(item.norm) < 4 or not item.norm.isalpha():
            index += 1
            continue
        pairs = []
        if index > 0 and items[index - 1].norm.isalpha() and not items[index - 1].has("filler"):
            pairs.append((index - 1, f"{items[index - 1].norm} {item.norm}"))
        if index + 1 < len(items) and items[index + 1].norm.isalpha():
            pairs.append((index, f"{item.norm} {items[index + 1].norm}"))
        for first, phrase in pairs:
            match = lexicon.fuzzy(phrase)
            if match is not None and " " in match[0]:
                readings[first], readings[first + 1] = match[2], ()
                break
        else:
            match = lexicon.fuzzy(item.norm)
            if match is not None:
                readings[index] = match[2]
        if match is not None and candidates is not None:
            candidates.append(Candidate(value=match[0], score=match[1], source="fuzzy"))
        index += 1
    return readings


def _in_size(items: Sequence[Item], index: int) -> bool:
    """Whether the item at ``index`` joins two sides of a size ("50 by 100", "50 m by 100 m")."""
    if not items[index].has("dimension_joiner") or index == 0:
        return False
    previous = items[index - 1]
    if previous.has("length_unit") and index >= 2:
        previous = items[index - 2]
    return _is_number(previous)


def _is_number(item: Item | None) -> bool:
    return item is not None and (item.norm[:1].isdigit() or item.has("number", "fraction"))


def _counts_fields(items: Sequence[Item], readings: Sequence[Sequence[Any]], index: int) -> bool:
    """Whether the number at ``index`` counts fields ("two fields", "3 tomato plots")."""
    item = items[index]
    if not (item.norm.isdigit() or item.has("number", "quantity")):
        return False
    for later in range(index + 1, min(index + 4, len(items))):
        kinds = {s.kind for s in readings[later]}
        if kinds & set(_FIELD_SENSES):
            return True
        if kinds & {"area_unit", "length_unit", "number", "conjunction", "separator", "relation"}:
            return False
    return False


def _promote_weak_varieties(
    evidence: _Evidence, items: Sequence[Item], readings: Sequence[Sequence[Any]]
) -> None:
    """A weak variety word next to its crop's name is a variety ("Sonata strawberries")."""
    for index, senses in enumerate(readings):
        for sense in senses:
            if sense.kind != "variety" or (sense.crop, sense.value) not in evidence.weak_varieties:
                continue
            neighbours = [readings[j] for j in (index - 1, index + 1) if 0 <= j < len(items)]
            if any(s.kind == "crop" and s.value == sense.crop for n in neighbours for s in n):
                evidence.weak_varieties.discard((sense.crop, sense.value))


def _size_options(items: Sequence[Item], readings: Sequence[Sequence[Any]]) -> list[str]:
    """The sizes the words can state: ``"50 x 100 m"`` or ``"2 ha"``, numbers as written."""
    options: list[str] = []
    pending: list[str] = []
    sided: tuple[str, str] | None = None  # "100 m" waiting for "by 200 m"
    for item, senses in zip(items, readings, strict=True):
        kinds = {s.kind: s for s in senses}
        if item.norm[:1].isdigit():
            pending.append(item.norm)
        elif "fraction" in kinds:
            pending.append(f"{float(kinds['fraction'].value):g}")
        elif "number" in kinds and item.norm not in ("a", "an") and item.norm.isalpha():
            pending.append(str(kinds["number"].value))
        elif "area_unit" in kinds and pending:
            options.append(f"{pending[-1]} {_unit_word(item)}")
            pending, sided = [], None
        elif "length_unit" in kinds and pending:
            if len(pending) >= 2:
                options.append(f"{pending[-2]} x {pending[-1]} {_unit_word(item)}")
            elif sided is not None and sided[1] == _unit_word(item):
                square = f"{sided[0]} x {sided[0]} {_unit_word(item)}"
                if square in options:  # "40 m wide and 80 m long" is one rectangle
                    options.remove(square)
                options.append(f"{sided[0]} x {pending[-1]} {_unit_word(item)}")
                sided = None
            else:
                sided = (pending[-1], _unit_word(item))
            pending = []
        elif "side" in kinds and sided is not None:
            # "a 100 m long field": one side only reads as a square (as the lexical reader)
            options.append(f"{sided[0]} x {sided[0]} {sided[1]}")
        elif not (kinds.keys() & {"dimension_joiner", "filler"}):
            pending = []
    return list(dict.fromkeys(options))


def _unit_word(item: Item) -> str:
    """A unit as one word of a size option: "m2", not the tokens "m 2"."""
    return item.norm.replace(" ", "")


def _month_season(month: int, hemisphere: Hemisphere | None, table: Mapping[str, Any]) -> str:
    season = next(str(name) for name, months in table.items() if month in months)
    return _SOUTHERN[season] if hemisphere == "south" else season


def _add_senses(
    evidence: _Evidence, item: Item, senses: Sequence[Any], *, negated: bool, after_cue: bool
) -> None:
    for sense in senses:
        kind = sense.kind
        if kind == "crop":
            evidence.crops.setdefault(sense.value, item.raw)
            evidence.candidates.append(Candidate(value=sense.value, score=100, source="lexicon"))
        elif kind == "variety":
            key = (str(sense.crop), str(sense.value))
            evidence.varieties.setdefault(key, item.raw)
            if sense.weak:
                evidence.weak_varieties.add(key)
            evidence.candidates.append(
                Candidate(value=f"{sense.crop}/{sense.value}", score=100, source="lexicon")
            )
        elif kind == "category":
            evidence.categories.setdefault(sense.value, item.raw)
        elif kind == "plot":
            spec = sense.value
            evidence.noun = evidence.noun or str(spec["noun"])
            evidence.plot_options += [c for c in spec["options"] if c not in evidence.plot_options]
            evidence.plot_category = evidence.plot_category or spec["category"]
        elif kind == "other_crop":
            evidence.other.setdefault(sense.value.name, tuple(sense.value.like))
        elif kind in ("stage", "season"):
            evidence.add_state(kind, str(sense.value))
        elif kind == "month" and (after_cue or not sense.weak):
            evidence.states.setdefault("month", []).append(str(sense.value))
        elif kind == "health":
            evidence.add_state(
                "health", "Healthy" if negated and sense.value == "Ill" else sense.value
            )
        elif kind == "distinct":
            evidence.distinct = True
        elif kind == "all":
            evidence.all_words = True
        elif kind in ("area_unit", "length_unit"):
            evidence.units.setdefault(_unit_word(item), (kind, float(sense.value)))
        elif kind == "relation" or (kind == "relation_trailer" and sense.value == "next_to"):
            # "next to", "side by side" (the model reads trailing directions backwards);
            # "on either side of" is a "between" whose order the model decides
            evidence.relations.append("between" if sense.value == "flanks" else str(sense.value))
        elif kind == "hemisphere":
            evidence.hemisphere = sense.value
        elif kind == "place":
            evidence.place = sense.value


def _hemisphere(scene: _Evidence, context: ResolveContext) -> Hemisphere | None:
    if context.latitude_deg is not None:
        return "south" if context.latitude_deg < 0 else "north"
    location = scene.place or scene.hemisphere
    if location is None:
        return None
    return "south" if location[1] < 0 else "north"


def _describe(evidence: _Evidence) -> str:
    found = [
        *evidence.crops,
        *(f"{c}/{v}" for c, v in evidence.varieties),
        *(ANY_PREFIX + c for c in evidence.categories),
        *(f"{OTHER}: {name}" for name in evidence.other),
        *(f"{key}: {'/'.join(v)}" for key, v in evidence.states.items()),
    ]
    return "retrieved " + (", ".join(found) if found else "nothing")
