"""Editing a scene by words: only what the instruction touches changes."""

from __future__ import annotations

import functools

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from agrirecipe import PromptError, Scene, generate
from agrirecipe.edit import diff_recipes, edit_recipe
from agrirecipe.layout import layout_scene
from agrirecipe.recipe import SceneRecipe


@functools.cache
def scene(prompt: str) -> Scene:
    return generate(prompt, resolver="rules")


PEARS = "a Conference pear orchard next to Nantes carrots and a wheat field, in summer"


def test_make_the_pears_ill_changes_only_their_health() -> None:
    before = scene(PEARS)
    after = before.edit("make the pears ill")
    pears = after.recipe.field("pear_orchard_1")
    assert pears.health == "Ill" and "health" in pears.stated
    assert pears.agronomy.disease is not None
    assert after.changes == ("~ pear_orchard_1: health Healthy -> Ill",)
    assert after.recipe.fields[1:] == before.recipe.fields[1:]
    assert after.recipe.relations == before.recipe.relations


def test_remove_the_carrots_drops_the_field_and_its_relations() -> None:
    before = scene(PEARS)
    after = edit_recipe(before.recipe, "remove the carrots")
    assert [f.id for f in after.recipe.fields] == ["pear_orchard_1", "wheat_field_1"]
    assert all("carrot_field_1" not in (r.subject, *r.objects) for r in after.recipe.relations)
    assert after.touched == ("carrot_field_1",)
    assert after.changes[0].startswith("- carrot_field_1 (Nantes carrot field)")


def test_add_a_field_south_of_the_orchard() -> None:
    before = scene(PEARS)
    after = edit_recipe(before.recipe, "add a maize field south of the orchard")
    maize = after.recipe.fields[-1]
    pears = after.recipe.field("pear_orchard_1")
    assert maize.crop == "Maize" and maize.season == "Summer"
    assert "season" in maize.inferred  # taken from the scene, not said
    top_of_maize = max(y for _, y in maize.geometry.corners_m())
    assert top_of_maize <= min(y for _, y in pears.geometry.corners_m())
    kinds = {(r.kind, r.subject, r.objects) for r in after.recipe.relations}
    assert ("south_of", maize.id, ("pear_orchard_1",)) in kinds
    assert after.recipe.fields[:3] == before.recipe.fields
    assert after.touched == (maize.id,)


def test_an_added_field_of_a_crop_already_there_gets_a_new_id_and_label() -> None:
    before = scene("a Nantes carrot field")
    after = edit_recipe(before.recipe, "add a Nantes carrot field next to it")
    ids = [f.id for f in after.recipe.fields]
    labels = [f.label for f in after.recipe.fields]
    assert ids == ["carrot_field_1", "carrot_field_2"]
    assert len(set(labels)) == 2


def test_rows_50_cm_apart_in_a_one_field_scene() -> None:
    before = scene("10 rows of maize, 80 m long, 76 cm apart")
    after = before.edit("rows 50 cm apart")
    maize = after.recipe.fields[0]
    assert maize.agronomy.row_spacing_m == pytest.approx(0.5)
    assert "row_spacing" in maize.stated
    assert maize.geometry.origin_m == before.recipe.fields[0].geometry.origin_m
    assert any("row spacing 0.76 -> 0.5 m" in line for line in after.changes)


def test_a_new_season_moves_inferred_stages_and_the_sun() -> None:
    before = scene(PEARS)
    after = before.edit("make it winter")
    assert {f.season for f in after.recipe.fields} == {"Winter"}
    assert after.recipe.environment.season == "Winter"
    assert after.recipe.environment.sun != before.recipe.environment.sun
    assert after.recipe.field("pear_orchard_1").stage != "Reproductive"


def test_a_variety_change_relabels_the_field() -> None:
    after = scene(PEARS).edit("make the pears Comice")
    pears = after.recipe.field("pear_orchard_1")
    assert pears.variety == "Doyenne du Comice"
    assert pears.label == "Doyenne du Comice pear orchard"


