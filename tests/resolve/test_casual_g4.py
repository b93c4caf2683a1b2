"""Casual text of blind set g4 (issue 8): a listed crop that is also a tomato variety,
counted members without commas, and a member named again inside the listing."""

from __future__ import annotations

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def test_cherry_blocks_list_cherry_varieties() -> None:
    scene = recipe("3 cherry blocks: sweetheart lapins, regina & bing, all blossoming rn")
    assert [(f.crop, f.variety, f.stage) for f in scene.fields] == [
        ("Cherry", "Lapins", "Reproductive"),
        ("Cherry", "Regina", "Reproductive"),
        ("Cherry", "Bing", "Reproductive"),
    ]


def test_counted_members_without_commas() -> None:
    scene = recipe("pls make 4 fields: 2 wheat 2 corn")
    assert [f.crop for f in scene.fields] == ["Wheat", "Wheat", "Maize", "Maize"]


def test_a_member_named_again_is_not_one_more_member() -> None:
    scene = recipe("2 fields pls: bintje spuds & nantes carrots, carrots east of the spuds")
    assert [f.crop for f in scene.fields] == ["Potato", "Carrot"]
    assert [(r.kind, r.subject, r.objects) for r in scene.relations] == [
        ("east_of", scene.fields[1].id, (scene.fields[0].id,))
    ]
