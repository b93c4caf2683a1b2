"""Every way a prompt or argument can fail: a clear AgrirecipeError subclass, never a guess."""

from __future__ import annotations

import pytest

from agrirecipe import (
    AgrirecipeError,
    ConfigurationError,
    PromptError,
    UnknownCropError,
)
from agrirecipe.recipe import MAX_PLANTS_PER_INSTANCE
from agrirecipe.resolve import resolve


@pytest.mark.parametrize("prompt", ["", "   ", "\n\t"])
def test_empty_prompt(prompt: str) -> None:
    with pytest.raises(PromptError, match="empty") as caught:
        resolve(prompt, resolver="rules")
    assert caught.value.hint and "apple orchard" in caught.value.hint


@pytest.mark.parametrize(
    ("prompt", "word"),
    [
        ("build a parking lot", "parking lot"),
        ("a city skyline at night", "city"),
        ("a sunny beach", "beach"),
        ("a forest of oak", "forest"),
    ],
)
def test_non_agricultural_prompt(prompt: str, word: str) -> None:
    with pytest.raises(PromptError, match="not an agricultural scene") as caught:
        resolve(prompt, resolver="rules")
    assert word in str(caught.value)
    assert not isinstance(caught.value, UnknownCropError)


def test_nothing_recognised() -> None:
    with pytest.raises(PromptError, match="no crop or field found") as caught:
        resolve("make it look nice please", resolver="rules")
    assert caught.value.stage == "resolve"


@pytest.mark.parametrize(
    ("prompt", "requested", "nearest"),
    [
        ("a mango plantation", "mango", {"Orange", "Banana"}),
        ("a field of barley", "barley", {"Wheat"}),
        ("olive trees in Spain", "olive", {"Orange"}),
        ("cucumbers next to tomatoes", "cucumbers", {"Tomato"}),
        ("spring onions", "spring onions", {"Onion"}),
    ],
)
def test_crops_we_do_not_hold(prompt: str, requested: str, nearest: set[str]) -> None:
    with pytest.raises(UnknownCropError) as caught:
        resolve(prompt, resolver="rules")
    error = caught.value
    assert error.requested == requested
    assert nearest <= set(error.nearest)
    assert "nearest known" in str(error)


@pytest.mark.parametrize(
    ("prompt", "crop", "word"),
    [
        ("gala and braeburn blocks, autumn", "Apple", "braeburn"),
        ("vineyard rows of merlot in september", "Grape", "merlot"),
        ("a field of maris piper potatoes", "Potato", "maris piper"),
        ("a Cabernet Franc vineyard", "Grape", "Cabernet Franc"),
    ],
)
def test_a_variety_the_hierarchy_does_not_hold(prompt: str, crop: str, word: str) -> None:
    with pytest.raises(
        UnknownCropError, match="variety the asset hierarchy does not hold"
    ) as caught:
        resolve(prompt, resolver="rules")
    assert caught.value.requested == word
    assert caught.value.hint and caught.value.hint.startswith(f"{crop} varieties: ")
    # the varieties it does hold are unaffected
    assert resolve("a Cabernet Sauvignon vineyard", resolver="rules").recipe.fields


def test_an_unknown_word_where_a_crop_belongs() -> None:
    with pytest.raises(UnknownCropError) as caught:
        resolve("a zorblax field", resolver="rules")
    assert caught.value.requested == "zorblax"
    assert caught.value.nearest  # by spelling when nothing better is known


def test_an_unknown_variety() -> None:
    with pytest.raises(UnknownCropError) as caught:
        resolve("a Honeycrisp apple orchard", resolver="rules")
    assert "Apple varieties" in str(caught.value)


def test_a_variety_of_another_crop() -> None:
    with pytest.raises(UnknownCropError, match="variety of Carrot"):
        resolve("Nantes apples", resolver="rules")


@pytest.mark.parametrize(
    ("prompt", "match"),
    [
        ("a healthy diseased orchard", "healthy and ill"),
        ("an apple orchard in summer and winter", "Summer and Winter"),
        ("young ripe carrots", "Maturation and Vegetative"),
        ("a 2 ha carrot field of 50 by 100 m", "two sizes"),
        ("an apple orchard in summer and a pear orchard, all in winter", "all fields"),
    ],
)
def test_contradictions(prompt: str, match: str) -> None:
    with pytest.raises(PromptError, match=match):
        resolve(prompt, resolver="rules")


