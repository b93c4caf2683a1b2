"""Knowledge lookups for every crop, checked against reference/crops.md."""

from __future__ import annotations

import math

import pytest

from agrirecipe import HierarchyError, KnowledgeBaseError
from agrirecipe.hierarchy import AssetKey, Hierarchy
from agrirecipe.knowledge import KnowledgeBase
from agrirecipe.recipe import Agronomy, FieldGeometry, FieldSpec

# reference/crops.md section A for each crop's default variety:
# pattern, row (or bed) spacing, in-row spacing, rows per bed, row spacing in the bed,
# max height, Kc mid.
SECTION_A = {
    "Apple": ("tree_rows", 3.4, 1.0, 1, 0.0, 4.0, 0.95),
    "Pear": ("tree_rows", 3.5, 1.0, 1, 0.0, 4.0, 0.95),
    "Cherry": ("tree_rows", 4.6, 2.4, 1, 0.0, 4.0, 0.95),
    "Orange": ("tree_rows", 7.2, 3.8, 1, 0.0, 4.0, 0.65),
    "Grape": ("trellis_rows", 2.5, 1.6, 1, 0.0, 1.75, 0.70),
    "Strawberry": ("double_rows_on_beds", 1.5, 0.30, 2, 0.30, 0.2, 0.85),
    # Cavendish is Dwarf Cavendish: 1.8-2.4 m [17]; the crop's 4 m is the second-year banana.
    "Banana": ("double_rows_on_beds", 4.75, 2.25, 2, 1.0, 2.1, 1.20),
    "Tomato": ("rows", 1.5, 0.5, 1, 0.0, 0.6, 1.15),
    "Potato": ("ridges", 0.75, 0.33, 1, 0.0, 0.6, 1.15),
    "Carrot": ("ridges", 0.75, 0.02, 2, 0.07, 0.3, 1.05),
    "Lettuce": ("rows", 0.35, 0.30, 1, 0.0, 0.3, 1.00),
    "Cabbage": ("rows", 0.75, 0.45, 1, 0.0, 0.4, 1.05),
    "Onion": ("rows", 0.30, 0.10, 1, 0.0, 0.4, 1.05),
    "Pepper": ("double_rows_on_beds", 1.45, 0.45, 2, 0.45, 0.7, 1.05),
    "Maize": ("rows", 0.75, 0.15, 1, 0.0, 2.0, 1.20),
    "Wheat": ("drilled_rows", 0.125, 0.05, 1, 0.0, 1.0, 1.15),
}
# Planting densities the sources give, as (low, high) plants per hectare.
SOURCED_DENSITY_PER_HA = {
    "Apple": (2_200, 3_200),  # [1][2]
    "Pear": (2_500, 3_000),  # [3]
    "Banana": (1_800, 1_900),  # 1,840/ha [15]
    "Potato": (33_000, 43_000),  # 0.75 x 0.31-0.40 [20][21]; AQ 40,000
    "Carrot": (1_110_000, 2_220_000),  # 111-222 plants/m2 [24]
    "Lettuce": (60_000, 100_000),  # [26]
    "Maize": (80_000, 90_000),  # grain maize [33]
    "Wheat": (700_000, 1_700_000),  # 70-170 plants/m2 [36]
}
# reference/crops.md section B: default variety, growth form, leaf habit, disease, ill tint.
SECTION_B = {
    "Apple": ("Jonagold", "tree", "deciduous", "apple scab", "necrotic"),
    "Pear": ("Conference", "tree", "deciduous", "fire blight", "necrotic"),
    "Cherry": ("Kordia", "tree", "deciduous", "brown rot", "necrotic"),
    "Orange": ("Valencia", "tree", "evergreen", "citrus greening (HLB)", "chlorotic"),
    "Grape": ("Chardonnay", "vine", "deciduous", "downy mildew", "chlorotic"),
    "Strawberry": ("Elsanta", "row_crop", "perennial", "grey mould (Botrytis)", "necrotic"),
    "Banana": ("Cavendish", "tree", "evergreen", "black Sigatoka", "necrotic"),
    "Tomato": ("Roma", "bush", "annual", "late blight", "necrotic"),
    "Potato": ("Bintje", "row_crop", "annual", "late blight", "necrotic"),
    "Carrot": ("Nantes", "row_crop", "biennial", "Alternaria leaf blight", "necrotic"),
    "Lettuce": ("Butterhead", "leafy_head", "annual", "downy mildew", "chlorotic"),
    "Cabbage": ("Savoy", "leafy_head", "biennial", "black rot", "chlorotic"),
    "Onion": ("Sturon", "row_crop", "biennial", "downy mildew", "chlorotic"),
    "Pepper": ("California Wonder", "bush", "annual", "bacterial spot", "necrotic"),
    "Maize": ("Dent", "cereal", "annual", "northern corn leaf blight", "necrotic"),
    "Wheat": ("Winter Wheat", "cereal", "annual", "yellow rust", "chlorotic"),
}
# The stage assumed for a crop in a season when the prompt says nothing (Belgian calendar).
TYPICAL_STAGE = {
    ("Apple", "Spring"): "Reproductive",  # full bloom mid-April [37]
    ("Apple", "Fall"): "Maturation",
    ("Apple", "Winter"): "Vegetative",
    ("Cherry", "Summer"): "Maturation",  # harvest June-July [45][46]
    ("Grape", "Fall"): "Maturation",
    ("Strawberry", "Summer"): "Maturation",
    ("Potato", "Spring"): "Vegetative",  # planted mid-April [21]
    ("Potato", "Fall"): "Maturation",
    ("Maize", "Summer"): "Reproductive",
    ("Maize", "Fall"): "Maturation",
    ("Wheat", "Winter"): "Vegetative",  # sown Oct-Nov [36]
    ("Wheat", "Summer"): "Maturation",
}
YELLOW = (0.8, 0.75, 0.2)
BROWN = (0.45, 0.3, 0.15)


