"""Every validator rejects nonsense with a message that names the offending field path."""

from __future__ import annotations

import json
from collections.abc import Callable
from typing import Any

import pytest

from agrirecipe.recipe import FieldSpec, Relation, SceneRecipe, check_recipe_data, parse_recipe

Breaker = Callable[[dict[str, Any]], None]
FieldFactory = Callable[..., FieldSpec]
RecipeFactory = Callable[..., SceneRecipe]
DataOf = Callable[[SceneRecipe], dict[str, Any]]
ProblemsOf = Callable[..., dict[str, str]]


def _set(path: str, value: Any) -> Breaker:
    """A breaker that sets ``data[a][0][b]...`` given ``"a.0.b"``."""

    def breaker(data: dict[str, Any]) -> None:
        *parents, last = path.split(".")
        target: Any = data
        for part in parents:
            target = target[int(part)] if part.isdigit() else target[part]
        target[int(last) if last.isdigit() else last] = value

    return breaker


# (case id, breaker, expected problem path, fragment of the message)
SINGLE_FIELD_CASES: list[tuple[str, Breaker, str, str]] = [
    (
        "zero row spacing",
        _set("fields.0.agronomy.row_spacing_m", 0),
        "fields[0].agronomy.row_spacing_m",
        "greater than 0",
    ),
    (
        "negative in-row spacing",
        _set("fields.0.agronomy.in_row_spacing_m", -0.5),
        "fields[0].agronomy.in_row_spacing_m",
        "greater than 0",
    ),
    (
        "field smaller than one plant",
        _set("fields.0.geometry.size_m", [1.0, 1.0]),
        "fields[0].geometry.size_m",
        "too small for one Apple plant",
    ),
    (
        "headland eats the field",
        _set("fields.0.geometry.headland_m", 40.0),
        "fields[0].geometry.size_m",
        "40 m headland is too small",
    ),
    (
        "negative field size",
        _set("fields.0.geometry.size_m", [-60.0, 100.0]),
        "fields[0].geometry.size_m[0]",
        "greater than 0",
    ),
    (
        "hemisphere contradicts latitude",
        _set("environment.hemisphere", "south"),
        "environment.hemisphere",
        "contradicts latitude_deg 50.8",
    ),
    (
        "latitude beyond the pole",
        _set("environment.latitude_deg", 95.0),
        "environment.latitude_deg",
        "less than or equal to 90",
    ),
    (
        "two rows per bed without a bed row spacing",
        _set("fields.0.agronomy.rows_per_bed", 2),
        "fields[0].agronomy.bed_row_spacing_m",
        "must be positive when rows_per_bed > 1",
    ),
    (
        "bed row spacing on single rows",
        _set("fields.0.agronomy.bed_row_spacing_m", 0.3),
        "fields[0].agronomy.bed_row_spacing_m",
        "must be 0 when rows_per_bed is 1",
    ),
    (
        "plant taller than its maximum",
        _set("fields.0.agronomy.plant_height_m", 9.0),
        "fields[0].agronomy.plant_height_m",
        "exceeds max_height_m",
    ),
    (
        "stated and inferred at once",
        _set("fields.0.stated", ["crop", "stage"]),
        "fields[0].stated",
        "['stage'] cannot be both stated and inferred",
    ),
    (
        "asset path of another variety",
        _set("fields.0.variety", "Gala"),
        "fields[0].asset_path",
        "expected '/Game/Agriculture/Fruits/Apple/Gala/Reproductive/Summer/Healthy/",
    ),
    (
        "asset path without an object name",
        _set("fields.0.asset_path", "/Game/Agriculture/SM_Apple"),
        "fields[0].asset_path",
        "is not an Unreal object path",
    ),
    (
        "unknown variety",
        _set("fields.0.variety", "Honeycrisp"),
        "fields[0].variety",
        "'Honeycrisp' is not a variety of Apple",
    ),
    (
        "unknown crop names the nearest",
        _set("fields.0.crop", "Aple"),
        "fields[0].crop",
        "nearest: Apple",
    ),
    (
        "category of another crop",
        _set("fields.0.category", "Cereals"),
        "fields[0].category",
        "'Cereals' does not match crop Apple",
    ),
    ("unknown stage", _set("fields.0.stage", "Flowering"), "fields[0].stage", "'Vegetative'"),
    ("unsafe field id", _set("fields.0.id", "Apples 1"), "fields[0].id", "pattern"),
    ("unknown key", _set("fields.0.colour", "red"), "fields[0].colour", "Extra inputs"),
    ("no fields", _set("fields", []), "fields", "at least 1 item"),
    (
        "unknown schema version",
        _set("schema_version", "0.9"),
        "schema_version",
        "'1.0'",
    ),
]


