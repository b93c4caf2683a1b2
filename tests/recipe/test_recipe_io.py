"""Recipe files: load(dump(r)) == r, byte-stable dumps, clear errors for bad files."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from agrirecipe import RecipeValidationError
from agrirecipe.enrich import build_environment, build_field
from agrirecipe.hierarchy import AssetKey, default_hierarchy
from agrirecipe.knowledge import default_knowledge_base
from agrirecipe.recipe import (
    FieldGeometry,
    FieldSpec,
    Placement,
    Relation,
    SceneRecipe,
    dump_recipe,
    load_recipe,
    parse_recipe,
)

RecipeFactory = Callable[..., SceneRecipe]
FieldFactory = Callable[..., FieldSpec]

_ASSETS = list(default_hierarchy().assets())
_ATTRIBUTES = ("category", "crop", "variety", "stage", "season", "health", "size")


@st.composite
def recipes(draw: st.DrawFn) -> SceneRecipe:
    """Valid recipes of one to three fields side by side, with arbitrary text and numbers."""
    hierarchy, knowledge = default_hierarchy(), default_knowledge_base()
    count = draw(st.integers(1, 3))
    fields = []
    x = draw(st.floats(-1e5, 1e5, allow_nan=False))
    y = draw(st.floats(-1e5, 1e5, allow_nan=False))
    for index in range(count):
        key: AssetKey = draw(st.sampled_from(_ASSETS))
        width, length = knowledge.default_field_size_m(key.crop, key.variety)
        scale = draw(st.floats(0.5, 1.5))
        size = (width * scale, length * scale)
        stated = draw(st.lists(st.sampled_from(_ATTRIBUTES), unique=True, max_size=4))
        inferred = [name for name in _ATTRIBUTES if name not in stated]
        placement = Placement(
            jitter_m=draw(st.floats(0.0, 0.5)),
            missing_rate=draw(st.floats(0.0, 0.5)),
            size_variation=draw(st.floats(0.0, 0.5)),
            yaw_variation_deg=draw(st.floats(0.0, 180.0)),
        )
        fields.append(
            build_field(
                hierarchy=hierarchy,
                knowledge=knowledge,
                field_id=f"field_{index}",
                label=draw(st.text(min_size=1, max_size=40)),
                crop=key.crop,
                variety=key.variety,
                stage=key.stage,  # type: ignore[arg-type]
                season=key.season,  # type: ignore[arg-type]
                health=key.health,  # type: ignore[arg-type]
                geometry=FieldGeometry(
                    origin_m=(x, y),
                    size_m=size,
                    headland_m=knowledge.default_headland_m(key.crop, key.variety),
                ),
                placement=placement,
                stated=stated,  # type: ignore[arg-type]
                inferred=inferred,  # type: ignore[arg-type]
            )
        )
        x += size[0] + draw(st.floats(0.0, 50.0))
    relations = (
        [Relation(kind="west_of", subject="field_0", objects=("field_1",))] if count > 1 else []
    )
    return SceneRecipe(
        prompt=draw(st.text(max_size=200)),
        seed=draw(st.integers(0, 2**63 - 1)),
        environment=build_environment(
            draw(st.sampled_from(["Spring", "Summer", "Fall", "Winter"])),
            draw(st.floats(-89.0, 89.0)),
        ),
        fields=tuple(fields),
        relations=tuple(relations),
        warnings=tuple(draw(st.lists(st.text(max_size=30), max_size=2))),
    )


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(recipe=recipes())
def test_round_trip_is_exact_and_byte_stable(recipe: SceneRecipe) -> None:
    text = dump_recipe(recipe)
    parsed = parse_recipe(text)
    assert parsed == recipe
    assert dump_recipe(parsed) == text
    assert dump_recipe(recipe) == text


def test_dump_is_pretty_utf8_json_ending_in_a_newline(make_recipe: RecipeFactory) -> None:
    recipe = make_recipe(prompt='Jalapeño "peppers"\nnext to\tcarrots')
    text = dump_recipe(recipe)
    assert text.endswith("}\n")
    assert "Jalapeño" in text  # not \u-escaped: a person edits these files
    assert json.loads(text)["prompt"] == 'Jalapeño "peppers"\nnext to\tcarrots'
    assert text.splitlines()[1] == '  "schema_version": "1.0",'


def test_fields_dump_flat_attributes(make_recipe: RecipeFactory) -> None:
    dumped = make_recipe().fields[0].model_dump()
    assert {name: dumped[name] for name in ("crop", "variety", "stage", "season", "health")} == {
        "crop": "Apple",
        "variety": "Pink Lady",
        "stage": "Reproductive",
        "season": "Summer",
        "health": "Healthy",
    }
    assert dumped["asset_path"] == (
        "/Game/Agriculture/Fruits/Apple/PinkLady/Reproductive/Summer/Healthy/"
        "SM_Apple_PinkLady_Reproductive_Summer_Healthy.SM_Apple_PinkLady_Reproductive_Summer_Healthy"
    )


def test_load_recipe_reads_a_file(make_recipe: RecipeFactory, tmp_path: Path) -> None:
    recipe = make_recipe()
    path = tmp_path / "recipe.json"
    path.write_text(dump_recipe(recipe), encoding="utf-8")
    assert load_recipe(path) == recipe
    assert load_recipe(str(path)) == recipe


def test_missing_file(tmp_path: Path) -> None:
    with pytest.raises(RecipeValidationError, match="does not exist"):
        load_recipe(tmp_path / "nope.json")


def test_file_that_is_not_utf8(tmp_path: Path) -> None:
    path = tmp_path / "latin1.json"
    path.write_bytes('{"prompt": "Jalapeño"}'.encode("latin-1"))
    with pytest.raises(RecipeValidationError, match="is not UTF-8 text"):
        load_recipe(path)


def test_text_that_is_not_json() -> None:
    with pytest.raises(RecipeValidationError, match="line 2 column 1") as caught:
        parse_recipe('{"prompt": "x",\n}', source="broken.json")
    assert str(caught.value).startswith("broken.json is not valid JSON")
    assert caught.value.problems[0][0] == "<recipe>"


def test_a_list_is_not_a_recipe() -> None:
    with pytest.raises(RecipeValidationError) as caught:
        parse_recipe("[1, 2]")
    assert caught.value.problems[0][0] == "<recipe>"


def test_frozen_recipes_cannot_be_mutated(make_recipe: RecipeFactory) -> None:
    recipe = make_recipe()
    with pytest.raises(ValueError, match="frozen"):
        recipe.fields[0].crop = "Pear"  # type: ignore[misc]
