"""Where fields added by an edit go: beside the field they are placed by, never over another."""

from __future__ import annotations

from collections.abc import Sequence

from agrirecipe._errors import PromptError
from agrirecipe.layout import DEFAULT_GAP_M
from agrirecipe.recipe import FieldGeometry, FieldSpec

__all__ = ["Box", "box_of", "place_block"]

Box = tuple[float, float, float, float]  # min x, min y, max x, max y (metres)

# The sides tried, in order, for "next to": east, north, west, south.
_NEXT_TO = ("east_of", "north_of", "west_of", "south_of")


def box_of(geometries: Sequence[FieldGeometry]) -> Box:
    """The axis-aligned box around (possibly turned) fields."""
    xs = [x for g in geometries for x, _ in g.corners_m()]
    ys = [y for g in geometries for _, y in g.corners_m()]
    return min(xs), min(ys), max(xs), max(ys)


def _beside(block: Box, anchor: Box, side: str, gap: float) -> tuple[float, float]:
    """The shift that puts ``block`` on ``side`` of ``anchor``, aligned on its first edge."""
    width, length = block[2] - block[0], block[3] - block[1]
    if side == "south_of":
        x, y = anchor[0], anchor[1] - gap - length
    elif side == "north_of":
        x, y = anchor[0], anchor[3] + gap
    elif side == "east_of":
        x, y = anchor[2] + gap, anchor[1]
    else:  # west_of
        x, y = anchor[0] - gap - width, anchor[1]
    return x - block[0], y - block[1]


def _moved(box: Box, dx: float, dy: float) -> Box:
    return box[0] + dx, box[1] + dy, box[2] + dx, box[3] + dy


def _clash(box: Box, others: Sequence[Box], gap: float) -> Box | None:
    """The first box that ``box`` comes closer to than ``gap`` (overlap included)."""
    for other in others:
        if (
            box[0] < other[2] + gap - 1e-9
            and other[0] < box[2] + gap - 1e-9
            and box[1] < other[3] + gap - 1e-9
            and other[1] < box[3] + gap - 1e-9
        ):
            return other
    return None


def _slide(block: Box, side: str, others: Sequence[Box], gap: float) -> tuple[float, float]:
    """Move ``block`` further out along ``side`` until it clashes with no other field."""
    dx = dy = 0.0
    for _ in range(len(others) + 1):
        clash = _clash(_moved(block, dx, dy), others, gap)
        if clash is None:
            return dx, dy
        moved = _moved(block, dx, dy)
        if side == "south_of":
            dy += clash[1] - gap - moved[3]
        elif side == "north_of":
            dy += clash[3] + gap - moved[1]
        elif side == "east_of":
            dx += clash[2] + gap - moved[0]
        else:
            dx += clash[0] - gap - moved[2]
    return dx, dy


def place_block(
    block: Sequence[FieldGeometry],
    existing: Sequence[FieldSpec],
    *,
    anchor: Sequence[FieldSpec] = (),
    side: str | None = None,
    gap: float = DEFAULT_GAP_M,
) -> tuple[float, float]:
    """The shift (dx, dy) that places new fields ``block`` in the scene.

    With an ``anchor`` and a ``side`` (a relation kind: north_of, south_of,
    east_of, west_of, next_to) the block goes on that side of the anchor
    fields, aligned with them, further out if another field is in the way;
    "next to" takes the first free side (east, north, west, south). Without
    one it goes east of the whole scene. Neighbours stay ``gap`` apart.
    """
    if side == "between":
        raise PromptError(
            "an edit cannot put a new field between two existing ones",
            stage="edit",
            hint="place it next to or north/south/east/west of one field",
        )
    block_box = box_of(block)
    others = [box_of([spec.geometry]) for spec in existing]
    if not anchor or side is None:
        scene = box_of([spec.geometry for spec in existing])
        first = _beside(block_box, scene, "east_of", gap)
        more = _slide(_moved(block_box, *first), "east_of", others, gap)
        return first[0] + more[0], first[1] + more[1]
    anchor_box = box_of([spec.geometry for spec in anchor])
    sides = _NEXT_TO if side == "next_to" else (side,)
    for candidate in sides:
        shift = _beside(block_box, anchor_box, candidate, gap)
        if _clash(_moved(block_box, *shift), others, gap) is None:
            return shift
    first = _beside(block_box, anchor_box, sides[0], gap)
    more = _slide(_moved(block_box, *first), sides[0], others, gap)
    return first[0] + more[0], first[1] + more[1]