def test_a_field_named_by_id() -> None:
    after = scene(PEARS).edit("set carrot_field_1 to autumn")
    assert after.recipe.field("carrot_field_1").season == "Fall"
    assert after.recipe.field("pear_orchard_1").season == "Summer"


@pytest.mark.parametrize(
    ("instruction", "message"),
    [
        ("make it ill", "does not say which field"),
        ("rows 50 cm apart", "does not say which field"),
        ("make the apples ill", "no apple field"),
        ("remove the vineyard", "no"),
        ("remove everything", "every field"),
        ("", "empty"),
        ("make the pears", "changes nothing"),
        ("replace the apples with potatoes", "no apple field"),
        ("add a wheat field between the pears and the carrots", "between"),
    ],
)
def test_instructions_that_cannot_be_applied_say_why(instruction: str, message: str) -> None:
    before = scene(PEARS)
    with pytest.raises(PromptError) as caught:
        edit_recipe(before.recipe, instruction)
    assert message in str(caught.value)
    assert caught.value.stage == "edit"


def test_an_ambiguous_instruction_lists_the_fields() -> None:
    with pytest.raises(PromptError) as caught:
        scene(PEARS).edit("make it ill")
    hint = caught.value.hint or ""
    assert all(name in hint for name in ("pear_orchard_1", "carrot_field_1", "wheat_field_1"))


def test_a_size_that_would_overlap_a_neighbour_is_refused() -> None:
    before = scene("a Nantes carrot field north of a wheat field")
    with pytest.raises(PromptError, match="overlaps"):
        before.edit("the wheat field 50 ha")


def test_diff_of_equal_recipes_is_empty() -> None:
    recipe = scene(PEARS).recipe
    assert diff_recipes(recipe, recipe) == ()


# Every edit, whatever it touches, leaves the other fields and their plants as they were.
_SCENES = (
    PEARS,
    "a Pink Lady apple orchard north of a vineyard, with a lettuce field east of the vineyard",
    "two carrot fields and a potato field in autumn",
    "a small strawberry patch next to a tomato field",
)
_INSTRUCTIONS = (
    "make the pears ill",
    "remove the carrots",
    "add a maize field south of the orchard",
    "the carrots in spring",
    "make the apples flowering",
    "remove the vineyard",
    "add a lettuce field",
    "make everything ill",
    "the potatoes 0.5 ha",
    "the tomatoes ripening",
    "remove the strawberries",
    "add an onion field next to the potatoes",
    "make the grapes Riesling",
    "make it winter",
)


def _plants(recipe: SceneRecipe) -> dict[str, bytes]:
    layout = layout_scene(recipe)
    return {
        plants.field_id: b"".join(
            array.tobytes() for array in (plants.xyz, plants.yaw_rad, plants.scale, plants.height_m)
        )
        for plants in layout.fields
    }


@settings(
    max_examples=30,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
    derandomize=True,
)
@given(st.sampled_from(_SCENES), st.lists(st.sampled_from(_INSTRUCTIONS), min_size=1, max_size=3))
def test_untouched_fields_and_their_plants_stay_byte_identical(
    prompt: str, instructions: list[str]
) -> None:
    recipe = scene(prompt).recipe
    for instruction in instructions:
        try:
            result = edit_recipe(recipe, instruction)
        except PromptError:
            continue  # names nothing in this scene: nothing was changed
        before_plants, after_plants = _plants(recipe), _plants(result.recipe)
        before = {f.id: f for f in recipe.fields}
        kept = [f for f in result.recipe.fields if f.id not in result.touched]
        for spec in kept:
            assert spec.model_dump_json() == before[spec.id].model_dump_json()
            assert after_plants[spec.id] == before_plants[spec.id]
        assert set(result.touched) <= set(before) | {f.id for f in result.recipe.fields}
        for field_id in result.touched:  # every touched field is in the diff
            assert any(line[2:].startswith(field_id) for line in result.changes)
        recipe = result.recipe
