"""Text of blind set g16 (issue 8): fruit borne or described after fields named, patches
of a field, parts of plants counted, a plot of many plants, spacing keys in brackets,
counted plots named after a question, "both" before its members, an order said before
its list, beds at a pitch, rows turned west of north, a month opening the prompt, and a
size said "each" by the last of a list."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe

#: The fixture named_relations' answer (tests/resolve/conftest.py).
NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


@pytest.mark.parametrize(
    ("prompt", "crops"),
    [
        (
            "Jalapeños in late August: bushy plants hung with glossy fruit, some already turning "
            "red, and a line of pickers with buckets",
            ["Pepper"],
        ),
        (
            "Inside the glasshouse: beef tomatoes on the left and sweet peppers on the right, "
            "both carrying fruit",
            ["Tomato", "Pepper"],
        ),
        (
            "My tomato plots: San Marzano on the north side, fruit red and ready, and plum "
            "tomatoes to the south of them",
            ["Tomato", "Tomato"],
        ),
        (
            "Here's what the Russets looked like yesterday: dark, water-soaked blotches on the "
            "leaves, white mould on the undersides and whole patches collapsing.",
            ["Potato"],
        ),
        (
            "A January photo of our Riesling, dormant vines pruned back to two canes, frost on "
            "the posts and wires",
            ["Grape"],
        ),
        (
            "Need a carrot test bed for the weeding robot: Nantes, 16 ridges on 75 cm centres, "
            "plants at the 2-3 true leaf stage.",
            ["Carrot"],
        ),
    ],
)
def test_no_phantom_field_from_words_about_the_plants(prompt: str, crops: list[str]) -> None:
    assert [f.crop for f in recipe(prompt).fields] == crops


def test_patches_with_a_look_after_fields_are_no_unknown_crop() -> None:
    scene = recipe(
        "Early April: the spring wheat we drilled in March is a green haze of seedlings, and "
        "over the hedge the Durondeau pears are in blossom. Lapwings are on the bare patches."
    )
    assert [f.crop for f in scene.fields] == ["Wheat", "Pear"]
    # patches of a crop are still its fields
    assert len(recipe("strawberry patches").fields) == 2


def test_a_plot_of_many_and_a_spacing_key() -> None:
    cavendish, lady = recipe(
        "Banana counting dataset: 450 Dwarf Cavendish plants east of a Ladyfinger block of "
        "300, both at 4 m by 3 m (row by plant)."
    ).fields
    assert cavendish.nominal_plant_count == pytest.approx(450, rel=0.02)
    assert lady.nominal_plant_count == pytest.approx(300, rel=0.02)


@pytest.mark.parametrize(
    "prompt",
    [
        "two adjacent blocks for our robot sim? Gala apples on 12 ft rows, and Comice pears "
        "on 13 ft rows.",
        "Spray-drone trial, mid-April, both blocks in full bloom. Conference pears planted "
        "3.5 m x 1.0 m (row x tree) and, north of them, Kordia cherries at 4.6 m x 2.4 m.",
    ],
)
def test_counted_plots_named_in_the_sentence_after(prompt: str) -> None:
    assert len(recipe(prompt).fields) == 2


def test_an_order_said_before_its_list() -> None:
    scene = recipe(
        "three strips side by side, west to east wheat, maize, potatoes. Each strip 12 m wide "
        "and 150 m long."
    )
    assert [f.crop for f in scene.fields] == ["Wheat", "Maize", "Potato"]
    assert ("west_of", scene.fields[0].id, (scene.fields[1].id,)) in {
        (r.kind, r.subject, r.objects) for r in scene.relations
    }


def test_beds_at_a_pitch_and_rows_turned_west_of_north() -> None:
    (onions,) = recipe("Onion beds at 1.5 m pitch with 4 rows each").fields
    assert (onions.agronomy.row_spacing_m, onions.agronomy.rows_per_bed) == (1.5, 4)
    (vines,) = recipe("1 ha of vines, 2.8 m rows, rows turned 15 degrees west of north.").fields
    # a bearing of 345 (the same line as 165): rotation is minus the bearing, mod 180
    assert (-vines.geometry.rotation_deg) % 180 == pytest.approx(165)


def test_a_month_opening_the_prompt() -> None:
    fields = recipe("May flight: Winter Wheat and Spring Wheat plots next to each other").fields
    assert [f.season for f in fields] == ["Spring", "Spring"]


def test_a_size_said_each_by_the_last_of_a_list() -> None:
    fields = recipe("wheat north of maize north of potatoes 1 ha each!!!").fields
    for field in fields:
        width, length = field.geometry.size_m
        assert width * length == pytest.approx(10_000, rel=0.01)


@pytest.mark.parametrize(
    ("prompt", "expected"),
    [
        # an order said as a walk from one side to the opposite one
        (
            "Starting at the bottom of the farm by the road and working up to the top: Red "
            "Baron onions, then Chantenay carrots, then Fontane potatoes up against the woods.",
            {("south_of", "Red Baron", ("Chantenay",)), ("south_of", "Chantenay", ("Fontane",))},
        ),
        # a zone said with what it is part of
        (
            "Top third of the slope: Pinot Noir. Middle third: Riesling. Bottom third: Chardonnay.",
            {("north_of", "Pinot Noir", ("Riesling",)), ("north_of", "Riesling", ("Chardonnay",))},
        ),
        # zone words misspelt
        (
            "ok so the farm: cherrys at the top, then a big feild of wheat, then the carrots at "
            "the botom near the pond",
            {("north_of", "Cherry", ("Wheat",)), ("north_of", "Wheat", ("Carrot",))},
        ),
        # "on the eastern block ... on the western block"
        (
            "Queensland banana farm in July: Lady Finger on the eastern block, Cavendish on the "
            "western block.",
            {("east_of", "Lady Finger", ("Cavendish",))},
        ),
        # the two on either side of a field "in between" are in that order themselves
        (
            "We're a fruit farm: cherries on the north block, pears on the south block, and "
            "strawberries in tunnels in between.",
            {("north_of", "Cherry", ("Pear",))},
        ),
        # "east of that block": the block named before, after scenery placed it
        (
            "It's March, the Royal Gala block north of the packhouse is ripe, and the Bartlett "
            "pears east of that block are ripening too.",
            {("east_of", "Williams", ("Gala",))},
        ),
        # the next bed over
        (
            "Close-up of the capsicum beds, leaves peppered with dark spots, while the tomatoes "
            "in the next bed over look perfectly fine.",
            {("next_to", "Tomato", ("Pepper",))},
        ),
        # "w/ the onions": the onions named before, placed
        (
            "danvers carrots + stuttgarter onions + cayenne peppers w/ the onions in the middle",
            {("between", "Stuttgarter", ("Danvers", "Cayenne"))},
        ),
    ],
)
def test_fields_placed_in_other_words(
    prompt: str,
    expected: set[tuple[str, str, tuple[str, ...]]],
    named_relations: Callable[[str], NamedRelations],
) -> None:
    said = named_relations(prompt)
    for relation in expected:
        kind, subject, objects = relation
        inverse = {"north_of": "south_of", "south_of": "north_of"}
        inverse |= {"east_of": "west_of", "west_of": "east_of"}
        flipped = (inverse.get(kind, kind), objects[0], (subject,)) if len(objects) == 1 else None
        assert relation in said or flipped in said, (relation, said)


def test_the_royal_gala_block_is_not_placed_by_the_packhouse_against_the_pears(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    said = named_relations(
        "the Royal Gala block north of the packhouse is ripe, and the Bartlett pears east of "
        "that block are ripening too."
    )
    assert said == {("east_of", "Williams", ("Gala",))}


@pytest.mark.parametrize(
    ("prompt", "crops"),
    [
        # produce a container holds is scenery
        (
            "September shot of the chilli patch: Cayenne on one side with long thin red pods "
            "and Padron on the other. A string of dried peppers hangs on the shed wall.",
            ["Pepper", "Pepper"],
        ),
        ("a Gala orchard in autumn, a basket of pears on the grass", ["Apple"]),
        # ... unless it is all the prompt names
        ("a basket of pears", ["Pear"]),
        # a plot word for any crop heading counted plots
        (
            "Market garden, two plots: 100 ft x 40 ft of staked San Marzano tomatoes, and "
            "right next to it a plot of Padron peppers exactly the same size.",
            ["Tomato", "Pepper"],
        ),
        # "one X one Y" in brackets, without commas
        (
            "iceberg lettuce in between 2 cabbage fields (one red express one january king)",
            ["Lettuce", "Cabbage", "Cabbage"],
        ),
    ],
)
def test_no_phantom_field_from_produce_titles_and_bracketed_members(
    prompt: str, crops: list[str]
) -> None:
    assert [f.crop for f in recipe(prompt).fields] == crops


def test_a_crop_said_of_both_blocks_before_them_describes_each() -> None:
    fields = recipe(
        "LiDAR canopy dataset, late August, grapes ripening in both blocks. Chardonnay: 25 "
        "rows x 80 m. Cabernet: 18 rows x 80 m, east of the Chardonnay."
    ).fields
    assert [(f.variety, f.stage) for f in fields] == [
        ("Chardonnay", "Maturation"),
        ("Cabernet Sauvignon", "Maturation"),
    ]


def test_still_green_is_a_look_and_veraison_is_ripening() -> None:
    scene = generate(
        "Across the farm track there's a field of sweet peppers, still green and young.",
        resolver="hybrid",
    )
    assert scene.recipe.fields[0].stage == "Vegetative"
    assert any("still green" in w for w in scene.recipe.warnings)
    (vines,) = recipe("The vines at veraison, half the berries purple and half still green.").fields
    assert vines.stage == "Maturation"
    (tomatoes,) = recipe("a tomato plot, fruit still green").fields
    assert tomatoes.stage == "Reproductive"


def test_its_may_is_the_month() -> None:
    (pears,) = recipe(
        "omg durondeau pears sick w/ fire blight, shepherds crook tips n all, its may"
    ).fields
    assert (pears.season, pears.health) == ("Spring", "Ill")
