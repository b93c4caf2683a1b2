"""Measures shared between listed plots (issue 8): "respectively" lists, a run of
measures after "each"/"both", measures closed by "in both", "the west half", and a bare
in-row length after the rows' spacing."""

from __future__ import annotations

import pytest

from agrirecipe import PromptError, generate
from agrirecipe.recipe import SceneRecipe


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def test_respectively_gives_each_value_to_its_field_in_order() -> None:
    scene = recipe(
        "Jonagored apples and Bartlett pears, two blocks, 3.4 m and 3.5 m row spacing "
        "respectively, 1 m in-row in both; pears on the north side."
    )
    assert [f.crop for f in scene.fields] == ["Apple", "Pear"]
    assert [f.agronomy.row_spacing_m for f in scene.fields] == [3.4, 3.5]
    assert [f.agronomy.in_row_spacing_m for f in scene.fields] == [1.0, 1.0]


def test_respectively_reads_counts_and_lists_of_three() -> None:
    scene = recipe(
        "three tomato plots, Roma, San Marzano and Beefsteak, with 10, 12 and 14 rows respectively"
    )
    assert [f.variety for f in scene.fields] == ["Roma", "San Marzano", "Beefsteak"]
    widths = [f.geometry.size_m[0] for f in scene.fields]
    assert widths == sorted(widths) and len(set(widths)) == 3
    assert [f.stated.count("rows") for f in scene.fields] == [1, 1, 1]


def test_respectively_with_fewer_fields_than_values_is_refused() -> None:
    with pytest.raises(PromptError, match="respectively") as error:
        recipe("maize, 36 and 40 rows respectively")
    assert "one field for each value" in (error.value.hint or "")


def test_measures_after_an_each_clause_go_to_every_field() -> None:
    scene = recipe(
        "Vineyard sim request: Pinot Nero block north of a Chardonnay block. Each block is "
        "40 rows x 150 m on a VSP trellis, rows 2.5 m apart, 1.2 m between vines, rows run N-S."
    )
    for field in scene.fields:
        assert field.agronomy.row_spacing_m == 2.5
        assert field.agronomy.in_row_spacing_m == 1.2
        assert "row_direction" in field.stated


def test_measures_closed_by_in_both_go_to_both_fields() -> None:
    scene = recipe(
        "HLB detection plots: a Valencia block with citrus greening and a healthy Hamlin "
        "block, rows 6 m apart and trees 3 m apart in both, Valencia east of Hamlin."
    )
    assert [f.agronomy.row_spacing_m for f in scene.fields] == [6.0, 6.0]
    assert [f.agronomy.in_row_spacing_m for f in scene.fields] == [3.0, 3.0]
    assert [f.health for f in scene.fields] == ["Ill", "Healthy"]


def test_both_blocks_after_listed_members_is_every_member() -> None:
    scene = recipe(
        "drone camera calibration site = two potato blocks side by side, Bintje on the west "
        "half and Agria on the east half. Both blocks 36 rows at 0.75 m, rows 100 m."
    )
    assert [f.variety for f in scene.fields] == ["Bintje", "Agria"]
    assert [f.agronomy.row_spacing_m for f in scene.fields] == [0.75, 0.75]
    assert scene.fields[0].geometry.size_m == scene.fields[1].geometry.size_m
    kinds = {(r.kind, r.subject) for r in scene.relations}
    assert ("west_of", scene.fields[0].id) in kinds


def test_a_bare_length_after_the_rows_spacing_is_the_in_row_spacing() -> None:
    scene = recipe(
        "Drone mapping of three orchard blocks, 8 rows each: apples at 3.4 m rows with 1.0 m "
        "between trees, pears at 3.5 m rows and 0.9 m, cherries at 4.6 m rows and 2.4 m."
    )
    assert [f.agronomy.row_spacing_m for f in scene.fields] == [3.4, 3.5, 4.6]
    assert [f.agronomy.in_row_spacing_m for f in scene.fields] == [1.0, 0.9, 2.4]
    assert all("in_row_spacing" in f.stated for f in scene.fields)


def test_bare_letter_labels_name_plots_and_place_them() -> None:
    scene = recipe(
        "Fruit-counting camera test, three tomato plots: A = Roma, B = San Marzano, "
        "C = Beefsteak. Each 10 rows at 1.5 m, 50 cm between plants, 40 m rows. Put B "
        "between A and C."
    )
    ids = {f.variety: f.id for f in scene.fields}
    assert list(ids) == ["Roma", "San Marzano", "Beefsteak"]
    assert [(r.kind, r.subject, r.objects) for r in scene.relations] == [
        ("between", ids["San Marzano"], (ids["Roma"], ids["Beefsteak"]))
    ]
    assert all(f.row_count == 10 for f in scene.fields)


def test_farm_quarters_lie_on_both_axes() -> None:
    scene = recipe(
        "Think of the farm in quarters: orchard in the NW quarter, vines in the NE, root veg "
        "in the SW and grain in the SE."
    )
    nw, ne, sw, se = (f.id for f in scene.fields)
    assert {(r.kind, r.subject, r.objects) for r in scene.relations} == {
        ("north_of", nw, (sw,)),
        ("north_of", ne, (se,)),
        ("west_of", nw, (ne,)),
        ("west_of", sw, (se,)),
    }


@pytest.mark.parametrize(
    "prompt",
    [
        "Chardonnay vines, and west of the vineyard there's a block of Navel oranges.",
        "a Chardonnay vineyard; west of the vineyard is a block of Navel oranges.",
    ],
)
def test_a_new_plot_after_there_is_is_not_the_plot_before(prompt: str) -> None:
    scene = recipe(prompt)
    grape, orange = scene.fields
    assert (grape.crop, orange.crop, orange.variety) == ("Grape", "Orange", "Navel")
    assert [(r.kind, r.subject, r.objects) for r in scene.relations] == [
        ("west_of", orange.id, (grape.id,))
    ]


def test_a_vineyard_of_oranges_is_still_a_contradiction() -> None:
    with pytest.raises(PromptError, match="contradiction"):
        recipe("a vineyard of Navel oranges")


@pytest.mark.parametrize(
    ("prompt", "areas"),
    [
        ("a wheat field and a maize field, 2 ha and 3 ha respectively", [20_000, 30_000]),
        (
            "centenary strawberries south of the elsanta ones, both ripe in june, 30x40m and "
            "30x60m resp.",
            [1_200, 1_800],
        ),
    ],
)
def test_sizes_given_respectively(prompt: str, areas: list[int]) -> None:
    scene = recipe(prompt)
    assert [f.geometry.area_m2 for f in scene.fields] == pytest.approx(areas, rel=0.01)


def test_sizes_given_respectively_need_as_many_fields() -> None:
    with pytest.raises(PromptError, match="respectively"):
        recipe("a wheat field, 2 ha and 3 ha respectively")
