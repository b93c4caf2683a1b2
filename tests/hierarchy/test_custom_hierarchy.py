"""A user's own hierarchy (more crops, other varieties) works downstream; bad files fail."""

from __future__ import annotations

import json
import shutil
from pathlib import Path
from typing import Any

import pytest
import yaml

from agrirecipe import HierarchyError, KnowledgeBaseError, RecipeValidationError
from agrirecipe.enrich import build_environment, build_field
from agrirecipe.hierarchy import Hierarchy, default_hierarchy, load_hierarchy
from agrirecipe.knowledge import KnowledgeBase, load_knowledge_base
from agrirecipe.recipe import FieldGeometry, SceneRecipe, dump_recipe, parse_recipe

MINIMAL = """
stages: [Vegetative, Reproductive, Maturation]
seasons: [Spring, Summer, Fall, Winter]
health: [Healthy, Ill]
categories:
  Fruits:
    crops:
      Apple:
        varieties:
          - {name: Gala}
"""


@pytest.fixture(scope="module")
def custom_files(tmp_path_factory: pytest.TempPathFactory, repo_root: Path) -> tuple[Path, Path]:
    """A hierarchy with a new crop (Blueberry) and a new apple variety, and its crops folder."""
    folder = tmp_path_factory.mktemp("custom")
    raw: dict[str, Any] = yaml.safe_load((repo_root / "hierarchy.yaml").read_text("utf-8"))
    raw["content_root"] = "/Game/MyFarm"
    fruits = raw["categories"]["Fruits"]["crops"]
    fruits["Apple"]["varieties"].append({"name": "Honeycrisp", "aliases": ["Honey Crisp"]})
    fruits["Blueberry"] = {
        "aliases": ["blueberries"],
        "varieties": [{"name": "Duke", "aliases": []}, {"name": "Bluecrop", "aliases": []}],
    }
    hierarchy_file = folder / "hierarchy.yaml"
    hierarchy_file.write_text(yaml.safe_dump(raw, sort_keys=False), encoding="utf-8")

    crops = folder / "crops"
    shutil.copytree(repo_root / "crops", crops)
    blueberry: dict[str, Any] = yaml.safe_load((crops / "apple.yaml").read_text("utf-8"))
    blueberry.update(
        crop="Blueberry",
        default_variety={"value": "Duke", "source": "est."},
        growth_form="bush",
        max_height_m={"value": 1.8, "source": "est."},
        canopy_width_m={"value": 1.0, "source": "est."},
        varieties={
            "Bluecrop": {"colours": {"fruit_rgb": {"value": [0.2, 0.25, 0.5], "source": "est."}}}
        },
    )
    blueberry["planting"].update(
        pattern="rows",
        row_spacing_m={"value": 3.0, "source": "est."},
        in_row_spacing_m={"value": 1.2, "source": "est."},
    )
    (crops / "blueberry.yaml").write_text(yaml.safe_dump(blueberry), encoding="utf-8")
    return hierarchy_file, crops


@pytest.fixture(scope="module")
def custom(custom_files: tuple[Path, Path]) -> tuple[Hierarchy, KnowledgeBase]:
    hierarchy_file, crops = custom_files
    hierarchy = load_hierarchy(hierarchy_file)
    return hierarchy, load_knowledge_base(crops, hierarchy)


def test_custom_catalogue(custom: tuple[Hierarchy, KnowledgeBase]) -> None:
    hierarchy, _ = custom
    assert len(hierarchy.crops) == 17
    assert len(hierarchy.varieties) == 66 + 1 + 2
    assert len(hierarchy) == 69 * 24
    for key in hierarchy.assets():
        assert hierarchy.parse_asset_path(hierarchy.asset_path(key)) == key
    key = hierarchy.key("Blueberry", "Duke", "Reproductive", "Spring", "Healthy")
    assert hierarchy.asset_path(key) == (
        "/Game/MyFarm/Fruits/Blueberry/Duke/Reproductive/Spring/Healthy/"
        "SM_Blueberry_Duke_Reproductive_Spring_Healthy.SM_Blueberry_Duke_Reproductive_Spring_Healthy"
    )


def _recipe(
    custom: tuple[Hierarchy, KnowledgeBase], crop: str, variety: str, stage: str, season: str
) -> SceneRecipe:
    """A one-field recipe built from the custom hierarchy and knowledge (default field size)."""
    hierarchy, knowledge = custom
    field = build_field(
        hierarchy=hierarchy,
        knowledge=knowledge,
        field_id="field",
        label=f"{variety} {crop.lower()}",
        crop=crop,
        variety=variety,
        stage=stage,  # type: ignore[arg-type]
        season=season,  # type: ignore[arg-type]
        health="Healthy",
        geometry=FieldGeometry(
            origin_m=(0.0, 0.0),
            size_m=knowledge.default_field_size_m(crop, variety),
            headland_m=knowledge.default_headland_m(crop, variety),
        ),
    )
    return SceneRecipe(
        prompt=f"{variety} {crop.lower()}",
        seed=1,
        environment=build_environment(season),  # type: ignore[arg-type]
        fields=(field,),
    )


