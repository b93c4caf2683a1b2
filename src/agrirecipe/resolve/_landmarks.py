"""Fields placed by scenery (issue 8): a landmark between fields, a structure holding one.

"east of the yard apples, west of the yard pears" puts the apples east of the pears;
"In the tomato tunnel: ... right beside the tunnel, peppers" puts the peppers next to
the tomatoes. A field placed only by scenery ("a test strip along the farm track") is
placed by nothing the recipe holds: --explain lists it as not used.
"""

from __future__ import annotations

from collections.abc import Sequence

from agrirecipe.resolve._intent import RelationIntent, TraceStep
from agrirecipe.resolve._lexicon import Item, singular
from agrirecipe.resolve._links import ARTICLES, OPPOSITE, field_relations
from agrirecipe.resolve._measures import sentence_start
from agrirecipe.resolve._mentions import Clause, Mention

__all__ = [
    "across_landmarks",
    "held_by",
    "landmark_again",
    "landmark_of",
    "landmark_said_before",
]


def held_by(
    clauses: Sequence[Clause], position: int, landmark: str | None
) -> tuple[Mention, Mention] | None:
    """The field a structure holds ("In the tomato tunnel: ...") and the field placed
    against that structure by clause ``position`` ("... beside the tunnel, 6 rows of
    peppers"; "peppers beside the tunnel"), or None."""
    if landmark is None:
        return None
    named = [m for c in clauses[:position] for m in c.named]
    holders = list({id(m): m for m in named if _holds(m, landmark)}.values())
    if len(holders) != 1:
        return None
    container = holders[0]
    if named[-1] is not container and named[-1].clause == position - 1:
        return container, named[-1]
    own = clauses[position].mentions
    if len(own) == 1 and own[0] is not container and own[0].has_crop:
        # "... and right beside the tunnels an orchard of Bing cherries": the field named
        # right after the structure, in the same words
        return container, own[0]
    following = clauses[position + 1] if position + 1 < len(clauses) else None
    if (
        following is not None
        and following.link is not None
        and following.link.norm == ","
        and len(following.named) == 1
    ):
        return container, following.named[0]
    return None


def _holds(mention: Mention, landmark: str) -> bool:
    """Whether ``mention`` is said to grow in ``landmark`` ("In the tomato tunnel"; "The
    polytunnel field is planted with Albion", then "... south of the tunnels")."""
    items = sorted(mention.items, key=lambda i: i.start)
    for index, item in enumerate(items):
        if (
            (item.role == "filler" and item.data.get("scenery") in ("structures", "buildings"))
            or item.role == "non_agricultural"
        ) and _same_structure(item.norm, landmark):
            following = items[index + 1] if index + 1 < len(items) else None
            return any(i.norm in ("in", "inside") for i in items[max(0, index - 4) : index]) or (
                following is not None and following.role == "plot"
            )
    return False


def _same_structure(word: str, landmark: str) -> bool:
    """Whether a structure said in a field's words is the landmark said later ("the
    farmhouse" and "the house", "polytunnel" and "the tunnels")."""
    own, other = singular(word.removeprefix("farm").strip()), singular(landmark)
    return own == other or (len(other) >= 4 and own.endswith(other))


def landmark_of(clause: Clause) -> str | None:
    """The scenery a relation's object is ("east of the yard ..."), or None."""
    for item in clause.items:
        if item.norm in ARTICLES or item.data.get("counts_scenery") or item.role == "unknown":
            continue  # "between the two tracks", "north of the packing shed"
        if (item.role == "filler" and "scenery" in item.data) or item.role == "non_agricultural":
            # ("the farmhouse" and "the house", "the packing shed" and "the shed" are one
            # landmark: its last word)
            return item.norm.split()[-1].removeprefix("farm").strip()
        return None
    return None


def across_landmarks(
    landmarks: Sequence[tuple[str, str, Mention, Item]],
    members: dict[int, list[int]],
    trace: list[TraceStep],
) -> list[RelationIntent]:
    """Fields on opposite sides of one landmark: "east of the yard apples, west of the
    yard pears" puts the apples east of the pears. Others are placed by scenery only."""
    relations: list[RelationIntent] = []
    paired: set[int] = set()
    for first, (kind, landmark, mention, link) in enumerate(landmarks):
        for second in range(first + 1, len(landmarks)):
            other_kind, other_landmark, other, _ = landmarks[second]
            if other_landmark == landmark and OPPOSITE.get(kind) == other_kind:
                relations.extend(field_relations(kind, mention, (other,), members, link, trace))
                paired.update((first, second))
    for index, (_, landmark, _, link) in enumerate(landmarks):
        if index not in paired:
            trace.append(
                TraceStep(
                    stage="decompose",
                    subject=f"{link.raw} the {landmark}",
                    detail="relative to scenery: not used",
                )
            )
    return relations


def landmark_said_before(clauses: Sequence[Clause], position: int) -> str | None:
    """The landmark "it" stands for in a relation "<field> north of it" whose field is the
    first the prompt names, after a sentence about that landmark alone ("The farmhouse is
    in the middle. Wheat to the north of it"); else None."""
    clause = clauses[position]
    link = clause.link
    named = [m for c in clauses[:position] for m in c.named]
    if (
        link is None
        or link.role != "relation"
        or clause.mentions
        or [i.norm for i in clause.items] != ["it"]
        or len(named) != 1
        or named[0].clause != position - 1
    ):
        return None
    start = sentence_start(clauses, position - 1)
    if start == 0:
        return None
    found = [landmark_of(c) for c in clauses[:start] if not c.mentions]
    said = [f for f in found if f is not None]
    return said[-1] if said else None


def landmark_again(
    clauses: Sequence[Clause], position: int, landmark: str | None, kind: str
) -> str | None:
    """``landmark`` (that of the relation said before, of kind ``kind``) when the relation
    at ``position`` is the opposite side of it said of the field right before ("wheat
    north of the farmhouse, maize south of it"; "Wheat to the north of it, maize to the
    south"); else None."""
    clause = clauses[position]
    link = clause.link
    named = [m for c in clauses[:position] for m in c.named]
    if (
        landmark is None
        or link is None
        # (compass sides both: "the Riesling parcel by the village, the Pinot parcel
        # right next to it" is next to the Riesling)
        or not {str(link.data.get("value")), kind} <= set(OPPOSITE)
        or clause.mentions
        or not named
        or named[-1].clause != position - 1
    ):
        return None
    said = [i.norm for i in clause.items]
    # ("maize to the south" answers "wheat to the north of it"; not "... and popping corn
    # further east again", placed past the field before)
    answers = not said and OPPOSITE.get(kind) == link.data.get("value")
    if (link.role == "relation" and said == ["it"]) or (link.role == "trailer" and answers):
        return landmark
    return None
