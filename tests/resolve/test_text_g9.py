"""Text of blind set g9 (issue 8): the field a crop is "in" said after it, tunnels a
list of crops is grown in, shades named by a crop ("olive green"), ripening and damage
seen on a part of the plant, thousands written "70k", plots named by the number said for
them, "the first ... north of the second", "a 120-tree orchard", counted crop beds and
words of a request ("digital twin", "arable plots")."""

from __future__ import annotations

import itertools

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


@pytest.mark.parametrize(
    "prompt",
    [
        "Bibb lettuce transplants just planted in early May, little rosettes on white plastic "
        "mulch, in a field bordered by a drainage ditch and a barbed-wire fence.",
        "Golden Acre cabbages in my photo, round and pale green and clearly harvest-ready, in "
        "a field with an old stone wall.",
    ],
)
def test_the_field_a_crop_is_in_is_no_other_field(prompt: str) -> None:
    assert len(recipe(prompt).fields) == 1


def test_another_field_placed_with_in_is_still_a_field() -> None:
    assert [f.crop for f in recipe("wheat, and in a field next to it, maize").fields] == [
        "Wheat",
        "Maize",
    ]


@pytest.mark.parametrize(
    ("prompt", "count"),
    [
        (
            "plum tomatoes and California Wonder peppers in two long tunnels side by side, "
            "fans running and a hosepipe across the floor",
            2,
        ),
        (
            "Tomatoes and peppers just transplanted into two fields side by side, with a "
            "planting machine and three people on it at the far end.",
            2,
        ),
        (
            "Strawberries under the two tunnels - Elsanta in one and Malling Centenary in the "
            "other, both loaded with ripe fruit.",
            2,
        ),
    ],
)
def test_plots_and_tunnels_a_list_is_grown_in(prompt: str, count: int) -> None:
    assert len(recipe(prompt).fields) == count


@pytest.mark.parametrize(
    ("prompt", "stage", "health"),
    [
        (
            "pic of the Golden Delicious trees by the road - fruit nearly ready, and the leaves "
            "have olive green blotches.",
            None,
            "Ill",
        ),
        (
            "the huge banana leaves are streaked with dark brown-black stripes and lots of "
            "them have gone ragged and dry at the edges.",
            None,
            "Ill",
        ),
        (
            "a bed of San Marzano tomatoes just starting to turn red. Rusty watering can and "
            "compost heap in the corner.",
            "Maturation",
            "Healthy",
        ),
        (
            "Cayenne pepper plants, long thin chillies hanging in clusters and most of them "
            "already bright red.",
            "Maturation",
            "Healthy",
        ),
        (
            "chantenay carrots in mid October, tops still green but the roots we pulled are "
            "full size and ready for lifting",
            "Maturation",
            "Healthy",
        ),
    ],
)
def test_looks_of_the_plants(prompt: str, stage: str | None, health: str) -> None:
    (field,) = recipe(prompt).fields
    assert field.health == health
    if stage is not None:
        assert field.stage == stage


def test_a_field_named_by_its_density_in_thousands() -> None:
    north, south = recipe(
        "two maize plots of 12 rows x 40 m, 75 cm rows, one sown at 70,000 plants/ha and one "
        "at 95,000 plants/ha; the 70k plot lies north of the 95k plot."
    ).fields
    scene = recipe(
        "two maize plots of 12 rows x 40 m, 75 cm rows, one sown at 70,000 plants/ha and one "
        "at 95,000 plants/ha; the 95k plot lies north of the 70k plot."
    )
    assert north.plants_per_ha < south.plants_per_ha
    (relation,) = scene.relations
    assert (relation.kind, relation.subject, relation.objects) == (
        "north_of",
        scene.fields[1].id,
        (scene.fields[0].id,),
    )


@pytest.mark.parametrize(
    ("said", "subject"),
    [("plot 1 north of plot 2", 0), ("the second is north of the first", 1)],
)
def test_ordinal_members_in_a_relation(said: str, subject: int) -> None:
    scene = recipe(f"two maize plots, plot 1 at 70,000 plants/ha, plot 2 at 100,000; {said}.")
    (relation,) = scene.relations
    assert relation.subject == scene.fields[subject].id
    assert relation.objects == (scene.fields[1 - subject].id,)


