"""``agrirecipe.generate``: the one call of the public contract (DESIGN.md)."""

from __future__ import annotations

from pathlib import Path

import pytest

from agrirecipe import PromptError, Scene, SceneRecipe, UnknownCropError, generate, load_recipe


def test_the_design_example() -> None:
    scene = generate("Generate a healthy Pink Lady apple orchard in summer", seed=0)
    assert isinstance(scene, Scene)
    assert isinstance(scene.recipe, SceneRecipe)
    field = scene.recipe.fields[0]
    assert (field.crop, field.variety, field.season, field.health) == (
        "Apple",
        "Pink Lady",
        "Summer",
        "Healthy",
    )
    assert field.stage in ("Vegetative", "Reproductive", "Maturation")
    assert field.asset_path == (
        f"/Game/Agriculture/Fruits/Apple/PinkLady/{field.stage}/Summer/Healthy/"
        f"SM_Apple_PinkLady_{field.stage}_Summer_Healthy."
        f"SM_Apple_PinkLady_{field.stage}_Summer_Healthy"
    )
    dumped = field.model_dump()
    for key in ("crop", "variety", "stage", "season", "health", "asset_path"):
        assert key in dumped


def test_every_strategy_name_is_accepted() -> None:
    for name in ("auto", "rules", "hybrid"):
        scene = generate("two carrot fields next to a wheat field", resolver=name)  # type: ignore[arg-type]
        assert len(scene.recipe.fields) == 3


def test_explain() -> None:
    scene = generate("some fruit and vegetable fields", seed=3, explain=True)
    assert scene.explanation is not None
    assert "[choose]" in scene.explanation.render()
    assert generate("a vineyard").explanation is None


def test_errors_reach_the_caller() -> None:
    with pytest.raises(UnknownCropError):
        generate("a mango plantation")
    with pytest.raises(PromptError):
        generate("build a parking lot")


def test_a_generated_recipe_round_trips_through_a_file(tmp_path: Path) -> None:
    scene = generate("a 2 ha Granny Smith orchard north of a 50 by 100 m field of Bintje potatoes")
    written = scene.write(tmp_path, backends=[])
    assert written == [tmp_path / "recipe.json"]
    assert load_recipe(tmp_path / "recipe.json") == scene.recipe
