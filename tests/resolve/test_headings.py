"""List headings (resolve/_headings.py): a plot word or crop named before the fields
that say what it holds is their heading, not one more field."""

from __future__ import annotations

import pytest

from agrirecipe import generate


@pytest.mark.parametrize(
    ("prompt", "crops"),
    [
        (
            "My allotment in one picture: a strawberry bed, a patch of sweetcorn",
            ["Strawberry", "Maize"],
        ),
        (
            "Pruning-robot vineyard, two blocks: Chardonnay, 40 rows, and Cabernet, 36 rows",
            ["Grape", "Grape"],
        ),
        (
            "Rain-cover test for cherries: two blocks, Kordia and Regina, 16 rows each.",
            ["Cherry", "Cherry"],
        ),
        ("vineyard in NZ, cabernet on one block n chardonnay on the other", ["Grape", "Grape"]),
        ("onoins!!! just 1 big field of onions!!", ["Onion"]),
        ("Wheat. A 2 ha wheat field next to a barn.", ["Wheat"]),
    ],
)
def test_a_heading_is_no_field(prompt: str, crops: list[str]) -> None:
    assert [f.crop for f in generate(prompt).recipe.fields] == crops


@pytest.mark.parametrize(
    ("prompt", "count"),
    [
        ("Wheat. Maize. A maize field", 2),
        ("Potatoes! two fields of potatoes", 2),
        ("a potato field: nice and green", 1),
    ],
)
def test_a_crop_named_alone_is_a_field_unless_its_field_follows(prompt: str, count: int) -> None:
    assert len(generate(prompt).recipe.fields) == count
