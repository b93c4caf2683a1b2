"""The example recipes under ``examples/recipes`` are valid and agree with the knowledge base."""

from __future__ import annotations

from pathlib import Path

import pytest

from agrirecipe.hierarchy import Hierarchy
from agrirecipe.knowledge import KnowledgeBase
from agrirecipe.recipe import GEOMETRY_ATTRIBUTES, dump_recipe, load_recipe

_SPACING_FIELDS = ("row_spacing_m", "in_row_spacing_m", "rows_per_bed", "bed_row_spacing_m")

EXAMPLES = sorted((Path(__file__).resolve().parents[2] / "examples" / "recipes").glob("*.json"))


def test_there_are_examples() -> None:
    assert len(EXAMPLES) >= 4


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_example_is_valid_and_byte_stable(path: Path) -> None:
    recipe = load_recipe(path)
    assert dump_recipe(recipe) == path.read_text(encoding="utf-8")


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_example_agrees_with_the_knowledge_base(
    path: Path, hierarchy: Hierarchy, knowledge: KnowledgeBase
) -> None:
    recipe = load_recipe(path)
    for spec in recipe.fields:
        key = hierarchy.key(spec.crop, spec.variety, spec.stage, spec.season, spec.health)
        # Spacing the prompt stated replaces the knowledge base's (issue 8).
        stated = set(spec.stated) & set(GEOMETRY_ATTRIBUTES) - {"row_direction"}
        expected = knowledge.agronomy(key)
        if stated:
            expected = expected.model_copy(
                update={name: getattr(spec.agronomy, name) for name in _SPACING_FIELDS}
            )
        assert spec.agronomy == expected, (
            f"{path.name}: field {spec.id!r} no longer matches crops/{spec.crop.lower()}.yaml; "
            "update the example's agronomy"
        )
        assert spec.placement == knowledge.default_placement(spec.crop, spec.variety)
        if not stated:
            assert spec.geometry.headland_m == knowledge.default_headland_m(spec.crop, spec.variety)
        assert not set(spec.stated) & set(spec.inferred)
        assert {"crop", "variety"} <= set(spec.stated)
