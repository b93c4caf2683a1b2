"""The checked-in JSON Schema is the one the models generate, and it accepts real recipes."""

from __future__ import annotations

import json
from pathlib import Path

import jsonschema
import pytest

from agrirecipe.recipe import recipe_json_schema, schema_text

SCHEMA_FILE = Path(__file__).resolve().parents[1] / "schemas" / "scene-recipe.schema.json"
EXAMPLES = sorted((SCHEMA_FILE.parents[1] / "examples" / "recipes").glob("*.json"))


def test_checked_in_schema_has_not_drifted() -> None:
    assert SCHEMA_FILE.read_text(encoding="utf-8") == schema_text(), (
        "the recipe models changed; regenerate the schema with\n"
        "  .venv/bin/python -m agrirecipe schema > schemas/scene-recipe.schema.json"
    )


def test_schema_is_a_valid_draft_2020_12_schema() -> None:
    schema = json.loads(SCHEMA_FILE.read_text(encoding="utf-8"))
    jsonschema.Draft202012Validator.check_schema(schema)
    assert schema["$schema"] == "https://json-schema.org/draft/2020-12/schema"
    assert schema == recipe_json_schema()


def test_field_attributes_are_flat_and_required() -> None:
    schema = recipe_json_schema()
    field = schema["$defs"]["FieldSpec"]
    for name in ("category", "crop", "variety", "stage", "season", "health", "asset_path"):
        assert name in field["required"]
        assert (
            field["properties"][name].get("type") == "string" or "enum" in field["properties"][name]
        )
    assert field["properties"]["stage"]["enum"] == ["Vegetative", "Reproductive", "Maturation"]
    assert field["properties"]["season"]["enum"] == ["Spring", "Summer", "Fall", "Winter"]
    assert field["properties"]["health"]["enum"] == ["Healthy", "Ill"]
    assert field["additionalProperties"] is False


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_examples_follow_the_checked_in_schema(path: Path) -> None:
    schema = json.loads(SCHEMA_FILE.read_text(encoding="utf-8"))
    jsonschema.Draft202012Validator(schema).validate(json.loads(path.read_text(encoding="utf-8")))


def test_schema_rejects_a_broken_recipe() -> None:
    schema = json.loads(SCHEMA_FILE.read_text(encoding="utf-8"))
    data = json.loads(EXAMPLES[0].read_text(encoding="utf-8"))
    data["fields"][0]["agronomy"]["row_spacing_m"] = 0
    errors = list(jsonschema.Draft202012Validator(schema).iter_errors(data))
    assert [list(error.absolute_path) for error in errors] == [
        ["fields", 0, "agronomy", "row_spacing_m"]
    ]
