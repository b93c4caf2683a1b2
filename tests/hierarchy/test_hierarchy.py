"""The shipped hierarchy and its catalogue of 1,584 Unreal object paths."""

from __future__ import annotations

import re

import pytest

from agrirecipe import HierarchyError
from agrirecipe.hierarchy import AssetKey, Hierarchy, load_hierarchy, pascal_case

# The canonical hierarchy of reference/crops.md: names are part of the public contract.
CANONICAL = {
    "Fruits": {
        "Apple": ["Pink Lady", "Gala", "Golden Delicious", "Granny Smith", "Fuji", "Jonagold"],
        "Pear": ["Conference", "Doyenne du Comice", "Williams", "Durondeau"],
        "Cherry": ["Bing", "Lapins", "Kordia", "Regina"],
        "Orange": ["Valencia", "Navel", "Hamlin", "Moro"],
        "Grape": ["Chardonnay", "Pinot Noir", "Cabernet Sauvignon", "Riesling"],
        "Strawberry": ["Elsanta", "Sonata", "Malling Centenary", "Albion"],
        "Banana": ["Cavendish", "Grand Nain", "Gros Michel", "Lady Finger"],
    },
    "Vegetables": {
        "Tomato": ["Roma", "San Marzano", "Beefsteak", "Cherry"],
        "Potato": ["Bintje", "Fontane", "Agria", "Russet Burbank"],
        "Carrot": ["Nantes", "Chantenay", "Imperator", "Danvers"],
        "Lettuce": ["Romaine", "Iceberg", "Butterhead", "Lollo Rosso"],
        "Cabbage": ["Savoy", "January King", "Red Express", "Golden Acre"],
        "Onion": ["Sturon", "Red Baron", "Stuttgarter", "Walla Walla"],
        "Pepper": ["California Wonder", "Jalapeno", "Cayenne", "Padron"],
    },
    "Cereals": {
        "Maize": ["Sweet Corn", "Dent", "Flint", "Popcorn"],
        "Wheat": ["Winter Wheat", "Spring Wheat", "Durum", "Spelt"],
    },
}
PATH = re.compile(
    r"^/Game/Agriculture/(?P<category>[A-Za-z]+)/(?P<crop>[A-Za-z]+)/(?P<variety>[A-Za-z]+)/"
    r"(?P<stage>[A-Za-z]+)/(?P<season>[A-Za-z]+)/(?P<health>[A-Za-z]+)/"
    r"(?P<object>SM_(?P=crop)_(?P=variety)_(?P=stage)_(?P=season)_(?P=health))\.(?P=object)$"
)


def test_canonical_names(hierarchy: Hierarchy) -> None:
    assert {
        category.name: {
            crop: [v.name for v in hierarchy.crops[crop].varieties] for crop in category.crops
        }
        for category in hierarchy.categories.values()
    } == CANONICAL
    assert hierarchy.stages == ("Vegetative", "Reproductive", "Maturation")
    assert hierarchy.seasons == ("Spring", "Summer", "Fall", "Winter")
    assert hierarchy.health == ("Healthy", "Ill")


def test_catalogue_size(hierarchy: Hierarchy) -> None:
    assert (len(hierarchy.categories), len(hierarchy.crops), len(hierarchy.varieties)) == (
        3,
        16,
        66,
    )
    assert len(hierarchy) == 1584
    assert len(list(hierarchy.assets())) == 1584
    assert len(set(hierarchy.assets())) == 1584


def test_path_and_attributes_are_exact_inverses_on_every_asset(hierarchy: Hierarchy) -> None:
    paths = set()
    for key in hierarchy.assets():
        path = hierarchy.asset_path(key)
        match = PATH.match(path)
        assert match, path
        assert match["crop"] == pascal_case(key.crop)
        assert match["variety"] == pascal_case(key.variety)
        assert hierarchy.parse_asset_path(path) == key
        paths.add(path)
    assert len(paths) == 1584


def test_design_example_path(hierarchy: Hierarchy) -> None:
    key = hierarchy.key("Apple", "Pink Lady", "Maturation", "Summer", "Healthy")
    assert key == AssetKey("Fruits", "Apple", "Pink Lady", "Maturation", "Summer", "Healthy")
    assert hierarchy.asset_path(key) == (
        "/Game/Agriculture/Fruits/Apple/PinkLady/Maturation/Summer/Healthy/"
        "SM_Apple_PinkLady_Maturation_Summer_Healthy.SM_Apple_PinkLady_Maturation_Summer_Healthy"
    )