@pytest.fixture(scope="module")
def kb(knowledge: KnowledgeBase) -> KnowledgeBase:
    return knowledge


def _agronomy(
    kb: KnowledgeBase,
    crop: str,
    variety: str | None,
    stage: str,
    season: str,
    health: str = "Healthy",
) -> Agronomy:
    variety = variety or kb.default_variety(crop)
    return kb.agronomy(kb.hierarchy.key(crop, variety, stage, season, health))


def _distance(a: tuple[float, ...], b: tuple[float, ...]) -> float:
    return math.dist(a, b)


def test_every_crop_is_covered(kb: KnowledgeBase) -> None:
    assert set(SECTION_A) == set(SECTION_B) == set(kb.hierarchy.crops)


@pytest.mark.parametrize("crop", sorted(SECTION_A))
def test_section_a_values(kb: KnowledgeBase, crop: str) -> None:
    pattern, row, in_row, rows_per_bed, bed_rows, height, kc = SECTION_A[crop]
    agronomy = _agronomy(kb, crop, None, "Maturation", "Summer")
    assert agronomy.planting_pattern == pattern
    assert agronomy.row_spacing_m == pytest.approx(row)
    assert agronomy.in_row_spacing_m == pytest.approx(in_row)
    assert agronomy.rows_per_bed == rows_per_bed
    assert agronomy.bed_row_spacing_m == pytest.approx(bed_rows)
    assert agronomy.max_height_m == pytest.approx(height)
    assert agronomy.kc_mid == pytest.approx(kc)
    assert agronomy.plant_height_m == pytest.approx(height)  # full height at maturation
    assert "F12" in agronomy.sources


@pytest.mark.parametrize("crop", sorted(SOURCED_DENSITY_PER_HA))
def test_spacing_gives_the_sourced_density(kb: KnowledgeBase, crop: str) -> None:
    planting = kb.crop_file(crop).planting
    per_ha = (
        planting.rows_per_bed
        * 10_000
        / (planting.row_spacing_m.value * planting.in_row_spacing_m.value)
    )
    low, high = SOURCED_DENSITY_PER_HA[crop]
    assert low <= per_ha <= high


@pytest.mark.parametrize("crop", sorted(SECTION_B))
def test_section_b_values(kb: KnowledgeBase, crop: str) -> None:
    default, form, habit, disease, tint = SECTION_B[crop]
    assert kb.default_variety(crop) == default
    entry = kb.crop_file(crop)
    assert (entry.growth_form, entry.leaf_habit) == (form, habit)
    assert (entry.disease.name, entry.disease.ill_tint) == (disease, tint)
    assert entry.disease.sign
    assert entry.default_variety.note, "say why this variety is the default"


@pytest.mark.parametrize(("crop", "season"), sorted(TYPICAL_STAGE))
def test_typical_stage(kb: KnowledgeBase, crop: str, season: str) -> None:
    assert kb.typical_stage(crop, season) == TYPICAL_STAGE[crop, season]