@pytest.mark.parametrize(
    ("breaker", "path", "fragment"),
    [case[1:] for case in SINGLE_FIELD_CASES],
    ids=[case[0] for case in SINGLE_FIELD_CASES],
)
def test_rejection_names_the_field_path(
    make_recipe: RecipeFactory,
    breaker: Breaker,
    path: str,
    fragment: str,
    recipe_data: DataOf,
    problems_of: ProblemsOf,
) -> None:
    data = recipe_data(make_recipe())
    breaker(data)
    problems = problems_of(data)
    assert path in problems, problems
    assert fragment in problems[path]


def test_unknown_variety_is_not_also_reported_as_a_path_mismatch(
    make_recipe: RecipeFactory, recipe_data: DataOf, problems_of: ProblemsOf
) -> None:
    data = recipe_data(make_recipe())
    data["fields"][0]["variety"] = "Honeycrisp"
    assert list(problems_of(data)) == ["fields[0].variety"]


def test_plant_cap_is_configurable(
    make_recipe: RecipeFactory, recipe_data: DataOf, problems_of: ProblemsOf
) -> None:
    recipe = make_recipe()
    assert recipe.nominal_plant_count == 1335  # 15 rows x 89 trees (60 x 100 m, 6 m headland)
    data = recipe_data(recipe)
    problems = problems_of(data, max_plants=1000)
    assert "cap of 1,000" in problems["fields[0].geometry.size_m"]
    assert "1,335 plants" in problems["fields[0].geometry.size_m"]
    parse_recipe(json.dumps(data), max_plants=1335)  # exactly at the cap is fine


def test_plant_cap_names_the_field_that_crosses_it(
    two_orchards: SceneRecipe,
    recipe_data: DataOf,
    problems_of: ProblemsOf,
) -> None:
    problems = problems_of(recipe_data(two_orchards), max_plants=2000)
    assert list(problems) == ["fields[1].geometry.size_m"]
    assert "by field 'b'" in problems["fields[1].geometry.size_m"]


def test_overlapping_fields(
    two_orchards: SceneRecipe,
    recipe_data: DataOf,
    problems_of: ProblemsOf,
) -> None:
    data = recipe_data(two_orchards)
    data["fields"][1]["geometry"]["origin_m"] = [59.0, 10.0]
    problems = problems_of(data)
    assert "field 'b' overlaps field 'a'" in problems["fields[1].geometry"]


def test_rotated_fields_overlap_by_their_corners(
    make_field: FieldFactory, make_recipe: RecipeFactory
) -> None:
    # 'b' starts 5 m east of 'a' but is turned 90 degrees counter-clockwise, so
    # it extends west across 'a'.
    a = make_field("a")
    b = make_field("b", origin_m=(65.0, 0.0), rotation_deg=90.0)
    with pytest.raises(ValueError, match=r"fields\[1\]\.geometry: field .b. overlaps field .a."):
        make_recipe(a, b)


