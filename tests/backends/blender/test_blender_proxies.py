"""Proxy plans: parts and colours follow growth form, stage, season and health (no bpy needed)."""

from __future__ import annotations

from typing import Any

import pytest
import yaml
from blender_recipes import field
from pydantic import ValidationError

from agrirecipe.backends._blender._proxies import BlenderStyle, load_style, proxy_plan
from agrirecipe.recipe import FieldGeometry, FieldSpec, HealthState, Season, Stage

GEOMETRY = FieldGeometry(origin_m=(0.0, 0.0), size_m=(30.0, 30.0), headland_m=1.0)


def spec(crop: str, stage: Stage, season: Season, health: HealthState = "Healthy") -> FieldSpec:
    return field("plot", crop, GEOMETRY, stage=stage, season=season, health=health)


def roles(plan: dict[str, Any]) -> set[str]:
    return {part["role"] for part in plan["parts"]}


def signature(plan: dict[str, Any]) -> tuple[tuple[str, str, str, int], ...]:
    return tuple(
        (part["role"], part["shape"], part["kind"], part["repeat"]) for part in plan["parts"]
    )


def test_each_growth_form_has_its_own_proxy() -> None:
    crops = {
        "tree": "Apple",
        "vine": "Grape",
        "bush": "Tomato",
        "row_crop": "Carrot",
        "leafy_head": "Lettuce",
        "cereal": "Wheat",
    }
    signatures = {}
    for form, crop in crops.items():
        plan = proxy_plan(spec(crop, "Vegetative", "Summer"))
        assert plan["growth_form"] == form
        signatures[form] = signature(plan)
    assert len(set(signatures.values())) == len(crops)


def test_winter_apple_is_bare_trunk_and_branches() -> None:
    winter = spec("Apple", "Vegetative", "Winter")
    assert winter.agronomy.foliage == "leafless"
    plan = proxy_plan(winter)
    assert roles(plan) == {"trunk", "branch"}
    assert set(plan["materials"]) == {"bark"}


def test_summer_apple_carries_fruit_in_the_fruit_colour() -> None:
    summer = spec("Apple", "Maturation", "Summer")
    assert summer.agronomy.foliage == "fruiting"
    plan = proxy_plan(summer)
    assert {"trunk", "branch", "canopy", "fruit"} <= roles(plan)
    assert "blossom" not in roles(plan)
    assert summer.agronomy.fruit_rgb is not None
    assert plan["materials"]["fruit"] == list(summer.agronomy.fruit_rgb)
    assert plan["materials"]["foliage"] == list(summer.agronomy.foliage_rgb)


def test_flowering_apple_has_blossom_and_no_fruit() -> None:
    spring = spec("Apple", "Reproductive", "Spring")
    assert spring.agronomy.foliage == "flowering"
    plan = proxy_plan(spring)
    assert "blossom" in roles(plan)
    assert "fruit" not in roles(plan)
    blossom = plan["materials"]["blossom"]
    assert min(blossom) > 0.8  # pale blossom, not leaf green


def test_autumn_foliage_colour_differs_from_summer() -> None:
    summer = proxy_plan(spec("Apple", "Maturation", "Summer"))
    autumn_spec = spec("Apple", "Maturation", "Fall")
    assert autumn_spec.agronomy.foliage == "autumn"
    autumn = proxy_plan(autumn_spec)
    assert autumn["materials"]["foliage"] == list(autumn_spec.agronomy.foliage_rgb)
    assert autumn["materials"]["foliage"] != summer["materials"]["foliage"]
    red, green, _ = autumn["materials"]["foliage"]
    assert red > green  # yellow/orange/red, no longer green


def test_ill_tint_reaches_the_foliage_material() -> None:
    healthy = proxy_plan(spec("Carrot", "Vegetative", "Summer"))
    ill_spec = spec("Carrot", "Vegetative", "Summer", "Ill")
    ill = proxy_plan(ill_spec)
    assert ill["materials"]["foliage"] == list(ill_spec.agronomy.foliage_rgb)
    assert ill["materials"]["foliage"] != healthy["materials"]["foliage"]
    # Stems follow the (tinted) foliage too.
    assert ill["materials"]["stem"] != healthy["materials"]["stem"]


def test_senescent_cereal_is_golden_with_ears_and_young_cereal_has_none() -> None:
    ripe_spec = spec("Wheat", "Maturation", "Summer")
    assert ripe_spec.agronomy.foliage == "senescent"
    ripe = proxy_plan(ripe_spec)
    assert "ear" in roles(ripe)
    red, green, blue = ripe["materials"]["foliage"]
    assert red > green > blue and red > 0.6
    young = proxy_plan(spec("Wheat", "Vegetative", "Spring"))
    assert "ear" not in roles(young)
    assert young["materials"]["foliage"][1] > young["materials"]["foliage"][0]  # green


def _top(plan: dict[str, Any]) -> float:
    tops = []
    for part in plan["parts"]:
        if part["kind"] == "segment":
            tops.append(max(part["start"][2], part["end"][2]))
        else:
            tops.append(part["at"][2] + part["size"][2] / 2)
    return max(tops)


@pytest.mark.parametrize("crop", ["Apple", "Grape", "Tomato", "Carrot", "Lettuce", "Wheat"])
def test_proxy_is_as_tall_as_the_plant(crop: str) -> None:
    plot = spec(crop, "Maturation", "Summer")
    plan = proxy_plan(plot)
    assert _top(plan) == pytest.approx(plot.agronomy.plant_height_m, rel=0.1)


def test_budding_leaves_are_smaller_than_full_leaves() -> None:
    budding_spec = spec("Apple", "Vegetative", "Spring")
    assert budding_spec.agronomy.foliage == "budding"
    budding = proxy_plan(budding_spec)
    leafy = proxy_plan(spec("Apple", "Vegetative", "Summer"))

    def canopy_volume(plan: dict[str, Any]) -> float:
        sizes = [p["size"] for p in plan["parts"] if p["role"] == "canopy"]
        return sum(x * y * z for x, y, z in sizes)

    assert 0 < canopy_volume(budding) < 0.5 * canopy_volume(leafy)


def test_vine_cordon_reaches_its_neighbours_along_the_row() -> None:
    vines = spec("Grape", "Maturation", "Summer")
    cordon = next(p for p in proxy_plan(vines)["parts"] if p["role"] == "branch")
    assert cordon["end"][1] - cordon["start"][1] == pytest.approx(
        vines.agronomy.in_row_spacing_m, rel=1e-6
    )


def test_shipped_style_is_complete() -> None:
    style = load_style()
    assert set(style.growth_forms) == {"tree", "vine", "bush", "row_crop", "leafy_head", "cereal"}
    assert style.variants >= 2


def test_style_rejects_an_unknown_role_and_a_missing_growth_form(repo_root: Any) -> None:
    from importlib import resources

    text = resources.files("agrirecipe.backends._blender").joinpath("style.yaml").read_text()
    raw = yaml.safe_load(text)
    raw["growth_forms"]["tree"][0]["role"] = "root"
    with pytest.raises(ValidationError, match="unknown role 'root'"):
        BlenderStyle.model_validate(raw)
    raw = yaml.safe_load(text)
    del raw["growth_forms"]["cereal"]
    with pytest.raises(ValidationError, match="no proxy for growth form 'cereal'"):
        BlenderStyle.model_validate(raw)