def test_typical_stage_is_plausible_wherever_the_crop_grows(kb: KnowledgeBase) -> None:
    for crop in kb.hierarchy.crops.values():
        for variety in crop.varieties:
            for season in kb.hierarchy.seasons:
                stage = kb.typical_stage(crop.name, season, variety.name)
                grown = bool(kb.plausible_stages(crop.name, season, variety.name))
                reason = kb.implausibility(crop.name, variety.name, stage, season)
                assert (reason is None) == grown, (crop.name, variety.name, season, reason)


def test_typical_season(kb: KnowledgeBase) -> None:
    assert kb.typical_season("Apple", "Reproductive") == "Spring"
    assert kb.typical_season("Apple", "Maturation") == "Fall"
    assert kb.typical_season("Wheat", "Maturation") == "Summer"
    assert kb.typical_season("Potato", "Vegetative") == "Spring"


@pytest.mark.parametrize("crop", ["Apple", "Pear", "Cherry", "Grape"])
def test_deciduous_crops_are_leafless_in_winter(
    kb: KnowledgeBase, hierarchy: Hierarchy, crop: str
) -> None:
    for variety in hierarchy.crop(crop).varieties:
        for stage in hierarchy.stages:
            for health in hierarchy.health:
                agronomy = _agronomy(kb, crop, variety.name, stage, "Winter", health)
                assert agronomy.foliage == "leafless"
                assert (
                    agronomy.foliage_rgb
                    == _agronomy(kb, "Apple", None, "Vegetative", "Winter").foliage_rgb
                )


@pytest.mark.parametrize("crop", ["Orange", "Banana"])
def test_evergreen_crops_keep_their_leaves(
    kb: KnowledgeBase, hierarchy: Hierarchy, crop: str
) -> None:
    for key in hierarchy.assets():
        if key.crop == crop:
            agronomy = kb.agronomy(key)
            assert agronomy.foliage not in ("leafless", "autumn", "budding")
            assert agronomy.leaf_habit == "evergreen"


@pytest.mark.parametrize("crop", ["Apple", "Pear", "Cherry", "Grape"])
def test_autumn_colouring(kb: KnowledgeBase, crop: str) -> None:
    agronomy = _agronomy(kb, crop, None, "Vegetative", "Fall")
    summer = _agronomy(kb, crop, None, "Vegetative", "Summer")
    assert agronomy.foliage == "autumn"
    assert agronomy.foliage_rgb == kb.crop_file(crop).colours.autumn_rgb.value  # type: ignore[union-attr]
    assert agronomy.foliage_rgb[0] > summer.foliage_rgb[0] + 0.3  # turned red/orange/yellow


def test_red_grapes_colour_red(kb: KnowledgeBase) -> None:
    pinot = _agronomy(kb, "Grape", "Pinot Noir", "Vegetative", "Fall").foliage_rgb
    chardonnay = _agronomy(kb, "Grape", "Chardonnay", "Vegetative", "Fall").foliage_rgb
    assert pinot[0] > pinot[1] + 0.3
    assert chardonnay[1] > pinot[1]


def test_seasonal_foliage_of_an_apple_tree(kb: KnowledgeBase) -> None:
    assert _agronomy(kb, "Apple", None, "Vegetative", "Spring").foliage == "budding"
    assert _agronomy(kb, "Apple", None, "Reproductive", "Spring").foliage == "flowering"
    # In July an orchard carries growing fruit, not blossom.
    assert _agronomy(kb, "Apple", None, "Reproductive", "Summer").foliage == "fruiting"
    assert _agronomy(kb, "Apple", None, "Maturation", "Summer").foliage == "fruiting"
    assert _agronomy(kb, "Apple", None, "Vegetative", "Summer").foliage == "leafy"


def test_flowering_follows_each_crops_calendar(kb: KnowledgeBase) -> None:
    assert _agronomy(kb, "Banana", None, "Reproductive", "Fall").foliage == "flowering"
    assert _agronomy(kb, "Grape", None, "Reproductive", "Summer").foliage == "flowering"
    assert _agronomy(kb, "Maize", None, "Reproductive", "Summer").foliage == "flowering"
    assert _agronomy(kb, "Strawberry", "Albion", "Reproductive", "Fall").foliage == "flowering"
    assert _agronomy(kb, "Strawberry", "Elsanta", "Reproductive", "Fall").foliage == "fruiting"


