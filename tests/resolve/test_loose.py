"""Words of clauses that name no field, given to their fields (resolve/_loose.py)."""

from __future__ import annotations

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def test_opening_words_about_the_season_are_the_scene_s() -> None:
    fields = recipe("In autumn, Gala apples and Conference pears").fields
    assert [f.season for f in fields] == ["Fall", "Fall"]


def test_each_after_a_list_is_said_of_every_member() -> None:
    fields = recipe("field corn, flint corn and popping corn, 8 rows each at 76 cm").fields
    assert [f.agronomy.row_spacing_m for f in fields] == [0.76, 0.76, 0.76]
    assert all("rows" in f.stated for f in fields)


def test_a_relative_clause_is_about_the_field_named_last() -> None:
    tomatoes, peppers = recipe(
        "Beefsteak tomatoes with big fruit still green, and behind them Padrón peppers whose "
        "fruit has raised scabby spots."
    ).fields
    assert (tomatoes.health, peppers.health) == ("Healthy", "Ill")


def test_a_description_goes_on_for_the_field_it_is_about() -> None:
    cavendish, ladyfinger = recipe(
        "Dwarf Cavendish up front, and the Ladyfinger block next to them has yellowing, mottled "
        "leaves and some plants wilting."
    ).fields
    assert (cavendish.health, ladyfinger.health) == ("Healthy", "Ill")


def test_words_about_every_field_are_the_scene_s() -> None:
    fields = recipe("wheat, maize and potatoes, blight everywhere").fields
    assert [f.health for f in fields] == ["Ill", "Ill", "Ill"]
