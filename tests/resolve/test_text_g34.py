"""Text of blind set g34 (issue 8): a rough count after the plots ("veg plots?? like 4 or
5"), a crop spelt by ear ("lettus"), fields "sharing a border", "top half corn bottom half
wheat", a bare "Southern boundary:", "beyond them, to the south", numbered members of a
counted plural ("strip 2 south of strip 1"), a field's own trees after "next to it", a
day of the month ("the 2nd of May"), "vines dead and brown" of potatoes, a bare word for
the fruit after a dash, "the first field" among fields named in order, and scenery placed
by a field named before."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe

NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


@pytest.mark.parametrize(
    ("prompt", "count", "category"),
    [
        ("can i get some veg plots?? like 4 or 5, need it b4 monday thx", 4, "Vegetables"),
        ("a few fruit fields idk 2 or 3", 2, "Fruits"),
    ],
)
def test_a_rough_count_after_the_plots(prompt: str, count: int, category: str) -> None:
    fields = recipe(prompt).fields
    assert len(fields) == count
    assert {f.category for f in fields} == {category}


def test_a_crop_spelt_by_ear() -> None:
    (lettuce,) = recipe("cn u make a lettus field thx").fields
    assert lettuce.crop == "Lettuce"
    # (a word of its own that sounds like no crop is not read as one: "canes")
    (vines,) = recipe("Picture of the young vines, tiny shoots tied to bamboo canes").fields
    assert vines.crop == "Grape"


def test_fields_sharing_a_border(named_relations: Callable[[str], NamedRelations]) -> None:
    fields = recipe("orchard + vineyard sharing a border pls, thats it").fields
    assert {f.category for f in fields} == {"Fruits"}
    assert [r.kind for r in recipe("orchard + vineyard sharing a border").relations] == ["next_to"]
    assert named_relations("the vineyard shares a border with the carrot field") == {
        ("next_to", "Grape", ("Carrot",))
    }


def test_sides_said_without_a_mark_and_bare_boundaries(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    corn, wheat = recipe("top half corn bottom half wheat, simple as that lol").fields
    assert (corn.crop, wheat.crop) == ("Maize", "Wheat")
    assert named_relations("top half corn bottom half wheat, simple as that lol") == {
        ("north_of", "Maize", ("Wheat",))
    }
    prompt = (
        "Along the northern boundary: Bing cherries. Middle: Danvers carrots. Southern "
        "boundary: popcorn."
    )
    assert {
        ("north_of", "Bing", ("Danvers",)),
        ("north_of", "Danvers", ("Popcorn",)),
    } <= named_relations(prompt)


def test_beyond_them_to_a_side_is_that_side() -> None:
    result = recipe(
        "Cherry trees along the lane, and beyond them, to the south, two fields of potatoes."
    )
    cherries, *potatoes = result.fields
    assert cherries.crop == "Cherry" and [p.crop for p in potatoes] == ["Potato", "Potato"]
    assert {(r.kind, r.subject, r.objects) for r in result.relations} == {
        ("south_of", p.id, (cherries.id,)) for p in potatoes
    }


def test_numbered_members_of_a_counted_plural() -> None:
    result = recipe(
        "Three wheat strips, 10 x 50 m each, drilled at 12.5 cm row spacing with the rows "
        "running east-west. Strip 2 sits directly south of strip 1 and strip 3 south of strip 2."
    )
    one, two, three = result.fields
    assert {f.crop for f in result.fields} == {"Wheat"}
    kinds = {(r.kind, r.subject, r.objects) for r in result.relations}
    assert {("south_of", two.id, (one.id,)), ("south_of", three.id, (two.id,))} <= kinds
    groves = recipe(
        "Two citrus groves for a canopy LiDAR run, 7 m x 4 m spacing (row x tree), 100 trees "
        "each, separated by a 10 m track; grove 2 south of grove 1."
    )
    first, second = groves.fields
    assert first.crop == second.crop == "Orange"
    assert ("south_of", second.id, (first.id,)) in {
        (r.kind, r.subject, r.objects) for r in groves.relations
    }


def test_a_fields_own_trees_said_after_next_to_it() -> None:
    vines, cherries = recipe(
        "Drone spraying test over a 1.5 ha block of vines (rows 2.5 m apart, vines 1.6 m "
        "apart, 2,500 vines/ha, rows E-W) and a 1 ha cherry orchard next to it with trees at "
        "5 x 3 m (row x tree)."
    ).fields
    assert (vines.crop, cherries.crop) == ("Grape", "Cherry")
    assert cherries.agronomy.row_spacing_m == 5.0
    assert cherries.agronomy.in_row_spacing_m == 3.0


def test_a_day_of_the_month_counts_no_fields() -> None:
    (strawberries,) = recipe(
        "Malling Centenary under the tunnel on the 2nd of May: rows of white flowers with "
        "yellow centres and only a few small green berries, rain drumming on the plastic."
    ).fields
    assert (strawberries.variety, strawberries.season) == ("Malling Centenary", "Spring")


def test_potato_vines_dead_and_brown() -> None:
    (potatoes,) = recipe(
        "A Russet potato field in Idaho, vines dead and brown, a harvester digging the first "
        "rows under a huge sky."
    ).fields
    assert (potatoes.variety, potatoes.stage) == ("Russet Burbank", "Maturation")


def test_a_bare_word_for_the_fruit_after_a_dash() -> None:
    (tomatoes,) = recipe(
        "Look at these Beefsteak tomatoes - massive ribbed fruit, but the lower leaves are "
        "brown with dark water-soaked blotches and white mould underneath. Humid, grey August "
        "day."
    ).fields
    assert (tomatoes.variety, tomatoes.health) == ("Beefsteak", "Ill")


def test_the_first_field_among_fields_named_in_order() -> None:
    result = recipe(
        "In the photo, left to right: Bintje, Agria and Fontane potatoes, all three in flower, "
        "with the sprayer boom folded up by the first field and an electricity pole in the "
        "hedge."
    )
    assert [f.variety for f in result.fields] == ["Bintje", "Agria", "Fontane"]
    assert "next_to" not in {r.kind for r in result.relations}
    wheat, maize, potatoes = recipe("wheat, maize and potatoes; the second field is ill").fields
    assert (wheat.health, maize.health, potatoes.health) == ("Healthy", "Ill", "Healthy")


def test_scenery_placed_by_a_field_named_before() -> None:
    result = recipe("Bintje and Agria potatoes, with a tractor parked by the Bintje")
    assert len(result.fields) == 2
    assert result.relations == ()