def test_ripe_cereals_turn_to_straw(kb: KnowledgeBase) -> None:
    for crop, variety in (("Wheat", "Winter Wheat"), ("Maize", "Dent")):
        ripe = _agronomy(kb, crop, variety, "Maturation", "Summer")
        assert ripe.foliage == "senescent"
        red, green, blue = ripe.foliage_rgb
        assert red > green > blue and red > 0.7  # golden straw
    # Sweet corn is picked green, at the milk stage.
    assert _agronomy(kb, "Maize", "Sweet Corn", "Maturation", "Summer").foliage == "fruiting"


@pytest.mark.parametrize("crop", sorted(SECTION_B))
def test_ill_plants_show_their_disease(kb: KnowledgeBase, crop: str) -> None:
    stage = kb.typical_stage(crop, "Summer")
    healthy = _agronomy(kb, crop, None, stage, "Summer")
    ill = _agronomy(kb, crop, None, stage, "Summer", "Ill")
    entry = kb.crop_file(crop)
    assert (healthy.disease, healthy.disease_sign) == (None, None)
    assert (ill.disease, ill.disease_sign) == (entry.disease.name, entry.disease.sign)
    assert entry.disease.source in ill.sources
    assert ill.plant_height_m < healthy.plant_height_m  # stunted
    target = YELLOW if entry.disease.ill_tint == "chlorotic" else BROWN
    assert _distance(ill.foliage_rgb, target) < _distance(healthy.foliage_rgb, target)


def test_ill_leafless_trees_stay_bare(kb: KnowledgeBase) -> None:
    ill = _agronomy(kb, "Pear", None, "Vegetative", "Winter", "Ill")
    healthy = _agronomy(kb, "Pear", None, "Vegetative", "Winter")
    assert ill.foliage == "leafless"
    assert ill.foliage_rgb == healthy.foliage_rgb
    assert ill.disease == "fire blight"


def test_flowering_apple_in_winter_is_implausible(kb: KnowledgeBase, hierarchy: Hierarchy) -> None:
    reason = kb.implausibility("Apple", "Gala", "Reproductive", "Winter")
    assert reason is not None
    assert "not normally flowering or setting fruit in Winter" in reason
    assert "dormant and leafless" in reason
    assert reason.endswith("plausible: Vegetative")
    entry = kb.lookup(hierarchy.key("Apple", "Gala", "Reproductive", "Winter", "Healthy"))
    assert not entry.plausible
    assert entry.implausibility == reason
    assert kb.implausibility("Apple", "Gala", "Reproductive", "Spring") is None


def test_field_vegetables_are_not_grown_in_winter(kb: KnowledgeBase) -> None:
    for crop in ("Tomato", "Potato", "Lettuce", "Pepper", "Maize", "Onion", "Carrot"):
        reason = kb.implausibility(crop, kb.default_variety(crop), "Vegetative", "Winter")
        assert reason is not None and "not normally grown in the field in Winter" in reason
    # Winter cabbages and winter wheat are.
    assert kb.implausibility("Cabbage", "Savoy", "Maturation", "Winter") is None
    assert kb.implausibility("Wheat", "Winter Wheat", "Vegetative", "Winter") is None


def test_variety_overrides(kb: KnowledgeBase) -> None:
    cavendish = _agronomy(kb, "Banana", "Cavendish", "Maturation", "Summer")
    assert cavendish.max_height_m == 2.1 and "17" in cavendish.sources
    assert _agronomy(kb, "Banana", "Gros Michel", "Maturation", "Summer").max_height_m > 4.0
    assert _agronomy(kb, "Maize", "Sweet Corn", "Maturation", "Summer").max_height_m == 1.5
    # Spring wheat is sown in spring; winter wheat stands over winter.
    assert kb.plausible_stages("Wheat", "Winter", "Spring Wheat") == ()
    assert kb.plausible_stages("Wheat", "Winter", "Winter Wheat") == ("Vegetative",)
    # Early cabbages are cut before winter.
    assert kb.plausible_stages("Cabbage", "Winter", "Golden Acre") == ()
    # Valencia is the late orange: picked in spring.
    assert kb.typical_stage("Orange", "Spring", "Valencia") == "Maturation"
    assert kb.typical_stage("Orange", "Spring", "Navel") == "Reproductive"
    assert kb.typical_stage("Orange", "Winter", "Navel") == "Maturation"  # picked Nov-Mar


def _fruit(kb: KnowledgeBase, crop: str, variety: str) -> tuple[float, float, float]:
    fruit = _agronomy(kb, crop, variety, "Maturation", "Summer").fruit_rgb
    assert fruit is not None
    return fruit