def test_a_count_of_trees_before_its_orchard() -> None:
    _, cherries = recipe(
        "A 0.6 ha strawberry field on 1.5 m beds, directly south of a 120-tree cherry orchard."
    ).fields
    assert cherries.nominal_plant_count == 120


def test_counted_crop_beds_and_a_digital_twin() -> None:
    scene = recipe(
        "Market-garden digital twin: 10 strawberry beds (1.5 m centres, 2 rows per bed) south "
        "of a 12-row lettuce block at 35 cm row spacing. Rows 30 m long in both."
    )
    assert [(f.crop, f.bed_count) for f in scene.fields] == [("Strawberry", 10), ("Lettuce", 12)]


def test_arable_plots_are_plots() -> None:
    scene = recipe(
        "Two arable plots for the GNSS guidance trial: a 2 ha maize field, and east of it a "
        "3 ha wheat field."
    )
    assert [f.crop for f in scene.fields] == ["Maize", "Wheat"]


def test_a_category_naming_a_site_is_no_field_and_a_plural_crop_is_all_its_blocks() -> None:
    scene = recipe(
        "Fruit research station digital twin, three blocks north to south: Comice pears, "
        "Durondeau pears, Sweetheart Lapins cherries. Pears planted 3.5 m x 1 m, cherries "
        "4.6 m x 2.4 m; each block 0.4 ha."
    )
    assert [(f.variety, f.agronomy.row_spacing_m) for f in scene.fields] == [
        ("Doyenne du Comice", 3.5),
        ("Durondeau", 3.5),
        ("Lapins", 4.6),
    ]
    assert all(round(f.geometry.area_m2) == 4000 for f in scene.fields)


def test_a_block_said_after_the_measures_of_its_crop() -> None:
    (field,) = recipe(
        "Lady Finger bananas on our Queensland test farm: 3 m x 3 m grid, 1,111 plants/ha, a "
        "90 x 60 m block, filmed in July for a drone obstacle dataset."
    ).fields
    assert field.geometry.size_m == (90.0, 60.0)


@pytest.mark.parametrize(
    ("prompt", "count"),
    [
        ("a lil orchard & a veg patch in front of the barn", 2),
        ("a few diff fruits, like 4 fields, all summer", 4),
        ("pls generate an orchard, just an orchard, idc what trees", 1),
        ("some veggies idk maybe 2 or 3 fields", 2),
    ],
)
def test_casual_counts_said_again(prompt: str, count: int) -> None:
    assert len(recipe(prompt).fields) == count


def test_members_with_a_size_each_and_no_comma() -> None:
    scene = recipe("2 blocks of gala, one 40x60m one 30x60m")
    assert [f.geometry.size_m for f in scene.fields] == [(40.0, 60.0), (30.0, 60.0)]


@pytest.mark.parametrize(
    "prompt",
    [
        "lettuce (cos) in between carrots (nantes) & cabbage (savoy) pls",
        "california wonder peppers in the middle, cayenne on one side, padron on the other",
    ],
)
def test_the_middle_one_between_the_two_named_with_it(prompt: str) -> None:
    scene = recipe(prompt)
    first, second, third = (f.id for f in scene.fields)
    assert [(r.kind, r.subject, r.objects) for r in scene.relations] == [
        ("between", first, (second, third))
    ]


def test_rows_in_a_line_north_to_south_in_short() -> None:
    scene = recipe("red express, january king & savoy cabbages, 3 plots in a line n to s")
    first, second, third = (f.id for f in scene.fields)
    kinds = {(r.kind, r.subject, r.objects) for r in scene.relations}
    assert ("north_of", first, (second,)) in kinds
    assert ("north_of", second, (third,)) in kinds


def test_a_label_without_a_mark_among_labels_with_one() -> None:
    scene = recipe(
        "Plot 1 is Gala apples in full bloom, plot 2 Kordia cherries also blossoming, and plot "
        "3 is Elsanta strawberries we only just planted. It's mid-April."
    )
    assert [f.variety for f in scene.fields] == ["Gala", "Kordia", "Elsanta"]


