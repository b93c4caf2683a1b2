"""The field packer: no overlaps, farm tracks between fields, relations honoured or refused."""

from __future__ import annotations

import itertools
import math

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from agrirecipe import ConfigurationError, PromptError
from agrirecipe.layout import FieldRequest, pack_fields
from agrirecipe.recipe import FieldGeometry, Relation, RelationKind

GAP = 4.0
EPS = 1e-9

Box = tuple[float, float, float, float]  # xmin, ymin, xmax, ymax


def box(geometry: FieldGeometry) -> Box:
    (x, y), (w, h) = geometry.origin_m, geometry.size_m
    assert geometry.rotation_deg == 0.0
    return x, y, x + w, y + h


def separated(a: Box, b: Box, gap: float) -> bool:
    """At least ``gap`` apart along X or along Y."""
    return (
        a[2] + gap <= b[0] + EPS
        or b[2] + gap <= a[0] + EPS
        or a[3] + gap <= b[1] + EPS
        or b[3] + gap <= a[1] + EPS
    )


def overlap_1d(a0: float, a1: float, b0: float, b1: float) -> bool:
    return min(a1, b1) - max(a0, b0) > EPS


def intersects(a: Box, b: Box) -> bool:
    return overlap_1d(a[0], a[2], b[0], b[2]) and overlap_1d(a[1], a[3], b[1], b[3])


def relation_holds(relation: Relation, boxes: dict[str, Box]) -> bool:
    """An independent reading of each relation on the packed rectangles."""
    a = boxes[relation.subject]
    if relation.kind == "north_of":
        return a[1] >= boxes[relation.objects[0]][3] + GAP - EPS
    if relation.kind == "south_of":
        return a[3] + GAP <= boxes[relation.objects[0]][1] + EPS
    if relation.kind == "east_of":
        return a[0] >= boxes[relation.objects[0]][2] + GAP - EPS
    if relation.kind == "west_of":
        return a[2] + GAP <= boxes[relation.objects[0]][0] + EPS
    if relation.kind == "next_to":
        b = boxes[relation.objects[0]]
        others = [v for k, v in boxes.items() if k not in (relation.subject, relation.objects[0])]
        if overlap_1d(a[1], a[3], b[1], b[3]) and not overlap_1d(a[0], a[2], b[0], b[2]):
            lo, hi = (a, b) if a[0] < b[0] else (b, a)
            corridor = (lo[2], max(a[1], b[1]), hi[0], min(a[3], b[3]))
        elif overlap_1d(a[0], a[2], b[0], b[2]) and not overlap_1d(a[1], a[3], b[1], b[3]):
            lo, hi = (a, b) if a[1] < b[1] else (b, a)
            corridor = (max(a[0], b[0]), lo[3], min(a[2], b[2]), hi[1])
        else:
            return False
        return not any(intersects(corridor, other) for other in others)
    first, second = (boxes[name] for name in relation.objects)
    for lo_i, hi_i, other_lo, other_hi in ((0, 2, 1, 3), (1, 3, 0, 2)):
        for low, high in ((first, second), (second, first)):
            if (
                low[hi_i] <= a[lo_i] + EPS
                and a[hi_i] <= high[lo_i] + EPS
                and overlap_1d(a[other_lo], a[other_hi], low[other_lo], low[other_hi])
                and overlap_1d(a[other_lo], a[other_hi], high[other_lo], high[other_hi])
            ):
                return True
    # on a diagonal: between the two along X and along Y ("an orchard in the NE corner,
    # vegetables in the SW corner and a cereal field between them")
    return all(
        any(
            low[hi_i] <= a[lo_i] + EPS and a[hi_i] <= high[lo_i] + EPS
            for low, high in ((first, second), (second, first))
        )
        for lo_i, hi_i in ((0, 2), (1, 3))
    )


def check_packing(
    requests: list[FieldRequest], relations: list[Relation]
) -> dict[str, FieldGeometry]:
    placed = pack_fields(requests, relations, gap_m=GAP)
    assert list(placed) == [r.id for r in requests]
    boxes = {name: box(g) for name, g in placed.items()}
    for request in requests:
        geometry = placed[request.id]
        assert geometry.size_m == (request.width_m, request.length_m)
        assert geometry.headland_m == request.headland_m
    for (name_a, a), (name_b, b) in itertools.combinations(boxes.items(), 2):
        assert separated(a, b, GAP), f"{name_a} and {name_b} are closer than the gap"
    for relation in relations:
        assert relation_holds(relation, boxes), f"not honoured: {relation}"
    return placed


def rel(kind: RelationKind, subject: str, *objects: str) -> Relation:
    return Relation(kind=kind, subject=subject, objects=objects)