def _foliage(kb: KnowledgeBase, crop: str, variety: str) -> tuple[float, float, float]:
    return _agronomy(kb, crop, variety, "Vegetative", "Summer").foliage_rgb


def test_variety_colours(kb: KnowledgeBase) -> None:
    r, g, b = _fruit(kb, "Apple", "Granny Smith")
    assert g > r > b  # green
    r, g, b = _fruit(kb, "Apple", "Golden Delicious")
    assert r > 0.8 and g > 0.7 and b < 0.4  # yellow
    r, g, b = _fruit(kb, "Orange", "Moro")
    assert r > 2 * g  # blood orange: red-blushed
    r, g, b = _fruit(kb, "Onion", "Red Baron")
    assert r > 2 * g
    r, g, b = _foliage(kb, "Lettuce", "Lollo Rosso")
    assert r > 2 * g
    r, g, b = _foliage(kb, "Cabbage", "Red Express")
    assert r > g
    r, g, b = _fruit(kb, "Pepper", "Jalapeno")
    assert g > r
    r, g, b = _fruit(kb, "Pepper", "Cayenne")
    assert r > 5 * g
    r, g, b = _fruit(kb, "Pepper", "Padron")
    assert g > r


def test_stage_heights_of_annuals_and_trees(kb: KnowledgeBase) -> None:
    for crop in ("Potato", "Maize", "Lettuce"):
        vegetative = _agronomy(kb, crop, None, "Vegetative", "Summer")
        reproductive = _agronomy(kb, crop, None, "Reproductive", "Summer")
        assert 0.3 <= vegetative.plant_height_m / vegetative.max_height_m <= 0.7
        assert reproductive.plant_height_m == reproductive.max_height_m
    for crop in ("Apple", "Orange", "Grape", "Banana"):
        heights = {
            _agronomy(kb, crop, None, stage, "Summer").plant_height_m
            for stage in kb.hierarchy.stages
        }
        assert len(heights) == 1  # trees and vines keep their height (crops.md C)


def test_lookup_answers_every_catalogue_asset(kb: KnowledgeBase, hierarchy: Hierarchy) -> None:
    entries = list(kb.entries())
    assert len(entries) == 1584
    descriptors = set()
    for key, entry in zip(hierarchy.assets(), entries, strict=True):
        assert entry.key == key
        assert kb.lookup(key) == entry
        agronomy = entry.agronomy
        assert 0 < agronomy.plant_height_m <= agronomy.max_height_m
        assert agronomy.sources and all(agronomy.sources)
        assert f"{key.crop} {key.variety}" in entry.descriptor
        assert f"{key.stage} stage in {key.season}, {key.health}." in entry.descriptor
        descriptors.add(entry.descriptor)
    assert len(descriptors) == 1584  # retrieval can tell every asset apart
    assert 0.4 < sum(entry.plausible for entry in entries) / 1584 < 0.8


def test_lookup_of_an_unknown_asset(kb: KnowledgeBase) -> None:
    with pytest.raises(HierarchyError, match="'Honeycrisp' is not a variety of Apple"):
        kb.lookup(AssetKey("Fruits", "Apple", "Honeycrisp", "Vegetative", "Spring", "Healthy"))
    with pytest.raises(KnowledgeBaseError, match="'Autumn' is not a season"):
        kb.plausible_stages("Apple", "Autumn")


def test_default_fields_hold_plants_and_stay_light(kb: KnowledgeBase) -> None:
    for crop in kb.hierarchy.crops.values():
        for variety in crop.varieties:
            entry = kb.lookup(
                kb.hierarchy.key(crop.name, variety.name, "Maturation", "Summer", "Healthy")
            )
            spec = FieldSpec(
                id="f",
                label="f",
                category=crop.category,
                crop=crop.name,
                variety=variety.name,
                stage="Maturation",
                season="Summer",
                health="Healthy",
                asset_path=kb.hierarchy.asset_path(entry.key),
                agronomy=entry.agronomy,
                geometry=FieldGeometry(
                    origin_m=(0.0, 0.0),
                    size_m=kb.default_field_size_m(crop.name, variety.name),
                    headland_m=kb.default_headland_m(crop.name, variety.name),
                ),
                placement=kb.default_placement(crop.name, variety.name),
            )
            assert 100 <= spec.nominal_plant_count < 250_000, (crop.name, spec.nominal_plant_count)
            assert spec.placement.jitter_m < entry.agronomy.in_row_spacing_m / 2