def test_a_category_plot_and_a_field_of_another_category_placed_against_it() -> None:
    scene = recipe("Vegetable garden east of the farmhouse, fruit on the west side of it.")
    garden, fruit = scene.fields
    (relation,) = scene.relations
    # (the fruit west of the garden, said either way round: "it" is the farmhouse or the
    # garden, and both put the fruit on the garden's west)
    assert (relation.kind, relation.subject, relation.objects) in (
        ("west_of", fruit.id, (garden.id,)),
        ("east_of", garden.id, (fruit.id,)),
    )


@pytest.mark.parametrize(
    ("prompt", "stage", "season"),
    [
        (
            "It's October and we're lifting the Imperator carrots, sown back in April; the crop "
            "is clean.",
            "Maturation",
            "Fall",
        ),
        (
            "just the one feild this year, jalapenos, planted out last week, its june now and "
            "they look healthy",
            "Vegetative",
            "Summer",
        ),
    ],
)
def test_what_is_being_done_says_the_stage(prompt: str, stage: str, season: str) -> None:
    (field,) = recipe(prompt).fields
    assert (field.stage, field.season) == (stage, season)


@pytest.mark.parametrize(
    ("prompt", "kind", "subject", "obj"),
    [
        (
            "North of the packing shed is the Doyenné du Comice block; south of the shed we "
            "have the Williams' Bon Chrétien pears.",
            "north_of",
            0,
            1,
        ),
        (
            "Valencia Late oranges on the flat ground, with Gros Michel bananas along the "
            "stream to the east of them.",
            "east_of",
            1,
            0,
        ),
        (
            "Our estate in Chile: Cabernet on the western slopes, Chardonnay on the eastern "
            "ones, bunches ripening on both.",
            "west_of",
            0,
            1,
        ),
    ],
)
def test_placed_by_landmarks_and_slopes(prompt: str, kind: str, subject: int, obj: int) -> None:
    scene = recipe(prompt)
    ids = [f.id for f in scene.fields]
    assert (kind, ids[subject], (ids[obj],)) in {
        (r.kind, r.subject, r.objects) for r in scene.relations
    }


def test_a_row_of_fields_going_southwards() -> None:
    scene = recipe(
        "Going from the north boundary southwards it's vines, then apples, then peppers, and "
        "finally tomatoes."
    )
    ids = [f.id for f in scene.fields]
    relations = {(r.kind, r.subject, r.objects) for r in scene.relations}
    assert {("north_of", a, (b,)) for a, b in itertools.pairwise(ids)} <= relations


@pytest.mark.parametrize(
    ("prompt", "bearing"),
    [
        ("Hamlin oranges, 22 ft between rows, rows running 15 degrees west of north", 165.0),
        ("Nantes carrots, 24 ridges at 75 cm with two rows per ridge, ridges NE-SW", 45.0),
    ],
)
def test_row_directions_west_of_north_and_of_ridges(prompt: str, bearing: float) -> None:
    (field,) = recipe(prompt).fields
    assert field.row_bearing_deg == pytest.approx(bearing)


def test_the_same_layout_is_the_whole_planting() -> None:
    albion, sonata = recipe(
        "Albion strawberries on 60-inch beds, 2 rows per bed, plants 12 in apart, 6 beds of "
        "200-ft rows, and the same layout of Sonata right north of them."
    ).fields
    assert (sonata.bed_count, sonata.row_length_m) == (albion.bed_count, albion.row_length_m)
    assert sonata.bed_count == 6


def test_rows_said_before_a_sentence_for_every_field_stay_with_their_field() -> None:
    cabbage, lettuce = recipe(
        "Leafy-veg robot course - Red Express cabbage on 0.6 m x 0.35 m, 14 rows, next to Cos "
        "lettuce on 0.35 m x 0.3 m, 20 rows; all rows 40 m."
    ).fields
    assert (cabbage.row_count, lettuce.row_count) == (14, 20)


def test_a_member_placed_against_it() -> None:
    scene = recipe(
        "Two arable plots for the GNSS guidance trial: a 2 ha maize field with 75 cm rows "
        "running north-south, and east of it a 3 ha wheat field drilled in 12.5 cm rows."
    )
    maize, wheat = (f.id for f in scene.fields)
    assert [(r.kind, r.subject, r.objects) for r in scene.relations] == [
        ("east_of", wheat, (maize,))
    ]
