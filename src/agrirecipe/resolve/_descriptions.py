"""Words that describe the plants of a field already named are not more fields.

", fruit ripe" after the fields named, "half the vines show mildew", "branches bent with
fruit", "a wheelbarrow full of split fruit": :func:`dissolve_plant_parts` turns such a
mention into words for the field(s) it describes (the words are data:
``descriptive_heads``, ``plant_part_words`` and ``describing_verbs`` in vocabulary.yaml).
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence

from agrirecipe.resolve._lexicon import reader_words
from agrirecipe.resolve._mentions import Clause, Mention
from agrirecipe.resolve._own_crop import (
    may_hold,
    names_another_crop,
    placed_crop_of_its_own,
    plants_of_no_field_before,
    said_to_be_somewhere,
)
from agrirecipe.resolve._own_fruit import is_own_fruit
from agrirecipe.resolve._structure import (
    definite_before_head,
    describing_verbs,
    descriptive_words,
    names_a_variety,
    plant_part_words,
    strong_crops,
)

__all__ = ["dissolve_plant_parts", "said_with_a_verb"]


def dissolve_plant_parts(clauses: Sequence[Clause], crop_categories: dict[str, str]) -> list[str]:
    """Mentions that describe plants of a named field are attributes, not new fields.

    ", fruit ripe" after named fields, "half the vines show mildew, a riesling
    vineyard", "three orchards, each with a different fruit": a clause whose only
    mention is made of descriptive words (``descriptive_heads``: fruit, plants,
    vines, leaves...) becomes head-less, so its words go to the field(s) it
    describes (before it, or the next one when it opens the prompt). It stays a
    field with its own count, size or rows, as a member of a list ("apples and
    fruit trees"), or when no other field is named. "each with a different
    fruit" makes the fields before it different crops. Returns what was dissolved.
    """
    words = descriptive_words()
    dissolved: list[str] = []
    for clause in clauses:
        dissolved.extend(_dissolve_described_after_of(clause, words))
    dissolved.extend(_dissolve_held_produce(clauses))
    for position, clause in enumerate(clauses):
        if len(clause.mentions) != 1:
            continue
        others_before = any(c.mentions for c in clauses[:position])
        others_after = any(c.mentions for c in clauses[position + 1 :])
        # ("Ripeness classifier data, August, fruit ripening: three tomato plots ...": the
        # first mention of the prompt, after words that name no field)
        if not others_before and not others_after:
            continue
        mention = clause.mentions[0]
        definite = definite_before_head(clause, mention)  # "in the fruit", "the vines"
        following = clauses[position + 1] if position + 1 < len(clauses) else None
        listed = (
            clause.link is not None
            and clause.link.role == "conjunction"
            and bool(clauses[position - 1].mentions)
        ) or (  # "a mix of fruit and vegetables": the first member of a list
            following is not None
            and following.link is not None
            and following.link.role == "conjunction"
            and bool(following.mentions)
        )
        # "half the vines" (not "half fruit", a share of the fields)
        fraction = definite and any(i.role == "fraction" for i in mention.items)
        # "two vineyard blocks. block 1: 30 rows of vines, ...": a member's own plants
        member_plants = _plants_of_a_member(clauses, position, mention)
        own_size = not member_plants and any(i.role in ("size", "geometry") for i in mention.items)
        described = any(
            i.role in ("stage", "health", "cue", "season", "month")
            or "cue" in i.data
            or "described" in i.data  # "plants about three metres tall"
            or i.norm in reader_words("colours")  # "fruit red and ready"
            for i in mention.items
        )
        # "a few plants have fallen over": a verb says what the plants do or look like
        predicate = said_with_a_verb(clause, mention)
        # "one plant has wilted leaves": one plant described, not a field of one;
        # "a ladder leaning against one tree": one plant of the fields named ("the third
        # tree": one by its place in the row)
        one = mention.count == 1 or any(i.role == "reference" for i in mention.items)
        one_described = one and (
            described
            or (
                others_before
                and not mention.has_crop
                and all(h.role == "plot" and h.data["value"]["individual"] for h in mention.heads)
            )
        )
        # "the Navel block ..., full of orange fruit": the named crop's own fruit;
        # "a wheelbarrow full of split fruit": what the scenery holds
        own_fruit = is_own_fruit(clauses, position, mention, others_before=others_before)
        if any(i.role == "zone" for i in mention.items):
            continue  # "the vines are on the left and the orange grove on the right": placed
        if names_another_crop(clauses, position, mention, others_before):
            continue  # "Bare vines pruned back ..., and the pear trees ... are bare too"
        if definite and plants_of_no_field_before(clauses, position, mention):
            continue  # "the pear orchard has fire blight, the vines have downy mildew"
        if listed and plants_of_no_field_before(clauses, position, mention):
            continue  # "bare apple trees, dormant vines and a field of cabbages"
        if (
            definite
            and (not predicate or said_to_be_somewhere(mention))
            and placed_crop_of_its_own(clauses, position, mention, crop_categories)
        ):
            continue  # "pear trees beyond them and the vines on the hill": the grapes
        if definite and _relation_object_named_before(clauses, position, mention):
            continue  # "the cherries between the vines and the pears": the vineyard named
        if definite and _placed_again(clauses, position, mention, crop_categories):
            continue  # "a vineyard and an orange grove, with the vines to the north"
        if definite and _named_so_before(clauses[:position], mention):
            # "Half the farm is fruit and half is veg, ..., with the fruit on the east side":
            # the field named by that word before, named again
            continue
        if own_fruit:
            listed, described = False, True
        elif listed and _continues_with(clauses[position - 1], mention):
            # "apples with scab spots on the leaves and corky fruit": still the apples'
            listed, described = False, True
        elif others_before and _after_a_look(clauses[position - 1], clause, mention):
            # "Jonagored with scab, velvety olive spots on the leaves and split fruit"
            listed, described = False, True
        vague = any(i.role == "quantity" for i in mention.items)  # "loads of", "lots of"
        # "the fruit ones": the fields of fruit named before, not their fruit
        # (not "the Beefsteak ones have big fruit": the "ones" of another mention)
        ordered = sorted(mention.items, key=lambda i: i.start)
        ones = any(
            i.norm in ("ones", "fields", "plots", "blocks") and before in mention.heads
            for before, i in itertools.pairwise(ordered)
        )
        if (
            not (
                own_fruit
                or all(h.norm in words for h in mention.heads)
                # ("six little plots, each a different veg": a category word the fields
                # before are each a different crop of)
                or (mention.distinct and mention.category is not None and not mention.has_crop)
            )
            or ones
            or (
                mention.count is not None
                and not (definite or fraction or one_described or predicate or own_fruit)
                and not _a_different(mention)
                and not (vague and others_before and described)
            )
            # "a lot of" fruit asks for fields ("loads of rotten fruit with grey fuzz"
            # after the strawberries is theirs)
            or (
                mention.quantity is not None
                and not (definite or predicate or (others_before and described and vague))
            )
            or mention.other
            or own_size
            # ("San Marzano ..., fruit red and ready, and plum tomatoes ...": a described
            # part, not the first member of a list)
            or (listed and not (definite or predicate or (described and others_before)))
            or not (
                described
                or definite
                or fraction
                or mention.distinct
                or predicate
                or one_described
                or member_plants
            )
        ):
            continue
        if mention.distinct:
            for earlier in (m for c in clauses[:position] for m in c.mentions):
                earlier.distinct = True
                earlier.distinct_crops = True
                # "Five plots ..., each with a different vegetable"
                if (
                    mention.category is not None
                    and earlier.category is None
                    and not (earlier.has_crop)
                ):
                    earlier.category = mention.category
        crops = strong_crops(mention)
        for head in mention.heads:
            # ("the trees are just leafing out": the plants of the tree crops)
            options = head.data["value"]["options"] if head.role == "plot" else ()
            head.role = "filler"
            if crops or options:
                # "Half the vines show mildew": the grapes
                head.data["describes"] = crops or set(options)
        clause.loose = [*clause.loose, *(i for i in mention.items if i.role != "distinct")]
        clause.mentions = []
        dissolved.append(mention.text)
    return dissolved


def _plants_of_a_member(clauses: Sequence[Clause], position: int, mention: Mention) -> bool:
    """Whether "30 rows of vines" (a word for plants) follows "one:" or "the other:", a
    member of fields counted before ("two vineyard blocks") that allow only that crop."""
    crops = strong_crops(mention)
    if not crops or mention.count is not None or position == 0:
        return False
    before, link = clauses[position - 1], clauses[position].link
    member = (
        not before.mentions
        and bool(before.loose)
        and all(i.role in ("reference", "number") for i in before.loose)
        and link is not None
        and link.norm == ":"
    )
    return member and _grown_before(clauses[:position], crops, counted=True)


def _relation_object_named_before(
    clauses: Sequence[Clause], position: int, mention: Mention
) -> bool:
    """Whether "the vines" (a word for plants that names a crop) is what a field is placed
    against ("between the vines and the pears") and a field of that crop was named
    before: that field, named again by its plants."""
    crops = strong_crops(mention)
    link = clauses[position].link
    if not crops or link is None:
        return False
    previous = clauses[position - 1].link if position > 0 else None
    against = link.role in ("relation", "between") or (
        link.role == "conjunction" and previous is not None and previous.role == "between"
    )
    return against and _grown_before(clauses[:position], crops, counted=False)


def _grown_before(before: Sequence[Clause], crops: set[str], *, counted: bool) -> bool:
    """Whether a field named in ``before`` grows ``crops``: it names them, or its plot word
    allows only them ("a vineyard"); ``counted``: two or more such fields counted."""
    return any(
        (not counted or (m.count or 1) >= 2)
        and (
            crops <= strong_crops(m)
            or any(h.role == "plot" and set(h.data["value"]["options"]) == crops for h in m.heads)
        )
        for c in before
        for m in c.mentions
    )


def _dissolve_held_produce(clauses: Sequence[Clause]) -> list[str]:
    """'A string of dried peppers hangs on the shed wall', 'a basket of pears on the
    grass': a crop a container holds (the container, "of", describing words, the crop)
    is harvested produce, scenery, once a field is named elsewhere in the prompt."""
    containers = reader_words("produce_containers")
    held: list[tuple[Clause, Mention]] = []
    for clause in clauses:
        for mention in clause.mentions:
            if any(i.role in ("plot", "size", "geometry") for i in mention.items):
                continue  # "a sack of seed potatoes planted in 20 rows": a field
            start = min((h.start for h in mention.heads), default=None)
            before = [i for i in clause.items if start is not None and i.end <= start]
            while before and before[-1].role in ("unknown", "filler"):
                before.pop()  # "dried", "freshly picked"
            if len(before) >= 2 and before[-1].role == "of" and before[-2].norm in containers:
                held.append((clause, mention))
    fields = sum(len(c.mentions) for c in clauses)
    if not held or len(held) == fields:
        return []  # ("a basket of pears" alone is what the prompt asks for)
    for clause, mention in held:
        for head in mention.heads:
            head.role = "filler"
            head.data["scenery"] = "produce"
        clause.mentions = [m for m in clause.mentions if m is not mention]
        clause.loose = [*clause.loose, *mention.items]
    return [mention.text for _, mention in held]


def _continues_with(previous: Clause, mention: Mention) -> bool:
    """Whether ``mention`` (only words for fruit) goes on a "with ..." list of the field
    named in the clause before it: "apples with scab on the leaves and corky fruit"."""
    if not previous.mentions or not all(h.norm in plant_part_words() for h in mention.heads):
        return False
    owner = previous.mentions[-1]
    last_head = max(h.start for h in owner.heads)
    after = [i for i in owner.items if i.start > last_head]
    return (
        bool(after)
        and after[0].role == "of"
        and all(i.role in ("of", "health", "cue", "stage", "filler", "unknown") for i in after)
    )


def _dissolve_described_after_of(clause: Clause, words: frozenset[str]) -> list[str]:
    """ "the tomatoes in front of the house with the last fruit ripening": plant words
    after "with" describe the field just named in the same clause."""
    dissolved: list[str] = []
    for index in range(len(clause.mentions) - 1, 0, -1):
        mention, owner = clause.mentions[index], clause.mentions[index - 1]
        if (
            not (_ends_with_of(owner) or _has_before_head(mention) or _a_look_on(owner))
            or not (all(h.norm in words for h in mention.heads) or _coloured_fruit(owner, mention))
            or mention.count is not None
            or mention.quantity is not None
            or mention.other
            or any(i.role in ("size", "geometry") for i in mention.items)
        ):
            continue
        for head in mention.heads:
            head.role = "filler"
        owner.items.extend(mention.items)
        del clause.mentions[index]
        dissolved.append(mention.text)
    return dissolved


def _a_look_on(owner: Mention) -> bool:
    """ "strawberries ... have grey mould on the fruit": the mention ends with a disease
    or a look and "on"/"in", so the plant part after it is where that shows (also with a
    word or two between: "dark scabby spots on the fruit"; "on a lot of the fruit": a
    share of it)."""
    ordered = sorted(owner.items, key=lambda i: i.start)
    while ordered and ordered[-1].role in ("quantity", "fraction"):
        ordered.pop()
    return (
        len(ordered) >= 2
        and ordered[-1].norm in ("on", "in", "over", "across", "along")
        and any(i.role in ("health", "cue") for i in ordered[-4:-1])
        and all(i.role in ("health", "cue", "unknown", "filler") for i in ordered[-4:-1])
    )


def _coloured_fruit(owner: Mention, mention: Mention) -> bool:
    """ "the Cabernet rows are heavy with ripe black grapes": a colour and the crop's
    fruit ("black grapes" also names a variety) after a variety of that crop is its
    fruit, not another field."""
    return (
        len(mention.heads) == 1
        and len(mention.heads[0].norm.split()) == 2
        and mention.heads[0].norm.split()[0] in reader_words("colours")
        and names_a_variety(owner)
        and bool(strong_crops(mention))
        and strong_crops(mention) == strong_crops(owner)
    )


def _has_before_head(mention: Mention) -> bool:
    """ "the beef ones have big fruit just turning red": the plants' own fruit, said with
    "have"/"has" right before it (past describing words)."""
    head = min(h.start for h in mention.heads)
    before = [i for i in sorted(mention.items, key=lambda i: i.start) if i.end <= head]
    while (
        before
        and before[-1].role in ("filler", "unknown", "cue")
        and before[-1].norm not in (_HAVE)
    ):
        before.pop()
    return bool(before) and before[-1].norm in _HAVE


_HAVE = frozenset({"have", "has", "had", "bear", "bears", "carry", "carries", "carrying"})


def _ends_with_of(owner: Mention) -> bool:
    """Whether the mention ends in "with" / "of", or in "with" and adjectives ("with long")."""
    ofs = [index for index, item in enumerate(owner.items) if item.role == "of"]
    return bool(ofs) and all(
        item.role in ("filler", "side", "unknown") for item in owner.items[ofs[-1] + 1 :]
    )


def said_with_a_verb(clause: Clause, mention: Mention) -> bool:
    """Whether a describing verb follows the mention's head in its clause."""
    head = max(h.end for h in mention.heads)
    verbs = describing_verbs()
    after = [i for i in clause.items if i.start >= head]
    # (not "some fruit idk whatever looks nice": the verb of a free choice after it)
    choices = reader_words("free_choice")
    return any(
        i.norm in verbs and not (k and after[k - 1].norm in choices) for k, i in enumerate(after)
    )


def _after_a_look(previous: Clause, clause: Clause, mention: Mention) -> bool:
    """Whether ``mention`` (only words for fruit, no count) is joined by "and" to a clause
    that only says how the plants look ("velvety olive spots on the leaves")."""
    return (
        not previous.mentions
        and clause.link is not None
        and clause.link.role == "conjunction"
        and mention.count is None
        and all(h.norm in plant_part_words() for h in mention.heads)
        and any(i.role in ("cue", "health") for i in previous.items)
        # ("a lot of the trees have blotchy mottled leaves and small lopsided fruit"; "every
        # plant covered in flowers and small fruits")
        and all(
            i.role in ("cue", "health", "filler", "unknown", "of", "quantity", "all")
            for i in previous.items
        )
    )


def _a_different(mention: Mention) -> bool:
    """'four fields, each growing a different vegetable': "a" before "different" is an
    article, not a count of one field."""
    items = sorted(mention.items, key=lambda i: i.start)
    return any(
        a.role == "number" and a.norm in ("a", "an") and b.role == "distinct"
        for a, b in itertools.pairwise(items)
    )


def _placed_again(
    clauses: Sequence[Clause], position: int, mention: Mention, crop_categories: dict[str, str]
) -> bool:
    """Whether "the vines" (a word for the plants of a crop) is placed by the words right
    after it ("to the north", "east of the pears") and names the crop of exactly one field
    named before: that field, named again to place it."""
    following = clauses[position + 1] if position + 1 < len(clauses) else None
    crops = strong_crops(mention)
    if not crops or following is None or following.link is None:
        return False
    trailer = following.link.role == "trailer" and not following.items
    against = following.link.role == "relation" and bool(following.mentions)
    if not (trailer or against):
        return False
    # (not "vines on 2.5 m rows" after the vineyard: its plants again, no field of its own)
    words = descriptive_words()
    earlier = [
        m
        for c in clauses[:position]
        for m in c.mentions
        if not all(h.norm in words for h in m.heads)
    ]
    return sum(1 for m in earlier if may_hold(m, crop_categories) & crops) == 1


def _named_so_before(clauses: Sequence[Clause], mention: Mention) -> bool:
    """Whether an earlier field was asked for by the same word as this mention's head
    (a field of "fruit", a field of "vegetables"), naming no crop."""
    words = {h.norm for h in mention.heads}
    return any(
        not earlier.has_crop and words & {h.norm for h in earlier.heads}
        for clause in clauses
        for earlier in clause.mentions
    )
