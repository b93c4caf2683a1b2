"""Members of a counted plural said by their place (resolve/_member_refs.py)."""

from __future__ import annotations

import pytest

from agrirecipe.resolve._lexicon import Item, Token
from agrirecipe.resolve._member_refs import place_said
from agrirecipe.resolve._mentions import Mention


def _reference(words: str) -> Item:
    tokens = tuple(Token(w, w, i, i + 1) for i, w in enumerate(words.split()))
    return Item(tokens=tokens, senses=(), role="reference")


@pytest.mark.parametrize(
    ("words", "count", "expected"),
    [
        ("the middle one", 3, 1),
        ("the middle one", 5, 2),
        ("the middle one", 4, None),  # (no middle of an even count)
        ("the second one", 3, 1),
        ("the last one", 4, 3),
        ("the fourth one", 3, None),  # (past the count)
    ],
)
def test_a_member_said_by_its_place(words: str, count: int, expected: int | None) -> None:
    assert place_said(_reference(words), Mention(count=count)) == expected


def test_a_place_already_said_is_not_said_again() -> None:
    parent = Mention(count=3, refinements=[Mention(), Mention()])
    assert place_said(_reference("the second one"), parent) is None
    parent.refinements[1].unsaid = True
    assert place_said(_reference("the second one"), parent) == 1


def _placed(prompt: str) -> set[tuple[str, str, tuple[str, ...]]]:
    from agrirecipe import generate

    return {(r.kind, r.subject, r.objects) for r in generate(prompt).recipe.relations}


@pytest.mark.parametrize(
    ("said", "placed"),
    [
        ("the denser plot to the east", "maize_plot_1"),
        ("the sparser plot to the east", "maize_plot_2"),
        ("the first one to the east", "maize_plot_1"),
        ("the 9 plants/m2 plot to the east", "maize_plot_1"),
        ("the 7 plants/m2 plot to the east", "maize_plot_2"),
    ],
)
def test_a_member_said_already_named_again_by_a_measure_or_place(said: str, placed: str) -> None:
    other = {"maize_plot_1": "maize_plot_2", "maize_plot_2": "maize_plot_1"}[placed]
    assert _placed(
        f"two maize plots on 75 cm rows, one at 9 plants/m2 and one at 7 plants/m2, {said}"
    ) == {("east_of", placed, (other,))}


def test_a_member_named_by_its_number_alone_as_an_object() -> None:
    assert _placed(
        "Two maize plots for a density comparison, 9 plants/m2 in one and 7 plants/m2 in the "
        "other, the 9 plants/m2 plot east of the 7."
    ) == {("east_of", "maize_plot_1", ("maize_plot_2",))}


def test_the_bigger_plot_by_its_area() -> None:
    assert _placed(
        "two wheat fields, one of 2 ha and one of 5 ha, the bigger field to the north"
    ) == {("north_of", "wheat_field_2", ("wheat_field_1",))}
