"""Fields counted first, then named again in the order they lie (resolve/_named_in_order.py
and the directed row of resolve/_rows.py)."""

from __future__ import annotations

import pytest

from agrirecipe import generate


def _row(prompt: str) -> list[tuple[str, str, tuple[str, ...]]]:
    scene = generate(prompt).recipe
    return sorted((r.kind, r.subject, r.objects) for r in scene.relations)


@pytest.mark.parametrize(
    "prompt",
    [
        "Two wheat plots and one maize plot, laid out north to south as wheat, maize, wheat.",
        "Two wheat plots and one maize plot, north to south: wheat, maize, wheat.",
    ],
)
def test_a_kind_counted_twice_is_each_of_its_fields_in_turn(prompt: str) -> None:
    fields = generate(prompt).recipe.fields
    assert [f.crop for f in fields] == ["Wheat", "Wheat", "Maize"]
    first, second, maize = (f.id for f in fields)
    assert _row(prompt) == sorted(
        [
            ("between", maize, (first, second)),
            ("north_of", first, (maize,)),
            ("north_of", maize, (second,)),
        ]
    )


def test_categories_counted_then_named_again() -> None:
    prompt = (
        "Two vegetable plots and one fruit plot, 20 m x 20 m each, laid out north to south "
        "as veg, fruit, veg."
    )
    fields = generate(prompt).recipe.fields
    assert [f.category for f in fields] == ["Vegetables", "Vegetables", "Fruits"]
    first, second, fruit = (f.id for f in fields)
    assert ("north_of", first, (fruit,)) in _row(prompt)
    assert ("north_of", fruit, (second,)) in _row(prompt)


def test_a_list_naming_another_number_of_fields_is_not_them() -> None:
    # three names for four fields counted: not the same fields named again
    fields = generate("Two wheat plots and two maize plots, west to east: wheat, maize, wheat.")
    assert len(fields.recipe.fields) >= 4
