"""Decomposition: from role-tagged items to field mentions, their attributes and relations.

The prompt is cut into *clauses* at separators, conjunctions and relation
words. Inside a clause, consecutive compatible *heads* (crop, variety,
category and plot words) form one *mention* ("a healthy Pink Lady apple
orchard"); an incompatible head starts another ("an apple orchard with a
carrot field"). Attributes (stage, season, month, health, size) attach to the
mention of their clause; a clause without a head ("..., all in autumn",
"..., ripe and healthy") attaches to every field when it says so ("all",
"both"), else to its neighbour. A plural mention can be refined by the
clauses after it ("Two orchards: one of Gala, one of Fuji"). Relation words
link the mentions on either side ("north of", "next to", "between X and Y").
"""

from __future__ import annotations

import functools
import itertools
import math
from collections.abc import Collection, Sequence
from dataclasses import dataclass, field
from typing import Any

from agrirecipe._errors import PromptError, UnknownCropError
from agrirecipe.resolve._intent import SizeIntent
from agrirecipe.resolve._lexicon import Item, Token, vocabulary

__all__ = [
    "Clause",
    "Mention",
    "MentionBuilder",
    "colour_words",
    "decompose",
    "resolve_weak_varieties",
]

_BOUNDARIES = ("separator", "conjunction", "relation", "between", "trailer")
_HEADS = ("head", "plot", "other_crop")
# Roles that may stand right before a head as part of its noun phrase.
_PRE_HEAD = (
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


def _interpretations(item: Item) -> list[Interpretation]:
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


def _combine(
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


def _plots_agree(one: dict[str, Any], other: dict[str, Any], categories: dict[str, str]) -> bool:
    """Whether two plot words can name one field: a plot of a category ("vegetable
    garden") cannot be a plot of crops outside it ("vineyard")."""
    for first, second in ((one, other), (other, one)):
        category = first.get("category")
        if (
            category is not None
            and second["options"]
            and not any(categories.get(c) == category for c in second["options"])
        ):
            return False
    return True


class MentionBuilder:
    """Reads a clause's items into mentions; decides which heads can name one field."""

    def __init__(self, crop_categories: dict[str, str]) -> None:
        self.crop_categories = crop_categories

    def compatible(self, mention: Mention, item: Item) -> bool:
        """Whether head ``item`` can describe the same field as ``mention``."""
        if item.role == "other_crop":
            return (
                mention.interpretations is None
                and mention.category is None
                and not any(h.role == "other_crop" for h in mention.heads)
            )
        if any(h.role == "other_crop" for h in mention.heads):
            return item.role == "plot"
        if item.role == "plot":
            spec = item.data["value"]
            if (
                mention.plot is not None
                and spec["options"]
                and mention.plot["options"]
                and not set(spec["options"]) & set(mention.plot["options"])
            ):
                return False  # "an orchard vineyard": two plots, two fields
            if mention.plot is not None and not _plots_agree(
                spec, mention.plot, self.crop_categories
            ):
                return False  # "the vegetable garden south of the vineyard": two fields
            if mention.has_crop and spec["options"]:
                return not _plot_excludes(spec, mention)  # "a carrot orchard": two things
            # "cereals at the top, root veg at the bottom": two fields
            return (
                mention.category is None
                or not spec["options"]
                or any(self.crop_categories.get(c) == mention.category for c in spec["options"])
            )
        interpretations = _interpretations(item)
        categories = [str(s.value) for s in item.senses_of("category")]
        if categories and not interpretations:
            if mention.category is not None and mention.category not in categories:
                return False
            if (
                mention.plot is not None
                and mention.plot.get("category") is not None
                and mention.plot["category"] not in categories
            ):
                return False  # "Vegetable garden ..., fruit on the west side of it"
            if (
                mention.plot is not None
                and mention.plot["options"]
                and not any(
                    self.crop_categories.get(c) in categories for c in mention.plot["options"]
                )
            ):
                return False  # "an orchard, vegetables": two fields, not vegetable trees
            if mention.has_crop:
                return any(
                    self.crop_categories.get(c) in categories
                    for c, _, weak in mention.interpretations or ()
                    if not weak
                )
            return True
        category = mention.category or (
            mention.plot["category"]
            if mention.plot is not None and mention.plot.get("strict", False)
            else None
        )
        if category is not None:
            # ("a vegetable garden to the east, ..., wheat north of the orchard": two fields)
            interpretations = [
                i for i in interpretations if self.crop_categories.get(i[0]) == category
            ]
            if not interpretations:
                return False
        if mention.plot is not None and mention.plot["options"] and interpretations:
            # "a 2 ha orchard with a potato field": the orchard cannot be the potatoes
            allowed = (*mention.plot["options"], *mention.plot["tolerates"])
            if not any(c in allowed for c, _, _ in interpretations):
                return False
        return _combine(mention.interpretations, interpretations) is not None

    def add_head(self, mention: Mention, item: Item) -> None:
        """Add a head to a mention, narrowing its crop, variety, category or plot."""
        mention.heads.append(item)
        mention.items.append(item)
        if item.role == "plot":
            spec = item.data["value"]
            if spec["individual"] and mention.has_crop and _plot_excludes(spec, mention):
                return  # "tomato vines" are tomato plants, not a vineyard
            held = mention.plot["options"] if mention.plot is not None else ()
            if held and set(held) <= set(spec["options"]):
                return  # "stone fruit trees": the trees of the narrower group named first
            if mention.plot is None or spec["narrows"]:
                mention.plot = spec
            return
        if item.role == "other_crop":
            return
        categories = [str(s.value) for s in item.senses_of("category")]
        interpretations = _interpretations(item)
        if categories and not interpretations:
            mention.category = categories[0]
            if mention.interpretations is not None:
                mention.interpretations = [
                    i
                    for i in mention.interpretations
                    if self.crop_categories.get(i[0]) == mention.category
                ] or mention.interpretations
            return
        if mention.category is not None:
            interpretations = [
                i for i in interpretations if self.crop_categories.get(i[0]) == mention.category
            ] or interpretations
        combined = _combine(mention.interpretations, interpretations)
        mention.interpretations = combined if combined is not None else interpretations

    def read(self, clause: Clause) -> None:
        """Fill ``clause.mentions`` (or ``clause.loose`` when it names no field)."""
        current: Mention | None = None
        pending: list[Item] = []
        for index, item in enumerate(clause.items):
            if item.role not in _HEADS:
                pending.append(item)
                continue
            if current is None:
                current = Mention(clause=clause.index)
                self._absorb(current, pending, before_head=True)
            elif not pending and _names_plants_of(current, item):
                item.role = "filler"  # "tomato vines": the tomato's own vines
                current.items.append(item)
                continue
            elif self.compatible(current, item) and not (
                # "west of the vineyard there's a block of ...": a plot named by its kind
                # alone, then a new one ("on the chilli side there's a plot of ..." is
                # still the chilli plot); "the cherry orchard has a plot of ..."
                (
                    item.role == "plot"
                    and (
                        (not current.has_crop and _existential(clause, pending))
                        # ("... the 2 ha maize field there's a 1 ha strip of onions")
                        or (
                            _existential(clause, pending) and any(p.role == "size" for p in pending)
                        )
                        or _possessed(pending)
                        or (current.has_crop and _with_a_plot_of(clause.items, index, pending))
                        or _placed_new(clause, pending)
                    )
                )
                # "between the two groves a block of bananas": a plot counted again;
                # "north of the orchard a big block of Winter Wheat": a plot named again
                or (
                    current.plot is not None
                    and (
                        (current.count or 1) >= 2
                        # ("north of both onion fields a field of Danvers carrots")
                        or any(i.role == "all" and i.norm == "both" for i in current.items)
                        or (
                            # ("South of the grove a banana block": a crop named after
                            # the plot named again)
                            (item.role == "plot" or not current.has_crop)
                            and _opens_definite(current)
                            # (not "The only crop we have is a small block of ...")
                            and not any(p.norm in ("is", "are", "was", "were") for p in pending)
                        )
                    )
                    and any(
                        (p.role == "number" and p.norm in ("a", "an"))
                        # ("east of the grove the Dwarf Cavendish": a field named by "the")
                        or (
                            p.norm == "the"
                            and not current.has_crop
                            and current.count is None
                            and _opens_definite(current)
                            and item.has("crop", "variety")
                        )
                        for p in pending
                    )
                    and not any(p.role in ("of", "size", "geometry") for p in pending)
                )
            ):
                current.conflict = current.conflict or _plot_conflict(current, item, pending)
                self._absorb(current, pending, before_head=False, counts=_counts_fields(item))
            else:
                conflict = _plot_conflict(current, item, pending)
                current.continued = conflict is not None
                _check_adjacent_variety(current, item, pending)
                cut = _pre_head_start(pending)
                self._absorb(current, pending[:cut], before_head=False)
                clause.mentions.append(current)
                current = Mention(clause=clause.index, conflict=conflict)
                self._absorb(current, pending[cut:], before_head=True)
            pending = []
            self.add_head(current, item)
        if current is not None:
            self._absorb(current, pending, before_head=False)
            clause.mentions.append(current)
        else:
            clause.loose = pending
        for mention in clause.mentions:
            resolve_weak_varieties(mention)
            mention.distinct_crops = mention.distinct and not mention.has_crop

    @staticmethod
    def _absorb(
        mention: Mention, items: Sequence[Item], *, before_head: bool, counts: bool = True
    ) -> None:
        for index, item in enumerate(items):
            mention.items.append(item)
            # "an old wind pump in the corner of the field": the article is the pump's;
            # the field is named by "the" after it
            of_another = (
                before_head
                and item.norm in ("a", "an")
                and any(later.norm in ("the", "its", "their") for later in items[index + 1 :])
            )
            # "each carrying a double row of plants": the article is the row's
            of_another = of_another or (
                item.norm in ("a", "an")
                and index + 1 < len(items)
                and items[index + 1].role == "geometry"
            )
            # The amount nearest the head wins: "a combine ... a few cereal fields".
            counted = before_head or counts or bool(item.data.get("counts_kinds"))
            if item.role == "number" and counted and not of_another:
                value = float(item.data.get("value", 1))
                if before_head or item.norm not in ("a", "an"):
                    mention.count = _count(value, item)
                    mention.quantity = None
            elif item.role == "quantity" and (before_head or counts):
                mention.quantity = int(item.data["value"])
                if before_head:
                    mention.count = None
            elif item.role == "distinct":
                mention.distinct = True
            elif item.role == "other":
                mention.other = True


@functools.lru_cache(maxsize=1)
def _plant_words() -> frozenset[str]:
    nouns = vocabulary()["plot_nouns"]
    return frozenset(
        phrase.split()[-1] for phrase, spec in nouns.items() if (spec or {}).get("individual")
    )


def _counts_fields(item: Item) -> bool:
    """Whether a number before this head counts fields: "carrots in 3 fields", "two
    apples orchards" do; "an orchard with 200 trees" does not (it counts plants)."""
    if item.role == "plot":
        return not item.data["value"]["individual"]
    # "apple trees", "tomato plants": crop names that end in a word for the plants.
    return item.role == "head" and item.tokens[-1].norm not in _plant_words()


def _count(value: float, item: Item) -> int:
    if not math.isfinite(value) or value != int(value) or value < 1:
        raise PromptError(
            f"cannot make {item.raw!r} fields",
            stage="resolve",
            hint="say how many fields as a whole number, e.g. 'two carrot fields'",
        )
    if value > 64:
        raise PromptError(
            f"{int(value)} fields is more than a scene holds",
            stage="resolve",
            hint="ask for at most 64 fields",
        )
    return int(value)


#: "there's", "there is", "there are": words that bring in something new
_EXISTENTIAL = frozenset({"s", "is", "are", "was", "were", "stands", "lies", "sits"})
_ARTICLE = frozenset({"a", "an"})


def _said(pending: Sequence[Item], first: Collection[str], then: Collection[str]) -> bool:
    """Whether the words before a head hold a word of ``first`` right before one of
    ``then`` ("there" "is", "has" "a")."""
    norms = [t.norm for item in pending for t in item.tokens]
    return any(a in first and b in then for a, b in itertools.pairwise(norms))


def _existential(clause: Clause, pending: Sequence[Item]) -> bool:
    """'west of the vineyard there's a block of Navel oranges': after "there is" comes a
    new field, not more words about the one before; so it does after "west of the
    vineyard is a ..." (a place, then what stands there)."""
    if any(t.norm == "theres" for item in pending for t in item.tokens):
        return True
    if _said(pending, {"there"}, _EXISTENTIAL):
        return True
    return _placed_new(clause, pending)


#: "we've planted a", "we put in a": words that bring in a field newly planted
_PLANTED = frozenset({"planted", "put", "sown", "sowed", "grow", "growing", "set"})


def _placed_new(clause: Clause, pending: Sequence[Item]) -> bool:
    """'Next to the Navel oranges is a new block of Valencia', '... we've just planted a
    block of ...': after a place and the field it is said against, "is a" or "planted a"
    brings in a new field."""
    placed = clause.link is not None and clause.link.role == "relation"
    return placed and (_said(pending, _EXISTENTIAL, _ARTICLE) or _said(pending, _PLANTED, _ARTICLE))


def _possessed(pending: Sequence[Item]) -> bool:
    """'The cherry orchard has a plot of cherry tomatoes': what a field has is another."""
    return _said(pending, {"has", "have", "had"}, _ARTICLE)


def _with_a_plot_of(items: Sequence[Item], index: int, pending: Sequence[Item]) -> bool:
    """'5 ha of maize with a 1 ha field of onions': after "with a", a plot of another crop
    (the plot noun at ``index`` followed by "of" and a crop) is a field of its own."""
    norms = [p.norm for p in pending]
    said = [i for i, norm in enumerate(norms) if norm == "with"]
    if not said or norms[said[-1] + 1 : said[-1] + 2] not in (["a"], ["an"]):
        return False
    after = items[index + 1 : index + 3]
    return len(after) == 2 and after[0].norm == "of" and after[1].role == "head"


def _pre_head_start(pending: Sequence[Item]) -> int:
    """Where the next head's own noun phrase starts inside ``pending``."""
    cut = len(pending)
    # "1 ha of Red Baron onions with 1 ha of Sturon onions": the size is the next one's
    # ("a block of 2 hectares with golden acre cabbages": the block's own size)
    if cut >= 2 and pending[-1].norm == "of" and pending[-2].role == "size":
        cut -= 2
    while cut > 0 and pending[cut - 1].role in _PRE_HEAD:
        cut -= 1
        if pending[cut].role == "number" or pending[cut].norm in ("a", "an", "the"):
            break
    return cut


def _check_adjacent_variety(mention: Mention, item: Item, pending: Sequence[Item]) -> None:
    """'Nantes apples': a variety right before another crop's name is an unknown variety."""
    if pending or not mention.heads or item.role != "head":
        return
    last = mention.heads[-1]
    crops = [str(s.value) for s in item.senses_of("crop")]
    varieties = [s for s in last.senses_of("variety") if not s.weak]
    if crops and varieties and not last.senses_of("crop"):
        owner = varieties[0].crop or ""
        raise UnknownCropError(
            f"{last.raw!r} is a variety of {owner}, not of {crops[0]}: "
            f"no {crops[0]} variety is called {last.raw!r}",
            requested=f"{last.raw} {item.raw}",
            stage="resolve",
            hint=f"did you mean {last.raw} {owner.lower()}s, or another {crops[0]} variety?",
        )


# "of"-words that put the crop inside the plot ("a vineyard of cabbages", "an orchard
# planted with carrots"); "with" may as well mean a neighbour ("an orchard with a
# carrot field"), "under" a cover ("an orchard under snow").
_NOT_CONTAINMENT = frozenset({"with", "under"})


def _plot_conflict(mention: Mention, item: Item, pending: Sequence[Item]) -> PromptError | None:
    """'a vineyard of cabbages', 'a carrot orchard': a plot noun that cannot hold the crop.

    Only a plot noun for a kind of planting (orchard, grove, vineyard, cornfield)
    restricts its crops; a noun for the plants themselves ("tomato vines", "banana
    trees") just names the crop's plants, and crops a noun tolerates by usage
    ("a banana orchard") pass.
    """
    if item.role == "plot":
        plot, crops = item.data["value"], _named_crops(mention.interpretations)
        joined = not pending  # "a carrot orchard"
    elif item.role == "head" and mention.plot is not None and not mention.has_crop:
        plot, crops = mention.plot, _named_crops(_interpretations(item))
        # "a vineyard of (young) cabbages"
        joined = (
            bool(pending)
            and pending[0].role == "of"
            and pending[0].norm not in _NOT_CONTAINMENT
            and all(p.role in _PRE_HEAD for p in pending[1:])
        )
    else:
        return None
    allowed = (*plot["options"], *plot["tolerates"])
    if not joined or plot["individual"] or not plot["options"] or not crops:
        return None
    if any(crop in allowed for crop in crops):
        return None
    word = plot["noun"] or "plot"
    if plot["noun"] == "field":  # "cornfield", "wheatfield"
        word = next(h for h in (item, *mention.heads) if h.role == "plot").norm.rstrip("s")
    article = "an" if word[0] in "aeiou" else "a"
    crop = crops[0]
    return PromptError(
        f"{_phrase(mention, item, pending)!r} is a contradiction: {article} {word} holds "
        f"{_listing(plot['options'])}, and {crop} is not grown in one",
        stage="resolve",
        hint=f"ask for a {crop.lower()} field, or {article} {word} next to a {crop.lower()} field",
    )


def _names_plants_of(mention: Mention, item: Item) -> bool:
    """'tomato vines': a crop alias that is also a word for plants, right after another crop."""
    if item.role != "head" or not mention.has_crop:
        return False
    plots = [s.value for s in item.senses_of("plot") if s.value["individual"]]
    if not plots:
        return False
    return _combine(mention.interpretations, _interpretations(item)) is None


def _plot_excludes(plot: dict[str, Any], mention: Mention) -> bool:
    allowed = (*plot["options"], *plot["tolerates"])
    crops = _named_crops(mention.interpretations)
    return bool(plot["options"]) and not any(crop in allowed for crop in crops)


def _listing(names: Sequence[str]) -> str:
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " or " + names[-1]


def _named_crops(interpretations: Sequence[Interpretation] | None) -> list[str]:
    crops: list[str] = []
    for crop, _, weak in interpretations or ():
        if not weak and crop not in crops:
            crops.append(crop)
    return crops


def _phrase(mention: Mention, item: Item, pending: Sequence[Item]) -> str:
    words = sorted([*mention.heads, *pending, item], key=lambda i: i.start)
    return " ".join(w.raw for w in words)


def resolve_weak_varieties(mention: Mention) -> None:
    """A weak name ("golden", "navel") names a variety only next to its crop's name."""
    weak_items = [item for item in mention.items if item.role == "weak_variety"]
    if not weak_items:
        return
    strong_crops = {c for c, _, weak in mention.interpretations or () if not weak}
    plot_crops = set(mention.plot["options"]) if mention.plot and not strong_crops else set()
    for item in weak_items:
        options: list[Interpretation] = [
            (s.crop, str(s.value), False)
            for s in item.senses_of("variety")
            if s.crop in strong_crops
        ]
        if options and mention.interpretations is not None:
            combined = _combine(mention.interpretations, options)
            if combined:
                mention.interpretations = combined
                item.role = "head"
                mention.heads.append(item)
                continue
        # "a conference orchard": a plot that holds the variety's crop names it too
        held: list[Interpretation] = [
            (s.crop, str(s.value), False)
            for s in item.senses_of("variety")
            if s.crop is not None and s.crop in plot_crops
        ]
        if len({crop for crop, _, _ in held}) == 1 and mention.interpretations is None:
            mention.interpretations = held
            item.role = "head"
            mention.heads.append(item)
            continue
        # "Russet field": a name, not a colour, right before a plot of any crop names
        # the plot's variety (the mention names no crop of its own).
        named: list[Interpretation] = [
            (s.crop, str(s.value), False) for s in item.senses_of("variety") if s.crop
        ]
        if (
            len({crop for crop, _, _ in named}) == 1
            and mention.interpretations is None
            and _names_plot(mention, item)
        ):
            mention.interpretations = named
            item.role = "head"
            mention.heads.append(item)
            continue
        item.role = "filler"


def _names_plot(mention: Mention, item: Item) -> bool:
    """Whether ``item`` stands right before the mention's plot noun, which holds any crop,
    or right after it and "of" ("a block of Conference"), and is not also a colour word
    ("golden field" is a colour)."""
    if mention.plot is None or mention.plot.get("options") or mention.plot.get("category"):
        return False
    if item.norm in colour_words():
        return False
    position = next((k for k, i in enumerate(mention.items) if i is item), None)
    if position is None:
        return False
    following = mention.items[position + 1] if position + 1 < len(mention.items) else None
    if following is not None and following.role == "plot":
        return True
    before = mention.items[max(position - 2, 0) : position]
    return [i.role for i in before] == ["plot", "of"]


@functools.lru_cache(maxsize=1)
def colour_words() -> frozenset[str]:
    """The words of colours (``colour_words`` in vocabulary.yaml): "golden" is a look."""
    words = vocabulary()["colour_words"]
    return frozenset(str(w) for group in words.values() for w in group)


def _opens_definite(mention: Mention) -> bool:
    """Whether the mention opens with "the" (a plot named again: "the orchard")."""
    first = min(mention.items, key=lambda i: i.start, default=None)
    return first is not None and first.norm == "the"


def decompose(items: Sequence[Item], builder: MentionBuilder) -> list[Clause]:
    """Clauses with their mentions (refinements and coreference not yet applied)."""
    clauses = split_clauses(items)
    for clause in clauses:
        builder.read(clause)
    return _split_bare_lists(clauses)


def _split_bare_lists(clauses: list[Clause]) -> list[Clause]:
    """'3 fruit orchards: apple pear cherry', '4 veg plots: carrots onions lettuce &
    cabbage': crops named one after another with no mark between are a list, one clause
    per member as if commas parted them."""
    split: list[Clause] = []
    for clause in clauses:
        bare = len(clause.mentions) >= 2 and all(
            len(m.items) == 1 and m.items[0].role == "head" for m in clause.mentions
        )
        if not bare or len(clause.items) != len(clause.mentions):
            clause.index = len(split)
            for mention in clause.mentions:
                mention.clause = clause.index
            split.append(clause)
            continue
        for number, mention in enumerate(clause.mentions):
            link = clause.link
            if number:
                word = mention.items[0]
                mark = Token(",", ",", word.start, word.start)
                link = Item(tokens=(mark,), senses=(), role="separator")
            mention.clause = len(split)
            split.append(Clause(list(mention.items), link, len(split), mentions=[mention]))
    return split


def size_of(mention: Mention) -> list[SizeIntent]:
    """The sizes stated in a mention."""
    return [item.data["size"] for item in mention.items if item.role == "size"]