@pytest.mark.parametrize(
    "prompt",
    [
        "a tomato field 3 cm by 3 cm",
        "a 0 ha orchard",
        "a carrot field of 0 by 10 m",
        "a 100000 ha apple orchard",
        "100 apple orchards",
    ],
)
def test_impossible_sizes_and_counts(prompt: str) -> None:
    with pytest.raises(PromptError):
        resolve(prompt, resolver="rules")


@pytest.mark.parametrize("strategy", ["rules", "hybrid"])
@pytest.mark.parametrize(
    ("prompt", "plot", "crop"),
    [
        ("a vineyard of cabbages", "a vineyard holds Grape", "Cabbage"),
        ("an orchard of carrots", "an orchard holds Apple, Pear, Cherry or Orange", "Carrot"),
        ("a carrot orchard", "an orchard holds", "Carrot"),
        ("a vineyard full of young tomatoes", "a vineyard holds Grape", "Tomato"),
        ("an orchard planted with wheat", "an orchard holds", "Wheat"),
        ("a cornfield of wheat", "a cornfield holds Maize", "Wheat"),
    ],
)
def test_a_plot_that_cannot_hold_the_crop(strategy: str, prompt: str, plot: str, crop: str) -> None:
    with pytest.raises(PromptError, match="contradiction") as caught:
        resolve(prompt, resolver=strategy)
    assert plot in str(caught.value) and f"{crop} is not grown in one" in str(caught.value)
    assert caught.value.hint and f"{crop.lower()} field" in caught.value.hint


@pytest.mark.parametrize(
    ("prompt", "crops"),
    [
        # the plot noun agrees, or only names the plants, or may mean a neighbour
        ("an orchard of Gala apples", ["Apple"]),
        ("a banana orchard", ["Banana"]),
        ("tomato vines in summer", ["Tomato"]),
        ("banana trees", ["Banana"]),
        ("an apple orchard with a carrot field", ["Apple", "Carrot"]),
        ("cabbages next to a vineyard", ["Cabbage", "Grape"]),
        # a correction takes the contradiction back
        ("a vineyard of cabbages? no, sorry, a vineyard of Riesling", ["Grape"]),
    ],
)
def test_plots_that_hold_their_crop(prompt: str, crops: list[str]) -> None:
    recipe = resolve(prompt, resolver="rules").recipe
    assert [f.crop for f in recipe.fields] == crops


@pytest.mark.parametrize(
    ("prompt", "crop", "count"),
    [
        ("three different fruit crops, all of them apples", "Apple", 3),
        ("three different vegetables, all carrots", "Carrot", 3),
        ("two different vegetable fields, both potatoes", "Potato", 2),
        ("three different fruit crops, two of them apples", "Apple", 2),
        ("two different fruits: apples and apples", "Apple", 2),
    ],
)
def test_different_crops_named_the_same(prompt: str, crop: str, count: int) -> None:
    with pytest.raises(PromptError, match=f"makes {count} of them {crop}") as caught:
        resolve(prompt, resolver="rules")
    assert caught.value.hint and "drop 'different'" in caught.value.hint


@pytest.mark.parametrize(
    "prompt",
    [
        "a lettuce field of -2 hectares",
        "a carrot field -50 by 100 m",
        "a potato field -100 m long",
        "a wheat field of minus 4 hectares",
    ],
)
def test_negative_sizes(prompt: str) -> None:
    with pytest.raises(PromptError, match=r"cannot measure '(-|minus )"):
        resolve(prompt, resolver="rules")
    # a dash between numbers or words is not a minus sign
    assert resolve("a carrot field, 2 ha - healthy", resolver="rules").recipe.fields


def test_freshly_sown_and_ready_for_harvest_is_a_contradiction() -> None:
    with pytest.raises(PromptError, match="both Maturation and Vegetative"):
        resolve("a wheat field that is freshly sown and ready for harvest", resolver="rules")


def test_a_count_that_the_list_after_it_exceeds() -> None:
    with pytest.raises(PromptError, match="announces 5 field"):
        resolve("five fields: 2 of maize and 4 of wheat", resolver="rules")
    with pytest.raises(PromptError, match="announces 2 field") as caught:
        resolve("two fields: sweetcorn, durum wheat and romaine lettuce", resolver="rules")
    assert caught.value.hint and "count" in caught.value.hint
    listed = resolve("three fields: russet potatoes, chantenay carrots and sturon onions")
    assert [f.crop for f in listed.recipe.fields] == ["Potato", "Carrot", "Onion"]