def test_fields_sharing_an_edge_do_not_overlap(
    make_field: FieldFactory, make_recipe: RecipeFactory
) -> None:
    recipe = make_recipe(make_field("a"), make_field("b", origin_m=(60.0, 0.0)))
    assert [f.id for f in recipe.fields] == ["a", "b"]


def test_duplicate_field_ids(
    two_orchards: SceneRecipe,
    recipe_data: DataOf,
    problems_of: ProblemsOf,
) -> None:
    data = recipe_data(two_orchards)
    data["fields"][1]["id"] = "a"
    assert "duplicate field id 'a'" in problems_of(data)["fields[1].id"]


@pytest.mark.parametrize(
    ("relation", "path", "fragment"),
    [
        (
            {"kind": "north_of", "subject": "a", "objects": ["c"]},
            "relations[0]",
            "unknown field id 'c'",
        ),
        ({"kind": "between", "subject": "a", "objects": ["b"]}, "relations[0].objects", "takes 2"),
        ({"kind": "next_to", "subject": "a", "objects": ["a"]}, "relations[0].objects", "itself"),
        ({"kind": "above", "subject": "a", "objects": ["b"]}, "relations[0].kind", "'north_of'"),
    ],
    ids=["unknown id", "between needs two", "self relation", "unknown kind"],
)
def test_bad_relations(
    make_field: FieldFactory,
    make_recipe: RecipeFactory,
    relation: dict[str, Any],
    path: str,
    fragment: str,
    recipe_data: DataOf,
    problems_of: ProblemsOf,
) -> None:
    recipe = make_recipe(
        make_field("a"),
        make_field("b", origin_m=(70.0, 0.0)),
        relations=[Relation(kind="east_of", subject="b", objects=("a",))],
    )
    data = recipe_data(recipe)
    data["relations"][0] = relation
    problems = problems_of(data)
    assert path in problems, problems
    assert fragment in problems[path]


def test_every_problem_is_reported_once_in_document_order(
    make_field: FieldFactory,
    make_recipe: RecipeFactory,
    recipe_data: DataOf,
    problems_of: ProblemsOf,
) -> None:
    fields = [
        make_field(
            f"f{i}",
            crop="Lettuce",
            variety="Iceberg",
            origin_m=(i * 20.0, 0.0),
            size_m=(20.0, 20.0),
        )
        for i in range(11)
    ]
    data = recipe_data(make_recipe(*fields))
    data["fields"][10]["agronomy"]["in_row_spacing_m"] = 0
    data["fields"][2]["agronomy"]["row_spacing_m"] = -1
    data["environment"]["hemisphere"] = "south"
    data["seed"] = -3
    problems = problems_of(data)
    # The JSON Schema and the models both reject these; each is listed once.
    assert list(problems) == [
        "environment.hemisphere",
        "fields[2].agronomy.row_spacing_m",
        "fields[10].agronomy.in_row_spacing_m",
        "seed",
    ]


def test_schema_catches_what_lax_parsing_would_coerce(
    make_recipe: RecipeFactory, recipe_data: DataOf
) -> None:
    data = recipe_data(make_recipe())
    data["seed"] = "3"  # pydantic would quietly read 3; a recipe file must hold a number
    recipe, problems = check_recipe_data(data)
    assert recipe is None
    assert problems == [("seed", "'3' is not of type 'integer'")]


def test_a_valid_recipe_has_no_problems(make_recipe: RecipeFactory, recipe_data: DataOf) -> None:
    recipe = make_recipe()
    parsed, problems = check_recipe_data(recipe_data(recipe))
    assert problems == []
    assert parsed == recipe


def test_unknown_field_lookup_lists_the_fields(make_recipe: RecipeFactory) -> None:
    from agrirecipe import RecipeValidationError

    recipe: SceneRecipe = make_recipe()
    assert recipe.field("apples").crop == "Apple"
    with pytest.raises(RecipeValidationError, match="no field 'pears'") as caught:
        recipe.field("pears")
    assert caught.value.hint == "fields: apples"
