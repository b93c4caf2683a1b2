"""Reading, writing and checking recipe files.

``dump_recipe`` is byte-stable (same recipe, same bytes) and
``load_recipe(dump_recipe(r)) == r``. ``check_recipe_data`` runs both the
checked-in JSON Schema (jsonschema) and the pydantic models, plus the checks
that need the hierarchy (variety of crop, asset path matches attributes), and
returns every problem with its path instead of stopping at the first.
"""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any

from pydantic import ValidationError

from agrirecipe._errors import RecipeValidationError
from agrirecipe.hierarchy import AssetKey, Hierarchy, default_hierarchy
from agrirecipe.recipe._models import DEFAULT_MAX_PLANTS, SceneRecipe

__all__ = [
    "check_recipe",
    "check_recipe_data",
    "dump_recipe",
    "load_recipe",
    "parse_recipe",
    "recipe_json_schema",
    "schema_text",
]

_SUBPATH = re.compile(
    r"^(?:Value error, )?([A-Za-z_][\w]*(?:\[\d+\])?(?:\.[A-Za-z_]\w*(?:\[\d+\])?)*): (.*)$", re.S
)


def recipe_json_schema() -> dict[str, Any]:
    """The JSON Schema (draft 2020-12) of :class:`SceneRecipe`, generated from the models."""
    schema = SceneRecipe.model_json_schema(mode="validation")
    schema["$schema"] = "https://json-schema.org/draft/2020-12/schema"
    schema["$id"] = "https://agrirecipe.dev/schemas/scene-recipe.schema.json"
    return schema


def schema_text() -> str:
    """The JSON Schema as the exact text checked in at ``schemas/scene-recipe.schema.json``."""
    return json.dumps(recipe_json_schema(), indent=2, sort_keys=True, ensure_ascii=False) + "\n"


def dump_recipe(recipe: SceneRecipe) -> str:
    """Serialise a recipe to JSON text; the same recipe always gives the same bytes."""
    return recipe.model_dump_json(indent=2) + "\n"


def _join_path(loc: tuple[int | str, ...]) -> str:
    text = ""
    for part in loc:
        if isinstance(part, int):
            text += f"[{part}]"
        else:
            text += ("." if text else "") + part
    return text


def _pydantic_problems(exc: ValidationError) -> list[tuple[str, str]]:
    problems: list[tuple[str, str]] = []
    for error in exc.errors(include_url=False):
        path = _join_path(tuple(error["loc"]))
        message = str(error["msg"])
        match = _SUBPATH.match(message)
        if match:
            sub, message = match.group(1), match.group(2)
            path = f"{path}.{sub}" if path else sub
        problems.append((path or "<recipe>", message))
    return problems


def _schema_problems(data: Any) -> list[tuple[str, str]]:
    import jsonschema

    validator = jsonschema.Draft202012Validator(recipe_json_schema())
    problems = []
    for error in sorted(validator.iter_errors(data), key=lambda e: list(map(str, e.path))):
        problems.append((_join_path(tuple(error.absolute_path)) or "<recipe>", error.message))
    return problems


def check_recipe(recipe: SceneRecipe, hierarchy: Hierarchy | None = None) -> list[tuple[str, str]]:
    """Checks that need the hierarchy: every field's attributes and asset path are in it."""
    from agrirecipe._errors import HierarchyError

    hierarchy = hierarchy or default_hierarchy()
    problems: list[tuple[str, str]] = []
    for index, spec in enumerate(recipe.fields):
        key = AssetKey(spec.category, spec.crop, spec.variety, spec.stage, spec.season, spec.health)
        try:
            expected = hierarchy.asset_path(key)
        except HierarchyError as exc:
            problems.append((f"fields[{index}]", str(exc)))
            continue
        if spec.asset_path != expected:
            problems.append(
                (
                    f"fields[{index}].asset_path",
                    f"{spec.asset_path!r} does not match the field's attributes; "
                    f"expected {expected!r}",
                )
            )
    return problems


def check_recipe_data(
    data: Any,
    *,
    hierarchy: Hierarchy | None = None,
    max_plants: int = DEFAULT_MAX_PLANTS,
) -> tuple[SceneRecipe | None, list[tuple[str, str]]]:
    """Validate decoded JSON; return the recipe (when valid) and every problem found."""
    problems = _schema_problems(data)
    recipe: SceneRecipe | None = None
    try:
        recipe = SceneRecipe.model_validate(data, context={"max_plants": max_plants})
    except ValidationError as exc:
        for problem in _pydantic_problems(exc):
            if problem not in problems:
                problems.append(problem)
    if recipe is not None:
        problems.extend(check_recipe(recipe, hierarchy))
    return (recipe if not problems else None), problems


def parse_recipe(
    text: str,
    *,
    hierarchy: Hierarchy | None = None,
    max_plants: int = DEFAULT_MAX_PLANTS,
    source: str = "<recipe>",
) -> SceneRecipe:
    """Parse recipe JSON text; raise :class:`RecipeValidationError` listing every problem."""
    try:
        data = json.loads(text)
    except json.JSONDecodeError as exc:
        raise RecipeValidationError(
            f"{source} is not valid JSON: {exc.msg} at line {exc.lineno} column {exc.colno}",
            problems=[("<recipe>", exc.msg)],
            hint="a recipe is the JSON written by `agrirecipe generate` or dump_recipe()",
        ) from exc
    recipe, problems = check_recipe_data(data, hierarchy=hierarchy, max_plants=max_plants)
    if recipe is None:
        listing = "\n".join(f"  {path}: {message}" for path, message in problems)
        raise RecipeValidationError(
            f"{source} is not a valid recipe ({len(problems)} problem(s)):\n{listing}",
            problems=problems,
            hint="`agrirecipe schema` prints the accepted format",
        )
    return recipe


def load_recipe(
    path: str | Path,
    *,
    hierarchy: Hierarchy | None = None,
    max_plants: int = DEFAULT_MAX_PLANTS,
) -> SceneRecipe:
    """Read and validate a recipe file."""
    source = Path(path)
    try:
        text = source.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise RecipeValidationError(f"recipe file {str(source)!r} does not exist") from None
    except UnicodeDecodeError as exc:
        raise RecipeValidationError(f"recipe file {str(source)!r} is not UTF-8 text") from exc
    return parse_recipe(text, hierarchy=hierarchy, max_plants=max_plants, source=str(source))