@pytest.mark.parametrize(
    ("name", "segment"),
    [
        ("Doyenne du Comice", "DoyenneDuComice"),
        ("Jalapeño", "Jalapeno"),
        ("Williams' Bon Chrétien", "WilliamsBonChretien"),
        ("sweet corn", "SweetCorn"),
        ("Winter Wheat", "WinterWheat"),
    ],
)
def test_pascal_case(name: str, segment: str) -> None:
    assert pascal_case(name) == segment


def test_unknown_path_names_the_nearest(hierarchy: Hierarchy) -> None:
    right = hierarchy.asset_path(hierarchy.key("Pear", "Conference", "Vegetative", "Winter", "Ill"))
    typo = right.replace("Conference", "Conferance").replace("/Ill/", "/Il/")
    with pytest.raises(HierarchyError, match="is not an asset of this hierarchy") as caught:
        hierarchy.parse_asset_path(typo)
    assert caught.value.hint == f"nearest valid path: {right}"
    assert hierarchy.nearest_asset_path(typo) == right


def test_path_under_another_root_is_not_in_the_catalogue(hierarchy: Hierarchy) -> None:
    path = hierarchy.asset_path(hierarchy.key("Wheat", "Spelt", "Maturation", "Summer", "Healthy"))
    with pytest.raises(HierarchyError, match="nearest valid path"):
        hierarchy.parse_asset_path(path.replace("/Game/Agriculture/", "/Game/Other/"))


@pytest.mark.parametrize(
    ("attributes", "fragment"),
    [
        (("Aple", "Gala", "Vegetative", "Spring", "Healthy"), "nearest: Apple"),
        (("Apple", "Galla", "Vegetative", "Spring", "Healthy"), "nearest: Gala"),
        (("Apple", "Gala", "Flowering", "Spring", "Healthy"), "'Flowering' is not a stage"),
        (("Apple", "Gala", "Vegetative", "Autumn", "Healthy"), "accepted: Spring, Summer"),
        (("Apple", "Gala", "Vegetative", "Spring", "Sick"), "'Sick' is not a health"),
    ],
)
def test_key_checks_every_attribute(
    hierarchy: Hierarchy, attributes: tuple[str, ...], fragment: str
) -> None:
    with pytest.raises(HierarchyError) as caught:
        hierarchy.key(*attributes)
    assert fragment in str(caught.value)


def test_category_must_match_the_crop(hierarchy: Hierarchy) -> None:
    with pytest.raises(HierarchyError, match="Apple belongs to Fruits, not Cereals"):
        hierarchy.asset_path(
            AssetKey("Cereals", "Apple", "Gala", "Vegetative", "Spring", "Healthy")
        )


def test_aliases_and_trade_names(hierarchy: Hierarchy) -> None:
    apple = hierarchy.crop("Apple")
    assert "Cripps Pink" in apple.variety("Pink Lady").aliases
    assert "Bartlett" in hierarchy.crop("Pear").variety("Williams").aliases
    assert "Dwarf Cavendish" in hierarchy.crop("Banana").variety("Cavendish").aliases
    assert "corn" in hierarchy.crop("Maize").aliases


@pytest.mark.parametrize("root", ["/Game/MyFarm", "/Game/MyFarm/Crops/", "/MyPlugin/Plants"])
def test_configurable_content_root(hierarchy: Hierarchy, root: str) -> None:
    moved = hierarchy.with_content_root(root)
    assert load_hierarchy(content_root=root).content_root == moved.content_root
    assert moved.content_root == root.rstrip("/")
    for key in list(moved.assets())[::97]:
        path = moved.asset_path(key)
        assert path.startswith(root.rstrip("/") + "/")
        assert path.removeprefix(moved.content_root) == hierarchy.asset_path(key).removeprefix(
            "/Game/Agriculture"
        )
        assert moved.parse_asset_path(path) == key
    assert moved.digest() != hierarchy.digest()
    assert hierarchy.content_root == "/Game/Agriculture"  # the original is unchanged


@pytest.mark.parametrize("root", ["Game/Agriculture", "/Game/My Farm", "/Game/Agri-culture", "/"])
def test_bad_content_root(hierarchy: Hierarchy, root: str) -> None:
    with pytest.raises(HierarchyError, match="is not an Unreal package path"):
        hierarchy.with_content_root(root)


def test_digest_is_stable(hierarchy: Hierarchy) -> None:
    assert hierarchy.digest() == load_hierarchy(hierarchy.source).digest()
    assert re.fullmatch(r"[0-9a-f]{16}", hierarchy.digest())
