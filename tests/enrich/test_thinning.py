"""Dense fields thinned to fit the plant cap (issue 8): a whole drilled field is built,
every N-th plant drawn, each standing for N, rather than refused."""

from __future__ import annotations

import json

import numpy as np
import pytest

from agrirecipe import PromptError, generate
from agrirecipe.enrich import DENSE_PLANTS_PER_HA
from agrirecipe.layout import field_parameters, place_field, place_field_array
from agrirecipe.recipe import DEFAULT_MAX_PLANTS, MAX_PLANTS_PER_INSTANCE, SceneRecipe


def test_a_twenty_hectare_wheat_field_is_built_thinned() -> None:
    scene = generate(
        "Half the farm, 20 ha, is wheat; the other 20 ha half is potatoes.", resolver="hybrid"
    ).recipe
    wheat, potatoes = scene.fields
    assert wheat.geometry.area_m2 == pytest.approx(200_000, rel=0.01)
    stride = wheat.placement.plants_per_instance
    assert 1 < stride <= MAX_PLANTS_PER_INSTANCE
    # the fewest plants drawn that fit: one stride less would not
    drawn = sum(f.drawn_plant_count() for f in scene.fields)
    assert drawn <= DEFAULT_MAX_PLANTS
    assert wheat.drawn_plant_count(stride - 1) + potatoes.drawn_plant_count() > DEFAULT_MAX_PLANTS
    # the agronomy keeps every plant; the potatoes (40,000 per ha) are drawn whole
    assert wheat.nominal_plant_count > DEFAULT_MAX_PLANTS
    assert wheat.drawn_plant_count() == pytest.approx(wheat.nominal_plant_count / stride, rel=0.01)
    assert potatoes.placement.plants_per_instance == 1
    (warning,) = [w for w in scene.warnings if w.startswith(wheat.id)]
    assert f"each standing for {stride}" in warning and "max_plants" in warning


def test_a_thinned_field_draws_every_nth_plant_along_its_rows() -> None:
    generated = generate("a half hectare wheat field", resolver="hybrid", max_plants=300_000)
    (wheat,) = generated.recipe.fields
    stride = wheat.placement.plants_per_instance
    assert stride == 3  # about 780,000 plants: every third fits 300,000
    params = field_parameters(generated.recipe)[0]
    assert params["plants_per_instance"] == stride
    assert params["in_row_spacing_m"] == pytest.approx(wheat.agronomy.in_row_spacing_m * stride)
    plants = place_field(dict(params, missing_rate=0.0))
    assert len(plants) == wheat.drawn_plant_count()
    # the vectorised kernel (plants.csv) draws exactly the engines' positions
    xyz, _, _, _ = place_field_array(params)
    assert np.allclose(xyz, np.array([p[:3] for p in place_field(params)]))
    # each drawn plant stands for the stride's plants, in the layout and its annotations
    layout = generated.layout.field(wheat.id)
    assert layout.plants_per_instance == stride
    assert layout.attributes()["plants_per_instance"] == stride
    assert layout.nominal_plant_count == wheat.drawn_plant_count()


def test_orchards_and_sparse_fields_are_never_thinned() -> None:
    with pytest.raises(PromptError, match="cap of 2,000"):
        generate("a 5 ha apple orchard", resolver="hybrid", max_plants=2_000)
    scene = generate(
        "a 2 ha apple orchard next to a half hectare wheat field",
        resolver="hybrid",
        max_plants=400_000,
    ).recipe
    apples, wheat = scene.fields
    assert apples.placement.plants_per_instance == 1
    assert apples.nominal_plant_count / 2 < DENSE_PLANTS_PER_HA
    assert wheat.placement.plants_per_instance > 1


def test_a_forty_hectare_cereal_farm_is_built_one_plant_in_seven() -> None:
    scene = generate(
        "Our land: 40 ha of cereals, 10 ha of vegetables and a 2 ha orchard.", resolver="hybrid"
    ).recipe
    cereal, _vegetables, orchard = scene.fields
    assert cereal.geometry.area_m2 == pytest.approx(400_000, rel=0.01)
    assert cereal.placement.plants_per_instance == 7
    assert sum(f.drawn_plant_count() for f in scene.fields) <= DEFAULT_MAX_PLANTS
    assert orchard.placement.plants_per_instance == 1
    (warning,) = [w for w in scene.warnings if w.startswith(cereal.id)]
    assert "every seventh plant along each row is drawn" in warning


def test_an_eighty_hectare_wheat_field_is_built_one_plant_in_thirteen() -> None:
    scene = generate(
        "The whole farm is one 80 hectare wheat field, with a hawthorn hedge round the outside "
        "and a pylon in the middle.",
        resolver="hybrid",
    ).recipe
    (wheat,) = scene.fields
    assert wheat.geometry.area_m2 == pytest.approx(800_000, rel=0.01)
    assert wheat.placement.plants_per_instance == 13
    assert wheat.drawn_plant_count() <= DEFAULT_MAX_PLANTS < wheat.drawn_plant_count(12)


def test_a_field_too_big_even_thinned_is_refused_saying_how_much_fits() -> None:
    with pytest.raises(PromptError) as caught:
        generate("a 160 ha wheat field", resolver="hybrid")
    message = str(caught.value)
    assert "cap of 10,000,000" in message
    assert f"every {MAX_PLANTS_PER_INSTANCE} plants drawn as one" in message
    fits = float(message.split("at most ")[1].split(" ha")[0])
    assert 100 < fits < 160
    assert caught.value.hint is not None and "max_plants=N" in caught.value.hint


def test_a_thinned_recipe_round_trips_and_is_checked_against_the_cap() -> None:
    recipe = generate("a half hectare wheat field", resolver="hybrid", max_plants=300_000).recipe
    data = json.loads(recipe.model_dump_json())
    assert data["fields"][0]["placement"]["plants_per_instance"] == 3
    again = SceneRecipe.model_validate(data, context={"max_plants": 300_000})
    assert again == recipe
    # a recipe file that draws every plant of it is over that cap
    data["fields"][0]["placement"]["plants_per_instance"] = 1
    with pytest.raises(ValueError, match="cap of 300,000"):
        SceneRecipe.model_validate(data, context={"max_plants": 300_000})
    data["fields"][0]["placement"]["plants_per_instance"] = MAX_PLANTS_PER_INSTANCE + 1
    with pytest.raises(ValueError, match="plants_per_instance"):
        SceneRecipe.model_validate(data)
