"""After the strategy: validation, enrichment from the knowledge base, layout, ids, explain."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

from agrirecipe import UnknownCropError
from agrirecipe.enrich import DEFAULT_LATITUDE_DEG
from agrirecipe.hierarchy import default_hierarchy, load_hierarchy
from agrirecipe.knowledge import default_knowledge_base
from agrirecipe.recipe import dump_recipe
from agrirecipe.resolve import (
    FieldIntent,
    ResolveContext,
    Resolver,
    SceneIntent,
    build_recipe,
    resolve,
)


def test_unstated_attributes_come_from_the_knowledge_base() -> None:
    kb = default_knowledge_base()
    field = resolve("an apple orchard", resolver="rules").recipe.fields[0]
    assert field.variety == kb.default_variety("Apple")
    assert field.health == "Healthy"
    assert field.season == "Summer"  # the scene default
    assert field.stage == kb.typical_stage("Apple", "Summer", field.variety)
    assert set(field.inferred) == {"variety", "stage", "season", "health", "size"}
    assert field.stated == ("crop",)
    assert field.geometry.size_m == kb.default_field_size_m("Apple", field.variety)


def test_a_stated_stage_gives_its_typical_season() -> None:
    kb = default_knowledge_base()
    field = resolve("ripe Gala apples", resolver="rules").recipe.fields[0]
    assert field.season == kb.typical_season("Apple", "Maturation", "Gala")
    assert "season" in field.inferred and "stage" in field.stated


def test_a_stated_season_gives_the_typical_stage() -> None:
    kb = default_knowledge_base()
    field = resolve("a wheat field in winter", resolver="rules").recipe.fields[0]
    assert field.stage == kb.typical_stage("Wheat", "Winter", field.variety)


def test_a_season_said_once_is_the_scene_season() -> None:
    recipe = resolve("apples in autumn next to carrots", resolver="rules").recipe
    carrot = next(f for f in recipe.fields if f.crop == "Carrot")
    assert carrot.season == "Fall" and "season" in carrot.stated
    assert recipe.environment.season == "Fall"


def test_with_different_seasons_stated_the_rest_follow_the_most_common() -> None:
    recipe = resolve(
        "apples in autumn, pears in autumn, carrots in summer and a cabbage field",
        resolver="rules",
    ).recipe
    cabbage = next(f for f in recipe.fields if f.crop == "Cabbage")
    assert cabbage.season == "Fall" and "season" in cabbage.inferred
    assert recipe.environment.season == "Fall"


def test_implausible_stated_combinations_are_kept_with_a_warning() -> None:
    recipe = resolve("apple trees in full bloom in winter", resolver="rules").recipe
    field = recipe.fields[0]
    assert (field.stage, field.season) == ("Reproductive", "Winter")
    assert len(recipe.warnings) == 1 and field.id in recipe.warnings[0]


def test_plausible_requests_have_no_warnings() -> None:
    assert resolve("a healthy Pink Lady apple orchard in summer").recipe.warnings == ()


def test_ids_and_labels() -> None:
    recipe = resolve(
        "a Pink Lady apple orchard next to two Nantes carrot fields", resolver="rules"
    ).recipe
    assert [f.id for f in recipe.fields] == ["apple_orchard_1", "carrot_field_1", "carrot_field_2"]
    assert [f.label for f in recipe.fields] == [
        "Pink Lady apple orchard",
        "Nantes carrot field 1",
        "Nantes carrot field 2",
    ]


def test_the_label_keeps_the_user_noun() -> None:
    recipe = resolve("a banana plantation and a lettuce patch", resolver="rules").recipe
    assert [f.id for f in recipe.fields] == ["banana_plantation_1", "lettuce_patch_1"]


def test_the_environment() -> None:
    recipe = resolve("an apple orchard in autumn", resolver="rules").recipe
    assert recipe.environment.season == "Fall"
    assert recipe.environment.latitude_deg == DEFAULT_LATITUDE_DEG
    chile = resolve("an apple orchard in Chile", resolver="rules").recipe
    assert chile.environment.hemisphere == "south"
    given = resolve("an apple orchard in Chile", resolver="rules", latitude_deg=10.0).recipe
    assert given.environment.latitude_deg == 10.0
    assert any("argument wins" in w for w in given.warnings)


def test_fields_do_not_overlap_and_hold_plants() -> None:
    recipe = resolve("some fruit and vegetable fields and two wheat fields", seed=4).recipe
    assert len(recipe.fields) == 4
    assert all(f.nominal_plant_count > 0 for f in recipe.fields)


def test_a_small_stated_plot_keeps_room_for_plants() -> None:
    field = resolve("a 10 by 10 m strawberry patch", resolver="rules").recipe.fields[0]
    assert field.geometry.size_m == (10.0, 10.0)
    assert field.geometry.headland_m <= 1.0
    assert field.nominal_plant_count > 10


def test_the_recipe_records_the_strategy_and_seed() -> None:
    recipe = resolve("a vineyard", resolver="rules", seed=7).recipe
    assert (recipe.resolver, recipe.seed, recipe.prompt) == ("rules", 7, "a vineyard")


def test_explanation_shows_each_stage() -> None:
    resolution = resolve(
        "a Pink Lady orchard next to some vegetables", resolver="rules", explain=True
    )
    assert resolution.explanation is not None
    text = resolution.explanation.render()
    for stage in ("[decompose]", "[normalise]", "[choose]", "[enrich]", "[layout]"):
        assert stage in text
    assert "Pink Lady" in text and "next_to" in text
    assert resolve("a vineyard", resolver="rules").explanation is None


def test_a_custom_hierarchy_path(tmp_path: Path, repo_root: Path) -> None:
    raw = yaml.safe_load((repo_root / "hierarchy.yaml").read_text(encoding="utf-8"))
    raw["categories"]["Fruits"]["crops"]["Apple"]["varieties"].append(
        {"name": "Honeycrisp", "aliases": ["Honey Crisp"]}
    )
    path = tmp_path / "hierarchy.yaml"
    path.write_text(yaml.safe_dump(raw), encoding="utf-8")
    field = resolve("a honey crisp apple orchard", resolver="rules", hierarchy=path).recipe.fields[
        0
    ]
    assert (field.crop, field.variety) == ("Apple", "Honeycrisp")
    assert "/Apple/Honeycrisp/" in field.asset_path


def test_a_knowledge_folder_path(tmp_path: Path, repo_root: Path) -> None:
    folder = tmp_path / "crops"
    shutil.copytree(repo_root / "crops", folder)
    apple = yaml.safe_load((folder / "apple.yaml").read_text(encoding="utf-8"))
    apple["default_variety"]["value"] = "Fuji"
    (folder / "apple.yaml").write_text(yaml.safe_dump(apple), encoding="utf-8")
    field = resolve("an apple orchard", resolver="rules", knowledge=folder).recipe.fields[0]
    assert field.variety == "Fuji"


class _Guessing(Resolver):
    """A strategy that names a crop the hierarchy does not hold (as a faulty one might)."""

    name = "guessing"

    def resolve_intent(self, prompt: str, context: ResolveContext) -> SceneIntent:
        return SceneIntent(prompt=prompt, fields=(FieldIntent(text=prompt, crop="Mango"),))


def test_intents_are_validated_whatever_the_strategy() -> None:
    with pytest.raises(UnknownCropError, match="Mango"):
        resolve("a mango plantation", resolver=_Guessing())


def test_build_recipe_from_an_intent() -> None:
    context = ResolveContext(default_hierarchy(), default_knowledge_base(), seed=1)
    intent = SceneIntent(
        prompt="two cereal fields",
        fields=(
            FieldIntent(text="cereal", category="Cereals", generic=True, distinct_group=0),
            FieldIntent(text="cereal", category="Cereals", generic=True, distinct_group=0),
        ),
    )
    recipe, steps = build_recipe(intent, context, resolver="manual")
    assert sorted(f.crop for f in recipe.fields) == ["Maize", "Wheat"]
    assert any(step.stage == "choose" for step in steps)


_DETERMINISM_PROMPTS = [
    "a healthy Pink Lady apple orchard in summer next to young Nantes carrots",
    "a mixed farm with three different vegetables",
    "some fruit and vegetable fields, all in autumn",
]


def test_same_prompt_and_seed_give_the_same_bytes_across_processes(repo_root: Path) -> None:
    script = (
        "import sys\n"
        "from agrirecipe.resolve import resolve\n"
        "from agrirecipe.recipe import dump_recipe\n"
        "prompts = sys.argv[1:]\n"
        "sys.stdout.write('\\x00'.join(dump_recipe(resolve(p, seed=5).recipe) for p in prompts))\n"
    )
    outputs = []
    for hash_seed in ("1", "2"):
        result = subprocess.run(
            [sys.executable, "-c", script, *_DETERMINISM_PROMPTS],
            capture_output=True,
            text=True,
            encoding="utf-8",
            check=True,
            env={"PYTHONHASHSEED": hash_seed, "PATH": "", "HF_HUB_OFFLINE": "1"},
            cwd=repo_root,
        )
        outputs.append(result.stdout)
    here = "\x00".join(dump_recipe(resolve(p, seed=5).recipe) for p in _DETERMINISM_PROMPTS)
    assert outputs[0] == outputs[1] == here


def test_a_different_seed_may_choose_differently_but_never_changes_named_crops() -> None:
    named = {resolve("a Gala apple orchard", seed=s).recipe.fields[0].variety for s in range(5)}
    assert named == {"Gala"}


def test_load_hierarchy_objects_are_accepted() -> None:
    tree = load_hierarchy()
    assert resolve("a vineyard", hierarchy=tree).recipe.fields[0].crop == "Grape"


def test_a_knowledge_base_brings_its_hierarchy(tmp_path: Path, repo_root: Path) -> None:
    from agrirecipe import ConfigurationError
    from agrirecipe.knowledge import load_knowledge_base

    raw = yaml.safe_load((repo_root / "hierarchy.yaml").read_text(encoding="utf-8"))
    raw["categories"]["Fruits"]["crops"]["Apple"]["varieties"].append({"name": "Elstar"})
    path = tmp_path / "hierarchy.yaml"
    path.write_text(yaml.safe_dump(raw), encoding="utf-8")
    tree = load_hierarchy(path)
    knowledge = load_knowledge_base(repo_root / "crops", tree)
    field = resolve("Elstar apples", resolver="rules", knowledge=knowledge).recipe.fields[0]
    assert field.variety == "Elstar"
    with pytest.raises(ConfigurationError, match="another hierarchy"):
        resolve(
            "Elstar apples", resolver="rules", knowledge=knowledge, hierarchy=default_hierarchy()
        )