@pytest.mark.parametrize(
    "prompt",
    [
        "whats the weather in leuven tomorrow?",
        "whats up",
        "hi can you book me a train to ghent tomorrow morning",  # "train" is not "grain"
    ],
)
def test_everyday_words_are_not_typos_of_crops(prompt: str) -> None:
    with pytest.raises(PromptError):
        resolve(prompt, resolver="rules")


def test_the_plant_cap_is_a_setting() -> None:
    prompt = "winter wheat just emerging in autumn, 5 hectares"
    recipe = resolve(prompt, resolver="rules").recipe  # ~7.6 million plants
    assert 5_000_000 < recipe.nominal_plant_count <= 10_000_000
    assert recipe.fields[0].placement.plants_per_instance == 1
    # under a lower cap it is drawn thinner (every N-th plant, at most one in twenty) ...
    thinned = resolve(prompt, resolver="rules", max_plants=2_000_000).recipe
    assert thinned.fields[0].placement.plants_per_instance == 4
    # ... and refused where even one in twenty is too many
    with pytest.raises(PromptError, match="more than the cap of 250,000") as caught:
        resolve(prompt, resolver="rules", max_plants=250_000)
    assert caught.value.hint and "max_plants=N" in caught.value.hint
    big = resolve("a 10 ha wheat field", resolver="rules").recipe
    assert big.nominal_plant_count > 10_000_000
    assert big.fields[0].placement.plants_per_instance == 2
    drawn = resolve("a 10 ha wheat field", resolver="rules", max_plants=20_000_000).recipe
    assert drawn.fields[0].placement.plants_per_instance == 1
    # the error says how much of that field fits at its spacings, drawn one in twenty
    fits = float(str(caught.value).split("at most ")[1].split(" ha")[0])
    per_ha = recipe.nominal_plant_count / 5
    assert fits == pytest.approx(250_000 * MAX_PLANTS_PER_INSTANCE / per_ha, rel=0.02)


def test_impossible_relations() -> None:
    with pytest.raises(PromptError):
        resolve(
            "a wheat field north of an apple orchard, the apple orchard north of the wheat field",
            resolver="rules",
        )


@pytest.mark.parametrize(
    ("options", "match"),
    [
        ({"seed": -1}, "seed"),
        ({"seed": 1.5}, "seed"),
        ({"seed": True}, "seed"),
        ({"latitude_deg": 91.0}, "latitude"),
        ({"latitude_deg": float("nan")}, "latitude"),
        ({"resolver": "rulez"}, "did you mean 'rules'"),
        ({"resolver": 3}, "resolver"),
        ({"hierarchy": 3}, "hierarchy"),
        ({"knowledge": 3}, "knowledge"),
        ({"max_plants": 0}, "max_plants"),
        ({"max_plants": 2.5}, "max_plants"),
    ],
)
def test_bad_arguments(options: dict[str, object], match: str) -> None:
    with pytest.raises(ConfigurationError, match=match):
        resolve("an apple orchard", **options)  # type: ignore[arg-type]


def test_a_missing_hierarchy_file(tmp_path: object) -> None:
    with pytest.raises(AgrirecipeError, match="does not exist"):
        resolve("an apple orchard", resolver="rules", hierarchy="/nonexistent/hierarchy.yaml")


def test_latitude_in_the_prompt_must_be_on_earth() -> None:
    with pytest.raises(PromptError, match="not on Earth"):
        resolve("an apple orchard at latitude 123", resolver="rules")


@pytest.mark.parametrize(
    ("prompt", "word"),
    [
        ("a parking lot with trees", "parking lot"),
        ("a car park with some bushes", "car park"),
        ("a house with grass and flowers", "house"),
        ("a city full of plants", "city"),
        ("an airport surrounded by grass", "airport"),
        ("a road lined with trees", "road"),
    ],
)
def test_scenery_with_plants_in_general_is_not_a_crop_field(prompt: str, word: str) -> None:
    with pytest.raises(PromptError, match=word) as caught:
        resolve(prompt, resolver="rules")
    assert type(caught.value) is PromptError
    assert caught.value.hint and "crop fields" in caught.value.hint


@pytest.mark.parametrize(
    ("prompt", "crop"),
    [
        ("an apple orchard next to the road", "Apple"),
        ("a road between two wheat fields", "Wheat"),
        ("a parking lot next to a field of potatoes", "Potato"),
    ],
)
def test_crops_next_to_scenery_are_still_built(prompt: str, crop: str) -> None:
    recipe = resolve(prompt, resolver="rules").recipe
    assert {f.crop for f in recipe.fields} == {crop}
