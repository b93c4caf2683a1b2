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

_ROOT = "<recipe>"
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
    errors = exc.errors(include_url=False)
    locations = [tuple(error["loc"]) for error in errors]
    problems: list[tuple[str, str]] = []
    for error in errors:
        loc = tuple(error["loc"])
        # pydantic also calls a tuple "too short" when its items failed validation;
        # the item errors already say what is wrong.
        if error["type"] == "too_short" and any(
            len(other) > len(loc) and other[: len(loc)] == loc for other in locations
        ):
            continue
        path = _join_path(loc)
        message = str(error["msg"])
        match = _SUBPATH.match(message)
        if match:
            sub, message = match.group(1), match.group(2)
            path = f"{path}.{sub}" if path else sub
        problems.append((path or _ROOT, message))
    return problems


def _schema_problems(data: Any) -> list[tuple[str, str]]:
    import jsonschema

    validator = jsonschema.Draft202012Validator(recipe_json_schema())
    return [
        (_join_path(tuple(error.absolute_path)) or _ROOT, error.message)
        for error in validator.iter_errors(data)
    ]


def _covers(reported: str, path: str) -> bool:
    """True when a problem at ``reported`` already explains one at ``path`` (same or inside)."""
    if path == _ROOT or reported == path:
        return True
    return reported.startswith((f"{path}.", f"{path}["))


def _path_order(problem: tuple[str, str]) -> tuple[tuple[int, int | str], ...]:
    """Document order: ``fields[2]`` before ``fields[10]``, the whole recipe first."""
    path = problem[0]
    if path == _ROOT:
        return ()
    parts = re.findall(r"\[(\d+)\]|([^.\[\]]+)", path)
    return tuple((0, int(index)) if index else (1, name) for index, name in parts)


def check_recipe(recipe: SceneRecipe, hierarchy: Hierarchy | None = None) -> list[tuple[str, str]]:
    """Checks that need the hierarchy: every field's attributes and asset path are in it.

    Each problem names the attribute at fault (``fields[1].variety``), or the
    asset path when the attributes are fine but the path does not match them.
    """
    from agrirecipe._errors import HierarchyError

    hierarchy = hierarchy or default_hierarchy()
    problems: list[tuple[str, str]] = []
    for index, spec in enumerate(recipe.fields):
        where = f"fields[{index}]"
        try:
            crop = hierarchy.crop(spec.crop)
        except HierarchyError as exc:
            problems.append((f"{where}.crop", str(exc)))
            continue
        found: list[tuple[str, str]] = []
        if spec.category != crop.category:
            found.append(
                (
                    f"{where}.category",
                    f"{spec.category!r} does not match crop {crop.name} "
                    f"(which is in {crop.category!r})",
                )
            )
        try:
            crop.variety(spec.variety)
        except HierarchyError as exc:
            found.append((f"{where}.variety", str(exc)))
        for name, allowed in (
            ("stage", hierarchy.stages),
            ("season", hierarchy.seasons),
            ("health", hierarchy.health),
        ):
            value = getattr(spec, name)
            if value not in allowed:
                found.append(
                    (
                        f"{where}.{name}",
                        f"{value!r} is not a {name} of this hierarchy "
                        f"(accepted: {', '.join(allowed)})",
                    )
                )
        if found:
            problems.extend(found)
            continue
        key = AssetKey(spec.category, spec.crop, spec.variety, spec.stage, spec.season, spec.health)
        expected = hierarchy.asset_path(key)
        if spec.asset_path != expected:
            problems.append(
                (
                    f"{where}.asset_path",
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
    """Validate decoded JSON; return the recipe (when valid) and every problem found.

    Problems come from the pydantic models (which also run the cross-field
    checks), then from the JSON Schema for anything the models did not already
    report at the same place, then from the hierarchy; they are listed in
    document order, each as ``(path, message)``.
    """
    problems: list[tuple[str, str]] = []
    recipe: SceneRecipe | None = None
    try:
        recipe = SceneRecipe.model_validate(data, context={"max_plants": max_plants})
    except ValidationError as exc:
        problems.extend(_pydantic_problems(exc))
    for path, message in _schema_problems(data):
        if not any(_covers(reported, path) for reported, _ in problems):
            problems.append((path, message))
    if recipe is not None:
        problems.extend(check_recipe(recipe, hierarchy))
    problems.sort(key=_path_order)
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
            problems=[(_ROOT, exc.msg)],
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