def requests_of(*sizes: tuple[float, float]) -> list[FieldRequest]:
    return [FieldRequest(f"f{i}", w, h, 1.0) for i, (w, h) in enumerate(sizes)]


def test_unrelated_fields_are_packed_compactly_near_the_origin() -> None:
    requests = requests_of(*[(60.0, 100.0)] * 9)
    placed = check_packing(requests, [])
    boxes = [box(g) for g in placed.values()]
    assert min(b[0] for b in boxes) == 0.0 and min(b[1] for b in boxes) == 0.0
    width = max(b[2] for b in boxes)
    length = max(b[3] for b in boxes)
    # Nine equal fields: a roughly square farm, not one long strip.
    assert 0.4 < width / length < 2.5
    assert width * length < 2.5 * sum((b[2] - b[0]) * (b[3] - b[1]) for b in boxes)


def test_packing_is_deterministic() -> None:
    requests = requests_of((60, 100), (20, 40), (30, 30), (80, 10))
    relations = [rel("north_of", "f0", "f1"), rel("next_to", "f2", "f0")]
    assert pack_fields(requests, relations) == pack_fields(requests, relations)


@pytest.mark.parametrize(
    "relation",
    [
        rel("north_of", "f0", "f1"),
        rel("south_of", "f0", "f1"),
        rel("east_of", "f0", "f1"),
        rel("west_of", "f0", "f1"),
        rel("next_to", "f0", "f1"),
        rel("between", "f0", "f1", "f2"),
    ],
    ids=lambda r: r.kind,
)
def test_each_relation_kind_is_honoured(relation: Relation) -> None:
    requests = requests_of((60, 100), (30, 40), (50, 20), (25, 25))
    check_packing(requests, [relation])


def test_directional_relation_puts_fields_in_line() -> None:
    placed = check_packing(requests_of((60, 100), (30, 40)), [rel("north_of", "f0", "f1")])
    a, b = box(placed["f0"]), box(placed["f1"])
    assert overlap_1d(a[0], a[2], b[0], b[2]), "north_of should be directly north, not diagonal"


def test_relations_combine() -> None:
    requests = requests_of((60, 100), (30, 40), (50, 20), (25, 25), (40, 40))
    relations = [
        rel("north_of", "f0", "f1"),
        rel("next_to", "f2", "f0"),
        rel("between", "f3", "f1", "f2"),
        rel("west_of", "f4", "f1"),
    ]
    check_packing(requests, relations)


@pytest.mark.parametrize(
    ("relations", "named"),
    [
        (
            [rel("north_of", "f0", "f1"), rel("north_of", "f1", "f0")],
            ["f0 north_of f1", "f1 north_of f0"],
        ),
        (
            [rel("north_of", "f0", "f1"), rel("south_of", "f0", "f1")],
            ["f0 north_of f1", "f0 south_of f1"],
        ),
        (
            [rel("east_of", "f0", "f1"), rel("east_of", "f1", "f2"), rel("east_of", "f2", "f0")],
            ["f0 east_of f1", "f1 east_of f2", "f2 east_of f0"],
        ),
        (
            [rel("between", "f0", "f1", "f2"), rel("between", "f1", "f0", "f2")],
            ["f0 between f1 and f2", "f1 between f0 and f2"],
        ),
        (
            [
                rel("north_of", "f0", "f1"),
                rel("east_of", "f0", "f1"),
                rel("next_to", "f0", "f1"),
            ],
            ["f0 next_to f1"],
        ),
    ],
)
def test_unsatisfiable_relations_raise_prompt_error_naming_them(
    relations: list[Relation], named: list[str]
) -> None:
    with pytest.raises(PromptError) as caught:
        pack_fields(requests_of((60, 100), (30, 40), (50, 20)), relations)
    assert caught.value.stage == "layout"
    for words in named:
        assert words in str(caught.value)


def test_a_field_between_two_on_a_diagonal() -> None:
    # "an orchard in the NE corner, vegetables in the SW corner, a cereal field between"
    relations = [
        rel("north_of", "f0", "f1"),
        rel("west_of", "f1", "f0"),
        rel("between", "f2", "f0", "f1"),
    ]
    boxes = {
        k: box(g)
        for k, g in check_packing(requests_of((60, 100), (30, 60), (30, 40)), relations).items()
    }
    orchard, vegetables, cereal = boxes["f0"], boxes["f1"], boxes["f2"]
    assert vegetables[2] <= cereal[0] and cereal[2] <= orchard[0]
    assert vegetables[3] <= cereal[1] and cereal[3] <= orchard[1]