def test_custom_crop_is_built_validated_and_round_tripped(
    custom: tuple[Hierarchy, KnowledgeBase],
) -> None:
    hierarchy, knowledge = custom
    assert knowledge.default_variety("Blueberry") == "Duke"
    recipe = _recipe(custom, "Blueberry", "Bluecrop", "Maturation", "Summer")
    field = recipe.fields[0]
    assert field.asset_path.startswith("/Game/MyFarm/Fruits/Blueberry/Bluecrop/Maturation/")
    assert (field.agronomy.row_spacing_m, field.agronomy.max_height_m) == (3.0, 1.8)
    assert field.agronomy.fruit_rgb == (0.2, 0.25, 0.5)
    text = dump_recipe(recipe)
    assert parse_recipe(text, hierarchy=hierarchy) == recipe
    with pytest.raises(RecipeValidationError) as caught:
        parse_recipe(text)  # the shipped hierarchy has no blueberries
    assert [path for path, _ in caught.value.problems] == ["fields[0].crop"]


def test_new_variety_takes_the_crop_defaults(custom: tuple[Hierarchy, KnowledgeBase]) -> None:
    hierarchy, knowledge = custom
    key = hierarchy.key("Apple", "Honeycrisp", "Maturation", "Fall", "Healthy")
    agronomy = knowledge.agronomy(key)
    assert agronomy.row_spacing_m == 3.4
    assert agronomy.fruit_rgb == (0.78, 0.12, 0.10)  # apple.yaml's crop-level fruit colour


def test_shipped_crops_do_not_cover_a_custom_crop(custom: tuple[Hierarchy, KnowledgeBase]) -> None:
    hierarchy, _ = custom
    with pytest.raises(KnowledgeBaseError, match="no knowledge file for crop\\(s\\) Blueberry"):
        load_knowledge_base(hierarchy=hierarchy)


def test_recipe_json_from_a_custom_hierarchy_names_the_custom_root(
    custom: tuple[Hierarchy, KnowledgeBase],
) -> None:
    data = json.loads(dump_recipe(_recipe(custom, "Apple", "Honeycrisp", "Vegetative", "Winter")))
    assert data["fields"][0]["asset_path"].startswith("/Game/MyFarm/Fruits/Apple/Honeycrisp/")
    assert data["fields"][0]["agronomy"]["foliage"] == "leafless"


MALFORMED = [
    ("not a mapping", "- Apple\n- Pear\n", "must hold a mapping"),
    ("invalid YAML", "stages: [Vegetative\n", "is not valid YAML"),
    ("unknown stage", MINIMAL.replace("Reproductive,", "Flowering,"), "Flowering not accepted"),
    ("duplicate season", MINIMAL.replace("Fall, Winter", "Fall, Fall"), "duplicate names"),
    ("no categories", MINIMAL.split("categories:")[0], "categories: Field required"),
    (
        "crop without varieties",
        MINIMAL.replace("          - {name: Gala}\n", "").replace("varieties:", "varieties: []"),
        "Apple.varieties",
    ),
    ("unknown key", MINIMAL + "colour: red\n", "colour: Extra inputs are not permitted"),
    ("bad content root", MINIMAL + "content_root: Game/Farm\n", "is not an Unreal package path"),
    (
        "crop in two categories",
        MINIMAL + "  Cereals:\n    crops:\n      Apple:\n        varieties: [{name: Dent}]\n",
        "crop 'Apple' appears in both 'Fruits' and 'Cereals'",
    ),
    (
        "names that collide as path segments",
        MINIMAL + "          - {name: gala}\n",
        "'Gala' and 'gala' in varieties of Apple both become 'Gala'",
    ),
    (
        "name that does not start with a letter",
        MINIMAL + "          - {name: 3 Rivers}\n",
        "'3 Rivers' in varieties of Apple gives the path segment '3Rivers'",
    ),
]


@pytest.mark.parametrize(
    ("text", "fragment"), [case[1:] for case in MALFORMED], ids=[case[0] for case in MALFORMED]
)
def test_malformed_hierarchy_file(tmp_path: Path, text: str, fragment: str) -> None:
    path = tmp_path / "hierarchy.yaml"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(HierarchyError) as caught:
        load_hierarchy(path)
    assert fragment in str(caught.value)


def test_minimal_file_is_accepted(tmp_path: Path) -> None:
    path = tmp_path / "hierarchy.yaml"
    path.write_text(MINIMAL, encoding="utf-8")
    hierarchy = load_hierarchy(path)
    assert len(hierarchy) == 24
    assert hierarchy.content_root == "/Game/Agriculture"


def test_missing_and_unreadable_files(tmp_path: Path) -> None:
    with pytest.raises(HierarchyError, match="does not exist"):
        load_hierarchy(tmp_path / "nope.yaml")
    with pytest.raises(HierarchyError, match="cannot be read"):
        load_hierarchy(tmp_path)  # a folder
    binary = tmp_path / "binary.yaml"
    binary.write_bytes(b"\xff\xfe\x00stages")
    with pytest.raises(HierarchyError, match="cannot be read"):
        load_hierarchy(binary)


def test_default_is_the_shipped_file() -> None:
    assert load_hierarchy() is default_hierarchy()
