"""Looks said in turn of fields named one by one (resolve/_in_turn.py)."""

from __future__ import annotations

from agrirecipe import generate


def test_each_field_named_takes_its_ones_look_in_order() -> None:
    fields = generate("potatoes, carrots and onions, one with blight, one bolting, one fine")
    assert [(f.crop, f.health) for f in fields.recipe.fields] == [
        ("Potato", "Ill"),
        ("Carrot", "Healthy"),
        ("Onion", "Healthy"),
    ]
    assert fields.recipe.fields[1].stage == "Reproductive"


def test_a_count_said_again_between_them() -> None:
    first, second = generate(
        "tbh just wheat & more wheat, 2 fields, 1 sick 1 healthy"
    ).recipe.fields
    assert (first.crop, second.crop) == ("Wheat", "Wheat")
    assert (first.health, second.health) == ("Ill", "Healthy")


def test_not_when_the_ones_and_the_fields_differ_in_number() -> None:
    # two "one"s for three fields: not said in turn (the first look is every field's)
    healths = [
        f.health
        for f in generate("potatoes, carrots and onions, one with blight, one fine").recipe.fields
    ]
    assert healths != ["Ill", "Healthy", "Healthy"]


def test_sizes_said_in_turn_after_two_fields() -> None:
    tomatoes, chillies = generate(
        "roma toms north of cayenne chillies, 20x40m and 30x50m"
    ).recipe.fields
    assert tomatoes.geometry.size_m == (20.0, 40.0)
    assert chillies.geometry.size_m == (30.0, 50.0)