def test_a_field_between_itself_is_refused() -> None:
    # The schema refuses this too; the packer must not trust that relations were validated.
    bad = Relation.model_construct(kind="between", subject="f0", objects=("f0", "f1"))
    with pytest.raises(PromptError, match="f0 between f0 and f1"):
        pack_fields(requests_of((10, 10), (10, 10)), [bad])
    twice = Relation.model_construct(kind="between", subject="f0", objects=("f1", "f1"))
    with pytest.raises(PromptError, match="f0 between f1 and f1"):
        pack_fields(requests_of((10, 10), (10, 10)), [twice])


def test_unknown_field_in_a_relation_lists_the_fields() -> None:
    with pytest.raises(PromptError, match="unknown field 'nope'") as caught:
        pack_fields(requests_of((10, 10)), [rel("north_of", "f0", "nope")])
    assert caught.value.hint is not None and "f0" in caught.value.hint


@pytest.mark.parametrize(
    "request_",
    [
        FieldRequest("a", 0.0, 10.0, 1.0),
        FieldRequest("a", 10.0, -1.0, 1.0),
        FieldRequest("a", math.inf, 10.0, 1.0),
        FieldRequest("a", 10.0, 10.0, -2.0),
    ],
)
def test_bad_sizes_are_refused(request_: FieldRequest) -> None:
    with pytest.raises(PromptError, match="metres"):
        pack_fields([request_])


def test_duplicate_ids_and_bad_gap_are_refused() -> None:
    with pytest.raises(PromptError, match="share the id"):
        pack_fields([FieldRequest("a", 1, 1, 0), FieldRequest("a", 2, 2, 0)])
    with pytest.raises(ConfigurationError, match="gap_m"):
        pack_fields([FieldRequest("a", 1, 1, 0)], gap_m=-1.0)


# --- property tests ------------------------------------------------------------------------------

sizes = st.tuples(st.floats(5.0, 200.0), st.floats(5.0, 200.0))


@st.composite
def satisfiable_scenes(draw: st.DrawFn) -> tuple[list[FieldRequest], list[Relation]]:
    """Fields on random distinct grid cells and relations that are true of that arrangement."""
    count = draw(st.integers(1, 10))
    cells = draw(
        st.lists(
            st.tuples(st.integers(0, 3), st.integers(0, 3)),
            min_size=count,
            max_size=count,
            unique=True,
        )
    )
    requests = [FieldRequest(f"f{i}", *draw(sizes), 1.0) for i in range(count)]
    true_relations: list[Relation] = []
    for i, j in itertools.permutations(range(count), 2):
        (ci, ri), (cj, rj) = cells[i], cells[j]
        if ci == cj and ri > rj:
            true_relations.append(rel("north_of", f"f{i}", f"f{j}"))
        if ri == rj and ci > cj:
            true_relations.append(rel("east_of", f"f{i}", f"f{j}"))
        if ri == rj and ci == cj + 1:
            true_relations.append(rel("next_to", f"f{i}", f"f{j}"))
        if ci == cj and ri == rj - 1:
            true_relations.append(rel("south_of", f"f{i}", f"f{j}"))
    for i, j, k in itertools.permutations(range(count), 3):
        (ci, ri), (cj, rj), (ck, rk) = cells[i], cells[j], cells[k]
        if ri == rj == rk and cj < ci < ck and j < k:
            true_relations.append(rel("between", f"f{i}", f"f{j}", f"f{k}"))
    if not true_relations:
        return requests, []
    chosen = draw(st.lists(st.sampled_from(true_relations), max_size=6, unique=True))
    return requests, chosen


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(satisfiable_scenes())
def test_satisfiable_relations_are_always_honoured(
    scene: tuple[list[FieldRequest], list[Relation]],
) -> None:
    requests, relations = scene
    check_packing(requests, relations)


@st.composite
def arbitrary_scenes(draw: st.DrawFn) -> tuple[list[FieldRequest], list[Relation]]:
    count = draw(st.integers(3, 8))
    requests = [FieldRequest(f"f{i}", *draw(sizes), 0.0) for i in range(count)]
    ids = [r.id for r in requests]
    relations = []
    for _ in range(draw(st.integers(0, 5))):
        kind = draw(
            st.sampled_from(["north_of", "south_of", "east_of", "west_of", "next_to", "between"])
        )
        arity = 3 if kind == "between" else 2
        names = draw(st.permutations(ids))[:arity]
        relations.append(rel(kind, names[0], *names[1:]))
    return requests, relations


@settings(max_examples=150, deadline=None)
@given(arbitrary_scenes())
def test_any_relations_are_honoured_or_refused(
    scene: tuple[list[FieldRequest], list[Relation]],
) -> None:
    requests, relations = scene
    try:
        check_packing(requests, relations)
    except PromptError as error:
        assert error.stage == "layout"
        assert any(f"{r.subject} {r.kind}" in str(error) for r in relations), (
            "the error names the relations"
        )
